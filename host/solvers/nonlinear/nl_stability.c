/*
 * nl_stability.c — how far the current state is from losing stability
 * (tf_nonlinear_stability, nonlinear.h).
 *
 * The measure is the least eigenvalue mu_1 of the pencil K_t v = mu K_0 v:
 * K_t the tangent at the state, K_0 the tangent at rest (the linear
 * stiffness), both with the fixed DOFs' unit rows.  K_0 is positive
 * definite, so K_t - sigma K_0 is congruent to diag(mu_i - sigma) and, by
 * Sylvester's law of inertia, it is positive definite exactly when
 * sigma < mu_1: a Cholesky factorisation that succeeds or fails brackets
 * mu_1, and bisection narrows the bracket.  mu_1 = 1 at rest (and never
 * above 1 with fixed DOFs, whose unit rows give mu = 1); mu_1 <= 0 means
 * the state is at or past a limit or bifurcation point: no positive
 * definite matrix can then lead Newton's method to it, and a quasi-Newton
 * method that keeps a positive definite factor (nl_linear.c) minimises the
 * energy away from it.
 *
 * The mode: inverse iteration x <- (K_t - lo K_0)^-1 K_0 x with the factor
 * at the bracket's lower end (positive definite), which converges to the
 * eigenvector of the eigenvalue nearest above lo, mu_1; its Rayleigh
 * quotient x^T K_t x / x^T K_0 x estimates mu_1 within the bracket, and
 * the node whose parameters move most in it says where the body gives.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <omp.h>

#include "numerics/csc.h"
#include "solvers/nonlinear/nl_internal.h"
#include "solvers/nonlinear/nonlinear.h"

#define MAX_EXPANSIONS 40 /* doublings of the bracket before giving up */
#define INVERSE_ITERATIONS 30

typedef struct probe {
    nl_solver *s;
    tf_chol *c;          /* its own handle: the Newton solver's factors stay */
    const double *kt, *k0;
    double held;         /* the shift whose factor c holds (NAN: none) */
    size_t factorisations;
} probe;

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += a[i] * b[i];
    }
    return s;
}

/* Factorises K_t - sigma K_0 into p->c: *pd 1 when positive definite. */
static int definite_at(probe *p, double sigma, int *pd)
{
    tf_csc *k = &p->s->k;
    for (size_t q = 0; q < k->nnz; ++q) {
        k->x[q] = p->kt[q] - sigma * p->k0[q];
    }
    double t;
    tf_ctx *ctx = p->s->base.ctx;
    int rc = tf_chol_refactor(ctx, p->c, nl_factored(p->s), &t);
    p->factorisations++;
    if (rc < 0) {
        return -1;
    }
    *pd = rc == 0;
    p->held = rc == 0 ? sigma : NAN;
    return 0;
}

/* A bracket lo < mu_1 <= hi, then bisection to hi - lo <= tol; *pd0: K_t
 * itself is positive definite (the shift 0). */
static int bracket(probe *p, double tol, double *lo, double *hi, int *pd0)
{
    int pd;
    if (definite_at(p, 0, pd0) != 0) {
        return -1;
    }
    if (*pd0) { /* 0 < mu_1 <= 1 with fixed DOFs; weak conditions may put it above */
        *lo = 0;
        *hi = 1;
        for (int k = 0; k < MAX_EXPANSIONS; ++k) {
            if (definite_at(p, *hi, &pd) != 0) {
                return -1;
            }
            if (!pd) {
                break;
            }
            *lo = *hi;
            *hi *= 2;
        }
    } else { /* mu_1 <= 0: shifts -1, -2, -4, ... until positive definite */
        *hi = 0;
        *lo = -1;
        for (int k = 0;; ++k, *lo *= 2) {
            if (k == MAX_EXPANSIONS) {
                return tf_fail(p->s->base.ctx, "stability: the tangent is not positive definite "
                                               "for any shift down to mu = %g", *hi);
            }
            if (definite_at(p, *lo, &pd) != 0) {
                return -1;
            }
            if (pd) {
                break;
            }
            *hi = *lo;
        }
    }
    while (*hi - *lo > tol) {
        double mid = 0.5 * (*lo + *hi);
        if (definite_at(p, mid, &pd) != 0) {
            return -1;
        }
        *(pd ? lo : hi) = mid;
    }
    return 0;
}

