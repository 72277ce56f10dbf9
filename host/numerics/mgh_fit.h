/*
 * mgh_fit.h — one run of the Moré–Garbow–Hillstrom set (mgh_problems.h)
 * through tf_lm_solve, optionally with the parameters rescaled, scored by
 * the known minimum it reached.
 */
#ifndef TF_MGH_FIT_H
#define TF_MGH_FIT_H

#include <stddef.h>

#include "base/context.h"
#include "numerics/lm.h"
#include "numerics/mgh_problems.h"

typedef struct tf_mgh_score {
    tf_stop stop;
    double rss;                /* sum f_i^2 at the returned point */
    double x[TF_MGH_MAX_N];    /* the returned point, in the problem's units */
    size_t iterations, evals, jac_evals;
    int minimum;               /* index into tf_mgh_minima() of the minimum
                                  reached, -1 for none */
} tf_mgh_score;

/* The set's tolerances (those of the NIST runs): ftol = xtol = 1e-15,
 * gtol = 0, 10000 evaluations, factor 1. */
void tf_mgh_options(tf_lm_options *o, size_t n);

/* Index of the known minimum whose value rss equals (relative 1e-5, the
 * paper prints six digits; a zero minimum needs rss <= TF_MGH_ZERO), or
 * -1. */
#define TF_MGH_ZERO 1e-20
int tf_mgh_which_minimum(const tf_mgh_run *r, double rss);

/* buf = "global", "local F" (F = sum f_i^2 at that other known minimum)
 * or "none", for the index tf_mgh_which_minimum returned. */
void tf_mgh_describe(const tf_mgh_run *r, int minimum, char *buf, size_t len);

/* Solves run r from its start with o and the analytic Jacobian.  With
 * scale (n values, or NULL) the solver sees the parameters q = x / scale:
 * residual f(scale * q), Jacobian J diag(scale), start x0 / scale; the
 * score reports x = scale * q.  Returns 0, or -1 with a message. */
int tf_mgh_fit(tf_ctx *ctx, const tf_mgh_run *r, const tf_lm_options *o, const double *scale,
               tf_mgh_score *s);

#endif /* TF_MGH_FIT_H */
