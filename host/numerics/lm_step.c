/*
 * lm_step.c — the damped Levenberg–Marquardt step (see lm_step.h).
 *
 * Seed 000 eq. 37 solves (A + d I) delta_b = a_y with A = J^T J, the
 * normal equations.  Here the same step, with Marquardt's scaling D in
 * place of I, is the least-squares solution of the augmented system
 *     [ J             ]       [ -r ]
 *     [ sqrt(lambda) D ] p  =  [  0 ]
 * solved by QR: J P = Q R once per iteration (dgeqp3, in lm.c), then for
 * each lambda the small 2n x n matrix [R; sqrt(lambda) P^T D P] is factored
 * by dgeqrf into S.  S^T S = P^T (J^T J + lambda D^2) P, without ever
 * forming J^T J.
 *
 * lambda is chosen as in Moré (1978, §5): the step must satisfy
 * ||D p|| = delta within 10 %.  phi(lambda) = ||D p(lambda)|| - delta is
 * decreasing and convex, so a safeguarded Newton iteration on phi,
 * bracketed by [parl, paru], takes one to three solves in practice.
 */
#include "numerics/lm_step.h"

#include <cblas.h>
#include <float.h>
#include <math.h>
#include <string.h>

#define MAX_SOLVES 10 /* Moré's cap; the bracket makes more unnecessary */

/* Workspace: the augmented 2n x n matrix, its n Householder scalars, the
 * 2n right-hand side, then three vectors of n (scratch, w, z). */
size_t tf_lmstep_work_size(size_t n)
{
    return 2 * n * n + 6 * n;
}

static double *scratch(const tf_lmstep *s)
{
    return s->work + 2 * s->n * s->n + 3 * s->n;
}

static double *w_vector(const tf_lmstep *s)
{
    return scratch(s) + s->n;
}

static double *z_vector(const tf_lmstep *s)
{
    return scratch(s) + 2 * s->n;
}

static double norm2(const double *v, size_t n)
{
    return cblas_dnrm2((int)n, v, 1);
}

/* ||D p|| for p in parameter order. */
static double scaled_norm(const tf_lmstep *s, const double *p)
{
    double *dp = scratch(s);
    for (size_t j = 0; j < s->n; ++j) {
        dp[j] = s->diag[j] * p[j];
    }
    return norm2(dp, s->n);
}

/* step = -P z. */
static void unpivot(const tf_lmstep *s, const double *z, double *step)
{
    for (size_t j = 0; j < s->n; ++j) {
        step[s->piv[j] - 1] = -z[j];
    }
}

/* Gauss–Newton (lambda = 0): z = R11^-1 (Q^T r)_1 on the independent
 * columns, 0 on the dependent ones (the basic least-squares solution). */
static int gauss_newton(const tf_lmstep *s, double *z)
{
    memset(z, 0, s->n * sizeof *z);
    memcpy(z, s->qtf, s->rank * sizeof *z);
    if (s->rank == 0) {
        return 0;
    }
    return LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'N', 'N', (lapack_int)s->rank, 1, s->r,
                          (lapack_int)s->ldr, z, (lapack_int)s->n);
}

/* Damped (lambda > 0): QR of [R; sqrt(lambda) D_P] into the workspace,
 * whose upper triangle (leading dimension 2n) is then S. */
static int damped(const tf_lmstep *s, double lambda, double *z)
{
    const size_t n = s->n, ld = 2 * n;
    double *a = s->work, *tau = a + ld * n, *rhs = tau + n;
    memset(a, 0, ld * n * sizeof *a);
    memset(rhs, 0, ld * sizeof *rhs);
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i <= j && i < s->k; ++i) {
            a[i + j * ld] = s->r[i + j * s->ldr];
        }
        a[n + j + j * ld] = sqrt(lambda) * s->diag[s->piv[j] - 1];
    }
    memcpy(rhs, s->qtf, s->k * sizeof *rhs);
    lapack_int info = LAPACKE_dgeqrf(LAPACK_COL_MAJOR, (lapack_int)ld, (lapack_int)n, a,
                                     (lapack_int)ld, tau);
    if (info == 0) {
        info = LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', (lapack_int)ld, 1, (lapack_int)n, a,
                              (lapack_int)ld, tau, rhs, (lapack_int)ld);
    }
    if (info == 0) {
        info = LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'N', 'N', (lapack_int)n, 1, a,
                              (lapack_int)ld, rhs, (lapack_int)ld);
    }
    memcpy(z, rhs, n * sizeof *z);
    return info;
}

