/*
 * quadrature.h — Gauss-Legendre rules, the background cells of the volume
 * integral (seed §2.3: "fixed background units where Gaussian integral
 * points are determined by Gauss-Legendre formula in each unit") and the
 * points of a load patch on a face.
 */
#ifndef TF_QUADRATURE_H
#define TF_QUADRATURE_H

#include <stddef.h>

#include "geometry/simplex_rules.h"
#include "problem/problem.h"

#define TF_GAUSS_MAX 12

/* n-point Gauss-Legendre rule on [-1, 1] (1 <= n <= TF_GAUSS_MAX): nodes
 * ascending, exactly mirror-symmetric.  Returns 0, or -1 for a bad n. */
int tf_gauss_legendre(unsigned n, double *x, double *w);

/* A uniform grid of tetrahedra by bounding box, to find the one holding a
 * point (tet_cells.c). */
typedef struct tf_tet_locator {
    double lo[3], bin[3];
    unsigned dims[3];
    uint32_t *start; /* dims product + 1 offsets into items */
    uint32_t *items; /* tetrahedron indices, ascending within a bin */
} tf_tet_locator;

/* Background cells: a box split into cells[0] x cells[1] x cells[2] cells
 * with gauss^3 points each; equal cells, or on a graded cloud cells that
 * follow its grid lines (edges equidistant in the cloud's index space, so
 * one cell per grid interval when there are grid - 1 cells); or, after
 * tf_cells_use_tets, the tetrahedra of an organ's mesh with a symmetric
 * Gauss rule each (geometry/simplex_rules.h). */
typedef struct tf_cells {
    double lo[3];
    double size[3];    /* one cell, mm (equal cells); the mean cell (graded) */
    unsigned n[3];
    unsigned gauss;
    double gx[TF_GAUSS_MAX], gw[TF_GAUSS_MAX];
    double *edge[3];   /* graded: n[a] + 1 cell edges per axis, ascending; NULL: equal cells */
    const double *tet_xyz; /* tetrahedral cells: node coordinates (borrowed), or NULL */
    const size_t *tet;     /* 4 node indices per cell (borrowed) */
    size_t ntet;
    tf_simplex_rule rule;
    tf_tet_locator loc;
} tf_cells;

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
static inline size_t tf_cells_count(const tf_cells *c)
{
    return c->tet ? c->ntet : (size_t)c->n[0] * c->n[1] * c->n[2];
}
static inline size_t tf_cells_points(const tf_cells *c)
{
    return c->tet ? c->rule.n : (size_t)c->gauss * c->gauss * c->gauss;
}

/* Switches c to the ntet tetrahedra tet[] over the nodes xyz (both must
 * outlive c) with the Gauss rule of the given degree (1 to 5).  Returns 0,
 * or -1 (bad degree, out of memory). */
int tf_cells_use_tets(tf_cells *c, const double *xyz, const size_t *tet, size_t ntet,
                      unsigned degree);
/* Tetrahedral cells: the one holding x (the most interior when x lies on
 * shared faces; the nearest by barycentric coordinates when x is outside
 * every one). */
size_t tf_cells_locate(const tf_cells *c, const double x[3]);
/* Centre and half-size of cell `cell` (x fastest); a tetrahedron: its
 * centroid and the half-extent of its bounding box. */
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

/* Quadrature points of a surface patch (TF_PATCH_SURFACE): the degree-5
 * triangle rule (7 points, geometry/simplex_rules.h) on each of its
 * triangles.  The weights sum to the patch's area up to rounding, so a
 * uniform traction force / area applies the whole force.  Returns a
 * malloc'ed array (length in *n) or NULL when out of memory. */
tf_qpoint *tf_patch_surface_points(const tf_patch *p, const tf_cloud *cloud, size_t *n);

/* Area of a patch, mm^2 (0 for a point). */
double tf_patch_area(const tf_patch *p, const tf_cloud *cloud);

#endif /* TF_QUADRATURE_H */
