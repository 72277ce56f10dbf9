/*
 * resonant_modes.c — see resonant_modes.h.
 */
#include "fitting/resonant_modes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lapacke.h>

#include "fitting/families/common.h"
#include "model/forms/resonant.h"
#include "numerics/lm.h"

#define MAXK TFIT_RESONANT_MAX_MODES

/* What the LM residual needs: the data, the histories, K, work arrays. */
typedef struct fit {
    const tf_prony_data *d;
    const size_t *idx;
    size_t n;    /* histories */
    size_t rows; /* per axis: n n_ticks */
    int k;
    double *x;   /* 3 axes x rows x k, column-major per axis: the modes' s */
    double *y;   /* 3 x rows: target - g, what sum w_k s_k must reproduce */
    double *a, *b; /* dgels work: rows x k, rows */
    double w[MAXK][3];
} fit;

static size_t history_of(const size_t *idx, size_t i)
{
    return idx != NULL ? idx[i] : i;
}

/* s of mode (omega, zeta) at every selected tick, for every axis, into
 * x[axis][rows] with stride between axes `axis_stride`. */
static void mode_columns(const fit *f, double omega, double zeta, double *col, size_t axis_stride)
{
    const tf_prony_data *d = f->d;
    double F[4];
    tf_resonant_transition(omega * d->tick, zeta, F);
    size_t row = 0;
    for (size_t i = 0; i < f->n; ++i) {
        const double *g = d->g + history_of(f->idx, i) * d->n_ticks * 3;
        double s[3] = {0, 0, 0}, v[3] = {0, 0, 0};
        const double *prev = d->g_rest;
        for (size_t t = 0; t < d->n_ticks; ++t, g += 3, ++row) {
            for (int c = 0; c < 3; ++c) {
                const double e1 = s[c] - (g[c] - prev[c]);
                s[c] = F[0] * e1 + F[1] * v[c];
                v[c] = F[2] * e1 + F[3] * v[c];
                col[(size_t)c * axis_stride + row] = s[c];
            }
            prev = g;
        }
    }
}

/* Largest |v_i| of n values, or NAN when one is NaN. */
static double max_abs(const double *v, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        if (isnan(v[i])) {
            return NAN;
        }
        m = fabs(v[i]) > m ? fabs(v[i]) : m;
    }
    return m;
}

/* min |A w - b| for one axis (A in f->a, rows x k; b in f->b, w over its
 * first k), as LAPACK's dgels solves it: dgels first takes the largest
 * |a_ij| and |b_i| (dlange, a Fortran call per element, then LAPACKE's NaN
 * scan of both), and scales A or b only when one lies outside
 * [smlnum, 1/smlnum] (smlnum = safe minimum / precision, about 1e-292);
 * otherwise it runs dgeqrf, dormqr and dtrtrs, which this calls directly
 * (k <= 8 columns: their unblocked paths, whatever the workspace).  On a
 * resonant fit's tall, thin columns the scans took 40 % of the time; here
 * one loop finds the same magnitudes, and dgels itself runs in the cases
 * where it would scale or A is zero.  Returns nonzero where dgels (through
 * LAPACKE) would: a NaN, or a singular R. */
static int axis_least_squares(fit *f, lapack_int rows)
{
    const lapack_int k = f->k;
    const double small = LAPACKE_dlamch('S') / LAPACKE_dlamch('P'), big = 1 / small;
    const double anrm = max_abs(f->a, (size_t)rows * (size_t)k), bnrm = max_abs(f->b, (size_t)rows);
    if (isnan(anrm) || isnan(bnrm)) {
        return -1;
    }
    if (anrm == 0 || anrm < small || anrm > big || (bnrm > 0 && bnrm < small) || bnrm > big) {
        return LAPACKE_dgels(LAPACK_COL_MAJOR, 'N', rows, k, 1, f->a, rows, f->b, rows);
    }
    double tau[MAXK], work[MAXK];
    if (LAPACKE_dgeqrf_work(LAPACK_COL_MAJOR, rows, k, f->a, rows, tau, work, MAXK) != 0 ||
        LAPACKE_dormqr_work(LAPACK_COL_MAJOR, 'L', 'T', rows, 1, k, f->a, rows, tau, f->b, rows,
                            work, MAXK) != 0) {
        return -1;
    }
    return LAPACKE_dtrtrs_work(LAPACK_COL_MAJOR, 'U', 'N', 'N', k, 1, f->a, rows, f->b, rows);
}

/* The columns of every mode at p = (ln omega_k, ln zeta_k), then each axis's
 * weights by least squares; r = y - X w (3 rows per tick, axis-major).
 * Returns -1 when LAPACK fails (rank-deficient columns). */
