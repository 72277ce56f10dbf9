/*
 * bench_ordering.c — CHOLMOD's fill-reducing orderings on block48's
 * stiffness matrix (issue 13: AMD against the nested dissections), for
 * `make bench`: numbers are printed, never asserted.
 *
 *   bench_ordering NX,NY,NZ [ORDERING...]     (default: amd metis nesdis)
 *
 * For each ordering, in one process: the linear solver built with
 * solver.ordering forced, the three unit load cases solved; prints the
 * symbolic analysis and numeric factorisation times (wall), the factor's
 * entries and flops, CHOLMOD's peak memory, the largest difference of the
 * displacements from the first ordering's relative to their largest
 * magnitude, and a hash of the displacements' bits (run twice, or with
 * OMP_NUM_THREADS=1 and 2, to see that an ordering is deterministic).
 */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/blas_pin.h"
#include "base/context.h"
#include "scene/scene.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

/* FNV-1a over the bytes of the displacements. */
static uint64_t hash_bits(const double *u, size_t n)
{
    uint64_t h = 1469598103934665603ULL;
    const unsigned char *b = (const unsigned char *)u;
    for (size_t k = 0; k < n * sizeof *u; ++k) {
        h = (h ^ b[k]) * 1099511628211ULL;
    }
    return h;
}

/* One ordering: the solver built and the unit cases solved; the
 * displacements (9N, malloc'd) into *u. */
static int one_ordering(const char *const *sets, size_t ns, const char *ord, double **u,
                        size_t *n3, tf_galerkin_info *gi)
{
    char set_ord[64];
    const char *all[8];
    memcpy(all, sets, ns * sizeof *sets);
    snprintf(set_ord, sizeof set_ord, "solver.ordering=%s", ord);
    all[ns] = set_ord;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", all, ns + 1);
    if (s == NULL) {
        fprintf(stderr, "bench_ordering: %s\n", ctx.err);
        return -1;
    }
    const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
    *n3 = 3 * s->problem.cloud.n;
    *u = malloc(3 * *n3 * sizeof **u);
    if (sv == NULL || *u == NULL || tf_solver_solve(sv, 0, unit, 3, NULL, *u) != 0) {
        fprintf(stderr, "bench_ordering: %s: %s\n", ord, ctx.err);
        tf_solver_destroy(sv);
        tf_scene_free(s);
        return -1;
    }
    *gi = *tf_galerkin_info_of(sv);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return 0;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv);
    unsigned g[3];
    if (argc < 2 || sscanf(argv[1], "%u,%u,%u", &g[0], &g[1], &g[2]) != 3) {
        fprintf(stderr, "usage: bench_ordering NX,NY,NZ [amd|metis|nesdis|default ...]\n");
        return 2;
    }
    char set_grid[64], set_node[64];
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", argv[1]);
    snprintf(set_node, sizeof set_node, "contact.0.node=%u", g[0] / 2 + g[0] * (g[1] / 2) + 1);
    const char *sets[] = {set_grid, set_node};
    const char *const dflt[] = {"amd", "metis", "nesdis"};
    const char *const *ords = argc > 2 ? (const char *const *)argv + 2 : dflt;
    int nord = argc > 2 ? argc - 2 : 3;
    double *first = NULL;
    printf("block48 %s, OMP_NUM_THREADS %d, OpenBLAS %s; unit cases x, y, -z:\n", argv[1],
           omp_get_max_threads(), tf_blas_coretype());
    printf("  %-8s %10s %10s %10s %10s %9s %12s  %s\n", "ordering", "analyse s", "factor s",
           "nnz(L)", "flops", "peak MiB", "|du|/|u|", "hash of u");
    for (int k = 0; k < nord; ++k) {
        size_t n3 = 0;
        tf_galerkin_info gi;
        double *u = NULL;
        if (one_ordering(sets, 2, ords[k], &u, &n3, &gi) != 0) {
            return 1;
        }
        double diff = 0, big = 0;
        for (size_t q = 0; first != NULL && q < 3 * n3; ++q) {
            diff = fmax(diff, fabs(u[q] - first[q]));
            big = fmax(big, fabs(first[q]));
        }
        printf("  %-8s %10.3f %10.3f %10.3g %10.3g %9.0f %12.2e  %016llx (%s)\n", ords[k],
               gi.t_analyse, gi.t_factor - gi.t_analyse, gi.nnz_l, gi.flops, gi.chol_mib,
               first != NULL ? diff / big : 0.0, (unsigned long long)hash_bits(u, 3 * n3),
               gi.ordering);
        if (first == NULL) {
            first = u;
        } else {
            free(u);
        }
    }
    free(first);
    return 0;
}
