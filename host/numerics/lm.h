/*
 * lm.h — Levenberg–Marquardt for nonlinear least squares:
 * minimise ||r(p)||^2 over p in R^n, optionally inside a box.
 *
 * Method (docs/lm.md has the full account and its relation to seed 000,
 * eqs 33–37): Moré's trust-region form of Marquardt's method (Moré 1978),
 * with Moré's diagonal scaling D, the damped step solved by QR of the
 * augmented system [J; sqrt(lambda) D] (LAPACK dgeqp3 on J, then dgeqrf on
 * the small augmented triangle) — never the normal equations — and box
 * bounds by an active set with projection.
 *
 * Guards: a trial point with any non-finite residual is rejected and the
 * trust region shrinks; the relative-reduction stop needs a reduction ratio
 * that shows the linear model was right and a Gauss–Newton reduction that
 * shows a stationary point (see tf_stop); below the rounding floor of
 * ||r||^2 the model's step is taken and the region halves.
 */
#ifndef TF_LM_H
#define TF_LM_H

#include <stddef.h>

#include "base/context.h"
#include "numerics/lm_callbacks.h"

/* Why a fit stopped.  tf_stop_converged() says which ones are success. */
typedef enum tf_stop {
    TF_STOP_DIRECT = 0,     /* linear model: solved directly by QR (tf_lsfit) */
    TF_STOP_REDUCTION,      /* actual and predicted relative reduction <= ftol,
                               with a sane ratio (0.25..2) between them, and
                               the Gauss–Newton step's predicted one <= ftol */
    TF_STOP_STEP,           /* trust region <= xtol * ||D p|| */
    TF_STOP_GRADIENT,       /* cosine between r and every free column of J
                               <= gtol, or every parameter held by a bound */
    TF_STOP_ZERO_RESIDUAL,  /* r = 0 exactly */
    TF_STOP_PRECISION,      /* no change double precision can resolve: the
                               tolerances asked more than the arithmetic gives */
    TF_STOP_MAX_EVALS,      /* evaluation budget spent (not converged) */
    TF_STOP_NONFINITE,      /* the trust region collapsed after non-finite
                               trials: the edge of the model's domain, not a
                               minimum (not converged) */
    TF_STOP_UNDERFLOW,      /* the damped step underflowed to zero: the
                               parameters or their steps are at the bottom
                               of the double range (rescale them; not
                               converged) */
    TF_STOP_BAD_START,      /* non-finite residual at the starting point */
    TF_STOP_BAD_JACOBIAN,   /* non-finite Jacobian entry (analytic or differenced) */
    TF_STOP_CALLBACK,       /* a callback returned non-zero */
} tf_stop;

/* Short name, e.g. "reduction", "max-evals". */
const char *tf_stop_name(tf_stop s);
/* 1 for DIRECT, REDUCTION, STEP, GRADIENT, ZERO_RESIDUAL, PRECISION. */
int tf_stop_converged(tf_stop s);

typedef struct tf_lm_problem {
    size_t m, n;                 /* residuals, parameters (1 <= n) */
    tf_lm_residual_fn residual;
    tf_lm_jacobian_fn jacobian;  /* NULL: differences (tf_lm_options.central_diff) */
    void *ctx;
    const double *lower, *upper; /* NULL or n bounds each (+-INFINITY allowed) */
    double data_norm;            /* ||y|| when r = f(p) - y (0: unknown): the
                                    rounding of that difference sets the floor
                                    below which ||r||^2 cannot resolve a step */
} tf_lm_problem;

typedef struct tf_lm_options {
    double ftol;      /* relative reduction of ||r||^2 (actual and predicted) */
    double xtol;      /* relative size of the trust region */
    double gtol;      /* cosine between r and the columns of J */
    size_t max_evals; /* residual evaluations, finite differences included */
    double factor;    /* initial trust region: factor * ||D p0|| (or factor) */
    int central_diff; /* without a Jacobian: central differences (2n evaluations,
                         ~10 digits) instead of forward ones (n, ~8 digits) */
} tf_lm_options;

/* ftol = xtol = 1e-10, gtol = 0, max_evals = 200 (n + 1), factor = 1,
 * forward differences. */
void tf_lm_default_options(tf_lm_options *o, size_t n);

typedef struct tf_lm_result {
    tf_stop stop;
    double rss;            /* ||r||^2 at the returned point */
    size_t iterations;     /* accepted steps */
    size_t evals;          /* residual evaluations (finite differences included) */
    size_t jac_evals;      /* Jacobian evaluations (analytic or differenced) */
    double *jac;           /* caller's m x n buffer or NULL: the Jacobian at the
                              returned point, for the covariance */
    signed char *active;   /* caller's n entries or NULL: -1 at the lower
                              bound, +1 at the upper bound, 0 free */
} tf_lm_result;

/* Runs LM from p (clamped into the box first) and leaves the best point
 * found in p.  Returns 0 when the solver ran (res->stop says how it ended,
 * converged or not), -1 with a message in ctx->err on bad arguments (sizes,
 * lower > upper, NaN bound) or no memory. */
int tf_lm_solve(tf_ctx *ctx, const tf_lm_problem *pb, const tf_lm_options *opt, double *p,
                tf_lm_result *res);

#endif /* TF_LM_H */