static int project_out(fit *f, const double *p, double *r)
{
    const size_t rows = f->rows;
    for (int k = 0; k < f->k; ++k) {
        mode_columns(f, exp(p[2 * k]), exp(p[2 * k + 1]), f->x + (size_t)k * rows,
                     rows * (size_t)f->k);
    }
    for (int c = 0; c < 3; ++c) {
        const double *xc = f->x + (size_t)c * rows * (size_t)f->k, *yc = f->y + (size_t)c * rows;
        double *rc = r + (size_t)c * rows;
        if (f->k == 0) {
            memcpy(rc, yc, rows * sizeof *rc);
            continue;
        }
        memcpy(f->a, xc, rows * (size_t)f->k * sizeof *f->a);
        memcpy(f->b, yc, rows * sizeof *f->b);
        if (axis_least_squares(f, (lapack_int)rows) != 0) {
            return -1;
        }
        for (int k = 0; k < f->k; ++k) {
            f->w[k][c] = f->b[k];
            if (!(fabs(f->b[k]) <= TF_RESONANT_MAX_WEIGHT)) {
                return -1; /* cancelling modes, not a body's: outside the domain */
            }
        }
        for (size_t t = 0; t < rows; ++t) {
            double s = yc[t];
            for (int k = 0; k < f->k; ++k) {
                s -= xc[(size_t)k * rows + t] * f->w[k][c];
            }
            rc[t] = s;
        }
    }
    return 0;
}

static int residual(void *ctx, const double *p, double *r)
{
    fit *f = ctx;
    if (project_out(f, p, r) != 0) {
        for (size_t i = 0; i < 3 * f->rows; ++i) {
            r[i] = NAN; /* dependent modes: outside the model's domain */
        }
    }
    return 0;
}

static double rss_of(const double *r, size_t m)
{
    double s = 0;
    for (size_t i = 0; i < m; ++i) {
        s += r[i] * r[i];
    }
    return s;
}

/* LM from p (2k parameters) inside the log bounds; returns the RSS (inf on
 * failure) and leaves the point in p. */
static double run_lm(tf_ctx *ctx, fit *f, const tf_resonant_bounds *b, double *p, double *r)
{
    double lo[2 * MAXK], hi[2 * MAXK];
    for (int k = 0; k < f->k; ++k) {
        lo[2 * k] = log(b->omega_lo);
        hi[2 * k] = log(b->omega_hi);
        lo[2 * k + 1] = log(b->zeta_lo);
        hi[2 * k + 1] = log(b->zeta_hi);
    }
    const size_t m = 3 * f->rows;
    if (f->k == 0) {
        residual(f, p, r);
        return rss_of(r, m);
    }
    tf_lm_problem pb = {.m = m, .n = 2 * (size_t)f->k, .residual = residual, .ctx = f,
                        .lower = lo, .upper = hi};
    tf_lm_options o;
    tf_lm_default_options(&o, pb.n);
    o.ftol = o.xtol = 1e-9;
    o.max_evals = 60 * (pb.n + 1);
    tf_lm_result res = {0};
    if (tf_lm_solve(ctx, &pb, &o, p, &res) != 0) {
        return INFINITY;
    }
    residual(f, p, r);
    const double s = rss_of(r, m);
    return isfinite(s) ? s : INFINITY;
}

static void sort_modes(tf_resonant_modes *t)
{
    for (int i = 1; i < t->n; ++i) {
        for (int j = i; j > 0 && t->omega[j] < t->omega[j - 1]; --j) {
            double tmp = t->omega[j];
            t->omega[j] = t->omega[j - 1];
            t->omega[j - 1] = tmp;
            tmp = t->zeta[j];
            t->zeta[j] = t->zeta[j - 1];
            t->zeta[j - 1] = tmp;
            for (int c = 0; c < 3; ++c) {
                tmp = t->w[j][c];
                t->w[j][c] = t->w[j - 1][c];
                t->w[j - 1][c] = tmp;
            }
        }
    }
}

static int alloc_fit(fit *f, const tf_prony_data *d, const size_t *idx, size_t n, int k)
{
    memset(f, 0, sizeof *f);
    f->d = d;
    f->idx = idx;
    f->n = idx != NULL ? n : d->n_hist;
    f->rows = f->n * d->n_ticks;
    f->k = k;
    const size_t kk = k > 0 ? (size_t)k : 1;
    f->x = malloc(3 * f->rows * kk * sizeof *f->x);
    f->y = malloc(3 * f->rows * sizeof *f->y);
    f->a = malloc(f->rows * kk * sizeof *f->a);
    f->b = malloc(f->rows * sizeof *f->b);
    if (f->x == NULL || f->y == NULL || f->a == NULL || f->b == NULL) {
        return -1;
    }
    size_t row = 0;
    for (size_t i = 0; i < f->n; ++i) {
        const size_t at = history_of(idx, i) * d->n_ticks * 3;
        for (size_t t = 0; t < d->n_ticks; ++t, ++row) {
            for (int c = 0; c < 3; ++c) {
                f->y[(size_t)c * f->rows + row] = d->target[at + 3 * t + c] - d->g[at + 3 * t + c];
            }
        }
    }
    return 0;
}

