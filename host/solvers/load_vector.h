/*
 * load_vector.h — nodal force vectors (seed eq 25): F_I = integral over the patch
 * of Phi_I t, with Gauss points on the patch (quadrature.h) and the same
 * shape functions as the stiffness; a point force goes to its node (RPIM
 * shape functions interpolate: Phi_I(x_J) = delta_IJ).
 */
#ifndef TF_LOAD_VECTOR_H
#define TF_LOAD_VECTOR_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"
#include "meshfree/shape.h"

/* Adds to f (3N) the nodal forces of a total force spread uniformly over
 * the patch.  With ncol = 3 and force = NULL it writes instead the three
 * unit-force columns (column a: 1 N along axis a) into f (3N x 3, column
 * major, added to).  Returns 0, or -1 with a message. */
int tf_load_patch(tf_ctx *ctx, const tf_shape *sh, const tf_patch *p, const double *force,
                  double *f);

/* Adds to f the problem's analytic traction sigma n over the patch. */
int tf_load_exact(tf_ctx *ctx, const tf_shape *sh, const tf_problem *pr, const tf_patch *p,
                  double *f);

#endif /* TF_LOAD_VECTOR_H */
