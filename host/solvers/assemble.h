/*
 * assemble.h — the global stiffness matrix K (seed eqs 19-22) as a sparse
 * symmetric matrix, lower triangle in compressed columns, 3 DOFs per node
 * (DOF 3 i + a is component a of node i).
 *
 * Each background cell gathers the contributions of its Gauss points into a
 * dense matrix over the nodes its supports touch; cells are computed in
 * parallel (OpenMP) in fixed batches and added to K one after another in
 * cell order, so every entry is summed in the same order whatever the
 * thread count: the same scene gives the same bits.
 */
#ifndef TF_ASSEMBLE_H
#define TF_ASSEMBLE_H

#include <stddef.h>

#include "base/context.h"
#include "numerics/csc.h"
#include "materials/elasticity.h"
#include "meshfree/shape.h"
#include "solvers/boundary.h"
#include "solvers/sparsity.h"

typedef struct tf_assembly_info {
    double t_pattern;      /* s, wall: supports of every cell and the sparsity pattern */
    double t_values;       /* s, wall: shape functions and stiffness values */
    double shape_fraction; /* part of t_values the threads spent in shape functions */
    size_t points;         /* Gauss points */
    tf_shape_stats st;
} tf_assembly_info;

/* What K must hold beyond the Gauss points' supports. */
typedef struct tf_assembly_extra {
    int vci;                    /* corrected gradients (cell_gradients.h) */
    const tf_boundary *bnd;     /* weak boundary terms' points, or NULL */
    const struct tf_lame_field *field; /* the material at each Gauss point (material
                                          regions, cell_stiffness.h), or NULL: l */
} tf_assembly_extra;

/* The node set of every cell (the supports of its Gauss points, its
 * boundary points and, with VCI, of its face integrals; ascending) and K's
 * pattern with zero values (sparsity.h), on `threads` OpenMP threads.
 * ex may be NULL.  Returns 0, or -1 with a message in ctx->err. */
int tf_assemble_pattern(tf_ctx *ctx, const tf_shape *sh, const tf_assembly_extra *ex, int threads,
                        tf_nodesets *cells, tf_nodesets *blocks, tf_csc *k);

/* Assembles K for the shape functions sh and the material l; with bbar
 * the volumetric strain is averaged over each background cell (B-bar), on
 * `threads` OpenMP threads (>= 1; the same bits for any count); ex (NULL:
 * none) as above.  Returns 0, or -1 with a message in ctx->err (a singular
 * local system, out of memory). */
int tf_assemble_stiffness(tf_ctx *ctx, const tf_shape *sh, const tf_lame *l, int bbar,
                          const tf_assembly_extra *ex, int threads, tf_csc *k,
                          tf_assembly_info *info);

#endif /* TF_ASSEMBLE_H */
