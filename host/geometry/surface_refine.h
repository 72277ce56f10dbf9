/*
 * surface_refine.h — a finer skin on the same polyhedron: the surface's
 * triangles split by longest-edge bisection (Rivara's LEPP algorithm:
 * M.-C. Rivara, Int. J. Numer. Meth. Eng. 40, 1997) until no edge is
 * longer than a local size.  Every new vertex is the midpoint of an edge,
 * so it lies on the file's triangle (the geometry does not change), and
 * bisecting each triangle across its longest edge keeps the triangles'
 * smallest angle at least half the file's (Rosenberg and Stenger, Math.
 * Comp. 29, 1975).
 *
 * The file's vertices stay first, in their order and bit for bit; the new
 * ones follow with source -1 (not a vertex of the file).  The triangles
 * keep their winding.
 */
#ifndef TF_SURFACE_REFINE_H
#define TF_SURFACE_REFINE_H

#include <stddef.h>

#include "geometry/geom_msg.h"
#include "geometry/surface.h"

/* The edge length wanted at x, mm (> 0). */
typedef double (*tf_size_at)(const double x[3], const void *arg);

/* Splits every triangle whose longest edge is longer than ratio times
 * size(the edge's midpoint), and the triangles that bisection makes, until
 * none is.  s must be closed and consistently wound (surface_prepare.h).
 * Refuses (TF_GEOM_BAD_INPUT) a size that would make more than max_nv
 * vertices; TF_GEOM_FAILED when out of memory.  s is unchanged on failure. */
int tf_surface_refine(tf_surface *s, tf_size_at size, const void *arg, double ratio,
                      size_t max_nv, tf_geom_msg *m);

#endif /* TF_SURFACE_REFINE_H */
