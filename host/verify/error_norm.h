/*
 * error_norm.h — how far a solution is from the scene's reference
 * solution, integrated over the background cells:
 *
 *   L2:     sqrt( int |u_h - u|^2 / int |u|^2 )
 *   energy: sqrt( int (e_h - e)^T D (e_h - e) / int e^T D e )
 *
 * with u_h = sum_I phi_I u_I and e its strain, at `order`^3 Gauss points
 * per cell (independent of the solver's own quadrature, so that a Gauss
 * order study measures the solution, not the error integral).
 */
#ifndef TF_ERROR_NORM_H
#define TF_ERROR_NORM_H

#include <stddef.h>

#include "scene/scene.h"
#include "meshfree/shape.h"

/* Relative errors of u (3N) against s->reference.  Returns 0, or -1 with a
 * message (no reference, singular support, out of memory). */
int tf_error_norms(const tf_shape *sh, const tf_scene *s, const double *u, unsigned order,
                   double *l2, double *energy, char *err, size_t errlen);

#endif /* TF_ERROR_NORM_H */
