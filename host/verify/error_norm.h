/*
 * error_norm.h — how far a solution is from its problem's analytic
 * solution, integrated over background cells:
 *
 *   L2:     sqrt( int |u_h - u|^2 / int |u|^2 )
 *   energy: sqrt( int (e_h - e)^T D (e_h - e) / int e^T D e )
 *
 * with u_h the solver's displacement field of the nodal values (its
 * tf_solver_field) and e its strain, at `order`^3 Gauss points per cell of
 * the solver's background grid (independent of the solver's own quadrature,
 * so that a Gauss order study measures the solution, not the error
 * integral).
 */
#ifndef TF_ERROR_NORM_H
#define TF_ERROR_NORM_H

#include "solvers/solver.h"

/* Relative errors of u (3N) against the analytic solution of the solver's
 * problem.  Returns 0, or -1 with a message in the solver's context (no
 * analytic solution, no field, singular support, out of memory). */
int tf_error_norms(const tf_solver *s, const double *u, unsigned order, double *l2,
                   double *energy);

#endif /* TF_ERROR_NORM_H */
