/*
 * cmd_demo_model.c — `tissuefit demo-model`: a small model built in the host
 * without a scene or a solve, used to exercise the header path end to end.
 *
 * The model is the surface response of an elastic half-space to a force at
 * one point (Boussinesq for the normal part, Cerruti for the tangential
 * part; K. L. Johnson, Contact Mechanics, §2.2–2.3), softened with a core
 * radius a (r -> sqrt(r^2 + a^2)) so that the loaded point itself is finite.
 * The response is linear in the force, so the nodal family of degree 1 holds
 * it exactly; its held-out error measures only the float32 tables and
 * arithmetic, against the double-precision formula.
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "emit/emit_header.h"
#include "base/log.h"
#include "model/ref_eval.h"
#include "base/rng.h"

#define GRID 11
#define SPACING 4.8  /* mm */
#define YOUNG 0.32   /* MPa = N/mm^2 */
#define POISSON 0.49
#define CORE 2.4     /* mm */
#define HELDOUT 50

/* Displacement (mm) at surface offset (x, y) from a unit force along axis k;
 * z is the outward normal, so a pressing force has fz < 0. */
static void green(double x, double y, int k, double u[3])
{
    const double nu = POISSON, e = YOUNG;
    double r2 = x * x + y * y + CORE * CORE, r = sqrt(r2);
    if (k == 2) {
        double ur = (1 + nu) * (1 - 2 * nu) / (2 * M_PI * e * r);
        u[0] = ur * x / r;
        u[1] = ur * y / r;
        u[2] = (1 - nu * nu) / (M_PI * e * r);
        return;
    }
    double s = k == 0 ? x : y, t = k == 0 ? y : x; /* along / across the force */
    double c = (1 + nu) / (2 * M_PI * e * r);
    double along = c * (2 * (1 - nu) + 2 * nu * s * s / r2);
    double across = c * 2 * nu * s * t / r2;
    u[k] = along;
    u[1 - k] = across;
    u[2] = -(1 + nu) * (1 - 2 * nu) * s / (2 * M_PI * e * r2);
}

static void exact(const double f[3], int node, double u[3])
{
    double x = (node % GRID) * SPACING - 0.5 * (GRID - 1) * SPACING;
    double y = (node / GRID) * SPACING - 0.5 * (GRID - 1) * SPACING;
    u[0] = u[1] = u[2] = 0;
    for (int k = 0; k < 3; ++k) {
        double g[3];
        green(x, y, k, g);
        for (int i = 0; i < 3; ++i) {
            u[i] += g[i] * f[k];
        }
    }
}

static tf_model *build(tf_ctx *ctx, const char *name, double radius)
{
    const uint32_t dims[1] = {1};
    tf_model *m = tf_model_new(ctx, name, TFIT_FAMILY_NODAL, GRID * GRID, dims, 1);
    if (m == NULL) {
        return NULL;
    }
    const double centre[3] = {0, 0, 0};
    tf_model_set_ball(m, centre, radius);
    float *c = tf_model_tables(m); /* rows of 4: constant, g0, g1, g2 */
    for (int node = 0; node < GRID * GRID; ++node) {
        m->node_ids[node] = (uint32_t)node + 1;
        for (int k = 0; k < 3; ++k) {
            double f[3] = {0, 0, 0}, u[3];
            f[k] = radius; /* g_k = 1 */
            exact(f, node, u);
            for (int i = 0; i < 3; ++i) {
                c[(3 * node + i) * 4 + 1 + k] = (float)u[i];
            }
        }
    }
    return m;
}

/* Held-out error: the exact float32 result the target computes (the
 * reference evaluator reproduces it bit for bit) against the formula. */
