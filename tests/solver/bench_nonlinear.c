/*
 * bench_nonlinear.c — speed of the nonlinear solver on block48 (issue 13,
 * acceptance 5), for `make bench`: numbers are printed, never asserted.
 *
 *   bench_nonlinear GRID REPS [cases=N] [KEY=VALUE...]
 *
 * For each rep, in this order and in one process: one linear solve (scene
 * read, supports, shape functions, assembly, factorisation, one case), then
 * neo-Hookean and St. Venant-Kirchhoff cases from rest (each a fresh
 * solver: build and Newton): 3 N along -z, 1 N along x, and both at once.
 * Prints the medians of the wall-clock times (and of the process CPU time:
 * this machine is shared), the Newton iterations per load step, and the
 * ratio of the 3 N neo-Hookean case to the linear solve (the goal:
 * at most 3 at 41 x 41 x 9).  cases=N runs the first N cases only (2: the
 * linear solve and the 3 N neo-Hookean case, the goal's pair); scale=S
 * multiplies every case's force (0.8: the goal's case below the critical
 * point of the 41 x 41 x 9 body, docs/validation.md §13).
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/blas_pin.h"
#include "base/context.h"
#include "scene/scene.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#define MAX_REPS 9
#define MAX_SETS 16
#define CASES 7 /* the linear solve, then three per law */

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

typedef struct result {
    double wall, cpu;
    tf_nonlinear_info nl;
    int nonlinear;
    double uc[3]; /* mm: the contact node's displacement (the answer, to compare runs) */
} result;

