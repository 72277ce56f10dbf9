/*
 * lsq.c — linear least squares by scaled, column-pivoted QR (see lsq.h).
 *
 * Never the normal equations: forming A^T A squares the condition number,
 * and the polynomial families and the NIST problems (Hahn1, Thurber,
 * Lanczos) are ill-conditioned enough that this costs the digits we want.
 */
#include "numerics/lsq.h"

#include <cblas.h>
#include <lapacke.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct tf_lsq {
    size_t m, n, k;  /* k = min(m, n) Householder reflectors */
    size_t rank;
    double *qr;      /* m x n: R above the diagonal, reflectors below */
    double *tau;     /* k */
    double *scale;   /* n: norm of each weighted column (1 for a zero column) */
    double *sqrt_w;  /* m, or NULL when unweighted */
    lapack_int *piv; /* n: column j of the factor is parameter piv[j] - 1 */
};

static int fits_lapack(size_t v)
{
    return v <= (size_t)INT_MAX;
}

void tf_lsq_free(tf_lsq *f)
{
    if (f == NULL) {
        return;
    }
    free(f->qr);
    free(f->tau);
    free(f->scale);
    free(f->sqrt_w);
    free(f->piv);
    free(f);
}

/* Copies W^1/2 A into f->qr and scales its columns to unit norm. */
static int load_scaled(tf_ctx *ctx, tf_lsq *f, const double *a, size_t lda, const double *w)
{
    for (size_t i = 0; w != NULL && i < f->m; ++i) {
        if (!(w[i] >= 0) || !isfinite(w[i])) {
            return tf_fail(ctx, "weight %zu is %g (weights must be finite and >= 0)", i, w[i]);
        }
        f->sqrt_w[i] = sqrt(w[i]);
    }
    for (size_t j = 0; j < f->n; ++j) {
        double *col = f->qr + j * f->m, norm;
        for (size_t i = 0; i < f->m; ++i) {
            double v = a[i + j * lda];
            if (!isfinite(v)) {
                return tf_fail(ctx, "design matrix entry (%zu, %zu) is %g", i, j, v);
            }
            col[i] = w != NULL ? v * f->sqrt_w[i] : v;
        }
        norm = cblas_dnrm2((int)f->m, col, 1); /* scaled: no overflow */
        f->scale[j] = norm > 0 ? norm : 1.0;
        for (size_t i = 0; i < f->m; ++i) {
            col[i] /= f->scale[j];
        }
    }
    return 0;
}