/* Inverse iteration with the factor at lo; the mode into x (K_0-unit). */
static int mode(probe *p, double lo, double *x, double *mu)
{
    nl_solver *s = p->s;
    size_t n = s->k.n;
    int pd = 1;
    if (!(p->held == lo) && (definite_at(p, lo, &pd) != 0 || !pd)) {
        return pd ? -1 : tf_fail(s->base.ctx, "the shifted tangent lost definiteness");
    }
    tf_csc k0 = s->k, kt = s->k;
    k0.x = (double *)p->k0;
    kt.x = (double *)p->kt;
    double *y = malloc(n * sizeof *y);
    if (y == NULL) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    uint64_t r = 88172645463325252ULL;
    for (size_t i = 0; i < n; ++i) { /* a fixed start: the same mode every run */
        r ^= r << 13;
        r ^= r >> 7;
        r ^= r << 17;
        x[i] = (double)(r >> 11) / 9007199254740992.0 - 0.5;
    }
    tf_ctx *ctx = s->base.ctx;
    for (int it = 0; it < INVERSE_ITERATIONS; ++it) {
        tf_csc_symv(&k0, x, y, 1);
        if (tf_chol_solve(ctx, p->c, y, x, 1) != 0) {
            free(y);
            return -1;
        }
        tf_csc_symv(&k0, x, y, 1);
        double nrm = sqrt(dot(x, y, n));
        for (size_t i = 0; i < n; ++i) {
            x[i] /= nrm;
        }
    }
    tf_csc_symv(&kt, x, y, 1);
    *mu = dot(x, y, n); /* x^T K_0 x = 1 */
    free(y);
    return 0;
}

/* The node whose three parameters move most in x. */
static size_t largest_node(const double *x, size_t nodes)
{
    size_t best = 0;
    double most = -1;
    for (size_t i = 0; i < nodes; ++i) {
        double m = x[3 * i] * x[3 * i] + x[3 * i + 1] * x[3 * i + 1] + x[3 * i + 2] * x[3 * i + 2];
        if (m > most) {
            most = m;
            best = i;
        }
    }
    return best;
}

/* K_t at the state and K_0 at rest, eliminated, into kt and k0. */
static int tangents(nl_solver *s, double *kt, double *k0)
{
    size_t n = s->k.n;
    double *zero = calloc(n, sizeof *zero);
    if (zero == NULL) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    nl_fault f = {0};
    int rc = nl_assemble(s, s->d, &s->at, 0, 1, s->r, NULL, &f);
    if (rc == 0) {
        nl_eliminate(s);
        memcpy(kt, s->k.x, s->k.nnz * sizeof *kt);
        rc = nl_assemble(s, zero, &s->at, 0, 1, s->r, NULL, &f);
    }
    if (rc == 0) {
        nl_eliminate(s);
        memcpy(k0, s->k.x, s->k.nnz * sizeof *k0);
    }
    free(zero);
    return rc == 0 ? 0 : rc > 0 ? tf_fail(s->base.ctx, "a point inverts (J = %g)", f.j) : -1;
}

int nl_stability(nl_solver *s, double tol, tf_nonlinear_stability *out)
{
    if (s->relaxes || s->kskew != NULL) {
        return tf_fail(s->base.ctx, "stability: only for the elastic laws (a symmetric, "
                                    "time-independent tangent)");
    }
    double t0 = omp_get_wtime();
    size_t nnz = s->k.nnz, n = s->k.n;
    nl_stats keep = s->st; /* the Newton solver's counters are not this probe's */
    double *saved = malloc(nnz * sizeof *saved), *kt = malloc(nnz * sizeof *kt);
    double *k0 = malloc(nnz * sizeof *k0), *x = malloc(n * sizeof *x);
    size_t nhist = s->hist_new ? s->ncell * s->np * s->hb : 0;
    double *hist = nhist ? malloc(nhist * sizeof *hist) : NULL;
    probe p = {.s = s, .kt = kt, .k0 = k0, .held = NAN};
    int rc = saved && kt && k0 && x && (nhist == 0 || hist) ? 0
                                                                     : tf_fail(s->base.ctx, "out of memory");
    if (rc == 0) {
        memcpy(saved, s->k.x, nnz * sizeof *saved);
        if (hist) {
            memcpy(hist, s->hist_new, nhist * sizeof *hist);
        }
        rc = tangents(s, kt, k0);
    }
    if (rc == 0) {
        p.c = tf_chol_analyse(s->base.ctx, nl_factored(s), (tf_ordering)s->base.opts.ordering, 0,
                              &(tf_chol_info){0});
        rc = p.c ? bracket(&p, tol, &out->lo, &out->hi, &out->definite) : -1;
    }
    if (rc == 0) {
        rc = mode(&p, out->lo, x, &out->mu);
    }
    if (rc == 0) {
        out->node = largest_node(x, n / 3);
        const double *v = x + 3 * out->node;
        double nv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int a = 0; a < 3; ++a) {
            out->dir[a] = v[a] / nv;
        }
        out->factorisations = p.factorisations;
        out->seconds = omp_get_wtime() - t0;
    }
    if (saved) {
        memcpy(s->k.x, saved, nnz * sizeof *saved);
    }
    if (hist) {
        memcpy(s->hist_new, hist, nhist * sizeof *hist);
    }
    s->st = keep;
    tf_chol_free(p.c);
    free(saved);
    free(kt);
    free(k0);
    free(x);
    free(hist);
    return rc;
}
