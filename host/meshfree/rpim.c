/*
 * rpim.c — RPIM shape functions (rpim.h; seed eqs 11-17).
 */
#include "meshfree/rpim.h"

#include <float.h>
#include <cblas.h>
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

_Static_assert(sizeof(lapack_int) == sizeof(int), "LAPACKE with 32-bit integers");

/* dormqr's work: 64 (a block size) per row or column of what it updates. */
static size_t qwork_size(size_t cap, size_t cols)
{
    return 64 * (cap + 4 + cols);
}

int tf_rpim_work_init(tf_rpim_work *w, size_t cap)
{
    size_t k = cap + 4;
    w->cap = cap;
    w->n = w->m = 0;
    w->rhs_cap = 4;
    w->xs = malloc(3 * cap * sizeof *w->xs);
    w->g = malloc(k * k * sizeof *w->g);
    w->ipiv = malloc(k * sizeof *w->ipiv);
    w->qp = malloc(4 * k * sizeof *w->qp);
    w->pp = malloc(4 * w->rhs_cap * sizeof *w->pp);
    w->rhs = malloc(w->rhs_cap * k * sizeof *w->rhs);
    w->work = malloc(4 * k * sizeof *w->work);
    w->iwork = malloc(k * sizeof *w->iwork);
    w->qwork = malloc(qwork_size(cap, w->rhs_cap) * sizeof *w->qwork);
    if (!w->xs || !w->g || !w->ipiv || !w->qp || !w->pp || !w->rhs || !w->work || !w->iwork ||
        !w->qwork) {
        tf_rpim_work_free(w);
        return -1;
    }
    return 0;
}

void tf_rpim_work_free(tf_rpim_work *w)
{
    free(w->xs);
    free(w->g);
    free(w->ipiv);
    free(w->qp);
    free(w->pp);
    free(w->rhs);
    free(w->work);
    free(w->iwork);
    free(w->qwork);
    w->xs = w->g = w->qp = w->pp = w->rhs = w->work = w->qwork = NULL;
    w->ipiv = w->iwork = NULL;
    w->cap = w->rhs_cap = 0;
}

/* Multiquadric of a squared scaled distance (seed §2.2). */
static inline double mq(double r2, double c2, double q)
{
    return pow(r2 + c2, q);
}

/* (1 + u)^q - 1 - q u to full relative precision: its Taylor series
 * sum_{k >= 2} binom(q, k) u^k for small u (the series' terms fall at
 * least as u^k / k^2 for 0 < q < 2), else (1 + u)((1 + u)^(q-1) - 1) -
 * (q - 1) u with the bracket by expm1/log1p (at u >= 0.1 the subtraction
 * costs at most 1.3 digits). */
static double mq_tail(double u, double q)
{
    if (u < 0.1) {
        double term = q * (q - 1) / 2 * u * u, sum = 0;
        for (int k = 2; k < 60 && fabs(term) > 1e-18 * fabs(sum); ++k) {
            sum += term;
            term *= (q - k) / (k + 1) * u;
        }
        return sum;
    }
    return (1 + u) * expm1((q - 1) * log1p(u)) - (q - 1) * u;
}

/* The multiquadric with its constant and r^2 terms removed,
 * (r^2 + c^2)^q - c^2q - q c^(2q-2) r^2 = c^2q mq_tail(r^2 / c^2).  With
 * the linear polynomial the shape functions do not change when a kernel
 * gains a + b |x - y|^2 (both are absorbed by the polynomial part:
 * P^T a = p(x) fixes sum a_i and sum a_i x_i), and these two terms are
 * what dominates a flat multiquadric: without them the entries keep the
 * digits that distinguish the nodes. */
static inline double mq_reduced(double r2, const tf_rpim_work *w)
{
    return w->c2q * mq_tail(r2 / w->c2, w->q);
}

/* Its derivative in r^2: q c^(2q-2) ((1 + u)^(q-1) - 1), u = r^2 / c^2. */
static inline double mq_reduced_slope(double r2, const tf_rpim_work *w)
{
    return w->q * w->c2q / w->c2 * expm1((w->q - 1) * log1p(r2 / w->c2));
}

/* R_s into g (n x n, leading dimension ld, both triangles); reduced (above)
 * with the polynomial. */
static void rbf_matrix(const tf_rpim_work *w, double *g, size_t ld)
{
    for (size_t j = 0; j < w->n; ++j) {
        const double *xj = w->xs + 3 * j;
        for (size_t i = j; i < w->n; ++i) {
            const double *xi = w->xs + 3 * i;
            double d0 = xi[0] - xj[0], d1 = xi[1] - xj[1], d2 = xi[2] - xj[2];
            double r2 = d0 * d0 + d1 * d1 + d2 * d2;
            g[i + ld * j] = g[j + ld * i] = w->m ? mq_reduced(r2, w) : mq(r2, w->c2, w->q);
        }
    }
}

