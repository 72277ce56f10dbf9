/*
 * nodes.c — box node clouds (see nodes.h).
 */
#include "problem/nodes.h"

#include <math.h>
#include <stdlib.h>

#include "base/rng.h"

void tf_face_axes(tf_face f, int *u, int *v)
{
    switch (tf_face_axis(f)) {
    case 0:
        *u = 1;
        *v = 2;
        break;
    case 1:
        *u = 0;
        *v = 2;
        break;
    default:
        *u = 0;
        *v = 1;
        break;
    }
}

size_t tf_cloud_index(const tf_cloud *c, unsigned i, unsigned j, unsigned k)
{
    size_t nx = c->grid[0], ny = c->grid[1], nz = c->grid[2];
    return i + nx * j + nx * ny * (nz - 1 - k);
}

double tf_cloud_tol(const tf_cloud *c)
{
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
        d2 += (c->hi[a] - c->lo[a]) * (c->hi[a] - c->lo[a]);
    }
    return 1e-9 * sqrt(d2);
}

double tf_cloud_face_coord(const tf_cloud *c, tf_face f)
{
    int a = tf_face_axis(f);
    return tf_face_is_max(f) ? c->hi[a] : c->lo[a];
}

/* The grid lines of each axis: uniform (the historical formula, so that
 * ungraded clouds keep their bits) or graded. */
static int grid_lines(tf_cloud *c, const tf_cloud_grading *g)
{
    c->graded = 0;
    for (int a = 0; a < 3; ++a) {
        unsigned n = c->grid[a];
        c->axis[a] = malloc(n * sizeof *c->axis[a]);
        if (c->axis[a] == NULL) {
            return -1;
        }
        int graded = g != NULL && g->ratio[a] > 1 && g->n[a] > 0;
        if (!graded) {
            for (unsigned i = 0; i < n; ++i) {
                c->axis[a][i] = i + 1 == n ? c->hi[a] : c->lo[a] + i * c->spacing[a];
            }
        } else if (tf_cloud_grading_axis(c->lo[a], c->hi[a], n, g->ratio[a], (const double(*)[2])g->at[a],
                                   g->n[a], c->axis[a]) != 0) {
            return -1;
        } else {
            /* an axis whose attractors leave it uniform after all */
            for (unsigned i = 1; i + 1 < n && !c->graded; ++i) {
                c->graded = c->axis[a][i] != c->lo[a] + i * c->spacing[a];
            }
        }
    }
    return 0;
}

/* How far node i of axis a may be jittered: the nominal spacing on a
 * uniform grid, the smaller neighbouring interval on a graded one. */
static double jitter_scale(const tf_cloud *c, int a, unsigned i)
{
    if (!c->graded) {
        return c->spacing[a];
    }
    const double *x = c->axis[a];
    return fmin(x[i] - x[i - 1], x[i + 1] - x[i]);
}

int tf_cloud_box_graded(tf_cloud *c, const double lo[3], const double hi[3],
                        const unsigned grid[3], double jitter, uint64_t seed,
                        const tf_cloud_grading *g)
{
    c->xyz = NULL;
    for (int a = 0; a < 3; ++a) {
        c->lo[a] = lo[a];
        c->hi[a] = hi[a];
        c->grid[a] = grid[a];
        c->spacing[a] = (hi[a] - lo[a]) / (grid[a] - 1);
        c->axis[a] = NULL;
    }
    c->n = (size_t)grid[0] * grid[1] * grid[2];
    if (grid_lines(c, g) != 0 || (c->xyz = malloc(3 * c->n * sizeof *c->xyz)) == NULL) {
        tf_cloud_free(c);
        return -1;
    }
    /* Jitter is drawn in grid order (not index order) so that a node keeps
     * its offset whatever the numbering. */
    tf_rng r = {seed};
    for (unsigned k = 0; k < grid[2]; ++k) {
        for (unsigned j = 0; j < grid[1]; ++j) {
            for (unsigned i = 0; i < grid[0]; ++i) {
                const unsigned ijk[3] = {i, j, k};
                int interior = 1;
                for (int a = 0; a < 3; ++a) {
                    interior &= ijk[a] > 0 && ijk[a] + 1 < grid[a];
                }
                double *x = c->xyz + 3 * tf_cloud_index(c, i, j, k);
                for (int a = 0; a < 3; ++a) {
                    x[a] = c->axis[a][ijk[a]];
                    if (interior && jitter > 0) {
                        x[a] += jitter * jitter_scale(c, a, ijk[a]) * tf_rng_range(&r, -1, 1);
                    }
                }
            }
        }
    }
    return 0;
}

int tf_cloud_box(tf_cloud *c, const double lo[3], const double hi[3], const unsigned grid[3],
                 double jitter, uint64_t seed)
{
    return tf_cloud_box_graded(c, lo, hi, grid, jitter, seed, NULL);
}

/* The grid interval of axis a holding x (clamped to the first and last). */
static unsigned interval(const tf_cloud *c, int a, double x)
{
    return tf_cloud_lines_interval(c->axis[a], c->grid[a], x);
}

double tf_cloud_to_index(const tf_cloud *c, int a, double x)
{
    if (!c->graded || c->axis[a] == NULL) {
        return (x - c->lo[a]) / c->spacing[a];
    }
    unsigned i = interval(c, a, x);
    const double *g = c->axis[a];
    return i + (x - g[i]) / (g[i + 1] - g[i]);
}

double tf_cloud_from_index(const tf_cloud *c, int a, double xi)
{
    if (!c->graded || c->axis[a] == NULL) {
        return c->lo[a] + xi * c->spacing[a];
    }
    double f = floor(xi);
    unsigned last = c->grid[a] - 2;
    unsigned i = f < 0 ? 0 : f > last ? last : (unsigned)f;
    const double *g = c->axis[a];
    return g[i] + (xi - i) * (g[i + 1] - g[i]);
}

void tf_cloud_local_spacing(const tf_cloud *c, const double x[3], double h[3])
{
    for (int a = 0; a < 3; ++a) {
        if (!c->graded || c->axis[a] == NULL) {
            h[a] = c->spacing[a];
        } else {
            unsigned i = interval(c, a, x[a]);
            h[a] = c->axis[a][i + 1] - c->axis[a][i];
        }
    }
}

void tf_cloud_free(tf_cloud *c)
{
    free(c->xyz);
    c->xyz = NULL;
    for (int a = 0; a < 3; ++a) {
        free(c->axis[a]);
        c->axis[a] = NULL;
    }
    c->n = 0;
}
