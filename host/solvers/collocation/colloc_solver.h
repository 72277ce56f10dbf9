/*
 * colloc_solver.h — the MLS collocation solver (colloc.h) behind the solver
 * interface (solvers/solver.h), registered as "mls-collocation".
 *
 * A problem's node cloud becomes the particles (a box grid's tributary
 * volumes as their volumes), its fixed regions the prescribed components,
 * its loads and contact forces nodal forces through tributary face areas
 * (colloc_loads.c).  A static case is a dynamic relaxation (from u0 when
 * given, else from rest at u = 0); a load history is explicit dynamics with
 * the physical masses (scene solver.collocation.density) and damping
 * (solver.collocation.damping), each history step cut into substeps of at
 * most 0.9 of the stable step.  Capabilities: TIME_DEPENDENT (the history
 * has inertia); not AFFINE, even for the linear law: a relaxation ends
 * within a tolerance, so unit solves would superpose only to that.
 */
#ifndef TF_COLLOC_SOLVER_H
#define TF_COLLOC_SOLVER_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"
#include "solvers/solver.h"

extern const tf_solver_ops tf_colloc_ops;

/* The scene defaults of solver.collocation. */
tf_colloc_settings tf_colloc_settings_default(void);

/* Adds to f (3N) the nodal forces of a total force spread uniformly over
 * the patch; with force NULL writes the three unit columns instead (3N x 3,
 * column major, added to).  Returns 0, or -1 with a message. */
int tf_colloc_patch_forces(tf_ctx *ctx, const tf_problem *pr, const tf_patch *p,
                           const double *force, double *f);

/* Adds to f the problem's analytic traction over the patch. */
int tf_colloc_exact_forces(tf_ctx *ctx, const tf_problem *pr, const tf_patch *p, double *f);

#endif /* TF_COLLOC_SOLVER_H */
