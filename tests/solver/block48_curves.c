/*
 * block48_curves.c — node 61's force-displacement curve of block48 under a
 * nonlinear law (issue 13, acceptance 3 and 5), for the validation
 * (make nonlinear-validation) and the benchmark (make bench).
 *
 *   block48_curves GRID LAW FX,FY,FZ LEVELS [KEY=VALUE...]
 *
 * solves block48 (tests/solver/block48_seed.yaml, the grid's top-centre node as the
 * contact) under law (svk, neo-hookean) with the force raised to
 * (FX, FY, FZ) N in LEVELS equal load levels, each continuing from the one
 * before, and prints a CSV row per level: grid,law,factor,fx,fy,fz,ux,uy,uz
 * (the top centre, mm),steps,iterations,tangents,factorisations,seconds.
 * KEY=VALUE are scene overrides.
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "scene/scene.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#define MAX_SETS 16

int main(int argc, char **argv)
{
    unsigned g[3];
    double f[3];
    int levels = argc > 4 ? atoi(argv[4]) : 0;
    if (argc < 5 || sscanf(argv[1], "%u,%u,%u", &g[0], &g[1], &g[2]) != 3 ||
        sscanf(argv[3], "%lf,%lf,%lf", &f[0], &f[1], &f[2]) != 3 || levels < 1 ||
        argc - 5 > MAX_SETS - 3) {
        fprintf(stderr, "usage: block48_curves NX,NY,NZ LAW FX,FY,FZ LEVELS [KEY=VALUE...]\n");
        return 2;
    }
    char set_grid[64], set_node[64], set_law[64];
    unsigned node = g[0] / 2 + g[0] * (g[1] / 2) + 1;
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", argv[1]);
    snprintf(set_node, sizeof set_node, "contact.0.node=%u", node);
    snprintf(set_law, sizeof set_law, "material.law=%s", argv[2]);
    const char *sets[MAX_SETS] = {set_grid, set_node, set_law};
    size_t ns = 3;
    for (int k = 5; k < argc; ++k) {
        sets[ns++] = argv[k];
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    double t0 = omp_get_wtime();
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, ns);
    if (s == NULL) {
        fprintf(stderr, "block48_curves: %s\n", ctx.err);
        return 2;
    }
    tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
    double *u = malloc(3 * s->problem.cloud.n * sizeof *u);
    if (sv == NULL || u == NULL) {
        fprintf(stderr, "block48_curves: %s\n", sv ? "out of memory" : ctx.err);
        return 1;
    }
    char grid[64]; /* 11x11x3: no comma inside a CSV field */
    snprintf(grid, sizeof grid, "%ux%ux%u", g[0], g[1], g[2]);
    printf("grid,law,factor,fx,fy,fz,ux,uy,uz,steps,iterations,tangents,factorisations,seconds\n");
    for (int k = 1; k <= levels; ++k) {
        double a = (double)k / levels, fk[3] = {a * f[0], a * f[1], a * f[2]};
        if (tf_nonlinear_advance(sv, 1, 0, fk, 0) != 0 || tf_nonlinear_displacements(sv, u) != 0) {
            fprintf(stderr, "block48_curves: %s\n", ctx.err);
            printf("%s,%s,%g,%g,%g,%g,failed,,,,,,,\n", grid, argv[2], a, fk[0], fk[1], fk[2]);
            return 1;
        }
        tf_nonlinear_info in;
        tf_nonlinear_info_of(sv, &in);
        const double *un = u + 3 * (node - 1);
        printf("%s,%s,%g,%g,%g,%g,%.10g,%.10g,%.10g,%zu,%zu,%zu,%zu,%.3f\n", grid, argv[2], a,
               fk[0], fk[1], fk[2], un[0], un[1], un[2], in.steps, in.iterations, in.tangents,
               in.factorisations, omp_get_wtime() - t0);
        fflush(stdout);
    }
    tf_solver_report(sv);
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return 0;
}