tf_lsq *tf_lsq_factor(tf_ctx *ctx, size_t m, size_t n, const double *a, size_t lda, const double *w,
                      double rank_tol)
{
    if (m == 0 || n == 0 || lda < m || !fits_lapack(m) || !fits_lapack(n) ||
        !fits_lapack(m * n)) {
        tf_fail(ctx, "bad least-squares size %zu x %zu (lda %zu)", m, n, lda);
        return NULL;
    }
    if (!(rank_tol >= 0 && rank_tol < 1)) {
        tf_fail(ctx, "rank tolerance %g is not in [0, 1)", rank_tol);
        return NULL;
    }
    tf_lsq *f = calloc(1, sizeof *f);
    if (f == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    f->m = m;
    f->n = n;
    f->k = m < n ? m : n;
    f->qr = malloc(m * n * sizeof *f->qr);
    f->tau = malloc(f->k * sizeof *f->tau);
    f->scale = malloc(n * sizeof *f->scale);
    f->piv = calloc(n, sizeof *f->piv); /* 0: every column is free to move */
    f->sqrt_w = w != NULL ? malloc(m * sizeof *f->sqrt_w) : NULL;
    if (f->qr == NULL || f->tau == NULL || f->scale == NULL || f->piv == NULL ||
        (w != NULL && f->sqrt_w == NULL)) {
        tf_fail(ctx, "out of memory");
        tf_lsq_free(f);
        return NULL;
    }
    if (load_scaled(ctx, f, a, lda, w) != 0) {
        tf_lsq_free(f);
        return NULL;
    }
    lapack_int info = LAPACKE_dgeqp3(LAPACK_COL_MAJOR, (lapack_int)m, (lapack_int)n, f->qr,
                                     (lapack_int)m, f->piv, f->tau);
    if (info != 0) {
        tf_fail(ctx, "LAPACK dgeqp3 failed (info %d)", (int)info);
        tf_lsq_free(f);
        return NULL;
    }
    double r00 = fabs(f->qr[0]);
    while (f->rank < f->k && r00 > 0 &&
           fabs(f->qr[f->rank + f->rank * m]) > rank_tol * r00) {
        ++f->rank;
    }
    return f;
}

size_t tf_lsq_rank(const tf_lsq *f)
{
    return f->rank;
}

int tf_lsq_dependent(const tf_lsq *f, size_t j)
{
    for (size_t c = 0; c < f->rank; ++c) {
        if ((size_t)f->piv[c] - 1 == j) {
            return 0;
        }
    }
    return 1;
}

/* x = P S^-1 [z; 0] for the basic solution z of the independent block. */
static void unpivot(const tf_lsq *f, const double *z, double *x)
{
    for (size_t j = 0; j < f->n; ++j) {
        x[j] = 0;
    }
    for (size_t c = 0; c < f->rank; ++c) {
        size_t j = (size_t)f->piv[c] - 1;
        x[j] = z[c] / f->scale[j];
    }
}

int tf_lsq_solve(tf_ctx *ctx, const tf_lsq *f, size_t k, const double *y, size_t ldy, double *x,
                 size_t ldx, double *rss)
{
    const size_t m = f->m;
    if (k == 0) {
        return 0;
    }
    if (!fits_lapack(k) || !fits_lapack(m * k) || ldy < m || ldx < f->n) {
        return tf_fail(ctx, "bad right-hand side size %zu (ldy %zu, ldx %zu)", k, ldy, ldx);
    }
    double *c = malloc(m * k * sizeof *c);
    if (c == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t col = 0; col < k; ++col) {
        for (size_t i = 0; i < m; ++i) {
            double v = y[i + col * ldy];
            if (!isfinite(v)) {
                tf_fail(ctx, "data value (%zu, column %zu) is %g", i, col, v);
                free(c);
                return -1;
            }
            c[i + col * m] = f->sqrt_w != NULL ? v * f->sqrt_w[i] : v;
        }
    }
    /* One application of Q^T to all columns: the factor is shared. */
    lapack_int info = LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', (lapack_int)m, (lapack_int)k,
                                     (lapack_int)f->k, f->qr, (lapack_int)m, f->tau, c,
                                     (lapack_int)m);
    if (info == 0 && f->rank > 0) {
        info = LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'N', 'N', (lapack_int)f->rank, (lapack_int)k,
                              f->qr, (lapack_int)m, c, (lapack_int)m);
    }
    if (info != 0) {
        tf_fail(ctx, "LAPACK solve failed (info %d)", (int)info);
        free(c);
        return -1;
    }
    for (size_t col = 0; col < k; ++col) {
        const double *cc = c + col * m;
        unpivot(f, cc, x + col * ldx);
        if (rss != NULL) {
            /* The residual is the part of Q^T y the independent columns
             * cannot reach: rows rank..m-1. */
            double s = 0;
            for (size_t i = f->rank; i < m; ++i) {
                s += cc[i] * cc[i];
            }
            rss[col] = s;
        }
    }
    free(c);
    return 0;
}

int tf_lsq_cov(const tf_lsq *f, double *cov)
{
    const size_t n = f->n, r = f->rank;
    memset(cov, 0, n * n * sizeof *cov);
    if (r == 0) {
        return 0;
    }
    double *t = malloc(r * r * sizeof *t);
    if (t == NULL) {
        return -1;
    }
    for (size_t j = 0; j < r; ++j) {
        for (size_t i = 0; i < r; ++i) {
            t[i + j * r] = i <= j ? f->qr[i + j * f->m] : 0;
        }
    }
    /* (R^T R)^-1 = R^-1 R^-T: invert the triangle, then dlauum forms the
     * product in place (upper triangle). */
    lapack_int info = LAPACKE_dtrtri(LAPACK_COL_MAJOR, 'U', 'N', (lapack_int)r, t, (lapack_int)r);
    if (info == 0) {
        info = LAPACKE_dlauum(LAPACK_COL_MAJOR, 'U', (lapack_int)r, t, (lapack_int)r);
    }
    if (info != 0) { /* cannot happen: the rank test keeps R_kk away from 0 */
        free(t);
        return -1;
    }
    for (size_t b = 0; b < r; ++b) {
        for (size_t a = 0; a <= b; ++a) {
            size_t ja = (size_t)f->piv[a] - 1, jb = (size_t)f->piv[b] - 1;
            double v = t[a + b * r] / (f->scale[ja] * f->scale[jb]);
            cov[ja + jb * n] = v;
            cov[jb + ja * n] = v;
        }
    }
    free(t);
    return 0;
}