static void measure(tf_model *m, double radius)
{
    tf_rng r = {20170912};
    float *out = malloc(3 * m->n_out * sizeof *out);
    double max = 0, sum2 = 0;
    for (int c = 0; c < HELDOUT; ++c) {
        double f[3], n2;
        do {
            for (int i = 0; i < 3; ++i) {
                f[i] = tf_rng_range(&r, -radius, radius);
            }
            n2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
        } while (n2 > radius * radius);
        float ff[3] = {(float)f[0], (float)f[1], (float)f[2]};
        double fd[3] = {ff[0], ff[1], ff[2]};
        tf_ref_eval(m, ff, out, NULL);
        for (uint32_t node = 0; node < m->n_out; ++node) {
            double u[3];
            exact(fd, (int)node, u);
            for (int i = 0; i < 3; ++i) {
                double e = fabs((double)out[3 * node + (uint32_t)i] - u[i]);
                max = e > max ? e : max;
                sum2 += e * e;
            }
        }
    }
    free(out);
    m->heldout_max = max;
    m->heldout_rms = sqrt(sum2 / (HELDOUT * 3.0 * m->n_out));
    m->heldout_cases = HELDOUT;
}

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit demo-model -o FILE.h [--envelope N]\n\n"
            "Writes FILE.h and FILE_golden.h holding a built-in model: the surface\n"
            "response of a soft elastic half-space (E = 0.32 MPa, nu = 0.49) to a force\n"
            "at its centre, on an 11 x 11 grid 4.8 mm apart (Boussinesq-Cerruti,\n"
            "softened over a 2.4 mm core).  Family nodal, degree 1 (exact for this\n"
            "linear response); the held-out error is measured at %d random forces.\n\n"
            "Options:\n"
            "  -o, --out FILE.h   header to write (its _golden.h is written beside it)\n"
            "  --envelope N       force envelope radius in newtons (default 1)\n",
            HELDOUT);
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    static const struct option opts[] = {
        {"out", required_argument, NULL, 'o'}, {"envelope", required_argument, NULL, 'e'}, {0}};
    const char *path = NULL;
    double radius = 1.0;
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "o:", opts, NULL)) != -1) {
        char *end;
        switch (c) {
        case 'o':
            path = optarg;
            break;
        case 'e':
            radius = strtod(optarg, &end);
            if (*end != '\0' || !(radius > 0) || !isfinite(radius)) {
                tf_error(ctx, "demo-model: --envelope '%s' is not a positive number of newtons",
                         optarg);
                return TF_EXIT_USAGE;
            }
            break;
        default:
            tf_error(ctx, "demo-model: bad option '%s' (see tissuefit demo-model --help)",
                     argv[optind - 1]);
            return TF_EXIT_USAGE;
        }
    }
    if (path == NULL || optind != argc) {
        tf_error(ctx, "demo-model: expected -o FILE.h and no other arguments");
        return TF_EXIT_USAGE;
    }

    char base[TF_NAME_MAX], name[TF_NAME_MAX + 16];
    if (tf_emit_check_path(ctx, path, strlen("_forward")) != 0) {
        tf_error(ctx, "demo-model: %s", ctx->err);
        return TF_EXIT_USAGE;
    }
    const char *slash = strrchr(path, '/');
    snprintf(base, sizeof base, "%s", slash ? slash + 1 : path);
    base[strcspn(base, ".")] = '\0';
    snprintf(name, sizeof name, "%s_forward", base);

    tf_model *m = build(ctx, name, radius);
    if (m == NULL) {
        tf_error(ctx, "demo-model: %s", ctx->err);
        return TF_EXIT_USAGE;
    }
    measure(m, radius);
    tf_info(ctx, "demo-model: held-out max error %.3g mm, rms %.3g mm over %d forces",
            m->heldout_max, m->heldout_rms, HELDOUT);
    const tf_emit_info info = {
        .source = "built-in demo model (no scene)",
        .notes = "Softened Boussinesq-Cerruti half-space, E = 0.32 MPa, nu = 0.49, core 2.4 mm;\n"
                 "11 x 11 surface points 4.8 mm apart, force at the centre (node 61).\n"
                 "Held-out error: float32 evaluation against the double-precision formula.",
        .golden_seed = 1,
    };
    int rc = tf_emit_header(ctx, path, &m, 1, &info);
    tf_model_free(m);
    if (rc != 0) {
        /* the path was checked: a failure while running */
        tf_error(ctx, "demo-model: %s", ctx->err);
        return TF_EXIT_FAIL;
    }
    tf_info(ctx, "demo-model: wrote %s and its golden vectors", path);
    return TF_EXIT_OK;
}

const tf_command tf_cmd_demo_model = {
    .name = "demo-model",
    .summary = "write a header from a built-in half-space model (no scene needed)",
    .run = run,
    .help = help,
};
