/*
 * neighbours.h — which nodes lie in a support domain: a uniform grid of bins
 * over the cloud, so that building is linear in the node count and a query
 * looks at 27 bins.
 *
 * A support domain is an ellipsoid with semi-axes radius[0..2] around the
 * query point (a sphere for an isotropic cloud; per-axis radii follow a
 * grid whose spacing differs by axis, e.g. block48's 4.8 x 4.8 x 3 mm).
 */
#ifndef TF_NEIGHBOURS_H
#define TF_NEIGHBOURS_H

#include <stddef.h>
#include <stdint.h>

typedef struct tf_nbr {
    const double *xyz; /* borrowed node coordinates */
    size_t n;
    double radius[3];
    double lo[3];
    double bin[3];     /* bin size per axis (>= radius) */
    unsigned dims[3];
    uint32_t *start;   /* dims product + 1 offsets into items */
    uint32_t *items;   /* node indices, ascending within a bin */
} tf_nbr;

/* Bins the n nodes xyz (kept by pointer) for queries of the given radii.
 * Returns 0, or -1 when out of memory. */
int tf_nbr_build(tf_nbr *g, const double *xyz, size_t n, const double radius[3]);
void tf_nbr_free(tf_nbr *g);

/* Nodes within the ellipsoid around x, ascending.  Writes at most cap
 * indices to out and returns how many there are (call again with a larger
 * buffer when the result exceeds cap). */
size_t tf_nbr_query(const tf_nbr *g, const double x[3], uint32_t *out, size_t cap);

/* The same for the ball of radius r around x (any radius: the bins it
 * overlaps are scanned). */
size_t tf_nbr_query_ball(const tf_nbr *g, const double x[3], double r, uint32_t *out, size_t cap);

/* Distance from x to its k-th nearest node (k >= 1, at most the node
 * count), or -1 when out of memory. */
double tf_nbr_kth_distance(const tf_nbr *g, const double x[3], size_t k);

#endif /* TF_NEIGHBOURS_H */
