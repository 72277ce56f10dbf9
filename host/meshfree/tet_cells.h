/*
 * tet_cells.h — tetrahedral integration cells (an organ's mesh) behind the
 * background-cell interface of quadrature.h: Gauss points, centroid and
 * extent of a cell; tf_cells_use_tets, tf_cells_locate and tf_cells_free
 * are declared there (tf_cells_free frees a graded box's edges and, through
 * tf_cells_tet_free, a mesh's locator).
 */
#ifndef TF_TET_CELLS_H
#define TF_TET_CELLS_H

#include <stddef.h>

#include "meshfree/quadrature.h"

/* Point p of tetrahedron `cell` and its weight (volume, mm^3). */
void tf_cells_tet_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w);

/* Centroid of tetrahedron `cell` and half the extent of its bounding box. */
void tf_cells_tet_box(const tf_cells *c, size_t cell, double centre[3], double half[3]);

/* Frees the locator tf_cells_use_tets built and forgets the tetrahedra
 * (nothing for box cells); tf_cells_free calls it. */
void tf_cells_tet_free(tf_cells *c);

#endif /* TF_TET_CELLS_H */
