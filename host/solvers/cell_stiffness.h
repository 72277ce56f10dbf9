/*
 * cell_stiffness.h — the stiffness of one background cell: the sum over its
 * Gauss points of w B^T D B (seed eq 19) as a dense matrix over the nodes
 * its supports touch.
 *
 * With cell-centred supports all points share one node set, and the sums
 * M^ab_ij = sum_g w_g d_a phi_i d_b phi_j come from one BLAS dsyrk; with
 * point-centred supports (the seed) each point adds its own blocks.  With
 * B-bar (Hughes 1980) the volumetric part lambda (div u)(div v) uses the
 * divergence averaged over the cell, which removes volumetric locking as
 * nu approaches 0.5.
 */
#ifndef TF_CELL_STIFFNESS_H
#define TF_CELL_STIFFNESS_H

#include <stddef.h>
#include <stdint.h>

#include "materials/elasticity.h"
#include "meshfree/shape.h"
#include "solvers/cell_gradients.h"

/* One thread's scratch. */
typedef struct tf_cell_work {
    tf_shape_work sw;
    int *map;       /* node -> local index in the current cell, or -1 (all -1 between calls) */
    double *x, *w;  /* Gauss points of a cell and their weights */
    double *y, *c;  /* scaled gradients and Y^T Y */
    size_t cap;     /* nodes per cell the buffers hold */
    double t_shape; /* seconds spent in shape functions */
    int vci;        /* gradients corrected (cell_gradients.h) */
    tf_grad_work gw;/* VCI: gradients over the cell's set */
    double *g;      /* VCI: 3 np cap gradients */
    size_t *loc;    /* cap local indices */
    tf_lame *pl;    /* np: each Gauss point's material, when it varies */
    double *wm;     /* np: the weights of one material's points (0 elsewhere) */
} tf_cell_work;

/* The material at a point of a body whose material varies (material
 * regions, problem/inclusions.h). */
typedef struct tf_lame_field {
    const void *data;
    tf_lame (*at)(const void *data, const double x[3]);
} tf_lame_field;

/* Scratch for n_nodes nodes and cells of up to cap nodes, with VCI's
 * corrected gradients when vci.  Returns 0, or -1 when out of memory. */
int tf_cell_work_init(tf_cell_work *w, const tf_shape *sh, size_t n_nodes, size_t cap, int vci);
void tf_cell_work_free(tf_cell_work *w);

/* kc (3m x 3m, column major, zeroed here; the lower block triangle is
 * filled) for cell `cell` whose supports touch the m nodes set[] (ascending).
 * The material is l, or with field (not with VCI) each Gauss point's own:
 * a cell whose points share one material is computed as with l; a cell an
 * inclusion cuts sums each material's points with its own Lame parameters
 * (with B-bar the divergence is averaged over each material's points of
 * the cell).  Returns 0, or -1 with a message in wk->sw.err (VCI: copied
 * there from wk->gw). */
int tf_cell_stiffness(const tf_shape *sh, const tf_lame *l, const tf_lame_field *field, int bbar,
                      tf_cell_work *wk, size_t cell, const uint32_t *set, size_t m, double *kc);

#endif /* TF_CELL_STIFFNESS_H */
