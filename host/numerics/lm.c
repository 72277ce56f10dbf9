/*
 * lm.c — Levenberg–Marquardt, Moré's trust-region form (see lm.h and
 * docs/lm.md).
 *
 * One outer iteration: Jacobian J at p, active set, scaling D, pivoted QR
 * of the free columns of J.  Inner loop: damped step for the current trust
 * radius delta (lm_step.c), trial point projected into the box, ratio of
 * actual to predicted reduction, radius update; repeat until a step is
 * accepted or a stop test fires.
 *
 * Relation to seed 000 (eqs 33–37): eq. 33 adds d * sum (b_j - b_j0)^2 to
 * the linearised sum of squares, eq. 37 solves (A + d I) delta_b = a_y, and
 * the text raises d while J grows and lowers it while J falls.  Here d is
 * lambda, I becomes D^2 (Marquardt's scaling: invariant to the units of each
 * parameter), the solve is by QR (lm_step.c), and instead of multiplying d
 * up or down, the radius delta = ||D delta_b|| is updated from the ratio of
 * actual to predicted reduction and lambda follows from delta.  The trust
 * region gives the same behaviour as the seed's rule — a failed step shrinks
 * the step, a good one lets it grow towards Gauss–Newton (d = 0) — with
 * Moré's convergence proof and his safeguards.
 */
#include "numerics/lm.h"

#include <cblas.h>
#include <float.h>
#include <lapacke.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/lm_box.h"
#include "numerics/lm_fdjac.h"
#include "numerics/lm_step.h"

#define ACCEPT_RATIO 1e-4 /* Moré: accept any step that gains this fraction */
#define SANE_LOW 0.25     /* reduction-ratio window in which the linear model */
#define SANE_HIGH 2.0     /* is trusted for the relative-reduction stop */
/* Rounding floor of the relative reduction 1 - (|r_t| / |r|)^2 (see
 * noise_floor()).  Below it the step the linear model chose is taken, since
 * the sum of squares cannot refute it, and the region halves so that the
 * iteration still ends; Gauss-Newton steps that shrink by at least half per
 * step, as they do near a minimum, still fit. */
#define NOISE_SHRINK 0.5

const char *tf_stop_name(tf_stop s)
{
    static const char *const names[] = {
        [TF_STOP_DIRECT] = "direct",
        [TF_STOP_REDUCTION] = "reduction",
        [TF_STOP_STEP] = "step",
        [TF_STOP_GRADIENT] = "gradient",
        [TF_STOP_ZERO_RESIDUAL] = "zero-residual",
        [TF_STOP_PRECISION] = "precision",
        [TF_STOP_MAX_EVALS] = "max-evals",
        [TF_STOP_NONFINITE] = "nonfinite",
        [TF_STOP_UNDERFLOW] = "underflow",
        [TF_STOP_BAD_START] = "bad-start",
        [TF_STOP_BAD_JACOBIAN] = "bad-jacobian",
        [TF_STOP_CALLBACK] = "callback",
    };
    return (unsigned)s < sizeof names / sizeof names[0] ? names[s] : "unknown";
}

int tf_stop_converged(tf_stop s)
{
    return s <= TF_STOP_PRECISION;
}

void tf_lm_default_options(tf_lm_options *o, size_t n)
{
    o->ftol = 1e-10;
    o->xtol = 1e-10;
    o->gtol = 0;
    o->max_evals = 200 * (n + 1);
    o->factor = 1;
    o->central_diff = 0;
}

typedef struct lm {
    const tf_lm_problem *pb;
    const tf_lm_options *opt;
    size_t m, n, nf;       /* nf: free parameters this iteration */
    double *p, *r, *jac;   /* current point, residuals, Jacobian (m x n) */
    double *pt, *rt;       /* trial point and residuals */
    double *qr, *qtf, *tau, *diag, *grad, *step, *js, *fdiag, *fstep, *typ, *cnorm, *dv;
    double *cscale; /* power of two near each column's norm: QR of J C^-1 */
    double *work;
    lapack_int *piv;
    size_t *free_idx;
    signed char *active;
    double rnorm, pnorm_scaled, delta, par;
    double gn_prered; /* relative reduction the Gauss–Newton step predicts */
    size_t evals, jac_evals, iterations;
    int wall;         /* a trial since the last accepted step was non-finite */
    int projected;    /* a bound cut the last trial step short */
} lm;

