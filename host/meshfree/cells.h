/*
 * cells.h — the background cells of the volume integral (quadrature.h) and
 * a weighted surface point, as types: box cells and tetrahedral cells
 * (tet_cells.h) both use them, and quadrature.c dispatches to tet_cells.c,
 * so the types sit below both.
 */
#ifndef TF_CELLS_H
#define TF_CELLS_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/simplex_rules.h"

#define TF_GAUSS_MAX 12

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

static inline size_t tf_cells_count(const tf_cells *c)
{
    return c->tet ? c->ntet : (size_t)c->n[0] * c->n[1] * c->n[2];
}
static inline size_t tf_cells_points(const tf_cells *c)
{
    return c->tet ? c->rule.n : (size_t)c->gauss * c->gauss * c->gauss;
}

/* A weighted point on a surface (weight: area, mm^2). */
typedef struct tf_qpoint {
    double x[3];
    double w;
} tf_qpoint;

#endif /* TF_CELLS_H */
