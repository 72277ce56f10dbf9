/*
 * history_run.h — a problem's load history solved step by step, as
 * `tissuefit solve` and the API's history solve (api/api.h) do: a nonlinear
 * solver (nonlinear/nonlinear.h) advances its state from rest through the
 * samples, time-dependent laws relaxing over each step; a linear one solves
 * each step's force (the scene's loads act throughout).
 */
#ifndef TF_HISTORY_RUN_H
#define TF_HISTORY_RUN_H

#include "base/context.h"
#include "problem/history.h"
#include "solvers/solver.h"

/* The samples smp (problem/history.h: tf_history_sample) at contact site
 * `contact` of solver sv, every node's displacements into u (3N per step,
 * smp->n steps).  Progress on stderr about once a second ("solve: step k of
 * n").  Returns 0, or -1 with a message in ctx->err. */
int tf_history_run(tf_ctx *ctx, tf_solver *sv, int contact, const tf_samples *smp, double *u);

#endif /* TF_HISTORY_RUN_H */
