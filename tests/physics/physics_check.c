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
 *
 *   physics_check SCENE HEADER INDEX.csv
 *
 * A nonlinear scene (block48_nh): the reference's cases (index lines
 * fx,fy,fz,file, each file node,x,y,z,ux,uy,uz, as tissuefit fit
 * --reference reads them), each solved here by another route than the
 * tool's: in LEVELS equal load levels from rest, each continuing from the
 * last (the tool solves each case in one go from rest).  The figure is
 * the largest displacement component error over the cases (no envelope
 * bound: the error is not linear in the force); the contact site's is its
 * relative error at the reference point on the contact node, times the
 * envelope's largest force.  Same verdict as above, with 1e-5 relative
 * slack (two Newton solves of the same equilibrium).
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
#define LEVELS 5
#define MAX_CASES 8

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

/* The header's two figures against the recomputed ones: 0 when they are
 * stated and neither understated nor more than 2 % above. */
static int verdict(const char *header, const char *scene_name, double worst, double site_n,
                   const char *how, double slack)
{
    char name[256], cname[256];
    snprintf(name, sizeof name, "TFIT_%s_FORWARD_DISCRETISATION_MAX_MM", scene_name);
    for (char *q = name; *q; ++q) {
        *q = (char)(*q >= 'a' && *q <= 'z' ? *q - 32 : *q);
    }
    const double stated = header_value(header, name);
    snprintf(cname, sizeof cname, "%.*s_CONTACT_DISCRETISATION_MAX_N",
             (int)(strstr(name, "_FORWARD_") - name), name);
    const double stated_n = header_value(header, cname);
    printf("%s: forward: recomputed %.6g mm %s, header %.6g mm; contact: recomputed "
           "%.6g N, header %.6g N\n",
           header, worst, how, stated, site_n, stated_n);
    int bad = !(stated >= worst * (1 - slack)) || !(stated <= worst * 1.02) ||
              !(stated_n >= site_n * (1 - slack)) || !(stated_n <= site_n * 1.02);
    if (bad) {
        fprintf(stderr, "physics_check: %s states an error against the physics that the recomputation "
                        "does not support\n", header);
    }
    return bad;
}

/* The scene and its solver, quiet but for warnings; NULL (the message
 * printed) when the scene does not load, *solver NULL when it does not build. */
static tf_scene *scene_and_solver(const char *path, tf_ctx *ctx, tf_solver **solver)
{
    tf_scene *s = tf_scene_load(ctx, path, NULL, 0);
    *solver = NULL;
    if (s == NULL) {
        fprintf(stderr, "physics_check: %s\n", ctx->err);
        return NULL;
    }
    tf_ctx_init(ctx);
    ctx->level = TF_LOG_WARN;
    *solver = tf_solver_create(&s->problem, NULL, ctx);
    return s;
}

/* The reference point on the contact node, or -1. */
static long site_point(const tf_solver *sv, const tf_problem *p, const points *ref)
{
    const tf_contact *ct = &p->contacts[0];
    const double *xn = ct->by_node ? tf_solver_coords(sv) + 3 * (size_t)ct->node : ct->at;
    for (size_t j = 0; j < ref->n; ++j) {
        if (fabs(ref->x[j][0] - xn[0]) + fabs(ref->x[j][1] - xn[1]) + fabs(ref->x[j][2] - xn[2]) < 1e-6) {
            return (long)j;
        }
    }
    return -1;
}

/* One reference case solved in LEVELS load levels; its largest component
 * error and its contact-site relative error.  Returns 0 or -1. */
static int nonlinear_case(tf_solver *sv, const tf_problem *p, const double f[3], const points *ref,
                          double *worst, double *site)
{
    const size_t dofs = 3 * p->cloud.n;
    double *u = malloc(LEVELS * dofs * sizeof *u), *grad = malloc(9 * ref->n * sizeof *grad);
    double *uh = malloc(3 * ref->n * sizeof *uh), level[LEVELS][3];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    for (int l = 0; l < LEVELS; ++l) {
        for (int k = 0; k < 3; ++k) {
            level[l][k] = f[k] * (l + 1) / LEVELS;
        }
    }
    int rc = u && grad && uh ? 0 : -1;
    for (int l = 0; rc == 0 && l < LEVELS; ++l) {
        rc = tf_solver_solve(sv, 0, (const double(*)[3])level[l], 1, l ? u + (size_t)(l - 1) * dofs : NULL,
                             u + (size_t)l * dofs);
    }
    rc = rc ? rc
            : tf_solver_field(&ctx, sv, u + (LEVELS - 1) * dofs, &ref->x[0][0], ref->n, uh, grad);
    const long at = rc == 0 ? site_point(sv, p, ref) : -1;
    for (size_t j = 0; rc == 0 && j < ref->n; ++j) {
        double e[3];
        for (int k = 0; k < 3; ++k) {
            e[k] = uh[3 * j + (size_t)k] - ref->u[j][k];
            *worst = fmax(*worst, fabs(e[k]));
        }
        if ((long)j == at) {
            *site = fmax(*site, hypot(hypot(e[0], e[1]), e[2]) /
                                    hypot(hypot(ref->u[j][0], ref->u[j][1]), ref->u[j][2]));
        }
    }
    free(u);
    free(grad);
    free(uh);
    return rc == 0 && at >= 0 ? 0 : -1;
}

