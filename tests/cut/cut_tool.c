/*
 * cut_tool.c — measurements of cut solves (docs/cutting.md).
 *
 *   cut_tool cod SCENE [KEY=VALUE]...
 *       solves the scene's loads and prints the crack-opening displacement
 *       along the depth of its first cut, at the middle of the first
 *       segment: CSV "z,cod" with cod = (u(x + e n) - u(x - e n)) . n,
 *       e = 1e-6 mm, n the cut's normal, at 21 depths from the top down to
 *       the front; then a comment line with the nodes, the points whose
 *       shape functions were recomputed and the times.
 *   cut_tool far [--bound=B | --bound-all=B] SCENE [KEY=VALUE]...
 *       solves the scene with its cuts and without them, and compares the
 *       nodal displacements at the nodes outside every affected support
 *       (every node of a support whose shape functions are recomputed for
 *       the cut, shape.c): prints the largest difference relative to the
 *       largest displacement, there and over all nodes, whether it meets
 *       acceptance 2 of issue 17 (1e-3), and with a `reference:` in the
 *       scene each solve's largest difference from it; exit 1 when the far
 *       difference exceeds B (default FAR_BOUND) or there is no far node,
 *       or with --bound-all when the difference over all nodes exceeds B.
 *
 * Exit 0 ok, 1 failure or a bound exceeded, 2 usage.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "meshfree/cut.h"
#include "problem/analytic.h"
#include "scene/scene.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define STEPS 20
#define FAR_ACCEPT 1e-3 /* issue 17, acceptance 2 */
#define FAR_BOUND 1e-2  /* default bound (--bound=B): a regression bound for RPIM with Gauss points */

static tf_solver *solve(const tf_problem *p, tf_ctx *ctx, double *u, double *t)
{
    double t0 = omp_get_wtime();
    tf_solver *s = tf_solver_create(p, NULL, ctx);
    if (s == NULL || tf_solver_solve(s, -1, NULL, 1, NULL, u) != 0) {
        fprintf(stderr, "cut_tool: %s\n", ctx->err);
        tf_solver_destroy(s);
        return NULL;
    }
    *t = omp_get_wtime() - t0;
    return s;
}

static int cod(const tf_problem *p, tf_ctx *ctx)
{
    if (p->n_cuts == 0) {
        fprintf(stderr, "cut_tool: %s has no cut\n", p->source);
        return 2;
    }
    double *u = malloc(3 * p->cloud.n * sizeof *u), t;
    tf_solver *s = u ? solve(p, ctx, u, &t) : NULL;
    if (s == NULL) {
        free(u);
        return 1;
    }
    const tf_cut *c = &p->cuts[0];
    double dx = c->xy[1][0] - c->xy[0][0], dy = c->xy[1][1] - c->xy[0][1], len = hypot(dx, dy);
    double n[2] = {dy / len, -dx / len}, e = 1e-6, x[6 * (STEPS + 1)], uh[6 * (STEPS + 1)],
           grad[18 * (STEPS + 1)];
    for (int k = 0; k <= STEPS; ++k) {
        double z = c->top - c->depth * k / STEPS;
        for (int side = 0; side < 2; ++side) {
            double *q = x + 3 * (2 * k + side), sgn = side ? 1 : -1;
            q[0] = 0.5 * (c->xy[0][0] + c->xy[1][0]) + sgn * e * n[0];
            q[1] = 0.5 * (c->xy[0][1] + c->xy[1][1]) + sgn * e * n[1];
            q[2] = z;
        }
    }
    int rc = 0;
    if (tf_solver_field(ctx, s, u, x, 2 * (STEPS + 1), uh, grad) != 0) {
        fprintf(stderr, "cut_tool: %s\n", ctx->err);
        rc = 1;
    }
    printf("z,cod\n");
    for (int k = 0; rc == 0 && k <= STEPS; ++k) {
        const double *lo = uh + 6 * k, *hi = lo + 3;
        printf("%.6f,%.10g\n", x[6 * k + 2], (hi[0] - lo[0]) * n[0] + (hi[1] - lo[1]) * n[1]);
    }
    const tf_galerkin_info *in = tf_galerkin_info_of(s);
    if (rc == 0 && in != NULL) {
        printf("# nodes %zu, points %zu, recomputed for the cut %zu, shape functions %.3f s, "
               "setup + solve %.3f s\n",
               p->cloud.n, in->st.points, in->st.cut_points, in->t_shape, t);
    }
    tf_solver_destroy(s);
    free(u);
    return rc;
}

