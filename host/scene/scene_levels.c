/*
 * scene_levels.c — the levels of a convergence study (scene_levels.h).
 */
#include "scene/scene_levels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The overrides that turn the base scene into level k. */
static void level_sets(const tf_problem *b, tf_vary vary, unsigned k, char sets[4][160],
                       size_t *n)
{
    if (vary == TF_VARY_GAUSS) {
        snprintf(sets[0], sizeof sets[0], "solver.gauss=%u", k + 1);
        *n = 1;
        return;
    }
    const tf_box_geometry *box = &b->geometry.as.box;
    double f = ldexp(1.0, (int)k), hi[3];
    unsigned grid[3], cells[3];
    for (int a = 0; a < 3; ++a) {
        int thin = box->grid[a] == 2;
        grid[a] = thin ? 2 : (box->grid[a] - 1) * (1u << k) + 1;
        cells[a] = thin ? b->solver.cells[a] : b->solver.cells[a] * (1u << k);
        hi[a] = thin ? box->min[a] + (box->max[a] - box->min[a]) / f : box->max[a];
    }
    snprintf(sets[0], sizeof sets[0], "geometry.grid=%u,%u,%u", grid[0], grid[1], grid[2]);
    snprintf(sets[1], sizeof sets[1], "geometry.box.max=%.17g,%.17g,%.17g", hi[0], hi[1], hi[2]);
    snprintf(sets[2], sizeof sets[2], "solver.cells=%u,%u,%u", cells[0], cells[1], cells[2]);
    /* an absolute d_c halves with the spacing; a relative one does by itself */
    snprintf(sets[3], sizeof sets[3], "solver.rbf.d_c=%.17g", b->solver.d_c / f);
    *n = b->solver.d_c_spacings > 0 ? 3 : 4;
}

tf_scene *tf_scene_level(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                         tf_vary vary, unsigned k, unsigned *label)
{
    tf_scene *base = tf_scene_load(ctx, path, sets, n_sets);
    if (base == NULL) {
        return NULL;
    }
    char extra[4][160];
    size_t n_extra;
    level_sets(&base->problem, vary, k, extra, &n_extra);
    tf_scene_free(base);
    const char **all = malloc((n_sets + n_extra) * sizeof *all);
    if (all == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    for (size_t i = 0; i < n_sets; ++i) {
        all[i] = sets[i];
    }
    for (size_t i = 0; i < n_extra; ++i) {
        all[n_sets + i] = extra[i];
    }
    tf_scene *s = tf_scene_load(ctx, path, all, n_sets + n_extra);
    free(all);
    if (s != NULL) {
        *label = vary == TF_VARY_GAUSS ? s->problem.solver.gauss : k;
    }
    return s;
}