/* physics_check SCENE HEADER INDEX.csv: a nonlinear scene's cases. */
static int check_nonlinear(const char *scene, const char *header, const char *index)
{
    FILE *fp = fopen(index, "r");
    char line[1024], file[512], path[1100];
    const char *slash = strrchr(index, '/');
    const int dir = slash ? (int)(slash - index + 1) : 0;
    static points ref[MAX_CASES];
    double force[MAX_CASES][3];
    size_t n = 0;
    if (fp == NULL || fgets(line, sizeof line, fp) == NULL) {
        fprintf(stderr, "physics_check: cannot read %s\n", index);
        return 2;
    }
    while (n < MAX_CASES && fgets(line, sizeof line, fp)) {
        if (sscanf(line, "%lf,%lf,%lf,%511[^\r\n]", &force[n][0], &force[n][1], &force[n][2], file) != 4) {
            fprintf(stderr, "physics_check: %s: expected fx,fy,fz,file\n", index);
            fclose(fp);
            return 2;
        }
        snprintf(path, sizeof path, "%.*s%s", dir, index, file);
        if (read_csv(path, &ref[n++]) != 0) {
            fclose(fp);
            return 2;
        }
    }
    fclose(fp);
    tf_ctx ctx;
    tf_solver *sv;
    tf_scene *s = n > 0 ? scene_and_solver(scene, &ctx, &sv) : NULL;
    if (s == NULL) {
        fprintf(stderr, "%s", n > 0 ? "" : "physics_check: no reference cases\n");
        return 2;
    }
    const tf_problem *p = &s->problem;
    double worst = 0, site = 0;
    int rc = sv ? 0 : -1;
    for (size_t k = 0; rc == 0 && k < n; ++k) {
        rc = nonlinear_case(sv, p, force[k], &ref[k], &worst, &site);
    }
    int bad = 1;
    if (rc != 0) {
        fprintf(stderr, "physics_check: a reference case did not solve, or has no point on the contact node\n");
    } else {
        const double *c = p->envelope.centre;
        char how[64];
        snprintf(how, sizeof how, "over %zu cases in %d load levels each", n, LEVELS);
        bad = verdict(header, p->name, worst, site * (p->envelope.radius + hypot(hypot(c[0], c[1]), c[2])),
                      how, 1e-5);
    }
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc == 4) {
        return check_nonlinear(argv[1], argv[2], argv[3]);
    }
    if (argc != 6) {
        fprintf(stderr, "usage: physics_check SCENE HEADER FX.csv FY.csv FZ.csv\n"
                        "       physics_check SCENE HEADER INDEX.csv   (a nonlinear scene)\n");
        return 2;
    }
    static points ref[3];
    for (int a = 0; a < 3; ++a) {
        if (read_csv(argv[3 + a], &ref[a]) != 0 || ref[a].n != ref[0].n) {
            return 2;
        }
    }
    tf_ctx ctx;
    tf_solver *sv;
    tf_scene *s = scene_and_solver(argv[1], &ctx, &sv);
    if (s == NULL) {
        return 2;
    }
    const tf_problem *p = &s->problem;
    const size_t dofs = 3 * p->cloud.n, np = ref[0].n;
    static const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    double *u = malloc(3 * dofs * sizeof *u), *grad = malloc(9 * np * sizeof *grad);
    static double d[3][MAXP][3];
    int rc = sv && u && grad ? tf_solver_solve(sv, 0, unit, 3, NULL, u) : -1;
    for (int a = 0; rc == 0 && a < 3; ++a) {
        rc =
            tf_solver_field(&ctx, sv, u + (size_t)a * dofs, &ref[a].x[0][0], np, &d[a][0][0], grad);
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
    const long at = site_point(sv, p, &ref[0]);
    double site = 0;
    for (int a = 0; at >= 0 && a < 3; ++a) {
        site = fmax(site, hypot(hypot(d[a][at][0], d[a][at][1]), d[a][at][2]) /
                              hypot(hypot(ref[a].u[at][0], ref[a].u[at][1]), ref[a].u[at][2]));
    }
    const double site_n = site * (r + hypot(hypot(c[0], c[1]), c[2]));
    char how[64];
    snprintf(how, sizeof how, "over %d directions", DIRECTIONS);
    const int bad = verdict(argv[2], p->name, worst, site_n, how, 1e-6);
    free(u);
    free(grad);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return bad ? 1 : 0;
}
