/*
 * block48.c — the static limit of the collocation solver on block48
 * (GUIDE §5): the box [0,48]^2 x [0,6] mm, E = 0.32 MPa, nu = 0.49,
 * lateral faces clamped, a force on the top patch [21.6, 26.4]^2 spread
 * as a uniform traction, here as nodal forces (the traction times each top
 * particle's tributary area inside the patch).  Prints the top centre's
 * (node 61's) displacement per newton for a force along +x and along -z.
 *
 *   block48 NX,NY,NZ [--load F] [--law svk|linear] [--stab S]
 *           [--neighbours K] [--support S] [--tol T]
 *
 * Output: "particles,ux_fx,uz_fz,steps_fx,steps_fz,seconds" (mm/N).  The
 * load F (default 0.01 N) is small: the answer is the small-strain limit.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solvers/collocation/colloc.h"

#define PATCH_LO 21.6
#define PATCH_HI 26.4

/* Length of [a - h/2, a + h/2] inside [0, 48] and the patch. */
static double overlap(double a, double h)
{
    double lo = fmax(fmax(a - h / 2, 0), PATCH_LO), hi = fmin(fmin(a + h / 2, 48), PATCH_HI);
    return hi > lo ? hi - lo : 0;
}

typedef struct opts {
    unsigned g[3], neighbours;
    double load, stab, support, tol;
    const char *law;
} opts;

static int parse(int argc, char **argv, opts *o)
{
    *o = (opts){.load = 0.01, .stab = -1, .support = -1, .tol = 1e-9, .law = "svk"};
    if (argc < 2 || sscanf(argv[1], "%u,%u,%u", &o->g[0], &o->g[1], &o->g[2]) != 3 ||
        o->g[0] < 3 || o->g[1] < 3 || o->g[2] < 2) {
        return -1;
    }
    for (int i = 2; i + 1 < argc; i += 2) {
        const char *k = argv[i], *v = argv[i + 1];
        if (!strcmp(k, "--law")) {
            if (strcmp(v, "svk") && strcmp(v, "linear")) {
                return -1;
            }
            o->law = v;
            continue;
        }
        char *end;
        double x = strtod(v, &end);
        if (end == v || *end) {
            return -1;
        }
        if (!strcmp(k, "--load")) {
            o->load = x;
        } else if (!strcmp(k, "--stab")) {
            o->stab = x;
        } else if (!strcmp(k, "--neighbours")) {
            o->neighbours = (unsigned)x;
        } else if (!strcmp(k, "--support")) {
            o->support = x;
        } else if (!strcmp(k, "--tol")) {
            o->tol = x;
        } else {
            return -1;
        }
    }
    return argc % 2 ? -1 : 0;
}

int main(int argc, char **argv)
{
    opts op;
    if (parse(argc, argv, &op) != 0) {
        fprintf(stderr, "usage: block48 NX,NY,NZ [--load F] [--law svk|linear] [--stab S] "
                        "[--neighbours K] [--support S] [--tol T]\n");
        return 2;
    }
    size_t nx = op.g[0], ny = op.g[1], nz = op.g[2], n = nx * ny * nz;
    double h[3] = {48.0 / (double)(nx - 1), 48.0 / (double)(ny - 1), 6.0 / (double)(nz - 1)};
    double *X = malloc(3 * n * sizeof *X), *vol = malloc(n * sizeof *vol), *pf = calloc(n, sizeof *pf);
    unsigned char *fixed = calloc(n, 1);
    if (!X || !vol || !pf || !fixed) {
        return 1;
    }
    for (size_t k = 0; k < nz; ++k) {
        for (size_t j = 0; j < ny; ++j) {
            for (size_t i = 0; i < nx; ++i) {
                size_t p = i + nx * (j + ny * k), idx[3] = {i, j, k}, dim[3] = {nx, ny, nz};
                double v = 1;
                for (int a = 0; a < 3; ++a) {
                    X[3 * p + a] = (double)idx[a] * h[a];
                    v *= idx[a] == 0 || idx[a] == dim[a] - 1 ? h[a] / 2 : h[a];
                }
                vol[p] = v;
                fixed[p] = i == 0 || j == 0 || i == nx - 1 || j == ny - 1 ? TF_COLLOC_FIX_ALL : 0;
                if (k == nz - 1) { /* share of the patch traction */
                    pf[p] = overlap(X[3 * p], h[0]) * overlap(X[3 * p + 1], h[1]) /
                            ((PATCH_HI - PATCH_LO) * (PATCH_HI - PATCH_LO));
                }
            }
        }
    }
    size_t top = nx / 2 + nx * (ny / 2 + ny * (nz - 1));
    tf_colloc_body body = {.n = n, .X = X, .fixed = fixed, .volume = vol,
                           .material = tf_material_of(tf_law_find(op.law)),
                           .density = 1e-9};
    tf_material_set(&body.material, "E", 0.32);
    tf_material_set(&body.material, "nu", 0.49);
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    o.stab = op.stab >= 0 ? op.stab : o.stab;
    o.support = op.support > 0 ? op.support : o.support;
    o.neighbours = op.neighbours ? op.neighbours : o.neighbours;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double t0 = omp_get_wtime(), out[2];
    size_t steps[2];
    tf_colloc *c = tf_colloc_new(&ctx, &body, &o);
    if (c == NULL) {
        fprintf(stderr, "block48: %s\n", ctx.err);
        return 1;
    }
    for (int load = 0; load < 2; ++load) { /* +x, then -z */
        double *fext = tf_colloc_fext(c), *u = tf_colloc_u(c);
        memset(u, 0, 3 * n * sizeof *u);
        for (size_t p = 0; p < n; ++p) {
            fext[3 * p] = load ? 0 : op.load * pf[p];
            fext[3 * p + 2] = load ? -op.load * pf[p] : 0;
        }
        tf_colloc_relax_opts ro;
        tf_colloc_relax_defaults(&ro);
        ro.tol = op.tol;
        ro.max_steps = 2000000;
        tf_colloc_relax_stats st;
        if (tf_colloc_relax(&ctx, c, &ro, &st) != 0) {
            fprintf(stderr, "block48: %s\n", st.converged ? ctx.err : "no convergence");
            return 1;
        }
        out[load] = (load ? -u[3 * top + 2] : u[3 * top]) / op.load * (load ? -1 : 1);
        steps[load] = st.steps;
    }
    printf("%zu,%.10g,%.10g,%zu,%zu,%.3f\n", n, out[0], out[1], steps[0], steps[1],
           omp_get_wtime() - t0);
    tf_colloc_free(c);
    free(X);
    free(vol);
    free(pf);
    free(fixed);
    return 0;
}
