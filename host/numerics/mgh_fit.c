/*
 * mgh_fit.c — one Moré–Garbow–Hillstrom run through tf_lm_solve (see
 * mgh_fit.h).
 */
#include "numerics/mgh_fit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void tf_mgh_options(tf_lm_options *o, size_t n)
{
    tf_lm_default_options(o, n);
    o->ftol = 1e-15;
    o->xtol = 1e-15;
    o->gtol = 0;
    o->max_evals = 10000;
}

int tf_mgh_which_minimum(const tf_mgh_run *r, double rss)
{
    double f[TF_MGH_MAX_MINIMA];
    size_t k = tf_mgh_minima(r, f);
    for (size_t i = 0; i < k; ++i) {
        if (f[i] == 0 ? rss <= TF_MGH_ZERO : fabs(rss - f[i]) <= 1e-5 * f[i]) {
            return (int)i;
        }
    }
    return -1;
}

void tf_mgh_describe(const tf_mgh_run *r, int minimum, char *buf, size_t len)
{
    double f[TF_MGH_MAX_MINIMA];
    size_t k = tf_mgh_minima(r, f);
    if (minimum == 0) {
        snprintf(buf, len, "global");
    } else if (minimum > 0 && (size_t)minimum < k) {
        snprintf(buf, len, "local %g", f[minimum]);
    } else {
        snprintf(buf, len, "none");
    }
}

typedef struct scaled {
    const tf_mgh_run *run;
    const double *scale; /* NULL: none */
    double x[TF_MGH_MAX_N];
} scaled;

static const double *unscale(scaled *c, const double *q)
{
    if (c->scale == NULL) {
        return q;
    }
    for (size_t j = 0; j < c->run->n; ++j) {
        c->x[j] = c->scale[j] * q[j];
    }
    return c->x;
}

static int residual(void *ctx, const double *q, double *f)
{
    scaled *c = ctx;
    tf_mgh_residual(c->run, unscale(c, q), f);
    return 0;
}

static int jacobian(void *ctx, const double *q, double *jac)
{
    scaled *c = ctx;
    const size_t m = c->run->m;
    tf_mgh_jacobian(c->run, unscale(c, q), jac);
    for (size_t j = 0; c->scale != NULL && j < c->run->n; ++j) {
        for (size_t i = 0; i < m; ++i) {
            jac[i + j * m] *= c->scale[j];
        }
    }
    return 0;
}

int tf_mgh_fit(tf_ctx *ctx, const tf_mgh_run *r, const tf_lm_options *o, const double *scale,
               tf_mgh_score *s)
{
    if (r->n < 1 || r->n > TF_MGH_MAX_N || r->m < r->n || r->m > TF_MGH_MAX_M) {
        return tf_fail(ctx, "MGH problem %d: bad size n = %zu, m = %zu", r->problem, r->n, r->m);
    }
    scaled c = {.run = r, .scale = scale};
    double q[TF_MGH_MAX_N];
    tf_mgh_start(r, q);
    for (size_t j = 0; scale != NULL && j < r->n; ++j) {
        q[j] /= scale[j];
    }
    tf_lm_problem pb = {r->m, r->n, residual, jacobian, &c, NULL, NULL, 0};
    tf_lm_result res = {0};
    if (tf_lm_solve(ctx, &pb, o, q, &res) != 0) {
        return -1;
    }
    memset(s, 0, sizeof *s);
    memcpy(s->x, unscale(&c, q), r->n * sizeof *s->x);
    s->stop = res.stop;
    s->rss = res.rss;
    s->iterations = res.iterations;
    s->evals = res.evals;
    s->jac_evals = res.jac_evals;
    s->minimum = tf_mgh_which_minimum(r, res.rss);
    return 0;
}
