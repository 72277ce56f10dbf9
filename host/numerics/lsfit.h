/*
 * lsfit.h — the one fitting interface: least squares for models linear in
 * their parameters (a design matrix, solved directly by pivoted QR, many
 * data columns at once) and for nonlinear ones (Levenberg–Marquardt,
 * lm.h), with the same data, weights, options and result.
 *
 * Both minimise  sum_i w_i (y_i - f_i(p))^2.  See docs/lm.md for a usage
 * example and the conventions for rank deficiency and bounds.
 */
#ifndef TF_LSFIT_H
#define TF_LSFIT_H

#include <stddef.h>

#include "base/context.h"
#include "numerics/lm.h"

/* Linear models: fill the m x n design matrix, a[i + j*lda] = d f_i / d p_j
 * (the basis function j at observation i).  Return 0, non-zero to abort. */
typedef int (*tf_lsfit_design_fn)(void *ctx, size_t m, size_t n, double *a, size_t lda);
/* Nonlinear models: f[i] = model value at observation i for parameters p. */
typedef int (*tf_lsfit_value_fn)(void *ctx, const double *p, double *f);
/* Optional: jac[i + j*m] = d f_i / d p_j (column-major, m x n). */
typedef int (*tf_lsfit_jacobian_fn)(void *ctx, const double *p, double *jac);

typedef struct tf_lsfit_model {
    size_t n_par;
    tf_lsfit_design_fn design;     /* set for a linear model ... */
    tf_lsfit_value_fn value;       /* ... or this for a nonlinear one */
    tf_lsfit_jacobian_fn jacobian; /* nonlinear, optional: NULL = finite differences */
    void *ctx;                   /* passed to the callbacks */
} tf_lsfit_model;

typedef struct tf_lsfit_data {
    size_t n_obs;         /* m */
    size_t n_rhs;         /* data columns; a nonlinear model takes 1 */
    const double *y;      /* y[i + k*ldy] */
    size_t ldy;           /* 0 means n_obs */
    const double *weight; /* NULL, or n_obs weights >= 0 (1 / variance) */
} tf_lsfit_data;

typedef struct tf_lsfit_options {
    const double *start;         /* nonlinear: n_par starting values (required) */
    const double *lower, *upper; /* nonlinear: NULL or n_par bounds (+-INFINITY ok) */
    double rank_tol;             /* relative, on the column-scaled R diagonal;
                                    at least 1e-6 with a differenced Jacobian */
    tf_lm_options lm;            /* nonlinear: tolerances and budget */
} tf_lsfit_options;

/* rank_tol 1e-10; tf_lm_default_options() for the rest; no start, no bounds. */
void tf_lsfit_default_options(tf_lsfit_options *o, size_t n_par);

/* What became of each parameter. */
typedef enum tf_par_state {
    TF_PAR_FREE = 0,  /* estimated; se and covariance are meaningful */
    TF_PAR_LOWER,     /* held at its lower bound (active) */
    TF_PAR_UPPER,     /* held at its upper bound (active) */
    TF_PAR_DEPENDENT, /* the data cannot separate it from the others */
} tf_par_state;

typedef struct tf_lsfit_result {
    size_t n_par, n_rhs, n_obs;
    double *par;        /* n_par x n_rhs: column k at par + k * n_par */
    double *rss;        /* n_rhs weighted residual sums of squares */
    double *sigma2;     /* n_rhs residual variances rss / (n_obs - rank);
                           NAN when n_obs == rank */
    double *cov;        /* n_par x n_par unscaled covariance (J^T W J)^-1 of
                           the FREE parameters, others' rows/columns zero;
                           the covariance of column k is sigma2[k] * cov */
    double *se;         /* n_par x n_rhs standard errors sqrt(sigma2 cov_jj);
                           NAN for parameters that are not FREE */
    tf_par_state *state; /* n_par */
    size_t rank;        /* free parameters the data determine */
    tf_stop stop;       /* DIRECT for linear models */
    size_t iterations, evals, jac_evals; /* nonlinear */
} tf_lsfit_result;

/* Fits model to data.  Returns 0 when a result was produced (for nonlinear
 * models check tf_stop_converged(res->stop)), or -1 with a message in ctx->err
 * (bad arguments, non-finite data, a callback that failed, no memory); res
 * then holds nothing to free.  Release a result with tf_lsfit_result_free(). */
int tf_lsfit(tf_ctx *ctx, const tf_lsfit_model *model, const tf_lsfit_data *data,
             const tf_lsfit_options *opt, tf_lsfit_result *res);

void tf_lsfit_result_free(tf_lsfit_result *res);

/* Covariance of parameters i and j for data column k: sigma2[k] * cov. */
double tf_lsfit_cov(const tf_lsfit_result *res, size_t k, size_t i, size_t j);

#endif /* TF_LSFIT_H */