/* Euclidean norm, scaled against overflow (BLAS dnrm2). */
static double norm2(const double *v, size_t n)
{
    return n > 0 ? cblas_dnrm2((int)n, v, 1) : 0;
}

static int all_finite(const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(v[i])) {
            return 0;
        }
    }
    return 1;
}

static double lower(const lm *s, size_t j)
{
    return s->pb->lower != NULL ? s->pb->lower[j] : -INFINITY;
}

static double upper(const lm *s, size_t j)
{
    return s->pb->upper != NULL ? s->pb->upper[j] : INFINITY;
}

/* ||D v||. */
static double scaled_norm(const lm *s, const double *v)
{
    for (size_t j = 0; j < s->n; ++j) {
        s->dv[j] = s->diag[j] * v[j];
    }
    return norm2(s->dv, s->n);
}

static int evaluate(lm *s, const double *p, double *r)
{
    ++s->evals;
    return s->pb->residual(s->pb->ctx, p, r);
}

/* ------------------------------------------------------------------------ */

static void lm_free(lm *s)
{
    free(s->p);
    free(s->piv);
    free(s->free_idx);
    free(s->active);
}

/* One block for all double arrays, so that freeing cannot leak half. */
static int lm_alloc(lm *s)
{
    const size_t m = s->m, n = s->n;
    size_t total = n + m + m * n + n + m + m * n + m + n + n + n + n + m + n + n + n + n + n + n +
                   tf_lmstep_work_size(n);
    s->p = malloc(total * sizeof *s->p);
    s->piv = malloc(n * sizeof *s->piv);
    s->free_idx = malloc(n * sizeof *s->free_idx);
    s->active = malloc(n * sizeof *s->active);
    if (s->p == NULL || s->piv == NULL || s->free_idx == NULL || s->active == NULL) {
        lm_free(s);
        return -1;
    }
    double *q = s->p + n;
    s->r = q, q += m;
    s->jac = q, q += m * n;
    s->pt = q, q += n;
    s->rt = q, q += m;
    s->qr = q, q += m * n;
    s->qtf = q, q += m;
    s->tau = q, q += n;
    s->diag = q, q += n;
    s->grad = q, q += n;
    s->step = q, q += n;
    s->js = q, q += m;
    s->fdiag = q, q += n;
    s->fstep = q, q += n;
    s->typ = q, q += n;
    s->cnorm = q, q += n;
    s->dv = q, q += n;
    s->cscale = q, q += n;
    s->work = q;
    return 0;
}

static int check_problem(tf_ctx *ctx, const tf_lm_problem *pb)
{
    if (pb->n == 0 || pb->m == 0 || pb->residual == NULL || pb->m > (size_t)INT_MAX ||
        pb->n > (size_t)INT_MAX || pb->m * pb->n > (size_t)INT_MAX) {
        return tf_fail(ctx, "bad least-squares problem (%zu residuals, %zu parameters)", pb->m,
                       pb->n);
    }
    for (size_t j = 0; j < pb->n; ++j) {
        double lo = pb->lower != NULL ? pb->lower[j] : -INFINITY;
        double hi = pb->upper != NULL ? pb->upper[j] : INFINITY;
        if (isnan(lo) || isnan(hi) || lo > hi || lo == INFINITY || hi == -INFINITY) {
            return tf_fail(ctx, "parameter %zu: bounds [%g, %g] hold no value", j, lo, hi);
        }
    }
    return 0;
}

/* ------------------------------------------------------------------------ */

static tf_stop jacobian(lm *s)
{
    ++s->jac_evals;
    if (s->pb->jacobian != NULL) {
        if (s->pb->jacobian(s->pb->ctx, s->p, s->jac) != 0) {
            return TF_STOP_CALLBACK;
        }
    } else {
        tf_fdjac fd = {s->pb->residual, s->pb->ctx,   s->m,  s->n, s->pb->lower,
                       s->pb->upper,    s->typ, s->opt->central_diff};
        int rc = tf_fdjac_eval(&fd, s->p, s->r, s->jac, s->pt, s->rt, s->js, &s->evals);
        if (rc != 0) {
            return rc < 0 ? TF_STOP_CALLBACK : TF_STOP_BAD_JACOBIAN;
        }
    }
    return all_finite(s->jac, s->m * s->n) ? TF_STOP_DIRECT : TF_STOP_BAD_JACOBIAN;
}

