/*
 * verify.h — a problem with an analytic solution, solved and measured
 * (`tissuefit verify`): one row of a convergence table, the L2 and energy
 * errors (error_norm.h) with the size and time of the solve.  The levels of
 * a study (finer grids, more Gauss points) are built from a scene by
 * scene/scene_levels.h.
 */
#ifndef TF_VERIFY_H
#define TF_VERIFY_H

#include <stddef.h>

#include "base/context.h"
#include "problem/problem.h"

typedef struct tf_verify_row {
    unsigned level;     /* as the caller labels it (grid: k; gauss: the Gauss order) */
    size_t nodes, dofs;
    double h;           /* nodal spacing along the first refined axis, mm */
    double error_l2, error_energy;
    double rate;        /* of error_l2 against h from the previous row; NAN for the first */
    double seconds;     /* solver build and solve */
} tf_verify_row;

/* Order of the Gauss rule the errors are integrated with. */
#define TF_VERIFY_ERROR_ORDER 5

/* Solves p with its own solver options under its loads (no contact force)
 * and fills row (rate NAN).  Returns 0; -2 when p has no analytic solution
 * (a problem that cannot be verified); -1 when the solve failed; with the
 * message in ctx. */
int tf_verify_problem(const tf_problem *p, unsigned level, tf_ctx *ctx, tf_verify_row *row);

/* Fills the rate column of rows[1..n) from consecutive rows. */
void tf_verify_rates(tf_verify_row *rows, size_t n);

#endif /* TF_VERIFY_H */
