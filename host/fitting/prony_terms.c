/*
 * prony_terms.c — see prony_terms.h.
 */
#include "fitting/prony_terms.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "fitting/families/common.h"
#include "numerics/lm.h"

/* What the LM residual needs: the data, the histories, K, and work arrays. */
typedef struct fit {
    const tf_prony_data *d;
    const size_t *idx;
    size_t n;   /* histories */
    size_t m;   /* residuals: 3 n n_ticks */
    int k;
    double *e;  /* m x k, column-major: the terms' e_k at every tick and axis */
    double *y;  /* m: g - target, what sum w_k e_k must reproduce */
    double w[TFIT_PRONY_MAX_TERMS];
    int ok;     /* the last weights were determined */
} fit;

static size_t history_of(const size_t *idx, size_t i)
{
    return idx != NULL ? idx[i] : i;
}

/* e_k of every selected tick and axis for time constant tau into col. */
static void term_column(const fit *f, double tau, double *col)
{
    const tf_prony_data *d = f->d;
    const double r = d->tick / tau, a = exp(-r), gain = -expm1(-r) / r;
    size_t row = 0;
    for (size_t i = 0; i < f->n; ++i) {
        const double *g = d->g + history_of(f->idx, i) * d->n_ticks * 3;
        double e[3] = {0, 0, 0};
        const double *prev = d->g_rest;
        for (size_t t = 0; t < d->n_ticks; ++t, g += 3) {
            for (int c = 0; c < 3; ++c) {
                e[c] = a * e[c] + gain * (g[c] - prev[c]);
                col[row++] = e[c];
            }
            prev = g;
        }
    }
}

/* Weights for the columns in use (mask) by least squares, from the normal
 * equations (K <= 8 columns: their Gram matrix is tiny, and Cholesky of it
 * costs nothing beside forming it); a negative weight drops its column and
 * the rest are solved again.  Returns 0, or -1 when the columns in use are
 * dependent (the Gram matrix not positive definite to working precision). */
static int weights(fit *f, unsigned mask)
{
    double gram[TFIT_PRONY_MAX_TERMS][TFIT_PRONY_MAX_TERMS], rhs[TFIT_PRONY_MAX_TERMS];
    for (int i = 0; i < f->k; ++i) {
        const double *ei = f->e + (size_t)i * f->m;
        rhs[i] = 0;
        for (size_t r = 0; r < f->m; ++r) {
            rhs[i] += ei[r] * f->y[r];
        }
        for (int j = 0; j <= i; ++j) {
            const double *ej = f->e + (size_t)j * f->m;
            double s = 0;
            for (size_t r = 0; r < f->m; ++r) {
                s += ei[r] * ej[r];
            }
            gram[i][j] = gram[j][i] = s;
        }
    }
    for (int round = 0; round <= f->k; ++round) {
        int cols[TFIT_PRONY_MAX_TERMS], nc = 0;
        double a[TFIT_PRONY_MAX_TERMS * TFIT_PRONY_MAX_TERMS], x[TFIT_PRONY_MAX_TERMS];
        for (int j = 0; j < f->k; ++j) {
            f->w[j] = 0;
            if (mask & (1u << j)) {
                cols[nc++] = j;
            }
        }
        if (nc == 0) {
            return 0;
        }
        for (int i = 0; i < nc; ++i) {
            x[i] = rhs[cols[i]];
            for (int j = 0; j < nc; ++j) {
                a[i + j * nc] = gram[cols[i]][cols[j]];
            }
        }
        if (LAPACKE_dposv(LAPACK_COL_MAJOR, 'L', nc, 1, a, nc, x, nc) != 0) {
            return -1;
        }
        unsigned negative = 0;
        for (int c = 0; c < nc; ++c) {
            f->w[cols[c]] = x[c];
            if (x[c] < 0) {
                negative |= 1u << cols[c];
            }
        }
        if (negative == 0) {
            return 0;
        }
        mask &= ~negative;
    }
    return 0;
}

/* The residual at time constants exp(p): y - E w(p). */
static int residual(void *ctx, const double *p, double *r)
{
    fit *f = ctx;
    for (int j = 0; j < f->k; ++j) {
        term_column(f, exp(p[j]), f->e + (size_t)j * f->m);
    }
    f->ok = weights(f, (1u << f->k) - 1) == 0;
    for (size_t i = 0; i < f->m; ++i) {
        double v = f->y[i];
        for (int j = 0; j < f->k; ++j) {
            v -= f->w[j] * f->e[(size_t)j * f->m + i];
        }
        r[i] = f->ok ? v : NAN; /* dependent columns: outside the model's domain */
    }
    return 0;
}

static int setup(fit *f, const tf_prony_data *d, const size_t *idx, size_t n, int k)
{
    memset(f, 0, sizeof *f);
    f->d = d;
    f->idx = idx;
    f->n = idx != NULL ? n : d->n_hist;
    f->m = 3 * f->n * d->n_ticks;
    f->k = k;
    f->e = malloc(f->m * (size_t)(k > 0 ? k : 1) * sizeof *f->e);
    f->y = malloc(f->m * sizeof *f->y);
    if (f->e == NULL || f->y == NULL) {
        free(f->e);
        free(f->y);
        return -1;
    }
    size_t row = 0;
    for (size_t i = 0; i < f->n; ++i) {
        const size_t base = history_of(idx, i) * d->n_ticks * 3;
        for (size_t t = 0; t < 3 * d->n_ticks; ++t) {
            f->y[row++] = d->g[base + t] - d->target[base + t];
        }
    }
    return 0;
}

