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

int tf_cloud_box(tf_cloud *c, const double lo[3], const double hi[3], const unsigned grid[3],
                 double jitter, uint64_t seed)
{
    for (int a = 0; a < 3; ++a) {
        c->lo[a] = lo[a];
        c->hi[a] = hi[a];
        c->grid[a] = grid[a];
        c->spacing[a] = (hi[a] - lo[a]) / (grid[a] - 1);
    }
    c->n = (size_t)grid[0] * grid[1] * grid[2];
    c->xyz = malloc(3 * c->n * sizeof *c->xyz);
    if (c->xyz == NULL) {
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
                    /* The last node sits exactly on hi, not on lo + (n-1) h. */
                    x[a] = ijk[a] + 1 == grid[a] ? hi[a] : lo[a] + ijk[a] * c->spacing[a];
                    if (interior && jitter > 0) {
                        x[a] += jitter * c->spacing[a] * tf_rng_range(&r, -1, 1);
                    }
                }
            }
        }
    }
    return 0;
}

void tf_cloud_free(tf_cloud *c)
{
    free(c->xyz);
    c->xyz = NULL;
    c->n = 0;
}