/* Gradient g = J^T r, column norms of J, and the active set: a parameter
 * on a bound whose descent direction -g points out of the box is held
 * there this iteration. */
static void active_set(lm *s)
{
    cblas_dgemv(CblasColMajor, CblasTrans, (int)s->m, (int)s->n, 1.0, s->jac, (int)s->m, s->r, 1,
                0.0, s->grad, 1);
    s->nf = 0;
    for (size_t j = 0; j < s->n; ++j) {
        double g = s->grad[j], lo = lower(s, j), hi = upper(s, j);
        s->cnorm[j] = norm2(s->jac + j * s->m, s->m);
        s->active[j] = 0;
        if (lo == hi || (s->p[j] <= lo && g > 0)) {
            s->active[j] = -1;
        } else if (s->p[j] >= hi && g < 0) {
            s->active[j] = 1;
        }
        if (s->active[j] == 0) {
            s->free_idx[s->nf++] = j;
        }
    }
}

/* Moré's scaling: D_j = the largest column norm of J seen so far, so the
 * method is invariant to rescaling the parameters. */
static void update_scaling(lm *s, int first)
{
    for (size_t j = 0; j < s->n; ++j) {
        double c = s->cnorm[j];
        if (first) {
            s->diag[j] = c > 0 ? c : 1.0;
        } else if (c > s->diag[j]) {
            s->diag[j] = c;
        }
    }
}

/* Column scale for the factorisation: the power of two nearest above the
 * column's norm (1 for a zero column), so that J C^-1 has columns of norm
 * in (1/2, 1] and the scaling itself is exact. */
static double column_scale(double norm)
{
    int e;
    return norm > 0 && isfinite(norm) ? (frexp(norm, &e), ldexp(1.0, e)) : 1.0;
}

/* Pivoted QR of the free columns of J C^-1 and Q^T r.  Returns the
 * numerical rank.
 *
 * The columns are scaled to about unit norm first (exactly, by powers of
 * two), so that pivoting and the rank decision do not depend on the units
 * of the parameters (docs/lm.md §2): on the unscaled J one column 1e15
 * times larger than the others made them all look dependent, and the
 * Gauss-Newton step and reduction ignored them. */
static int factor(lm *s, size_t *rank)
{
    const size_t m = s->m, nf = s->nf, k = m < nf ? m : nf;
    for (size_t c = 0; c < nf; ++c) {
        size_t j = s->free_idx[c];
        double cs = column_scale(s->cnorm[j]);
        s->cscale[j] = cs;
        for (size_t i = 0; i < m; ++i) {
            s->qr[i + c * m] = s->jac[i + j * m] / cs;
        }
        s->piv[c] = 0;
    }
    lapack_int info = LAPACKE_dgeqp3(LAPACK_COL_MAJOR, (lapack_int)m, (lapack_int)nf, s->qr,
                                     (lapack_int)m, s->piv, s->tau);
    if (info != 0) {
        return -1;
    }
    memcpy(s->qtf, s->r, m * sizeof *s->qtf);
    info = LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', (lapack_int)m, 1, (lapack_int)k, s->qr,
                          (lapack_int)m, s->tau, s->qtf, (lapack_int)m);
    if (info != 0) {
        return -1;
    }
    /* Rank for the Gauss–Newton step: columns beyond it are noise at the
     * level of double rounding in R (of the scaled columns, |R_00| ~ 1). */
    double r00 = fabs(s->qr[0]), tol = (double)(m > nf ? m : nf) * DBL_EPSILON * r00;
    *rank = 0;
    while (*rank < k && fabs(s->qr[*rank + *rank * m]) > tol) {
        ++*rank;
    }
    /* ||Q_1^T r||^2 / ||r||^2: the squared cosine between r and the range
     * of J, which is 0 exactly at a stationary point. */
    double q = norm2(s->qtf, *rank) / s->rnorm;
    s->gn_prered = q * q;
    return 0;
}