/* The nodes outside every affected support: a support is affected when
 * the shape functions at a point using it are recomputed for the cut
 * (shape.c: RPIM, the cell's support box meets a panel; EFG, an enriched
 * node is in it), and every node of an affected support is marked.  Tried
 * at every Gauss point and every corner of every background cell (the
 * face points of loads, Nitsche's terms and VCI lie on the cells'
 * closures; the supports of EFG grow and shrink with the point). */
static unsigned char *far_nodes(const tf_problem *p, const tf_shape *sh, size_t *count)
{
    unsigned char *far = malloc(p->cloud.n);
    tf_shape_work w;
    tf_shape_work_init(&w);
    if (far == NULL) {
        return NULL;
    }
    memset(far, 1, p->cloud.n);
    size_t np = tf_cells_points(&sh->cells);
    for (size_t c = 0; c < tf_cells_count(&sh->cells); ++c) {
        double at[3], half[3], x[3], wt;
        tf_cells_box(&sh->cells, c, at, half);
        for (size_t k = 0; k < np + 8; ++k) {
            if (k < np) {
                tf_cells_point(&sh->cells, c, k, x, &wt);
            }
            for (int a = 0; k >= np && a < 3; ++a) {
                /* just inside: a corner on a cut's plane has no side */
                x[a] = at[a] + ((k - np) >> a & 1 ? 1 : -1) * (1 - 1e-9) * half[a];
            }
            if (tf_shape_at(sh, &w, x, c, 0) != 0) {
                fprintf(stderr, "cut_tool: %s\n", w.err);
                free(far);
                tf_shape_work_free(&w);
                return NULL;
            }
            for (size_t i = 0; w.cut && i < w.n; ++i) {
                far[w.idx[i]] = 0;
            }
        }
    }
    tf_shape_work_free(&w);
    *count = 0;
    for (size_t i = 0; i < p->cloud.n; ++i) {
        *count += far[i];
    }
    return far;
}

/* Largest |u - u_ref| over the nodes, u_ref the scene's reference solution. */
static double reference_error(const tf_problem *p, const double *u)
{
    double d = 0, ur[3], g[9];
    for (size_t i = 0; i < p->cloud.n; ++i) {
        tf_analytic_eval(p, p->cloud.xyz + 3 * i, ur, g);
        for (int a = 0; a < 3; ++a) {
            d = fmax(d, fabs(u[3 * i + a] - ur[a]));
        }
    }
    return d;
}