/* One case from a fresh solver: build, solve, and the statistics. */
static int one_case(const char *const *sets, size_t ns, const char *law, const double f[3],
                    result *r)
{
    char set_law[64];
    const char *all[MAX_SETS + 1];
    memcpy(all, sets, ns * sizeof *sets);
    snprintf(set_law, sizeof set_law, "material.law=%s", law);
    all[ns] = set_law;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    double w0 = omp_get_wtime(), c0 = cpu_now();
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", all, ns + 1);
    if (s == NULL) {
        fprintf(stderr, "bench_nonlinear: %s\n", ctx.err);
        return -1;
    }
    tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
    double *u = sv ? malloc(3 * s->problem.cloud.n * sizeof *u) : NULL;
    const double fk[1][3] = {{f[0], f[1], f[2]}};
    if (u == NULL || tf_solver_solve(sv, 0, fk, 1, NULL, u) != 0) {
        fprintf(stderr, "bench_nonlinear: %s: %s\n", law, ctx.err);
        return -1;
    }
    r->wall = omp_get_wtime() - w0;
    r->cpu = cpu_now() - c0;
    r->nonlinear = tf_nonlinear_info_of(sv, &r->nl) == 0;
    memcpy(r->uc, u + 3 * (size_t)s->problem.contacts[0].node, sizeof r->uc);
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return 0;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv); /* the tool's OpenBLAS kernels and one BLAS thread */
    unsigned g[3];
    int reps = argc > 2 ? atoi(argv[2]) : 0;
    if (argc < 3 || sscanf(argv[1], "%u,%u,%u", &g[0], &g[1], &g[2]) != 3 || reps < 1 ||
        reps > MAX_REPS || argc - 3 > MAX_SETS - 2) {
        fprintf(stderr, "usage: bench_nonlinear NX,NY,NZ REPS (1 to %d) [cases=N] [scale=S] [KEY=VALUE...]\n",
                MAX_REPS);
        return 2;
    }
    char set_grid[64], set_node[64];
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", argv[1]);
    snprintf(set_node, sizeof set_node, "contact.0.node=%u", g[0] / 2 + g[0] * (g[1] / 2) + 1);
    const char *sets[MAX_SETS] = {set_grid, set_node};
    size_t ns = 2;
    int ncases = CASES, first = 3;
    double scale = 1;
    if (argc > first && sscanf(argv[first], "cases=%d", &ncases) == 1) {
        first++;
        if (ncases < 1 || ncases > CASES) {
            fprintf(stderr, "bench_nonlinear: cases=%d: from 1 to %d\n", ncases, CASES);
            return 2;
        }
    }
    if (argc > first && sscanf(argv[first], "scale=%lf", &scale) == 1) {
        first++;
        if (!(scale > 0 && scale <= 10)) {
            fprintf(stderr, "bench_nonlinear: scale=%g: from 0 to 10\n", scale);
            return 2;
        }
    }
    for (int k = first; k < argc; ++k) {
        sets[ns++] = argv[k];
    }
    const char *law[CASES] = {"linear", "neo-hookean", "neo-hookean", "neo-hookean",
                              "svk", "svk", "svk"};
    double force[CASES][3] = {{0, 0, -3}, {0, 0, -3}, {1, 0, 0}, {1, 0, -3},
                              {0, 0, -3}, {1, 0, 0}, {1, 0, -3}};
    for (int c = 0; c < CASES; ++c) {
        for (int a = 0; a < 3; ++a) {
            force[c][a] *= scale;
        }
    }
    double wall[CASES][MAX_REPS], cpu[CASES][MAX_REPS];
    result last[CASES];
    int ok[CASES];
    for (int c = 0; c < CASES; ++c) {
        ok[c] = c < ncases;
    }
    for (int r = 0; r < reps; ++r) {
        for (int c = 0; c < ncases; ++c) {
            result res;
            if (!ok[c] || one_case(sets, ns, law[c], force[c], &res) != 0) {
                ok[c] = 0;
                continue;
            }
            wall[c][r] = res.wall;
            cpu[c][r] = res.cpu;
            last[c] = res;
        }
    }
    printf("block48 %s, medians of %d runs (wall s, process CPU s):\n", argv[1], reps);
    double lin = ok[0] ? median(wall[0], reps) : 0;
    for (int c = 0; c < ncases; ++c) {
        if (!ok[c]) {
            printf("  %-12s (%g, %g, %g) N: failed (its message above)\n", law[c], force[c][0],
                   force[c][1], force[c][2]);
            continue;
        }
        double w = median(wall[c], reps), u = median(cpu[c], reps);
        printf("  %-12s (%g, %g, %g) N: %7.2f s wall, %7.2f s CPU, contact node u (%.4f, %.4f, "
               "%.4f) mm", law[c], force[c][0], force[c][1], force[c][2], w, u, last[c].uc[0],
               last[c].uc[1], last[c].uc[2]);
        if (last[c].nonlinear) {
            const tf_nonlinear_info *in = &last[c].nl;
            printf(", %zu load steps, %.1f Newton iterations per step, %zu factorisations, "
                   "%.2f x the linear solve",
                   in->steps, (double)in->iterations / (double)(in->steps ? in->steps : 1),
                   in->factorisations, lin > 0 ? w / lin : 0);
            printf("\n      %s ordering, L %.3g entries; %zu residual and %zu tangent assemblies, "
                   "%zu Krylov iterations, %zu LDL^T, %zu indefinite kept, %zu shifted (last %.3g); "
                   "s: gradients %.2f, residuals %.2f, tangents %.2f, factorisations %.2f, solves %.2f",
                   in->ordering ? in->ordering : "-", in->nnz_l, in->residuals, in->tangents,
                   in->krylov, in->indefinite, in->kept, in->shifted, in->shift, in->t_gradients,
                   in->t_residual, in->t_tangent, in->t_factor, in->t_solve);
            if (in->patch_dofs > 0) {
                printf("\n      patch tangent: %zu DOFs, %zu block updates (%zu not positive "
                       "definite), %.2f s",
                       in->patch_dofs, in->patches, in->patch_kept, in->t_patch);
            }
        }
        printf("\n");
    }
    if (ok[0] && ok[1]) {
        double lc = median(cpu[0], reps), nc = median(cpu[1], reps);
        printf("  goal: %g N neo-Hookean <= 3 x one linear solve: %.2f x wall (%s), "
               "%.2f x CPU (%s; CPU time is the measure on a shared machine)\n",
               -force[1][2], median(wall[1], reps) / lin,
               median(wall[1], reps) <= 3 * lin ? "met" : "not met",
               nc / lc, nc <= 3 * lc ? "met" : "not met");
    }
    return 0;
}