static void free_fit(fit *f)
{
    free(f->x);
    free(f->y);
    free(f->a);
    free(f->b);
}

int tf_resonant_fit_modes(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                          const tf_resonant_bounds *b, tf_resonant_modes *out)
{
    return tf_resonant_fit_modes_from(ctx, d, idx, n, k, b, TF_RESONANT_STARTS, out);
}

int tf_resonant_fit_modes_from(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n,
                               int k, const tf_resonant_bounds *b, int n_starts,
                               tf_resonant_modes *out)
{
    if (k < 0 || k > MAXK) {
        return tf_fail(ctx, "resonant: %d modes (0 .. %d)", k, MAXK);
    }
    double p[2 * MAXK], best_p[2 * MAXK];
    double best = INFINITY;
    int kk = 0;
    memset(out, 0, sizeof *out);
    /* grow from 0 modes: each new mode from TF_RESONANT_STARTS frequencies */
    for (int have = 0; have <= k; ++have) {
        fit f;
        if (alloc_fit(&f, d, idx, n, have) != 0) {
            free_fit(&f);
            return tf_fail(ctx, "resonant: out of memory");
        }
        double *r = malloc(3 * f.rows * sizeof *r);
        if (r == NULL) {
            free_fit(&f);
            return tf_fail(ctx, "resonant: out of memory");
        }
        const int starts = have == 0 ? 1 : n_starts;
        double level_best = INFINITY, level_p[2 * MAXK] = {0}, level_w[MAXK][3] = {{0}};
        for (int s = 0; s < starts; ++s) {
            memcpy(p, best_p, 2 * (size_t)kk * sizeof *p);
            if (have > 0) {
                const double u = (s + 0.5) / starts;
                p[2 * (have - 1)] = log(b->omega_lo) + u * (log(b->omega_hi) - log(b->omega_lo));
                p[2 * (have - 1) + 1] = log(fmin(fmax(0.05, b->zeta_lo), b->zeta_hi));
            }
            const double rss = run_lm(ctx, &f, b, p, r);
            if (rss < level_best) {
                level_best = rss;
                memcpy(level_p, p, 2 * (size_t)have * sizeof *p);
                memcpy(level_w, f.w, sizeof level_w);
            }
        }
        const size_t m = 3 * f.rows;
        free(r);
        free_fit(&f);
        if (!isfinite(level_best)) {
            return tf_fail(ctx, "%s: resonant: %zu histories do not determine %d modes",
                           TF_FAMILY_UNDETERMINED, idx != NULL ? n : d->n_hist, have);
        }
        memcpy(best_p, level_p, 2 * (size_t)have * sizeof *p);
        kk = have;
        best = level_best;
        out->n = have;
        for (int j = 0; j < have; ++j) {
            out->omega[j] = exp(best_p[2 * j]);
            out->zeta[j] = exp(best_p[2 * j + 1]);
            memcpy(out->w[j], level_w[j], sizeof out->w[j]);
        }
        out->rms = sqrt(best / (double)m);
    }
    sort_modes(out);
    return 0;
}

double tf_resonant_modes_rms(const tf_prony_data *d, const size_t *idx, size_t n,
                             const tf_resonant_modes *t)
{
    fit f;
    if (alloc_fit(&f, d, idx, n, t->n) != 0) {
        free_fit(&f);
        return INFINITY;
    }
    double *col = malloc(3 * f.rows * sizeof *col);
    double e2 = 0;
    if (col == NULL) {
        free_fit(&f);
        return INFINITY;
    }
    for (int k = 0; k < t->n; ++k) {
        mode_columns(&f, t->omega[k], t->zeta[k], col, f.rows);
        for (size_t i = 0; i < 3 * f.rows; ++i) {
            f.y[i] -= t->w[k][i / f.rows] * col[i];
        }
    }
    for (size_t i = 0; i < 3 * f.rows; ++i) {
        e2 += f.y[i] * f.y[i];
    }
    free(col);
    free_fit(&f);
    return sqrt(e2 / (double)(3 * f.rows));
}
