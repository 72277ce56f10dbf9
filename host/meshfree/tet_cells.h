/*
 * tet_cells.h — tetrahedral integration cells (an organ's mesh) behind the
 * background-cell interface of quadrature.h: Gauss points, centroid and
 * extent of a cell, switching cells to tetrahedra, locating a point, and
 * the points of a surface patch (tf_cells_free, in quadrature.h, frees a
 * graded box's edges and, through tf_cells_tet_free, a mesh's locator).
 */
#ifndef TF_TET_CELLS_H
#define TF_TET_CELLS_H

#include <stddef.h>

#include "meshfree/cells.h"
#include "problem/problem.h"

/* Point p of tetrahedron `cell` and its weight (volume, mm^3). */
void tf_cells_tet_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w);

/* Centroid of tetrahedron `cell` and half the extent of its bounding box. */
void tf_cells_tet_box(const tf_cells *c, size_t cell, double centre[3], double half[3]);

/* Frees the locator tf_cells_use_tets built and forgets the tetrahedra
 * (nothing for box cells); tf_cells_free calls it. */
void tf_cells_tet_free(tf_cells *c);

/* Switches c to the ntet tetrahedra tet[] over the nodes xyz (both must
 * outlive c) with the Gauss rule of the given degree (1 to 5).  Returns 0,
 * or -1 (bad degree, out of memory). */
int tf_cells_use_tets(tf_cells *c, const double *xyz, const size_t *tet, size_t ntet,
                      unsigned degree);
/* Tetrahedral cells: the one holding x (the most interior when x lies on
 * shared faces; the nearest by barycentric coordinates when x is outside
 * every one). */
size_t tf_cells_locate(const tf_cells *c, const double x[3]);

/* Quadrature points of a surface patch (TF_PATCH_SURFACE): the degree-5
 * triangle rule (7 points, geometry/simplex_rules.h) on each of its
 * triangles.  The weights sum to the patch's area up to rounding, so a
 * uniform traction force / area applies the whole force.  Returns a
 * malloc'ed array (length in *n) or NULL when out of memory. */
tf_qpoint *tf_patch_surface_points(const tf_patch *p, const tf_cloud *cloud, size_t *n);

#endif /* TF_TET_CELLS_H */
