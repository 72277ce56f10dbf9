/*
 * lsfit.c — the fitting interface (see fit.h): linear models through lsq.c,
 * nonlinear ones through lm.c, one result shape for both.
 */
#include "numerics/lsfit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/lsq.h"

/* A forward-difference Jacobian is good to about sqrt(eps) ~ 1.5e-8
 * relative (lm_fdjac.c), so two columns that are equal in exact arithmetic
 * differ at that level: the rank decision must not look finer than this.
 * 1e-6 leaves a factor of ~50 above the differencing noise and still
 * resolves scaled condition numbers up to 1e6 (the NIST problems reach
 * 6e4, Bennett5). */
#define FD_RANK_TOL 1e-6

void tf_lsfit_default_options(tf_lsfit_options *o, size_t n_par)
{
    memset(o, 0, sizeof *o);
    o->rank_tol = 1e-10;
    tf_lm_default_options(&o->lm, n_par);
}

void tf_lsfit_result_free(tf_lsfit_result *res)
{
    free(res->par);
    free(res->rss);
    free(res->sigma2);
    free(res->cov);
    free(res->se);
    free(res->state);
    memset(res, 0, sizeof *res);
}

double tf_lsfit_cov(const tf_lsfit_result *res, size_t k, size_t i, size_t j)
{
    return res->sigma2[k] * res->cov[i + j * res->n_par];
}

static int result_alloc(tf_lsfit_result *res, size_t n, size_t k, size_t m)
{
    memset(res, 0, sizeof *res);
    res->n_par = n;
    res->n_rhs = k;
    res->n_obs = m;
    res->par = calloc(n * k, sizeof *res->par);
    res->rss = calloc(k, sizeof *res->rss);
    res->sigma2 = calloc(k, sizeof *res->sigma2);
    res->cov = calloc(n * n, sizeof *res->cov);
    res->se = calloc(n * k, sizeof *res->se);
    res->state = calloc(n, sizeof *res->state);
    if (res->par == NULL || res->rss == NULL || res->sigma2 == NULL || res->cov == NULL ||
        res->se == NULL || res->state == NULL) {
        tf_lsfit_result_free(res);
        return -1;
    }
    return 0;
}

/* sigma2 and standard errors from rss, cov and state. */
static void finish_statistics(tf_lsfit_result *res)
{
    const size_t n = res->n_par;
    for (size_t k = 0; k < res->n_rhs; ++k) {
        res->sigma2[k] = res->n_obs > res->rank ? res->rss[k] / (double)(res->n_obs - res->rank)
                                                : NAN;
        for (size_t j = 0; j < n; ++j) {
            res->se[j + k * n] = res->state[j] == TF_PAR_FREE
                                     ? sqrt(res->sigma2[k] * res->cov[j + j * n])
                                     : NAN;
        }
    }
}

/* ------------------------------------------------------------------------ */
/* Linear: one factorisation, all data columns solved together. */

