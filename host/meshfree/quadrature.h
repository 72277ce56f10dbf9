/*
 * quadrature.h — Gauss-Legendre rules, the background cells of the volume
 * integral (seed §2.3: "fixed background units where Gaussian integral
 * points are determined by Gauss-Legendre formula in each unit") and the
 * points of a load patch on a face.
 */
#ifndef TF_QUADRATURE_H
#define TF_QUADRATURE_H

#include <stddef.h>

#include "problem/problem.h"

#define TF_GAUSS_MAX 12

/* n-point Gauss-Legendre rule on [-1, 1] (1 <= n <= TF_GAUSS_MAX): nodes
 * ascending, exactly mirror-symmetric.  Returns 0, or -1 for a bad n. */
int tf_gauss_legendre(unsigned n, double *x, double *w);

/* Background cells: a box split into cells[0] x cells[1] x cells[2] cells
 * with gauss^3 points each; equal cells, or on a graded cloud cells that
 * follow its grid lines (edges equidistant in the cloud's index space, so
 * one cell per grid interval when there are grid - 1 cells). */
typedef struct tf_cells {
    double lo[3];
    double size[3];    /* one cell, mm (equal cells); the mean cell (graded) */
    unsigned n[3];
    unsigned gauss;
    double gx[TF_GAUSS_MAX], gw[TF_GAUSS_MAX];
    double *edge[3];   /* graded: n[a] + 1 cell edges per axis, ascending; NULL: equal cells */
} tf_cells;

int tf_cells_init(tf_cells *c, const double lo[3], const double hi[3], const unsigned n[3],
                  unsigned gauss);
/* Cells over a cloud's box: equal cells on a uniform cloud (tf_cells_init),
 * graded ones on a graded cloud.  Returns 0, or -1 (bad gauss, out of
 * memory). */
int tf_cells_init_cloud(tf_cells *c, const tf_cloud *cloud, const unsigned n[3], unsigned gauss);
void tf_cells_free(tf_cells *c);
/* The cell index along axis a that holds coordinate x (clamped). */
unsigned tf_cells_slab(const tf_cells *c, int a, double x);
/* The smallest cell size along axis a, mm. */
double tf_cells_min_size(const tf_cells *c, int a);
static inline size_t tf_cells_count(const tf_cells *c)
{
    return (size_t)c->n[0] * c->n[1] * c->n[2];
}
static inline size_t tf_cells_points(const tf_cells *c)
{
    return (size_t)c->gauss * c->gauss * c->gauss;
}
/* Centre and half-size of cell `cell` (x fastest). */
void tf_cells_box(const tf_cells *c, size_t cell, double centre[3], double half[3]);
/* Point p (0 .. gauss^3 - 1) of a cell, and its weight (volume, mm^3). */
void tf_cells_point(const tf_cells *c, size_t cell, size_t p, double x[3], double *w);

/* A weighted point on a surface (weight: area, mm^2). */
typedef struct tf_qpoint {
    double x[3];
    double w;
} tf_qpoint;

/* Quadrature points covering a patch (not TF_PATCH_POINT) of the box face,
 * about two sub-cells per background cell along each in-face axis, gauss^2
 * points each (a disc: rings x sectors in polar coordinates).  Returns a
 * malloc'ed array and its length in *n, or NULL when out of memory. */
tf_qpoint *tf_patch_points(const tf_patch *p, const tf_cloud *cloud, const tf_cells *cells,
                           size_t *n);

/* Area of a patch, mm^2 (0 for a point). */
double tf_patch_area(const tf_patch *p, const tf_cloud *cloud);

#endif /* TF_QUADRATURE_H */
