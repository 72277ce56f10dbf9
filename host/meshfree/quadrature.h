/*
 * quadrature.h — Gauss-Legendre rules, the background cells of the volume
 * integral (seed §2.3: "fixed background units where Gaussian integral
 * points are determined by Gauss-Legendre formula in each unit") and the
 * points of a load patch on a face.
 */
#ifndef TF_QUADRATURE_H
#define TF_QUADRATURE_H

#include <stddef.h>

#include "meshfree/cells.h"
#include "problem/problem.h"

/* n-point Gauss-Legendre rule on [-1, 1] (1 <= n <= TF_GAUSS_MAX): nodes
 * ascending, exactly mirror-symmetric.  Returns 0, or -1 for a bad n. */
int tf_gauss_legendre(unsigned n, double *x, double *w);

int tf_cells_init(tf_cells *c, const double lo[3], const double hi[3], const unsigned n[3],
                  unsigned gauss);
/* Cells over a cloud's box: equal cells on a uniform cloud (tf_cells_init),
 * graded ones on a graded cloud.  Returns 0, or -1 (bad gauss, out of
 * memory). */
int tf_cells_init_cloud(tf_cells *c, const tf_cloud *cloud, const unsigned n[3], unsigned gauss);
/* Frees a graded box's cell edges and what tf_cells_use_tets allocated. */
void tf_cells_free(tf_cells *c);
/* The cell index along axis a that holds coordinate x (clamped). */
unsigned tf_cells_slab(const tf_cells *c, int a, double x);
/* The smallest cell size along axis a, mm. */
double tf_cells_min_size(const tf_cells *c, int a);
/* Centre and half-size of cell `cell` (x fastest); a tetrahedron: its
 * centroid and the half-extent of its bounding box. */
void tf_cells_box(const tf_cells *c, size_t cell, double centre[3], double half[3]);
/* Point p (0 .. gauss^3 - 1) of a cell, and its weight (volume, mm^3). */
void tf_cells_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w);

/* What the cells are, for a solver's log line: "N cells x g^3 Gauss
 * points" or "N tetrahedra x n Gauss points (degree d)". */
void tf_cells_describe(const tf_cells *c, char *buf, size_t len);

/* Quadrature points covering a patch (not TF_PATCH_POINT) of the box face,
 * about two sub-cells per background cell along each in-face axis, gauss^2
 * points each (a disc: rings x sectors in polar coordinates).  Returns a
 * malloc'ed array and its length in *n, or NULL when out of memory. */
tf_qpoint *tf_patch_points(const tf_patch *p, const tf_cloud *cloud, const tf_cells *cells,
                           size_t *n);

/* Area of a patch, mm^2 (0 for a point). */
double tf_patch_area(const tf_patch *p, const tf_cloud *cloud);

#endif /* TF_QUADRATURE_H */
