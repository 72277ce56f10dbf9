/*
 * physics_check.c — does a shipped header understate its error against the
 * physics?  (issue 14 acceptance 3)
 *
 *   physics_check SCENE HEADER FX.csv FY.csv FZ.csv
 *
 * Recomputes block48's discretisation figure by another route than the
 * tool's (fitting/discretisation.c): solves the unit loads +x, +y and -z,
 * evaluates the field at the CalculiX points of FX/FY/FZ (node,x,y,z,ux,uy,uz),
 * and searches the envelope's sphere |F - c| = R by 20,000 directions for the
 * largest displacement component error of the linear solve,
 * e(F) = Fx Dx + Fy Dy - Fz Dz (+ the centre's).  It also recomputes the
 * contact site's relative error.  Reads the header's
 * TFIT_<NAME>_FORWARD_DISCRETISATION_MAX_MM and _CONTACT_DISCRETISATION_MAX_N
 * and fails (exit 1) when either is below the recomputed figure (1e-6
 * relative slack for rounding) or more than 2 % above it (a bound that loose
 * says nothing).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define MAXP 4096
#define DIRECTIONS 20000

typedef struct points {
    double x[MAXP][3], u[MAXP][3];
    size_t n;
} points;

static int read_csv(const char *path, points *p)
{
    FILE *fp = fopen(path, "r");
    char line[512];
    if (fp == NULL || fgets(line, sizeof line, fp) == NULL) {
        fprintf(stderr, "physics_check: cannot read %s\n", path);
        if (fp) {
            fclose(fp);
        }
        return -1;
    }
    p->n = 0;
    long node;
    while (p->n < MAXP && fgets(line, sizeof line, fp) &&
           sscanf(line, "%ld,%lf,%lf,%lf,%lf,%lf,%lf", &node, &p->x[p->n][0], &p->x[p->n][1],
                  &p->x[p->n][2], &p->u[p->n][0], &p->u[p->n][1], &p->u[p->n][2]) == 7) {
        p->n++;
    }
    fclose(fp);
    return p->n > 0 ? 0 : -1;
}

/* A #define's number from the header, NAN when absent. */
static double header_value(const char *header, const char *macro)
{
    FILE *fp = fopen(header, "r");
    char line[1024], name[256];
    double v = NAN;
    while (fp && fgets(line, sizeof line, fp)) {
        double x;
        if (sscanf(line, "#define %255s %lf", name, &x) == 2 && strcmp(name, macro) == 0) {
            v = x;
        }
    }
    if (fp) {
        fclose(fp);
    }
    return v;
}

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: physics_check SCENE HEADER FX.csv FY.csv FZ.csv\n");
        return 2;
    }
    static points ref[3];
    for (int a = 0; a < 3; ++a) {
        if (read_csv(argv[3 + a], &ref[a]) != 0 || ref[a].n != ref[0].n) {
            return 2;
        }
    }
    char err[1024], name[256];
    tf_scene *s = tf_scene_load(argv[1], NULL, 0, err, sizeof err);
    if (s == NULL) {
        fprintf(stderr, "physics_check: %s\n", err);
        return 2;
    }
    const tf_problem *p = &s->problem;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    const size_t dofs = 3 * p->cloud.n, np = ref[0].n;
    static const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    double *u = malloc(3 * dofs * sizeof *u), *grad = malloc(9 * np * sizeof *grad);
    static double d[3][MAXP][3];
    int rc = sv && u && grad ? tf_solver_solve(sv, 0, unit, 3, NULL, u) : -1;
    for (int a = 0; rc == 0 && a < 3; ++a) {
        rc = tf_solver_field(sv, u + (size_t)a * dofs, &ref[a].x[0][0], np, &d[a][0][0], grad, err,
                             sizeof err);
        for (size_t j = 0; j < np; ++j) {
            for (int k = 0; k < 3; ++k) {
                d[a][j][k] -= ref[a].u[j][k];
            }
        }
    }
    if (rc != 0) {
        fprintf(stderr, "physics_check: the solve failed\n");
        return 1;
    }
    /* the sphere by Fibonacci directions: the largest component error */
    const double r = p->envelope.radius, *c = p->envelope.centre;
    double worst = 0;
    for (int k = 0; k < DIRECTIONS; ++k) {
        const double z = 1 - (2.0 * k + 1) / DIRECTIONS, rho = sqrt(1 - z * z);
        const double phi = k * M_PI * (3 - sqrt(5));
        const double f[3] = {c[0] + r * rho * cos(phi), c[1] + r * rho * sin(phi), c[2] + r * z};
        for (size_t j = 0; j < np; ++j) {
            for (int q = 0; q < 3; ++q) {
                worst = fmax(worst, fabs(f[0] * d[0][j][q] + f[1] * d[1][j][q] - f[2] * d[2][j][q]));
            }
        }
    }
    /* the contact site: the reference point at its node */
    const tf_contact *ct = &p->contacts[0];
    const double *xn = ct->by_node ? tf_solver_coords(sv) + 3 * (size_t)ct->node : ct->at;
    double site = 0;
    for (size_t j = 0; j < np; ++j) {
        if (fabs(ref[0].x[j][0] - xn[0]) + fabs(ref[0].x[j][1] - xn[1]) + fabs(ref[0].x[j][2] - xn[2]) < 1e-6) {
            for (int a = 0; a < 3; ++a) {
                site = fmax(site, hypot(hypot(d[a][j][0], d[a][j][1]), d[a][j][2]) /
                                      hypot(hypot(ref[a].u[j][0], ref[a].u[j][1]), ref[a].u[j][2]));
            }
        }
    }
    const double site_n = site * (r + hypot(hypot(c[0], c[1]), c[2]));
    snprintf(name, sizeof name, "TFIT_%s_FORWARD_DISCRETISATION_MAX_MM", p->name);
    for (char *q = name; *q; ++q) {
        *q = (char)(*q >= 'a' && *q <= 'z' ? *q - 32 : *q);
    }
    const double stated = header_value(argv[2], name);
    char cname[256];
    snprintf(cname, sizeof cname, "%.*s_CONTACT_DISCRETISATION_MAX_N",
             (int)(strstr(name, "_FORWARD_") - name), name);
    const double stated_n = header_value(argv[2], cname);
    printf("%s: forward: recomputed %.6g mm over %d directions, header %.6g mm; contact: recomputed "
           "%.6g N, header %.6g N\n",
           argv[2], worst, DIRECTIONS, stated, site_n, stated_n);
    int bad = !(stated >= worst * (1 - 1e-6)) || !(stated <= worst * 1.02) ||
              !(stated_n >= site_n * (1 - 1e-6)) || !(stated_n <= site_n * 1.02);
    if (bad) {
        fprintf(stderr, "physics_check: %s states an error against the physics that the recomputation "
                        "does not support\n", argv[2]);
    }
    free(u);
    free(grad);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return bad ? 1 : 0;
}
