/*
 * box_cloud.c — grids and jittered grids in a box (box_cloud.h).
 */
#include "box_cloud.h"

#include <stdlib.h>

#include "base/rng.h"

int box_cloud_make(box_cloud *b, const size_t dims[3], const double lo[3], const double hi[3],
                   double jitter, uint64_t seed)
{
    *b = (box_cloud){0};
    if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2) {
        return -1;
    }
    size_t n = dims[0] * dims[1] * dims[2];
    b->X = malloc(3 * n * sizeof *b->X);
    b->volume = malloc(n * sizeof *b->volume);
    b->fixed = calloc(n, 1);
    if (!b->X || !b->volume || !b->fixed) {
        box_cloud_free(b);
        return -1;
    }
    b->n = n;
    tf_rng r = {seed};
    double h[3];
    for (int a = 0; a < 3; ++a) {
        b->dims[a] = dims[a];
        h[a] = (hi[a] - lo[a]) / (double)(dims[a] - 1);
    }
    for (size_t k = 0; k < dims[2]; ++k) {
        for (size_t j = 0; j < dims[1]; ++j) {
            for (size_t i = 0; i < dims[0]; ++i) {
                size_t p = box_cloud_at(b, i, j, k), idx[3] = {i, j, k};
                double v = 1;
                for (int a = 0; a < 3; ++a) {
                    int edge = idx[a] == 0 || idx[a] == dims[a] - 1;
                    double t = edge ? 0 : tf_rng_range(&r, -jitter, jitter);
                    b->X[3 * p + a] = lo[a] + ((double)idx[a] + t) * h[a];
                    v *= edge ? h[a] / 2 : h[a];
                }
                b->volume[p] = v;
            }
        }
    }
    return 0;
}

void box_cloud_free(box_cloud *b)
{
    free(b->X);
    free(b->volume);
    free(b->fixed);
    *b = (box_cloud){0};
}
