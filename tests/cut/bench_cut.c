/*
 * bench_cut.c — what recomputing only the cut supports saves (make
 * bench-cut, docs/cutting.md): the shape functions (and gradients) at every
 * Gauss point of a scene, median of REPS passes each, uncut, with its cuts
 * (only the points whose support meets one recomputed), and with every
 * point sent through the cut path (sh.cut_all: what recomputing everything
 * would cost).  Prints the counts, the medians and the ratio.
 */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "meshfree/shape.h"
#include "scene/scene.h"

#define REPS 5

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One pass over every cell; the points recomputed for the cut in *cut. */
static int pass(const tf_shape *sh, double *t, size_t *cut, size_t *points)
{
    tf_shape_work w;
    tf_shape_work_init(&w);
    size_t np = tf_cells_points(&sh->cells);
    double *x = malloc(3 * np * sizeof *x), wt, t0 = omp_get_wtime();
    int rc = x ? 0 : -1;
    for (size_t c = 0; rc == 0 && c < tf_cells_count(&sh->cells); ++c) {
        for (size_t p = 0; p < np; ++p) {
            tf_cells_point(&sh->cells, c, p, x + 3 * p, &wt);
        }
        rc = tf_shape_cell_points(sh, &w, c, x, np, 1);
    }
    *t = omp_get_wtime() - t0;
    *cut = w.st.cut_points;
    *points = w.st.points;
    if (rc != 0) {
        fprintf(stderr, "bench_cut: %s\n", w.err);
    }
    free(x);
    tf_shape_work_free(&w);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 10) {
        fprintf(stderr, "usage: bench_cut SCENE [KEY=VALUE]...\n");
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, argv[1], (const char *const *)argv + 2, (size_t)(argc - 2));
    if (s == NULL) {
        fprintf(stderr, "bench_cut: %s\n", ctx.err);
        return 2;
    }
    const tf_problem *p = &s->problem;
    double lo[3], hi[3], med[3];
    size_t cut[3], points = 0;
    tf_problem_bounds(p, lo, hi);
    const char *name[3] = {"uncut", "cut, only the cut supports", "cut, every point"};
    for (int m = 0; m < 3; ++m) {
        tf_shape sh;
        double t[REPS];
        if (tf_shape_init(&sh, &p->cloud, lo, hi, &p->solver) != 0 ||
            (m > 0 && tf_shape_set_cuts(&ctx, &sh, p->cuts, p->n_cuts) != 0)) {
            fprintf(stderr, "bench_cut: cannot build the shape functions\n");
            return 1;
        }
        sh.cut_all = m == 2;
        for (int r = 0; r < REPS; ++r) {
            if (pass(&sh, &t[r], &cut[m], &points) != 0) {
                return 1;
            }
        }
        qsort(t, REPS, sizeof *t, cmp);
        med[m] = t[REPS / 2];
        printf("%-28s %7zu of %zu points recomputed for the cut, shape functions %.3f s "
               "(median of %d)\n",
               name[m], cut[m], points, med[m], REPS);
        tf_shape_free(&sh);
    }
    printf("recomputing only the cut supports: %.2fx the uncut time; recomputing every point "
           "would be %.2fx (saving %.0f %%)\n",
           med[1] / med[0], med[2] / med[0], 100 * (1 - med[1] / med[2]));
    tf_scene_free(s);
    return 0;
}
