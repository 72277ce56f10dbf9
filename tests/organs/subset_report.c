/*
 * subset_report.c — what an organ's near-contact outputs leave out: the
 * displacement of the surface vertices that are not outputs (a renderer
 * keeps them at rest) against that of the outputs, for the envelope's
 * largest force along x, y and z at the scene's first contact site.
 *
 *   subset_report SCENE...
 *
 * One Markdown row per scene (docs/scene-format.md, "What the subset
 * saves").
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"
#include "solvers/solver.h"

static double norm3(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

static int report(const char *path)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, path, NULL, 0);
    if (s == NULL) {
        fprintf(stderr, "subset_report: %s\n", ctx.err);
        return -1;
    }
    const tf_problem *p = &s->problem;
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    size_t n3 = 3 * p->cloud.n;
    double *u = malloc(3 * n3 * sizeof *u), r = p->envelope.radius;
    unsigned char *out = calloc(p->cloud.n, 1);
    const double f[3][3] = {{r, 0, 0}, {0, r, 0}, {0, 0, r}};
    int rc = sv && u && out && tf_solver_solve(sv, 0, f, 3, NULL, u) == 0 ? 0 : -1;
    if (rc != 0) {
        fprintf(stderr, "subset_report: %s: %s\n", path, sv ? ctx.err : "no solver");
    }
    for (size_t k = 0; rc == 0 && k < p->outputs.n_nodes; ++k) {
        out[p->outputs.nodes[k]] = 1;
    }
    double in_max = 0, left_max = 0, left_at = 0;
    for (int c = 0; rc == 0 && c < 3; ++c) {
        for (size_t i = 0; i < p->cloud.n_surface; ++i) {
            double m = norm3(u + (size_t)c * n3 + 3 * i);
            if (out[i]) {
                in_max = fmax(in_max, m);
            } else if (m > left_max) {
                left_max = m;
                const double *x = p->cloud.xyz + 3 * i, *y = p->cloud.xyz + 3 * p->contacts[0].node;
                left_at = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                               (x[2] - y[2]) * (x[2] - y[2]));
            }
        }
    }
    if (rc == 0) {
        printf("| %s | %zu of %zu | %.3g mm | %.3g mm (%.0f %%), %.0f mm from the contact |\n",
               p->name, p->outputs.n_nodes, p->cloud.n_surface, in_max, left_max,
               100 * left_max / in_max, left_at);
    }
    free(u);
    free(out);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return rc;
}

int main(int argc, char **argv)
{
    printf("| organ | outputs of surface vertices | largest |u| of an output | largest |u| "
           "left out |\n|---|---:|---:|---|\n");
    int rc = 0;
    for (int i = 1; i < argc; ++i) {
        rc |= report(argv[i]);
    }
    return rc ? 1 : 0;
}