/* Largest cosine between r and a free column of J (Moré's gtol test).
 * Divided one norm at a time: the product of a large column norm and
 * ||r|| overflows to infinity and made the cosine 0, a false "gradient"
 * stop; a cosine that cannot be computed (NaN from an overflowed J^T r)
 * counts as large. */
static double gradient_cosine(const lm *s)
{
    double g = 0;
    for (size_t c = 0; c < s->nf; ++c) {
        size_t j = s->free_idx[c];
        double cn = s->cnorm[j];
        if (cn > 0) {
            double cosine = fabs(s->grad[j]) / cn / s->rnorm;
            g = isnan(cosine) ? INFINITY : fmax(g, cosine);
        }
    }
    return g;
}

/* The damped step on the free parameters, projected into the box.  Sets
 * s->step to the damped step (the step taken when a bound cut it) and
 * s->pt to the trial point.  The factor is of J C^-1, so the step is
 * solved for C p with the scaling D C^-1 (the same ||D p||) and unscaled
 * (exactly, but it may underflow: C holds powers of two).  Returns
 * TF_STOP_DIRECT, or why no step could be made: BAD_JACOBIAN when LAPACK
 * failed, UNDERFLOW when the step is zero in every component. */
static tf_stop trial_step(lm *s, size_t rank)
{
    const size_t nf = s->nf;
    for (size_t c = 0; c < nf; ++c) {
        size_t j = s->free_idx[c];
        s->fdiag[c] = s->diag[j] / s->cscale[j];
    }
    tf_lmstep st = {nf, s->m < nf ? s->m : nf, s->qr, s->m, s->piv, rank, s->qtf, s->fdiag,
                    s->work};
    double par = tf_lmstep_solve(&st, s->delta, s->par, s->fstep);
    if (par == TF_LMSTEP_UNDERFLOW) {
        return TF_STOP_UNDERFLOW;
    }
    if (par < 0) {
        return TF_STOP_BAD_JACOBIAN;
    }
    s->par = par;
    memset(s->step, 0, s->n * sizeof *s->step);
    int moves = 0;
    for (size_t c = 0; c < nf; ++c) {
        size_t j = s->free_idx[c];
        s->step[j] = s->fstep[c] / s->cscale[j];
        moves |= s->step[j] != 0;
    }
    if (!moves) {
        return TF_STOP_UNDERFLOW;
    }
    s->projected = tf_lm_box_trial(s->n, s->pb->lower, s->pb->upper, s->p, s->step, s->pt);
    if (s->projected) {
        for (size_t j = 0; j < s->n; ++j) {
            s->step[j] = s->pt[j] - s->p[j];
        }
    }
    return TF_STOP_DIRECT;
}

/* Predicted relative reduction of ||r||^2 for the step (Moré eq. 4.4 and
 * 5.3 when unprojected), and dirder = (J^T r . step) / ||r||^2. */
static void predicted(lm *s, int projected, double *prered, double *dirder)
{
    const double rn2 = s->rnorm * s->rnorm;
    cblas_dgemv(CblasColMajor, CblasNoTrans, (int)s->m, (int)s->n, 1.0, s->jac, (int)s->m,
                s->step, 1, 0.0, s->js, 1);
    double jsn;
    jsn = norm2(s->js, s->m);
    if (!projected) {
        /* The LM step satisfies -step.g = ||J step||^2 + lambda ||D step||^2,
         * which gives the reduction as a sum of squares: no cancellation. */
        double t1 = jsn / s->rnorm, t2 = sqrt(s->par) * s->pnorm_scaled / s->rnorm;
        *prered = t1 * t1 + 2 * t2 * t2;
        *dirder = -(t1 * t1 + t2 * t2);
        return;
    }
    double sg = cblas_ddot((int)s->n, s->step, 1, s->grad, 1);
    *prered = -(2 * sg + jsn * jsn) / rn2;
    *dirder = sg / rn2;
}

/* Moré's radius update (1978, §4) from the reduction ratio; a non-finite
 * or ten-fold larger trial residual shrinks the radius ten-fold. */
