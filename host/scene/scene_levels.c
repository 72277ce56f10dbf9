/*
 * scene_levels.c — the levels of a convergence study (scene_levels.h).
 */
#include "scene/scene_levels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* A box's overrides for its nodal spacing times f. */
static size_t box_sets(const tf_problem *b, double f, char sets[4][160])
{
    const tf_box_geometry *box = &b->geometry.as.box;
    double hi[3];
    unsigned grid[3], cells[3];
    for (int a = 0; a < 3; ++a) {
        int thin = box->grid[a] == 2;
        grid[a] = thin ? 2 : (unsigned)lround((box->grid[a] - 1) / f) + 1;
        cells[a] = thin ? b->solver.cells[a] : (unsigned)fmax(1, lround(b->solver.cells[a] / f));
        hi[a] = thin ? box->min[a] + (box->max[a] - box->min[a]) * f : box->max[a];
    }
    snprintf(sets[0], sizeof sets[0], "geometry.grid=%u,%u,%u", grid[0], grid[1], grid[2]);
    snprintf(sets[1], sizeof sets[1], "geometry.box.max=%.17g,%.17g,%.17g", hi[0], hi[1], hi[2]);
    snprintf(sets[2], sizeof sets[2], "solver.cells=%u,%u,%u", cells[0], cells[1], cells[2]);
    return 3;
}

/* An organ's: its interior spacing (and a local refinement's) times f; the
 * surface's vertices stay (they are the file's). */
static size_t organ_sets(const tf_problem *b, double f, char sets[4][160])
{
    const tf_mesh_options *m = &b->geometry.as.mesh->mesh;
    snprintf(sets[0], sizeof sets[0], "geometry.spacing=%.17g", m->spacing * f);
    if (!m->graded) {
        return 1;
    }
    snprintf(sets[1], sizeof sets[1], "geometry.refine.spacing=%.17g", m->grade_spacing * f);
    return 2;
}

/* The overrides that turn the base scene into level k (grid: the spacing
 * times f). */
static void level_sets(const tf_problem *b, tf_vary vary, unsigned k, double f, char sets[4][160],
                       size_t *n)
{
    if (vary == TF_VARY_GAUSS) {
        snprintf(sets[0], sizeof sets[0], "solver.gauss=%u", k + 1);
        *n = 1;
        return;
    }
    *n = b->geometry.kind == TF_GEOMETRY_BOX ? box_sets(b, f, sets) : organ_sets(b, f, sets);
    /* an absolute d_c scales with the spacing; a relative one does by itself */
    if (!(b->solver.d_c_spacings > 0)) {
        snprintf(sets[*n], sizeof sets[*n], "solver.rbf.d_c=%.17g", b->solver.d_c * f);
        ++*n;
    }
}

static tf_scene *scene_at(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                          tf_vary vary, unsigned k, double f)
{
    tf_scene *base = tf_scene_load(ctx, path, sets, n_sets);
    if (base == NULL) {
        return NULL;
    }
    char extra[4][160];
    size_t n_extra;
    level_sets(&base->problem, vary, k, f, extra, &n_extra);
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
    return s;
}

tf_scene *tf_scene_scaled(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                          double f)
{
    return scene_at(ctx, path, sets, n_sets, TF_VARY_GRID, 0, f);
}

tf_scene *tf_scene_level(tf_ctx *ctx, const char *path, const char *const *sets, size_t n_sets,
                         tf_vary vary, unsigned k, unsigned *label)
{
    tf_scene *s = scene_at(ctx, path, sets, n_sets, vary, k, ldexp(1.0, -(int)k));
    if (s != NULL) {
        *label = vary == TF_VARY_GAUSS ? s->problem.solver.gauss : k;
    }
    return s;
}