static double rms_of(const double *r, size_t m)
{
    double s = 0;
    for (size_t i = 0; i < m; ++i) {
        s += r[i] * r[i];
    }
    return sqrt(s / (double)(m > 0 ? m : 1));
}

/* Starting time constants: spread log-evenly over [lo, hi], shifted by
 * `shift` of a spacing (several starts guard against a local minimum). */
static void start(int k, double lo, double hi, double shift, double *p)
{
    const double a = log(lo), b = log(hi);
    for (int j = 0; j < k; ++j) {
        p[j] = a + (b - a) * ((double)j + 0.5 + shift) / (double)k;
        p[j] = fmin(fmax(p[j], a), b);
    }
}

static int by_tau(const void *x, const void *y)
{
    const double *a = x, *b = y;
    return (a[0] > b[0]) - (a[0] < b[0]);
}

int tf_prony_fit_terms(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                       double tau_lo, double tau_hi, tf_prony_terms *out)
{
    return tf_prony_fit_terms_from(ctx, d, idx, n, k, tau_lo, tau_hi, 3, out);
}

int tf_prony_fit_terms_from(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                            double tau_lo, double tau_hi, int starts, tf_prony_terms *out)
{
    fit f;
    memset(out, 0, sizeof *out);
    if (k < 0 || k > TFIT_PRONY_MAX_TERMS || !(tau_lo > 0 && tau_lo < tau_hi)) {
        return tf_fail(ctx, "prony terms: K = %d, time constants in [%g, %g] s", k, tau_lo, tau_hi);
    }
    if (setup(&f, d, idx, n, k) != 0) {
        return tf_fail(ctx, "prony terms: out of memory for %zu histories", n);
    }
    out->n = k;
    double *r = malloc(f.m * sizeof *r);
    if (r == NULL) {
        tf_fail(ctx, "prony terms: out of memory");
        free(f.e);
        free(f.y);
        return -1;
    }
    if (k == 0) {
        out->rms = rms_of(f.y, f.m);
        free(r);
        free(f.e);
        free(f.y);
        return 0;
    }
    double lower[TFIT_PRONY_MAX_TERMS], upper[TFIT_PRONY_MAX_TERMS], best_rss = INFINITY;
    double best[TFIT_PRONY_MAX_TERMS][2];
    for (int j = 0; j < k; ++j) {
        lower[j] = log(tau_lo);
        upper[j] = log(tau_hi);
    }
    const tf_lm_problem pb = {.m = f.m, .n = (size_t)k, .residual = residual, .ctx = &f,
                              .lower = lower, .upper = upper};
    tf_lm_options opt;
    tf_lm_default_options(&opt, (size_t)k);
    opt.ftol = opt.xtol = 1e-9;
    const double shifts[3] = {0.0, -0.3, 0.3};
    for (int s = 0; s < starts && s < 3; ++s) {
        double p[TFIT_PRONY_MAX_TERMS];
        tf_lm_result res;
        memset(&res, 0, sizeof res);
        start(k, tau_lo, tau_hi, shifts[s], p);
        if (tf_lm_solve(ctx, &pb, &opt, p, &res) != 0) {
            free(r);
            free(f.e);
            free(f.y);
            return -1;
        }
        residual(&f, p, r); /* the weights at the returned point */
        if (f.ok && res.rss < best_rss) {
            best_rss = res.rss;
            for (int j = 0; j < k; ++j) {
                best[j][0] = exp(p[j]);
                best[j][1] = f.w[j];
            }
        }
    }
    free(r);
    free(f.e);
    free(f.y);
    if (!isfinite(best_rss)) {
        return tf_fail(ctx,
                       "%s: %d prony terms: the histories do not separate their time "
                       "constants",
                       TF_FAMILY_UNDETERMINED, k);
    }
    qsort(best, (size_t)k, sizeof best[0], by_tau);
    double sum = 0;
    for (int j = 0; j < k; ++j) {
        out->tau[j] = best[j][0];
        out->w[j] = best[j][1];
        sum += out->w[j];
    }
    if (sum > 1 + 1e-6) {
        return tf_fail(ctx,
                       "%s: %d prony terms: weights summing to %.6g > 1 (the histories "
                       "creep more than the relaxed static response allows)",
                       TF_FAMILY_UNDETERMINED, k, sum);
    }
    out->rms = sqrt(best_rss / (double)f.m);
    return 0;
}

double tf_prony_terms_rms(const tf_prony_data *d, const size_t *idx, size_t n,
                          const tf_prony_terms *t)
{
    fit f;
    if (setup(&f, d, idx, n, t->n) != 0) {
        return NAN;
    }
    for (int j = 0; j < t->n; ++j) {
        term_column(&f, t->tau[j], f.e + (size_t)j * f.m);
    }
    double s = 0;
    for (size_t i = 0; i < f.m; ++i) {
        double v = f.y[i];
        for (int j = 0; j < t->n; ++j) {
            v -= t->w[j] * f.e[(size_t)j * f.m + i];
        }
        s += v * v;
    }
    free(f.e);
    free(f.y);
    return sqrt(s / (double)f.m);
}
