/*
 * box_cloud.h — particle clouds in a box for the collocation tests: a grid
 * of nx x ny x nz points over [lo, hi], optionally jittered (interior
 * points moved by up to `jitter` spacings along each axis, boundary points
 * kept on their faces), with the grid's tributary volumes (exact for
 * jitter 0; for a jittered cloud the unjittered ones, which still sum to
 * the box's volume).
 */
#ifndef TF_BOX_CLOUD_H
#define TF_BOX_CLOUD_H

#include <stddef.h>
#include <stdint.h>

typedef struct box_cloud {
    size_t n, dims[3];
    double *X, *volume;
    unsigned char *fixed; /* all zero: the caller fixes what it needs */
} box_cloud;

/* Returns 0, or -1 when out of memory or a dimension is below 2. */
int box_cloud_make(box_cloud *b, const size_t dims[3], const double lo[3], const double hi[3],
                   double jitter, uint64_t seed);
void box_cloud_free(box_cloud *b);

/* Index of grid point (i, j, k). */
static inline size_t box_cloud_at(const box_cloud *b, size_t i, size_t j, size_t k)
{
    return i + b->dims[0] * (j + b->dims[1] * k);
}

#endif /* TF_BOX_CLOUD_H */
