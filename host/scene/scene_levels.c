/*
 * scene_levels.c — the levels of a convergence study (scene_levels.h).
 */
#include "scene/scene_levels.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>

#define MAX_SETS 12

/* Greatest common divisor. */
static unsigned gcd(unsigned a, unsigned b)
{
    while (b != 0) {
        const unsigned r = a % b;
        a = b;
        b = r;
    }
    return a;
}

/* The grid index of node index `node` on axis a (problem.h's numbering:
 * x, then y, then the layers from the top). */
static unsigned grid_index(const unsigned grid[3], uint32_t node, int a)
{
    const unsigned i = node % grid[0], j = node / grid[0] % grid[1], layer = node / (grid[0] * grid[1]);
    return a == 0 ? i : a == 1 ? j : grid[2] - 1 - layer;
}

/* The intervals of an axis of n intervals times 1/f, rounded to a multiple
 * of `step` (so that the nodes of the contact sites given by number stay
 * nodes; step 1: to the nearest whole number). */
static unsigned intervals(unsigned n, double f, unsigned step)
{
    const long m = (long)step * lround(n / f / step);
    return m >= (long)step ? (unsigned)m : step;
}

/* A box's overrides for its nodal spacing times f; a contact site given by
 * node number is renumbered to the node at the same point of the new grid
 * (the point stays a node: its axis's intervals are rounded to a multiple
 * that keeps it one). */
static size_t box_sets(const tf_problem *b, double f, char sets[MAX_SETS][160])
{
    const tf_box_geometry *box = &b->geometry.as.box;
    double hi[3];
    unsigned grid[3], cells[3], step[3] = {1, 1, 1};
    for (size_t c = 0; c < b->n_contacts; ++c) {
        for (int a = 0; a < 3 && b->contacts[c].by_node; ++a) {
            const unsigned n = box->grid[a] - 1, i = grid_index(box->grid, b->contacts[c].node, a);
            const unsigned q = n / gcd(i, n); /* the node sits at i/n = (i/g)/q of the axis */
            step[a] = step[a] / gcd(step[a], q) * q;
        }
    }
    for (int a = 0; a < 3; ++a) {
        int thin = box->grid[a] == 2;
        grid[a] = thin ? 2 : intervals(box->grid[a] - 1, f, step[a]) + 1;
        /* the cells keep their ratio to the node intervals (one per interval
         * by default): B-bar's volumetric average is per cell, and a cloud
         * with fewer cells than intervals is far softer (block48's 15 x 15 x 4
         * grid with 13 x 13 x 3 cells: 34 % at the centre) */
        cells[a] = thin ? b->solver.cells[a]
                        : (unsigned)fmax(1, lround((double)b->solver.cells[a] * (grid[a] - 1) /
                                                   (box->grid[a] - 1)));
        hi[a] = thin ? box->min[a] + (box->max[a] - box->min[a]) * f : box->max[a];
    }
    size_t n = 0;
    snprintf(sets[n++], sizeof sets[0], "geometry.grid=%u,%u,%u", grid[0], grid[1], grid[2]);
    snprintf(sets[n++], sizeof sets[0], "geometry.box.max=%.17g,%.17g,%.17g", hi[0], hi[1], hi[2]);
    snprintf(sets[n++], sizeof sets[0], "solver.cells=%u,%u,%u", cells[0], cells[1], cells[2]);
    for (size_t c = 0; c < b->n_contacts && n < MAX_SETS - 1; ++c) {
        if (!b->contacts[c].by_node) {
            continue;
        }
        unsigned at[3];
        for (int a = 0; a < 3; ++a) {
            const unsigned i = grid_index(box->grid, b->contacts[c].node, a), was = box->grid[a] - 1;
            at[a] = box->grid[a] == 2 ? i : i * (grid[a] - 1) / was; /* exact: a multiple of step */
        }
        const unsigned long number =
            at[0] + (unsigned long)grid[0] * at[1] + (unsigned long)grid[0] * grid[1] * (grid[2] - 1 - at[2]) + 1;
        snprintf(sets[n++], sizeof sets[0], "contact.%zu.node=%lu", c, number);
    }
    return n;
}

/* An organ's: its interior spacing (and a local refinement's) times f; the
 * surface's vertices stay (they are the file's). */
static size_t organ_sets(const tf_problem *b, double f, char sets[MAX_SETS][160])
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
static void level_sets(const tf_problem *b, tf_vary vary, unsigned k, double f, char sets[MAX_SETS][160],
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
    char extra[MAX_SETS][160];
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
