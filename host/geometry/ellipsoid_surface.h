/*
 * ellipsoid_surface.h — a closed triangle surface of an axis-aligned
 * ellipsoid (a material region's boundary, for a mesher that must conform
 * to it: tests/calculix/organ_deck.c): an icosahedron split into four
 * until its longest edge on the unit sphere is at most edge / largest
 * semi-axis, each new vertex pushed out to the sphere, then scaled by the
 * semi-axes.  Every vertex lies on the ellipsoid; the triangles wind
 * counter-clockwise seen from outside.
 */
#ifndef TF_ELLIPSOID_SURFACE_H
#define TF_ELLIPSOID_SURFACE_H

#include "geometry/surface.h"

/* At most this many halvings (20 x 4^7 = 327,680 triangles). */
#define TF_ELLIPSOID_MAX_LEVEL 7

/* Returns 0, or -1 when out of memory or when the semi-axes or edge are not
 * positive and finite or need more than TF_ELLIPSOID_MAX_LEVEL halvings
 * (s is then empty). */
int tf_surface_ellipsoid(tf_surface *s, const double centre[3], const double radii[3],
                         double edge);

#endif /* TF_ELLIPSOID_SURFACE_H */