static void update_radius(lm *s, double ratio, double actred, double dirder, double rtnorm)
{
    double pn = s->pnorm_scaled;
    if (ratio <= 0.25) {
        double t = actred >= 0 ? 0.5 : 0.5 * dirder / (dirder + 0.5 * actred);
        if (!(0.1 * rtnorm < s->rnorm) || !(t >= 0.1)) {
            t = 0.1;
        }
        s->delta = t * fmin(s->delta, 10 * pn);
        s->par /= t;
    } else if (s->par == 0 || ratio >= 0.75) {
        s->delta = 2 * pn;
        s->par *= 0.5;
    }
}

/* Stop tests after a trial (Moré's, with guards).  The relative-
 * reduction test needs the step's reduction ratio to be sane (the linear
 * model was right about it) and the Gauss–Newton reduction from this point
 * to be below ftol too: a trust region squeezed small makes any step's
 * predicted reduction small, and that is no sign of a minimum.  After a
 * step below the rounding floor of the sum of squares (unresolved) only the
 * size of the region can end the fit: the parameters may still be moving.
 * A collapse of the region after non-finite trials is reported as such.
 * Returns TF_STOP_DIRECT to go on. */
static tf_stop stop_test(const lm *s, double actred, double prered, double ratio, int unresolved)
{
    const tf_lm_options *o = s->opt;
    double pnorm = scaled_norm(s, s->p);
    int sane = ratio >= SANE_LOW && ratio <= SANE_HIGH;
    int reduction_says = !unresolved;
    if (s->rnorm == 0) {
        return TF_STOP_ZERO_RESIDUAL;
    }
    if (reduction_says && fabs(actred) <= o->ftol && prered <= o->ftol && sane &&
        s->gn_prered <= o->ftol) {
        return TF_STOP_REDUCTION;
    }
    if (s->delta <= o->xtol * pnorm) {
        return s->wall ? TF_STOP_NONFINITE : TF_STOP_STEP;
    }
    if (s->evals >= o->max_evals) {
        return TF_STOP_MAX_EVALS;
    }
    tf_stop floor = s->wall ? TF_STOP_NONFINITE : TF_STOP_PRECISION;
    if (reduction_says && fabs(actred) <= DBL_EPSILON && prered <= DBL_EPSILON &&
        0.5 * ratio <= 1) {
        return floor;
    }
    /* No step inside the region can change r beyond rounding. */
    if (s->delta <= DBL_EPSILON * fmax(pnorm, s->rnorm)) {
        return floor;
    }
    return TF_STOP_DIRECT;
}

/* The relative reduction of ||r||^2 below which a change is rounding:
 * each norm carries up to m rounding errors (a sum of m squares), 4 m eps
 * in the ratio of two; and each residual r_i = f_i - y_i carries about
 * eps |y_i| from the subtraction and as much from evaluating f_i, which
 * moves ||r||^2 by up to 2 (2 eps ||y||) ||r||: relative 4 eps ||y|| / ||r||.
 * The second dominates for small residuals (Lanczos3: 2e-11 against
 * 2e-14). */
static double noise_floor(const lm *s)
{
    double sum = 4 * (double)s->m * DBL_EPSILON;
    double diff = 4 * DBL_EPSILON * s->pb->data_norm / s->rnorm;
    return fmax(sum, diff);
}

/* One trial from the current factor.  Returns a stop reason or DIRECT;
 * *accepted tells whether the point moved. */
static tf_stop one_trial(lm *s, size_t rank, int first, int *accepted)
{
    *accepted = 0;
    tf_stop st = trial_step(s, rank);
    if (st != TF_STOP_DIRECT) {
        return st;
    }
    s->pnorm_scaled = scaled_norm(s, s->step);
    if (first) {
        s->delta = fmin(s->delta, s->pnorm_scaled);
    }
    if (evaluate(s, s->pt, s->rt) != 0) {
        return TF_STOP_CALLBACK;
    }
    int finite = all_finite(s->rt, s->m);
    s->wall |= !finite;
    double rtnorm = finite ? norm2(s->rt, s->m) : INFINITY;
    double actred = 0.1 * rtnorm < s->rnorm ? 1 - (rtnorm / s->rnorm) * (rtnorm / s->rnorm) : -1;
    double prered, dirder;
    predicted(s, s->projected, &prered, &dirder);
    double ratio = prered != 0 ? actred / prered : 0;
    double noise = noise_floor(s);
    int unresolved = finite && fabs(actred) <= noise && prered <= noise;
    update_radius(s, ratio, actred, dirder, rtnorm);
    if (unresolved) {
        s->delta = NOISE_SHRINK * fmin(s->delta, s->pnorm_scaled);
    }
    if (ratio >= ACCEPT_RATIO || unresolved) {
        memcpy(s->p, s->pt, s->n * sizeof *s->p);
        memcpy(s->r, s->rt, s->m * sizeof *s->r);
        s->rnorm = rtnorm;
        ++s->iterations;
        s->wall = 0;
        *accepted = 1;
    }
    return stop_test(s, actred, prered, ratio, unresolved);
}

