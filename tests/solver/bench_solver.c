/*
 * bench_solver.c — speed of the block48 solve (GUIDE §7), for `make bench`.
 *
 *   bench_solver GRID REPS      e.g. bench_solver 41,41,9 3
 *
 * Builds the solver REPS times (scene read, supports, shape functions,
 * assembly, loads, factorisation) and solves the three unit load cases,
 * then solves 150 load cases through the last factorisation (what the
 * fitting pipeline does).  Prints medians of the total and of each phase,
 * and the process's peak memory.
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "base/peak_memory.h"
#include "scene/scene.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define MAX_REPS 15
#define PHASES 7

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

int main(int argc, char **argv)
{
    unsigned g[3];
    int reps = argc > 2 ? atoi(argv[2]) : 0;
    if (argc != 3 || sscanf(argv[1], "%u,%u,%u", &g[0], &g[1], &g[2]) != 3 || reps < 1 ||
        reps > MAX_REPS) {
        fprintf(stderr, "usage: bench_solver NX,NY,NZ REPS (1 to %d)\n", MAX_REPS);
        return 2;
    }
    char set_grid[64], set_node[64];
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", argv[1]);
    snprintf(set_node, sizeof set_node, "contact.0.node=%u", g[0] / 2 + g[0] * (g[1] / 2) + 1);
    const char *sets[] = {set_grid, set_node};
    const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    double t[PHASES][MAX_REPS], many = 0;
    size_t nodes = 0, nnz_k = 0;
    double nnz_l = 0;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    for (int r = 0; r < reps; ++r) {
        double t0 = omp_get_wtime();
        tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, 2);
        if (s == NULL) {
            fprintf(stderr, "bench_solver: %s\n", ctx.err);
            return 1;
        }
        tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
        double *u = sv ? malloc(150 * 3 * s->problem.cloud.n * sizeof *u) : NULL;
        if (u == NULL || tf_solver_solve(sv, 0, unit, 3, NULL, u) != 0) {
            fprintf(stderr, "bench_solver: %s\n", ctx.err);
            return 1;
        }
        const tf_galerkin_info *in = tf_galerkin_info_of(sv);
        t[0][r] = omp_get_wtime() - t0;
        t[1][r] = in->t_pattern;
        t[2][r] = in->t_shape;
        t[3][r] = in->t_assemble;
        t[4][r] = in->t_loads;
        t[5][r] = in->t_factor;
        t[6][r] = tf_solver_info_of(sv)->t_solve;
        if (r == reps - 1) {
            double f[150][3];
            for (int k = 0; k < 450; ++k) {
                f[k / 3][k % 3] = ((k * 7919) % 2001 - 1000) / 1732.0; /* inside the 1 N ball */
            }
            double t1 = omp_get_wtime();
            if (tf_solver_solve(sv, 0, (const double(*)[3])f, 150, NULL, u) != 0) {
                fprintf(stderr, "bench_solver: %s\n", ctx.err);
                return 1;
            }
            many = omp_get_wtime() - t1;
            nodes = tf_solver_info_of(sv)->nodes;
            nnz_k = in->nnz_k;
            nnz_l = in->nnz_l;
        }
        free(u);
        tf_solver_destroy(sv);
        tf_scene_free(s);
    }
    static const char *const names[PHASES] = {"total (read to 3 solutions)", "pattern",
                                               "shape functions", "assembly", "loads",
                                               "factorisation", "3 solves"};
    printf("block48 %s: %zu nodes, %zu DOFs, K %zu entries, L %.3g entries; median of %d runs "
           "(OMP_NUM_THREADS %d):\n",
           argv[1], nodes, 3 * nodes, nnz_k, nnz_l, reps, omp_get_max_threads());
    for (int p = 0; p < PHASES; ++p) {
        printf("  %-28s %8.3f s\n", names[p], median(t[p], reps));
    }
    printf("  %-28s %8.3f s (through the same factorisation)\n", "150 more load cases", many);
    printf("  %-28s %8.0f MiB\n", "peak memory", tf_peak_mib());
    return 0;
}
