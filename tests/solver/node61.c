/*
 * node61.c — block48's top-centre compliance at one grid, for the
 * validation tables: one factorisation, the three unit load cases.
 *
 *   node61 NX,NY,NZ [KEY=VALUE]...
 *
 * Prints "nodes,ux_fx,uy_fy,uz_fz,seconds": the displacement (mm) of the
 * top-centre node (node 61 of the 11 x 11 grid) under 1 N along +x, +y and
 * -z, and the time to build the solver and solve.
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/context.h"
#include "scene/scene.h"
#include "solvers/solver.h"

int main(int argc, char **argv)
{
    unsigned g[3];
    if (argc < 2 || sscanf(argv[1], "%u,%u,%u", &g[0], &g[1], &g[2]) != 3 || argc > 18) {
        fprintf(stderr, "usage: node61 NX,NY,NZ [KEY=VALUE]...\n");
        return 2;
    }
    char set_grid[64], set_node[64];
    unsigned centre = g[0] / 2 + g[0] * (g[1] / 2); /* index of the top centre */
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", argv[1]);
    snprintf(set_node, sizeof set_node, "contact.0.node=%u", centre + 1);
    const char *sets[20] = {set_grid, set_node};
    for (int k = 2; k < argc; ++k) {
        sets[k] = argv[k];
    }
    const double f[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    double t0 = omp_get_wtime();
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, (size_t)argc);
    if (s == NULL) {
        fprintf(stderr, "node61: %s\n", ctx.err);
        return 1;
    }
    const tf_problem *p = &s->problem;
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    double *u = sv ? malloc(9 * p->cloud.n * sizeof *u) : NULL;
    if (u == NULL || tf_solver_solve(sv, 0, f, 3, NULL, u) != 0) {
        fprintf(stderr, "node61: %s\n", ctx.err);
        return 1;
    }
    size_t n3 = 3 * p->cloud.n;
    printf("%zu,%.10g,%.10g,%.10g,%.3f\n", p->cloud.n, u[3 * centre], u[n3 + 3 * centre + 1],
           u[2 * n3 + 3 * centre + 2], omp_get_wtime() - t0);
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return 0;
}