/* ||T^-T P^T D (D p) / ||D p|| ||^2 for the triangle T (R at lambda = 0,
 * S otherwise), with T^T T = P^T (J^T J + lambda D^2) P: phi'(lambda) is
 * -||D p|| times this, and Moré's correction (phi / delta) / this is the
 * Newton step on 1/||D p|| - 1/delta, which is nearly linear in lambda
 * (Moré 1978, §5). */
static double newton_denominator(const tf_lmstep *s, const double *t, size_t ldt,
                                 const double *step, double dxnorm, int *info)
{
    double *w = w_vector(s);
    for (size_t j = 0; j < s->n; ++j) {
        size_t p = (size_t)s->piv[j] - 1;
        w[j] = s->diag[p] * (s->diag[p] * step[p]) / dxnorm;
    }
    *info = LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'T', 'N', (lapack_int)s->n, 1, t,
                           (lapack_int)ldt, w, (lapack_int)s->n);
    double v = norm2(w, s->n);
    return v * v;
}

/* ||D^-1 J^T r|| = ||D^-1 P R^T (Q^T r)||: the scaled gradient. */
static double scaled_gradient(const tf_lmstep *s)
{
    double *g = scratch(s);
    for (size_t j = 0; j < s->n; ++j) {
        double sum = 0;
        for (size_t i = 0; i <= j && i < s->k; ++i) {
            sum += s->r[i + j * s->ldr] * s->qtf[i];
        }
        g[j] = sum / s->diag[s->piv[j] - 1];
    }
    return norm2(g, s->n);
}

double tf_lmstep_solve(const tf_lmstep *s, double delta, double par, double *step)
{
    const size_t n = s->n;
    double *z = z_vector(s);
    int info = gauss_newton(s, z);
    if (info != 0) {
        return TF_LMSTEP_FAILED;
    }
    unpivot(s, z, step);
    double dxnorm = scaled_norm(s, step), fp = dxnorm - delta;
    if (fp <= 0.1 * delta) {
        return 0; /* the Gauss–Newton step fits in the trust region */
    }
    /* Bracket: phi(parl) >= 0 >= phi(paru).  The lower bound is the
     * Newton step from lambda = 0, valid only when R has full rank. */
    double parl = 0;
    if (s->rank == n) {
        parl = (fp / delta) / newton_denominator(s, s->r, s->ldr, step, dxnorm, &info);
        if (info != 0) {
            return TF_LMSTEP_FAILED;
        }
    }
    double gnorm = scaled_gradient(s);
    double paru = gnorm / delta;
    if (paru == 0) {
        paru = DBL_MIN / fmin(delta, 0.1);
    }
    par = fmin(fmax(par, parl), paru);
    if (par == 0) {
        par = gnorm / dxnorm;
    }
    for (int iter = 1;; ++iter) {
        if (par == 0) {
            par = fmax(DBL_MIN, 0.001 * paru);
        }
        if (damped(s, par, z) != 0) {
            return TF_LMSTEP_FAILED;
        }
        unpivot(s, z, step);
        dxnorm = scaled_norm(s, step);
        if (dxnorm == 0) {
            /* A damped step with a non-zero gradient is non-zero in exact
             * arithmetic: this one underflowed.  Going on would divide
             * 0 by 0 in the Newton denominator. */
            return TF_LMSTEP_UNDERFLOW;
        }
        double previous = fp;
        fp = dxnorm - delta;
        /* Done when ||D p|| is within 10 % of delta, or when phi stopped
         * moving towards 0 from below with no lower bound to lean on. */
        if (fabs(fp) <= 0.1 * delta || (parl == 0 && fp <= previous && previous < 0) ||
            iter == MAX_SOLVES) {
            return par;
        }
        double parc = (fp / delta) / newton_denominator(s, s->work, 2 * n, step, dxnorm, &info);
        if (info != 0) {
            return TF_LMSTEP_FAILED;
        }
        if (fp > 0) {
            parl = fmax(parl, par);
        } else if (fp < 0) {
            paru = fmin(paru, par);
        }
        par = fmax(parl, par + parc);
    }
}