static tf_stop iterate(lm *s)
{
    int first = 1;
    for (;;) {
        tf_stop st = jacobian(s);
        if (st != TF_STOP_DIRECT) {
            return st;
        }
        active_set(s);
        update_scaling(s, first);
        if (first) {
            /* factor ||D p0||; at p0 = 0, factor ||r0|| rather than factor
             * itself: ||D p|| is in the units of r (D_j = ||J_j||), so an
             * absolute radius of 1 would depend on the parameters' units
             * (and with one large column stop the fit at the start, the
             * region below what double can resolve of ||r||). */
            double pn = scaled_norm(s, s->p);
            s->delta = s->opt->factor * (pn > 0 ? pn : s->rnorm);
            s->par = 0;
        }
        if (s->nf == 0) {
            return TF_STOP_GRADIENT; /* every parameter held by its bound */
        }
        size_t rank;
        if (factor(s, &rank) != 0) {
            return TF_STOP_BAD_JACOBIAN;
        }
        if (gradient_cosine(s) <= s->opt->gtol) {
            return TF_STOP_GRADIENT;
        }
        int accepted = 0;
        while (!accepted) {
            st = one_trial(s, rank, first, &accepted);
            if (st != TF_STOP_DIRECT) {
                return st;
            }
        }
        first = 0;
    }
}

/* The Jacobian at the returned point, for the covariance. */
static void final_jacobian(lm *s, tf_lm_result *res)
{
    if (res->jac == NULL) {
        return;
    }
    tf_stop st = jacobian(s);
    for (size_t i = 0; i < s->m * s->n; ++i) {
        res->jac[i] = st == TF_STOP_DIRECT ? s->jac[i] : NAN;
    }
}

int tf_lm_solve(tf_ctx *ctx, const tf_lm_problem *pb, const tf_lm_options *opt, double *p,
                tf_lm_result *res)
{
    if (check_problem(ctx, pb) != 0) {
        return -1;
    }
    lm s = {.pb = pb, .opt = opt, .m = pb->m, .n = pb->n};
    if (lm_alloc(&s) != 0) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t j = 0; j < s.n; ++j) {
        s.p[j] = tf_lm_box_clamp(p[j], lower(&s, j), upper(&s, j));
        s.typ[j] = s.p[j] != 0 ? fabs(s.p[j]) : 1.0; /* for finite differences */
    }
    tf_stop stop;
    int started = 0; /* a finite residual vector is held in s.r */
    if (evaluate(&s, s.p, s.r) != 0) {
        stop = TF_STOP_CALLBACK;
    } else if (!all_finite(s.r, s.m)) {
        stop = TF_STOP_BAD_START;
    } else {
        started = 1;
        s.rnorm = norm2(s.r, s.m);
        stop = s.rnorm == 0 ? TF_STOP_ZERO_RESIDUAL : iterate(&s);
    }
    memcpy(p, s.p, s.n * sizeof *p);
    res->stop = stop;
    res->rss = started ? s.rnorm * s.rnorm : NAN;
    if (started) {
        final_jacobian(&s, res);
    } else if (res->jac != NULL) {
        for (size_t i = 0; i < s.m * s.n; ++i) {
            res->jac[i] = NAN;
        }
    }
    for (size_t j = 0; res->active != NULL && j < s.n; ++j) {
        res->active[j] = (signed char)(s.p[j] <= lower(&s, j) ? -1 : s.p[j] >= upper(&s, j));
    }
    res->iterations = s.iterations;
    res->evals = s.evals;
    res->jac_evals = s.jac_evals;
    lm_free(&s);
    return 0;
}