/* LU of the k x k matrix at a (leading dimension ld) and its reciprocal
 * condition; 0, or -1 when singular to machine precision. */
static int lu_rcond(tf_rpim_work *w, double *a, size_t k, size_t ld, double *rcond)
{
    *rcond = 1;
    if (k == 0) {
        return 0;
    }
    double anorm = LAPACKE_dlange_work(LAPACK_COL_MAJOR, '1', (lapack_int)k, (lapack_int)k, a,
                                       (lapack_int)ld, w->work);
    if (LAPACKE_dgetrf_work(LAPACK_COL_MAJOR, (lapack_int)k, (lapack_int)k, a, (lapack_int)ld,
                            w->ipiv) != 0 ||
        LAPACKE_dgecon_work(LAPACK_COL_MAJOR, '1', (lapack_int)k, a, (lapack_int)ld, anorm, rcond,
                            w->work, w->iwork) != 0) {
        *rcond = 0;
        return -1;
    }
    /* A pivot that is zero only through rounding leaves nothing to trust. */
    return *rcond > DBL_EPSILON ? 0 : -1;
}

/* Applies Q (trans 'N') or Q^T ('T') of P's QR from side 'L' or 'R' to
 * the rows x cols matrix c (leading dimension ld). */
static void apply_q(tf_rpim_work *w, char side, char trans, size_t rows, size_t cols, double *c,
                    size_t ld)
{
    size_t nq = side == 'L' ? rows : cols;
    LAPACKE_dormqr_work(LAPACK_COL_MAJOR, side, trans, (lapack_int)rows, (lapack_int)cols, 4,
                        w->qp, (lapack_int)nq, w->tau, c, (lapack_int)ld, w->qwork,
                        (lapack_int)qwork_size(w->cap, w->rhs_cap));
}

/* With the polynomial: P = Q [R_P; 0], g = Q^T R_s Q, and the lower-right
 * (n - 4) block of g factorised (rpim.h). */
static int factor_projected(tf_rpim_work *w, double *rcond)
{
    size_t n = w->n;
    if (n < 4) {
        return -1; /* P cannot have rank 4 */
    }
    for (size_t i = 0; i < n; ++i) {
        const double *xi = w->xs + 3 * i;
        w->qp[i] = 1;
        w->qp[i + n] = xi[0];
        w->qp[i + 2 * n] = xi[1];
        w->qp[i + 3 * n] = xi[2];
    }
    double rp;
    if (LAPACKE_dgeqrf_work(LAPACK_COL_MAJOR, (lapack_int)n, 4, w->qp, (lapack_int)n, w->tau,
                            w->qwork, (lapack_int)qwork_size(w->cap, w->rhs_cap)) != 0 ||
        LAPACKE_dtrcon_work(LAPACK_COL_MAJOR, '1', 'U', 'N', 4, w->qp, (lapack_int)n, &rp,
                            w->work, w->iwork) != 0 ||
        !(rp > DBL_EPSILON)) {
        return -1; /* coplanar (or fewer distinct) nodes: P is rank-deficient */
    }
    rbf_matrix(w, w->g, n);
    apply_q(w, 'L', 'T', n, n, w->g, n);
    apply_q(w, 'R', 'N', n, n, w->g, n);
    int rc = lu_rcond(w, w->g + 4 + 4 * n, n - 4, n, rcond);
    *rcond = fmin(*rcond, rp);
    return rc;
}

int tf_rpim_factor(const tf_rpim *p, tf_rpim_work *w, const double *xyz, const uint32_t *idx,
                   size_t n, const double centre[3], double s, double *rcond)
{
    *rcond = 0;
    if (n > w->cap || n == 0) {
        return -1;
    }
    w->n = n;
    w->m = p->poly ? 4 : 0;
    w->s = s;
    w->c2 = (p->shape / s) * (p->shape / s);
    w->q = p->q;
    w->c2q = pow(w->c2, p->q);
    for (int a = 0; a < 3; ++a) {
        w->centre[a] = centre[a];
    }
    for (size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            w->xs[3 * i + a] = (xyz[3 * (size_t)idx[i] + a] - centre[a]) / s;
        }
    }
    if (w->m) {
        return factor_projected(w, rcond);
    }
    rbf_matrix(w, w->g, n);
    return lu_rcond(w, w->g, n, n, rcond);
}

/* Right-hand sides of one point: R(x) (and, when deriv, its x, y, z
 * derivatives) in four columns of length n at b, p(x) and its derivatives
 * in four columns of length 4 at pb (with the polynomial). */
