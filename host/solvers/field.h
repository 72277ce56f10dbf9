/*
 * field.h — the displacement field of nodal values (RPIM) or parameters
 * (EFG) between the nodes: u_h(x) = sum_I phi_I(x) d_I and its gradient,
 * point by point, for the solvers' tf_solver_ops.field.
 */
#ifndef TF_FIELD_H
#define TF_FIELD_H

#include <stddef.h>

#include "base/context.h"
#include "meshfree/shape.h"
#include "solvers/nodal_values.h"

/* uh (3 np) and grad (9 np, row-major du_i/dx_j) at the np points x.
 * Thread-safe.  Returns 0, or -1 with a message in ctx->err. */
int tf_shape_field(tf_ctx *ctx, const tf_shape *sh, const double *d, const double *x, size_t np,
                   double *uh, double *grad);

/* The same for u the nodal displacements: d = u (map NULL: interpolating
 * RPIM functions) or their parameters through map (EFG). */
int tf_nodal_field(tf_ctx *ctx, const tf_shape *sh, tf_nodal_map *map, const double *u,
                   const double *x, size_t np, double *uh, double *grad);

#endif /* TF_FIELD_H */