static int fit_linear(tf_ctx *ctx, const tf_lsfit_model *model, const tf_lsfit_data *data,
                      const tf_lsfit_options *o, tf_lsfit_result *res)
{
    const size_t m = data->n_obs, n = model->n_par, k = data->n_rhs;
    double *a = malloc(m * n * sizeof *a);
    if (a == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    if (model->design(model->ctx, m, n, a, m) != 0) {
        tf_fail(ctx, "the design-matrix callback failed");
        free(a);
        return -1;
    }
    tf_lsq *f = tf_lsq_factor(ctx, m, n, a, m, data->weight, o->rank_tol);
    free(a);
    if (f == NULL) {
        return -1;
    }
    if (result_alloc(res, n, k, m) != 0) {
        tf_fail(ctx, "out of memory");
        tf_lsq_free(f);
        return -1;
    }
    size_t ldy = data->ldy != 0 ? data->ldy : m;
    if (tf_lsq_solve(ctx, f, k, data->y, ldy, res->par, n, res->rss) != 0 ||
        tf_lsq_cov(f, res->cov) != 0) {
        if (ctx->err[0] == '\0') {
            tf_fail(ctx, "out of memory");
        }
        tf_lsq_free(f);
        tf_lsfit_result_free(res);
        return -1;
    }
    res->rank = tf_lsq_rank(f);
    for (size_t j = 0; j < n; ++j) {
        res->state[j] = tf_lsq_dependent(f, j) ? TF_PAR_DEPENDENT : TF_PAR_FREE;
    }
    tf_lsq_free(f);
    res->stop = TF_STOP_DIRECT;
    finish_statistics(res);
    return 0;
}

/* ------------------------------------------------------------------------ */
/* Nonlinear: weighted residuals r_i = sqrt(w_i) (f_i(p) - y_i) for lm.c. */

typedef struct nl_ctx {
    const tf_lsfit_model *model;
    const double *y;
    double *sqrt_w; /* NULL when unweighted */
    size_t m, n;
    int failed;     /* a model callback returned non-zero */
} nl_ctx;

static int nl_residual(void *ctx, const double *p, double *r)
{
    nl_ctx *c = ctx;
    if (c->model->value(c->model->ctx, p, r) != 0) {
        c->failed = 1;
        return 1;
    }
    for (size_t i = 0; i < c->m; ++i) {
        r[i] -= c->y[i];
        if (c->sqrt_w != NULL) {
            r[i] *= c->sqrt_w[i];
        }
    }
    return 0;
}

static int nl_jacobian(void *ctx, const double *p, double *jac)
{
    nl_ctx *c = ctx;
    if (c->model->jacobian(c->model->ctx, p, jac) != 0) {
        c->failed = 1;
        return 1;
    }
    for (size_t j = 0; c->sqrt_w != NULL && j < c->n; ++j) {
        for (size_t i = 0; i < c->m; ++i) {
            jac[i + j * c->m] *= c->sqrt_w[i];
        }
    }
    return 0;
}

/* Covariance of the free parameters from the Jacobian columns in idx. */
static int free_covariance(tf_ctx *ctx, const double *jac, const size_t *idx, size_t nf,
                           tf_lsfit_result *res, double rank_tol)
{
    const size_t m = res->n_obs, n = res->n_par;
    double *a = malloc(m * nf * sizeof *a), *c = malloc(nf * nf * sizeof *c);
    tf_lsq *f = NULL;
    if (a != NULL && c != NULL) {
        for (size_t q = 0; q < nf; ++q) {
            memcpy(a + q * m, jac + idx[q] * m, m * sizeof *a);
        }
        f = tf_lsq_factor(ctx, m, nf, a, m, NULL, rank_tol);
    } else {
        tf_fail(ctx, "out of memory");
    }
    int rc = f != NULL && tf_lsq_cov(f, c) == 0 ? 0 : -1;
    if (rc == 0) {
        res->rank = tf_lsq_rank(f);
        for (size_t q = 0; q < nf; ++q) {
            if (tf_lsq_dependent(f, q)) {
                res->state[idx[q]] = TF_PAR_DEPENDENT;
            }
            for (size_t t = 0; t < nf; ++t) {
                res->cov[idx[t] + idx[q] * n] = c[t + q * nf];
            }
        }
    } else if (f != NULL) {
        tf_fail(ctx, "out of memory");
    }
    tf_lsq_free(f);
    free(a);
    free(c);
    return rc;
}

/* Statistics from the weighted Jacobian at the solution, over the
 * parameters not held by a bound (a held parameter was not estimated, so
 * its column says nothing about its uncertainty).  Without a finite
 * Jacobian there (a fit that could not start) they are all NAN. */
static int nonlinear_statistics(tf_ctx *ctx, const double *jac, const signed char *active,
                                tf_lsfit_result *res, double rank_tol)
{
    const size_t m = res->n_obs, n = res->n_par;
    int finite = 1;
    for (size_t i = 0; i < m * n; ++i) {
        finite &= isfinite(jac[i]) != 0;
    }
    size_t nf = 0, *idx = malloc(n * sizeof *idx);
    if (idx == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t j = 0; j < n; ++j) {
        res->state[j] = active[j] < 0 ? TF_PAR_LOWER : active[j] > 0 ? TF_PAR_UPPER : TF_PAR_FREE;
        if (active[j] == 0) {
            idx[nf++] = j;
        }
    }
    res->rank = 0;
    int rc = 0;
    if (!finite) {
        for (size_t i = 0; i < n * n; ++i) {
            res->cov[i] = NAN;
        }
    } else if (nf > 0) {
        rc = free_covariance(ctx, jac, idx, nf, res, rank_tol);
    }
    free(idx);
    if (rc == 0) {
        finish_statistics(res);
    }
    return rc;
}

/* ||W^1/2 y||, the size of the data the residuals are differences from. */
static double weighted_norm(const double *y, const double *sqrt_w, size_t m)
{
    double s = 0, scale = 0;
    for (size_t i = 0; i < m; ++i) {
        scale = fmax(scale, fabs(sqrt_w != NULL ? sqrt_w[i] * y[i] : y[i]));
    }
    for (size_t i = 0; scale > 0 && i < m; ++i) {
        double v = (sqrt_w != NULL ? sqrt_w[i] * y[i] : y[i]) / scale;
        s += v * v;
    }
    return scale * sqrt(s);
}

static int fit_nonlinear(tf_ctx *ctx, const tf_lsfit_model *model, const tf_lsfit_data *data,
                         const tf_lsfit_options *o, tf_lsfit_result *res)
{
    const size_t m = data->n_obs, n = model->n_par;
    if (data->n_rhs != 1 || o->start == NULL) {
        return tf_fail(ctx, "a nonlinear fit needs one data column and starting values");
    }
    for (size_t i = 0; i < m; ++i) {
        double w = data->weight != NULL ? data->weight[i] : 1.0;
        if (!isfinite(data->y[i]) || !isfinite(w) || !(w >= 0)) {
            return tf_fail(ctx, "observation %zu: value %g, weight %g (need finite, weight >= 0)",
                           i, data->y[i], w);
        }
    }
    nl_ctx c = {model, data->y, NULL, m, n, 0};
    double *jac = malloc(m * n * sizeof *jac);
    signed char *active = malloc(n);
    c.sqrt_w = data->weight != NULL ? malloc(m * sizeof *c.sqrt_w) : NULL;
    if (jac == NULL || active == NULL || (data->weight != NULL && c.sqrt_w == NULL) ||
        result_alloc(res, n, 1, m) != 0) {
        tf_fail(ctx, "out of memory");
        free(jac);
        free(active);
        free(c.sqrt_w);
        return -1;
    }
    for (size_t i = 0; c.sqrt_w != NULL && i < m; ++i) {
        c.sqrt_w[i] = sqrt(data->weight[i]);
    }
    tf_lm_problem pb = {m, n, nl_residual, model->jacobian != NULL ? nl_jacobian : NULL, &c,
                        o->lower, o->upper, weighted_norm(data->y, c.sqrt_w, m)};
    tf_lm_result lr = {.jac = jac, .active = active};
    memcpy(res->par, o->start, n * sizeof *res->par);
    int rc = tf_lm_solve(ctx, &pb, &o->lm, res->par, &lr);
    if (rc == 0 && c.failed) {
        tf_fail(ctx, "the model callback failed");
        rc = -1;
    }
    if (rc == 0) {
        res->stop = lr.stop;
        res->rss[0] = lr.rss;
        res->iterations = lr.iterations;
        res->evals = lr.evals;
        res->jac_evals = lr.jac_evals;
        double tol = model->jacobian != NULL ? o->rank_tol : fmax(o->rank_tol, FD_RANK_TOL);
        rc = nonlinear_statistics(ctx, jac, active, res, tol);
    }
    free(jac);
    free(active);
    free(c.sqrt_w);
    if (rc != 0) {
        tf_lsfit_result_free(res);
    }
    return rc;
}

int tf_lsfit(tf_ctx *ctx, const tf_lsfit_model *model, const tf_lsfit_data *data,
             const tf_lsfit_options *opt, tf_lsfit_result *res)
{
    memset(res, 0, sizeof *res);
    ctx->err[0] = '\0'; /* fit_linear tells its own failures from tf_lsq_cov's by it */
    int linear = model->design != NULL, nonlinear = model->value != NULL;
    if (linear == nonlinear || model->n_par == 0 || data->n_obs == 0 || data->n_rhs == 0 ||
        data->y == NULL || (data->ldy != 0 && data->ldy < data->n_obs)) {
        return tf_fail(ctx, "bad fit description (give exactly one of design or value, "
                            "parameters, observations and data)");
    }
    return linear ? fit_linear(ctx, model, data, opt, res)
                  : fit_nonlinear(ctx, model, data, opt, res);
}