static void point_rhs(const tf_rpim_work *w, const double x[3], int deriv, double *b, double *pb)
{
    size_t n = w->n;
    double xs[3];
    for (int a = 0; a < 3; ++a) {
        xs[a] = (x[a] - w->centre[a]) / w->s;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *xi = w->xs + 3 * i;
        double d0 = xs[0] - xi[0], d1 = xs[1] - xi[1], d2 = xs[2] - xi[2];
        double t = d0 * d0 + d1 * d1 + d2 * d2;
        b[i] = w->m ? mq_reduced(t, w) : mq(t, w->c2, w->q);
        if (deriv) {
            /* dR/dx_a = 2 dR/d(r^2) (x_a - x_ia), in scaled units */
            double f = 2 * (w->m ? mq_reduced_slope(t, w) : w->q * b[i] / (t + w->c2));
            b[i + n] = f * d0;
            b[i + 2 * n] = f * d1;
            b[i + 3 * n] = f * d2;
        }
    }
    if (w->m) {
        const double pv[4] = {1, xs[0], xs[1], xs[2]};
        for (size_t j = 0; j < 4; ++j) {
            pb[j] = pv[j];
            if (deriv) {
                pb[j + 4] = j == 1;
                pb[j + 8] = j == 2;
                pb[j + 12] = j == 3;
            }
        }
    }
}

/* The projected solve (rpim.h) of cols right-hand sides: R-parts in rhs
 * (n x cols), p-parts in pp (4 x cols); Phi^T = a into rhs. */
static void solve_projected(tf_rpim_work *w, size_t cols)
{
    size_t n = w->n;
    lapack_int ln = (lapack_int)n, lc = (lapack_int)cols;
    /* R_P^T w = p(x) */
    cblas_dtrsm(CblasColMajor, CblasLeft, CblasUpper, CblasTrans, CblasNonUnit, 4, lc, 1.0,
                w->qp, ln, w->pp, 4);
    /* t = Q^T R(x); t2 -= (Q2^T R_s Q1) w; z = (Q2^T R_s Q2)^-1 t2 */
    apply_q(w, 'L', 'T', n, cols, w->rhs, n);
    if (n > 4) {
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, ln - 4, lc, 4, -1.0, w->g + 4, ln,
                    w->pp, 4, 1.0, w->rhs + 4, ln);
        LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', ln - 4, lc, w->g + 4 + 4 * n, ln, w->ipiv,
                            w->rhs + 4, ln);
    }
    /* a = Q [w; z] */
    for (size_t c = 0; c < cols; ++c) {
        memcpy(w->rhs + c * n, w->pp + 4 * c, 4 * sizeof *w->rhs);
    }
    apply_q(w, 'L', 'N', n, cols, w->rhs, n);
}

/* Room for cols right-hand sides. */
static int grow_rhs(tf_rpim_work *w, size_t cols)
{
    if (cols <= w->rhs_cap) {
        return 0;
    }
    double *rhs = realloc(w->rhs, cols * (w->cap + 4) * sizeof *rhs);
    if (rhs == NULL) {
        return -1;
    }
    w->rhs = rhs;
    double *pp = realloc(w->pp, 4 * cols * sizeof *pp);
    if (pp == NULL) {
        return -1;
    }
    w->pp = pp;
    double *qwork = realloc(w->qwork, qwork_size(w->cap, cols) * sizeof *qwork);
    if (qwork == NULL) {
        return -1;
    }
    w->qwork = qwork;
    w->rhs_cap = cols;
    return 0;
}

int tf_rpim_eval(tf_rpim_work *w, const double *x, size_t np, double *phi, double *dphi)
{
    size_t n = w->n, per = dphi ? 4 : 1, cols = per * np;
    if (grow_rhs(w, cols) != 0) {
        return -1;
    }
    for (size_t p = 0; p < np; ++p) {
        point_rhs(w, x + 3 * p, dphi != NULL, w->rhs + p * per * n, w->pp + p * per * 4);
    }
    if (w->m) {
        solve_projected(w, cols);
    } else {
        LAPACKE_dgetrs_work(LAPACK_COL_MAJOR, 'N', (lapack_int)n, (lapack_int)cols, w->g,
                            (lapack_int)n, w->ipiv, w->rhs, (lapack_int)n);
    }
    for (size_t p = 0; p < np; ++p) {
        const double *b = w->rhs + p * per * n;
        for (size_t i = 0; i < n; ++i) {
            phi[p * n + i] = b[i];
        }
        for (size_t a = 0; dphi && a < 3; ++a) {
            for (size_t i = 0; i < n; ++i) {
                dphi[(3 * p + a) * n + i] = b[i + (a + 1) * n] / w->s;
            }
        }
    }
    return 0;
}
