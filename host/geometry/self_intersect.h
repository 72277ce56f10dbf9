/*
 * self_intersect.h — pairs of triangles of a surface that cross each other.
 * gmsh's volume mesher cannot recover such a boundary ("PLC Error: A
 * segment and a facet intersect at point", without saying where); this
 * finds the place so that the message can.
 *
 * Pairs that share a vertex are not tested, and neither are touching or
 * coplanar contacts: an edge of one triangle must pass strictly through the
 * other's interior (orientation signs in double precision, not exact
 * predicates).
 */
#ifndef TF_SELF_INTERSECT_H
#define TF_SELF_INTERSECT_H

#include <stddef.h>

#include "geometry/surface.h"

typedef struct tf_crossing {
    size_t pairs;  /* crossing pairs found */
    size_t tri[2]; /* the first pair (lowest first triangle, then second) */
    double at[3];  /* where an edge of one passes through the other */
} tf_crossing;

/* Returns 0, or -1 when out of memory. */
int tf_surface_crossings(const tf_surface *s, tf_crossing *c);

/* Does segment pq pass strictly through the interior of triangle abc?
 * Sets *at to the crossing point when it does. */
int tf_segment_crosses_triangle(const double p[3], const double q[3], const double a[3],
                                const double b[3], const double c[3], double at[3]);

#endif /* TF_SELF_INTERSECT_H */