static int far(tf_problem *p, tf_ctx *ctx, double bound, int all)
{
    size_t n3 = 3 * p->cloud.n, nfar = 0, ncuts = p->n_cuts;
    double *uc = malloc(n3 * sizeof *uc), *u0 = malloc(n3 * sizeof *u0), tc, t0;
    tf_solver *sc = uc && u0 ? solve(p, ctx, uc, &tc) : NULL;
    p->n_cuts = 0;
    tf_solver *s0 = sc ? solve(p, ctx, u0, &t0) : NULL;
    p->n_cuts = ncuts;
    unsigned char *mask = s0 ? far_nodes(p, tf_galerkin_shape(sc), &nfar) : NULL;
    if (mask == NULL) {
        tf_solver_destroy(sc);
        tf_solver_destroy(s0);
        free(uc);
        free(u0);
        return 1;
    }
    double umax = 0, dfar = 0, dall = 0;
    size_t at = 0;
    for (size_t k = 0; k < n3; ++k) {
        umax = fmax(umax, fabs(u0[k]));
    }
    for (size_t k = 0; k < n3; ++k) {
        double d = fabs(uc[k] - u0[k]) / umax;
        dall = fmax(dall, d);
        if (mask[k / 3] && d > dfar) {
            dfar = d;
            at = k / 3;
        }
    }
    const tf_galerkin_info *in = tf_galerkin_info_of(sc);
    /* All nodes include the far ones: within the acceptance there means
     * within it far away too, also when every node is in an affected
     * support (EFG on a coarse cloud). */
    const char *verdict = dall <= FAR_ACCEPT                 ? "met (over all nodes)"
                          : nfar > 0 && dfar <= FAR_ACCEPT ? "met"
                                                           : "not met";
    char there[96] = "none there";
    if (nfar > 0) {
        snprintf(there, sizeof there, "%.2e there (at node %zu: %g, %g, %g mm)", dfar, at + 1,
                 p->cloud.xyz[3 * at], p->cloud.xyz[3 * at + 1], p->cloud.xyz[3 * at + 2]);
    }
    printf("%s (%s, %s integration): %zu nodes, %zu outside every affected support; cut vs "
           "uncut, largest difference / largest displacement: %s, %.2e over all nodes "
           "(acceptance 2 asks %.0e: %s; this check's bound %.0e %s); "
           "shape functions recomputed at %zu of %zu points\n",
           p->name, p->solver.method,
           p->solver.integration == TF_INTEGRATION_VCI ? "VCI" : "Gauss", p->cloud.n, nfar, there,
           dall, FAR_ACCEPT, verdict, bound, all ? "over all nodes" : "there",
           in->st.cut_points, in->st.points);
    if (p->analytic.kind != TF_ANALYTIC_NONE) {
        printf("%s: largest |u - u_reference| / largest displacement: uncut %.2e, cut %.2e\n",
               p->name, reference_error(p, u0) / umax, reference_error(p, uc) / umax);
    }
    int rc = all ? !(dall <= bound) : !(nfar > 0 && dfar <= bound);
    free(mask);
    tf_solver_destroy(sc);
    tf_solver_destroy(s0);
    free(uc);
    free(u0);
    return rc;
}

int main(int argc, char **argv)
{
    double bound = FAR_BOUND;
    int first = 2, all = 0;
    for (; argc > first + 1 && strcmp(argv[1], "far") == 0 && strncmp(argv[first], "--", 2) == 0;
         ++first) {
        const char *o = argv[first];
        int is_all = strncmp(o, "--bound-all=", 12) == 0;
        char *end;
        if (!is_all && strncmp(o, "--bound=", 8) != 0) {
            fprintf(stderr, "cut_tool: %s: unknown option\n", o);
            return 2;
        }
        bound = strtod(o + (is_all ? 12 : 8), &end);
        if (*end != '\0' || !(bound > 0)) {
            fprintf(stderr, "cut_tool: %s: the bound must be a number > 0\n", o);
            return 2;
        }
        all = is_all;
    }
    if (argc < first + 1 || argc > first + 16 ||
        (strcmp(argv[1], "cod") != 0 && strcmp(argv[1], "far") != 0)) {
        fprintf(stderr, "usage: cut_tool cod SCENE [KEY=VALUE]...\n"
                        "       cut_tool far [--bound=B | --bound-all=B] SCENE [KEY=VALUE]...\n");
        return 2;
    }
    const char *sets[16];
    for (int k = first + 1; k < argc; ++k) {
        sets[k - first - 1] = argv[k];
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, argv[first], sets, (size_t)(argc - first - 1));
    if (s == NULL) {
        fprintf(stderr, "cut_tool: %s\n", ctx.err);
        return 2;
    }
    int rc = strcmp(argv[1], "cod") == 0 ? cod(&s->problem, &ctx) : far(&s->problem, &ctx, bound, all);
    tf_scene_free(s);
    return rc;
}
