/*
 * probe.h — displacements where a problem asks for them, from a solution's
 * nodal values: at its output points (a node's own value, or the solver's
 * displacement field at a point between nodes, tf_solver_field) and at a
 * contact site (the node it was given as, or the field at its point).
 * Values at points do not depend on which nodes the grid happens to have,
 * so a scene can name the points it needs and be solved on any cloud.
 */
#ifndef TF_PROBE_H
#define TF_PROBE_H

#include <stddef.h>

#include "base/context.h"
#include "solvers/solver.h"

/* Problem p's outputs (p: the solver's problem, or a copy of it with other
 * outputs) from nodal values u (3N):
 * out[3 j + a], j over outputs.  Returns 0, or -1 with a message in ctx->err. */
int tf_solver_probe_outputs(tf_ctx *ctx, const tf_solver *s, const tf_problem *p, const double *u,
                            double *out);

/* The displacement of p's contact site k.  Returns 0, or -1 with a message. */
int tf_solver_probe_contact(tf_ctx *ctx, const tf_solver *s, const tf_problem *p, int k,
                            const double *u, double out[3]);

#endif /* TF_PROBE_H */
