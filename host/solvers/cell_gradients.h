/*
 * cell_gradients.h — the shape-function gradients at a background cell's
 * Gauss points over the cell's node set, optionally corrected so that the
 * discrete divergence theorem holds (variationally consistent integration,
 * VCI: Chen, Hillman & Rueter, IJNME 95, 2013, the first-order form with a
 * constant correction per node and integration cell).
 *
 * Why: a Galerkin method reproduces a linear field (the patch test) and a
 * homogeneous deformation only if, for every node I,
 *     sum_g w_g grad phi_I(x_g) = int_boundary phi_I n dA          (*)
 * Gauss points on meshfree shape functions miss (*) (rational functions,
 * supports not aligned with the cells) and RPIM's cell-centred supports make
 * phi_I jump between cells, so that the cells' boundary integrals do not
 * cancel.  The correction
 *     grad^ phi_I(x) = grad phi_I(x) + (b_I - sum_g w_g grad phi_I(x_g)) / V,
 *     b_I = int_{cell boundary} phi^_I n dA,
 * with phi^ single-valued on a face shared by two cells (their mean for
 * RPIM with cell-centred supports; MLS and point-centred RPIM are
 * single-valued already), makes each cell satisfy its own divergence
 * theorem, so (*) holds exactly; the corrected gradients still reproduce
 * linear fields (b of a linear field is its gradient times V) and stay
 * symmetric between test and trial functions.  Faces use the load patches'
 * rule (quadrature.h: 2 x 2 sub-rectangles of gauss^2 points), so a traction
 * on a whole face and a Nitsche term see the same points as (*).
 */
#ifndef TF_CELL_GRADIENTS_H
#define TF_CELL_GRADIENTS_H

#include <stddef.h>
#include <stdint.h>

#include "meshfree/shape.h"

/* A thread's scratch for one cell at a time. */
typedef struct tf_grad_work {
    tf_shape_work sw, fw; /* Gauss points, face points */
    int *map;             /* node -> local index in the current set, or -1 */
    double *x, *w;        /* Gauss points and weights of the cell */
    double *fx, *fwt, *fn;/* face points, weights, outward normals */
    size_t *fnb;          /* neighbour cell across each face point's face, SIZE_MAX on the box */
    size_t nf;            /* face points */
    double t_shape;       /* seconds in shape functions */
} tf_grad_work;

int tf_grad_work_init(tf_grad_work *w, const tf_shape *sh, size_t n_nodes);
void tf_grad_work_free(tf_grad_work *w);

/* Appends to list (length *len; mark: node -> stamp scratch, stamp unique to
 * this call) the nodes that VCI's face integrals of cell `cell` touch beyond
 * its Gauss points' supports.  Returns 0, or -1 with a message in
 * w->sw.err. */
int tf_vci_cell_nodes(const tf_shape *sh, tf_grad_work *w, size_t cell, uint32_t *mark,
                      uint32_t stamp, uint32_t *list, size_t *len);

/* Gradients g[(3 p + a) m + i] of the m nodes set[] (ascending; they must
 * hold every support met) at the cell's np Gauss points, corrected when
 * vci, with the points' weights in w->w.  Returns 0, or -1 with a message
 * in w->sw.err. */
int tf_cell_gradients(const tf_shape *sh, int vci, tf_grad_work *w, size_t cell,
                      const uint32_t *set, size_t m, double *g);

#endif /* TF_CELL_GRADIENTS_H */
