/*
 * lsq.h — dense linear least squares by column-pivoted QR (LAPACK dgeqp3),
 * with rank detection: factor a design matrix once, then solve for as many
 * right-hand sides as needed, and get the covariance from the same factor.
 *
 * The rank decision is scale-free: columns are scaled to unit 2-norm before
 * the factorisation, so a parameter measured in micrometres is not declared
 * dependent because its column is small.  Column k of the pivoted factor is
 * dependent when |R_kk| <= rank_tol * |R_00|.  Dependent parameters get the
 * value 0 (the "basic" solution: exactly the fit of the model without those
 * columns), zero rows and columns in the covariance, and are reported by
 * tf_lsq_dependent().
 */
#ifndef TF_LSQ_H
#define TF_LSQ_H

#include <stddef.h>

#include "base/context.h"

typedef struct tf_lsq tf_lsq;

/* Factors the m x n matrix A (column-major, a[i + j*lda]), each row i
 * multiplied by sqrt(w[i]) when w is not NULL (w[i] >= 0, finite).
 * m < n is allowed (the rank is then at most m).  Returns NULL with a
 * message in ctx->err on bad arguments, a non-finite entry or no memory. */
tf_lsq *tf_lsq_factor(tf_ctx *ctx, size_t m, size_t n, const double *a, size_t lda, const double *w,
                      double rank_tol);
void tf_lsq_free(tf_lsq *f);

/* Numerical rank found by the factorisation. */
size_t tf_lsq_rank(const tf_lsq *f);

/* 1 when parameter j (original order) was found dependent on the others. */
int tf_lsq_dependent(const tf_lsq *f, size_t j);

/* Solves min ||W^1/2 (A x_k - y_k)|| for k right-hand sides at once:
 * y is m x k (y[i + c*ldy]), x is n x k (x[j + c*ldx]), rss (k entries, may
 * be NULL) receives each column's weighted residual sum of squares.
 * Returns 0, or -1 with a message (non-finite data, no memory). */
int tf_lsq_solve(tf_ctx *ctx, const tf_lsq *f, size_t k, const double *y, size_t ldy, double *x,
                 size_t ldx, double *rss);

/* The unscaled covariance (A^T W A)^-1 of the independent parameters, in
 * the original parameter order, into cov (n x n, column-major); rows and
 * columns of dependent parameters are zero.  Multiply by the residual
 * variance rss / (m - rank) for the statistical covariance.  Returns 0, or
 * -1 when out of memory. */
int tf_lsq_cov(const tf_lsq *f, double *cov);

#endif /* TF_LSQ_H */
