/*
 * nl_linear.c — the linear system of each Newton iteration (nl_internal.h):
 * CHOLMOD's symbolic analysis once per solver, numeric factorisations of
 * the tangent when the strategy (tf_newton_opts.tangent) asks, and Krylov
 * methods preconditioned by the last factorisation: conjugate gradients for
 * a symmetric tangent, restarted GMRES (Saad & Schultz 1986) for the Kelvin
 * law's unsymmetric one, whose symmetric part is what CHOLMOD factorises.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solvers/nonlinear/nl_internal.h"

/* Relative residual the Krylov solves aim at (inexact Newton: the outer
 * iteration removes the rest). */
#define KRYLOV_RTOL 1e-8
#define GMRES_RESTART 30

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += a[i] * b[i];
    }
    return s;
}

void nl_eliminate(nl_solver *s)
{
    if (s->weak) {
        return;
    }
    const tf_csc *k = &s->k;
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            size_t i = (size_t)k->i[q];
            if (s->bc.fixed[i] || s->bc.fixed[j]) {
                k->x[q] = i == j ? 1.0 : 0.0;
                if (s->kskew) {
                    s->kskew[q] = 0;
                }
            }
        }
    }
}

const tf_csc *nl_factored(nl_solver *s)
{
    if (s->kf_at == NULL) {
        return &s->k;
    }
    for (size_t q = 0; q < s->kf.nnz; ++q) {
        s->kf.x[q] = s->k.x[s->kf_at[q]];
    }
    return &s->kf;
}

/* A tangent that is not positive definite (past a limit point, St.
 * Venant-Kirchhoff's material instability in compression) still has an
 * LDL^T factorisation unless a pivot vanishes; Newton's method then goes on
 * along the load path, and the step is cut only when that fails too. */
static int factor_indefinite(nl_solver *s, const tf_csc *k)
{
    tf_ctx *ctx = s->base.ctx;
    if (s->ldl == NULL) {
        tf_chol_info ci;
        s->ldl = tf_chol_analyse(ctx, k, (tf_ordering)s->base.opts.ordering, 1, &ci);
        if (s->ldl == NULL) {
            return -1;
        }
    }
    double t;
    int rc = tf_chol_refactor(ctx, s->ldl, k, &t);
    s->st.factorisations++;
    s->st.indefinite++;
    s->st.t_factor += t;
    s->chol_ok = rc == 0;
    s->use_ldl = rc == 0;
    return rc;
}

/* solver.newton.indefinite: shift.  Cholesky factorisations of the tangent
 * with its diagonal raised by a factor 1 + sigma, sigma = SHIFT_FIRST x 4^k
 * (from a quarter of the last shift that worked), until one is positive
 * definite.  The step -(K + sigma diag K)^-1 r then goes downhill in
 * energy, and the line search takes it along: a Levenberg-Marquardt
 * damping of Newton's method, which crosses a snap-through to the stable
 * equilibrium beyond it, where the LDL^T path follows the unstable branch
 * (docs/solver.md; docs/validation.md §13).  Each failed attempt costs up
 * to a factorisation (CHOLMOD stops at the first non-positive pivot). */
#define SHIFT_FIRST 1e-3
#define SHIFT_TRIES 12 /* 1e-3 x 4^11 = 4.2e3: a matrix that still fails is not an elastic tangent */

static int factor_shifted(nl_solver *s)
{
    tf_ctx *ctx = s->base.ctx;
    size_t n = s->k.n;
    const int *cp = s->k.p; /* lower triangle, rows ascending: the diagonal first (csc.h) */
    for (size_t j = 0; j < n; ++j) {
        if (cp[j] == cp[j + 1] || (size_t)s->k.i[cp[j]] != j) {
            return tf_fail(ctx, "shifted tangent: column %zu has no diagonal entry", j);
        }
    }
    double *diag = malloc(n * sizeof *diag);
    if (diag == NULL) {
        return tf_fail(ctx, "out of memory");
    }
    for (size_t j = 0; j < n; ++j) {
        diag[j] = s->k.x[cp[j]];
    }
    double sigma = s->shift > 0 ? fmax(SHIFT_FIRST, 0.25 * s->shift) : SHIFT_FIRST;
    int rc = 1;
    for (int k = 0; k < SHIFT_TRIES && rc == 1; ++k, sigma *= 4) {
        for (size_t j = 0; j < n; ++j) {
            s->k.x[cp[j]] = diag[j] + sigma * fabs(diag[j]);
        }
        double t;
        rc = tf_chol_refactor(ctx, s->chol, nl_factored(s), &t);
        s->st.factorisations++;
        s->st.shifted++;
        s->st.t_factor += t;
        s->shift = rc == 0 ? sigma : s->shift;
    }
    for (size_t j = 0; j < n; ++j) { /* the tangent itself stays in s->k */
        s->k.x[cp[j]] = diag[j];
    }
    free(diag);
    s->chol_ok = rc == 0;
    s->shifted = rc == 0;
    return rc;
}

/* Modified Newton and BFGS only need some positive definite matrix near
 * the tangent: while they hold a Cholesky factor they factorise a new
 * tangent into a spare handle and keep the old factor when the new tangent
 * is not positive definite (an iterate past a limit point, often a
 * transient far from equilibrium).  An LDL^T factorisation (CHOLMOD's
 * simplicial one: at 41 x 41 x 9 one took 2,339 of a case's 2,481 s) is
 * only made when they ask again while the last attempt was indefinite:
 * the equilibrium itself may be past a limit point (St. Venant-Kirchhoff
 * compressed to half its length), where a positive definite matrix cannot
 * lead Newton's method. */
static int keeps_factor(const nl_solver *s)
{
    tf_tangent_kind k = s->base.opts.newton.tangent;
    if (k == TF_TANGENT_PATCH && s->patch.on) {
        /* the patch tangent keeps its factor through any number of
         * indefinite tangents: at 41 x 41 x 9 both bfgs and patch met two
         * in a row in the 3 N case and spent 14.5 and 9 CPU minutes in the
         * LDL^T before they were stopped; a failed load step still drops
         * the factor (nl_advance), and the retry factorises afresh */
        return s->chol_ok && !s->use_ldl;
    }
    return (k == TF_TANGENT_BFGS || k == TF_TANGENT_MODIFIED || k == TF_TANGENT_PATCH) &&
           s->chol_ok && !s->use_ldl && !s->indef_kept;
}

static int factor_into_spare(nl_solver *s, const tf_csc *k)
{
    tf_ctx *ctx = s->base.ctx;
    if (s->spare == NULL) {
        s->spare = tf_chol_twin(ctx, s->chol, k);
        if (s->spare == NULL) {
            return -1;
        }
    }
    double t;
    int rc = tf_chol_refactor(ctx, s->spare, k, &t);
    s->st.factorisations++;
    s->st.t_factor += t;
    if (rc == 1) { /* not positive definite: the old factor and its pairs stay */
        s->indef_kept = 1;
        s->st.kept++;
        return 0;
    }
    if (rc == 0) {
        tf_chol *c = s->chol;
        s->chol = s->spare;
        s->spare = c;
        s->chol_rest = 0;
        s->indef_kept = 0;
        s->shifted = 0;
        nl_qn_reset(s);
        return nl_patch_base(s);
    }
    return rc;
}

int nl_factor(nl_solver *s)
{
    tf_ctx *ctx = s->base.ctx;
    nl_eliminate(s);
    const tf_csc *k = nl_factored(s); /* gathered once for the analysis and the factorisation */
    if (keeps_factor(s)) {
        return factor_into_spare(s, k);
    }
    if (s->chol == NULL) {
        tf_ordering ord = (tf_ordering)s->base.opts.ordering;
        s->chol = s->patch.on ? tf_chol_analyse_last(ctx, k, ord, s->patch.dof, &s->ci)
                              : tf_chol_analyse(ctx, k, ord, 0, &s->ci);
        if (s->chol == NULL) {
            return -1;
        }
    }
    double t;
    int rc = tf_chol_refactor(ctx, s->chol, k, &t);
    s->st.factorisations++;
    s->st.t_factor += t;
    s->chol_ok = rc == 0;
    s->chol_rest = rc == 0 && s->k_rest;
    s->rest_guess = 0;
    s->use_ldl = 0;
    s->indef_kept = 0;
    s->shifted = 0;
    nl_qn_reset(s);
    if (rc == 0) {
        return nl_patch_base(s);
    }
    s->patch.base = 0;
    if (rc == 1 && s->base.opts.newton.indefinite == TF_INDEFINITE_SHIFT && !s->patch.on) {
        return factor_shifted(s);
    }
    return rc == 1 ? factor_indefinite(s, k) : rc;
}

/* Whether a case may start from the rest tangent's factor: nothing
 * prescribed but zeros (every case's first tangent is then the same), a
 * strategy that uses the factor alone (BFGS, modified Newton) and a
 * symmetric tangent (an unsymmetric one's first solve is GMRES on the
 * tangent itself). */
static int rest_factor_serves(const nl_solver *s)
{
    tf_tangent_kind k = s->base.opts.newton.tangent;
    if (s->patch.on || s->kskew != NULL || (k != TF_TANGENT_BFGS && k != TF_TANGENT_MODIFIED)) {
        return 0;
    }
    for (size_t i = 0; !s->weak && i < s->k.n; ++i) {
        if (s->bc.ubar[i] != 0) {
            return 0;
        }
    }
    for (size_t q = 0; s->weak && q < s->bnd.n; ++q) {
        const double *u = s->bnd.pt[q].ubar;
        if (u[0] != 0 || u[1] != 0 || u[2] != 0) {
            return 0;
        }
    }
    return 1;
}

/* The rest tangent assembled and factorised (the state is nl_reset's). */
static int factor_rest(nl_solver *s)
{
    nl_target rest = {0, -1, {0, 0, 0}};
    nl_fault fault;
    int rc = nl_assemble(s, s->d, &rest, s->dt_relaxed, 1, s->r, NULL, &fault);
    if (rc == 0) {
        nl_eliminate(s);
        rc = nl_factor(s);
    }
    return rc == 0 && s->chol_rest && !s->use_ldl && !s->shifted ? 0 : rc < 0 ? -1 : 1;
}

int nl_factor_for_rest(nl_solver *s, int from_rest)
{
    int held = s->chol_ok && s->chol_rest && !s->use_ldl && !s->shifted;
    s->chol_ok = 0;
    s->rest_factor = 0;
    s->indef_kept = 0;
    nl_qn_reset(s);
    if (!rest_factor_serves(s)) {
        return 0;
    }
    if (!held && !from_rest) {
        int rc = factor_rest(s);
        if (rc != 0) {
            s->chol_ok = 0;
            return rc < 0 ? -1 : 0;
        }
        held = 1;
    }
    s->chol_ok = held;
    s->rest_factor = held;
    s->rest_guess = held && !from_rest;
    return 0;
}

void nl_qn_reset(nl_solver *s) { s->qn = 0; }

void nl_qn_update(nl_solver *s, const double *step, const double *dr)
{
    size_t n = s->k.n;
    if (s->qmax == 0) {
        return;
    }
    double ys = dot(dr, step, n);
    if (!(ys > 1e-12 * sqrt(dot(dr, dr, n) * dot(step, step, n)))) {
        return; /* no curvature along the step: the pair would spoil H */
    }
    if (s->qn == s->qmax) { /* drop the oldest */
        memmove(s->qs, s->qs + n, (s->qmax - 1) * n * sizeof *s->qs);
        memmove(s->qy, s->qy + n, (s->qmax - 1) * n * sizeof *s->qy);
        memmove(s->qrho, s->qrho + 1, (s->qmax - 1) * sizeof *s->qrho);
        s->qn--;
    }
    memcpy(s->qs + s->qn * n, step, n * sizeof *step);
    memcpy(s->qy + s->qn * n, dr, n * sizeof *dr);
    s->qrho[s->qn++] = 1 / ys;
}

static tf_chol *factor_of(nl_solver *s)
{
    return s->use_ldl ? s->ldl : s->chol;
}

static int precondition(nl_solver *s, const double *r, double *z)
{
    return tf_chol_solve(s->base.ctx, factor_of(s), r, z, 1);
}

/* Limited-memory BFGS (Nocedal's two-loop recursion, the last factorisation
 * as the initial inverse; Matthies & Strang 1979 for finite elements):
 * x = H b. */
static int bfgs(nl_solver *s, const double *b, double *x)
{
    size_t n = s->k.n, m = s->qn;
    double alpha[64], *q = malloc(n * sizeof *q);
    if (q == NULL) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    memcpy(q, b, n * sizeof *q);
    for (size_t i = m; i-- > 0;) {
        alpha[i] = s->qrho[i] * dot(s->qs + i * n, q, n);
        for (size_t k = 0; k < n; ++k) {
            q[k] -= alpha[i] * s->qy[i * n + k];
        }
    }
    int rc = precondition(s, q, x);
    free(q);
    if (rc != 0) {
        return -1;
    }
    for (size_t i = 0; i < m; ++i) {
        double beta = s->qrho[i] * dot(s->qy + i * n, x, n);
        for (size_t k = 0; k < n; ++k) {
            x[k] += s->qs[i * n + k] * (alpha[i] - beta);
        }
    }
    return 0;
}

void nl_tangent_apply(const nl_solver *s, const double *x, double *y)
{
    const tf_csc *k = &s->k;
    tf_csc_symv(k, x, y, 1);
    if (s->kskew == NULL) {
        return;
    }
    for (size_t j = 0; j < k->n; ++j) {
        for (int q = k->p[j]; q < k->p[j + 1]; ++q) {
            size_t i = (size_t)k->i[q];
            y[i] += s->kskew[q] * x[j];
            y[j] -= s->kskew[q] * x[i];
        }
    }
}

/* Preconditioned conjugate gradients for K x = b, x = 0 first.  Returns the
 * iterations (> 0) on convergence, 0 when it did not converge in max, -1
 * on a failure. */
static int pcg(nl_solver *s, const double *b, double *x, unsigned max)
{
    size_t n = s->k.n;
    double *r = s->wk, *z = r + n, *p = z + n, *q = p + n;
    memcpy(r, b, n * sizeof *r);
    memset(x, 0, n * sizeof *x);
    double bn = sqrt(dot(b, b, n));
    if (bn == 0) {
        return 1;
    }
    if (precondition(s, r, z) != 0) {
        return -1;
    }
    memcpy(p, z, n * sizeof *p);
    double rz = dot(r, z, n);
    for (unsigned it = 1; it <= max; ++it) {
        nl_tangent_apply(s, p, q);
        double pq = dot(p, q, n);
        if (!(pq > 0)) {
            return 0; /* the tangent is not positive definite here */
        }
        double alpha = rz / pq;
        for (size_t i = 0; i < n; ++i) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
        }
        s->st.krylov++;
        if (sqrt(dot(r, r, n)) <= KRYLOV_RTOL * bn) {
            return (int)it;
        }
        if (precondition(s, r, z) != 0) {
            return -1;
        }
        double rz1 = dot(r, z, n), beta = rz1 / rz;
        rz = rz1;
        for (size_t i = 0; i < n; ++i) {
            p[i] = z[i] + beta * p[i];
        }
    }
    return 0;
}

/* Restarted GMRES, right-preconditioned (K M^-1 y = b, x = M^-1 y), for
 * the unsymmetric tangent.  Returns as pcg. */
static int gmres(nl_solver *s, const double *b, double *x, unsigned max)
{
    size_t n = s->k.n, m = GMRES_RESTART < s->wk_cols ? GMRES_RESTART : s->wk_cols - 1;
    double *v = s->wk, *w = v + (m + 1) * n, *z = w + n;
    double h[(GMRES_RESTART + 1) * GMRES_RESTART], cs[GMRES_RESTART], sn[GMRES_RESTART],
        g[GMRES_RESTART + 1], y[GMRES_RESTART];
    double bn = sqrt(dot(b, b, n));
    memset(x, 0, n * sizeof *x);
    if (bn == 0) {
        return 1;
    }
    unsigned it = 0;
    while (it < max) {
        /* r = b - K x */
        nl_tangent_apply(s, x, w);
        for (size_t i = 0; i < n; ++i) {
            v[i] = b[i] - w[i];
        }
        double beta = sqrt(dot(v, v, n));
        if (beta <= KRYLOV_RTOL * bn) {
            return (int)(it > 0 ? it : 1);
        }
        for (size_t i = 0; i < n; ++i) {
            v[i] /= beta;
        }
        memset(g, 0, sizeof g);
        g[0] = beta;
        size_t k = 0;
        for (; k < m && it < max; ++k, ++it) {
            double *vk = v + k * n, *vn = v + (k + 1) * n;
            if (precondition(s, vk, z) != 0) {
                return -1;
            }
            nl_tangent_apply(s, z, vn);
            s->st.krylov++;
            for (size_t j = 0; j <= k; ++j) { /* modified Gram-Schmidt */
                double hj = dot(vn, v + j * n, n);
                h[j + (m + 1) * k] = hj;
                for (size_t i = 0; i < n; ++i) {
                    vn[i] -= hj * v[j * n + i];
                }
            }
            double hn = sqrt(dot(vn, vn, n));
            h[k + 1 + (m + 1) * k] = hn;
            for (size_t i = 0; hn > 0 && i < n; ++i) {
                vn[i] /= hn;
            }
            for (size_t j = 0; j < k; ++j) { /* Givens rotations */
                double a = h[j + (m + 1) * k], c = h[j + 1 + (m + 1) * k];
                h[j + (m + 1) * k] = cs[j] * a + sn[j] * c;
                h[j + 1 + (m + 1) * k] = -sn[j] * a + cs[j] * c;
            }
            double a = h[k + (m + 1) * k], c = h[k + 1 + (m + 1) * k], rr = hypot(a, c);
            cs[k] = rr > 0 ? a / rr : 1;
            sn[k] = rr > 0 ? c / rr : 0;
            h[k + (m + 1) * k] = rr;
            h[k + 1 + (m + 1) * k] = 0;
            g[k + 1] = -sn[k] * g[k];
            g[k] = cs[k] * g[k];
            if (fabs(g[k + 1]) <= KRYLOV_RTOL * bn) {
                ++k;
                ++it;
                break;
            }
        }
        for (size_t j = k; j-- > 0;) { /* back substitution */
            double t = g[j];
            for (size_t l = j + 1; l < k; ++l) {
                t -= h[j + (m + 1) * l] * y[l];
            }
            y[j] = t / h[j + (m + 1) * j];
        }
        memset(w, 0, n * sizeof *w);
        for (size_t j = 0; j < k; ++j) {
            for (size_t i = 0; i < n; ++i) {
                w[i] += y[j] * v[j * n + i];
            }
        }
        if (precondition(s, w, z) != 0) {
            return -1;
        }
        for (size_t i = 0; i < n; ++i) {
            x[i] += z[i];
        }
        if (k > 0 && fabs(g[k]) <= KRYLOV_RTOL * bn) {
            return (int)it;
        }
    }
    return 0;
}

/* Krylov on the current tangent; 1 on convergence. */
static int krylov(nl_solver *s, const double *b, double *x, int *failed)
{
    unsigned max = s->base.opts.newton.krylov_max;
    int it = s->kskew ? gmres(s, b, x, max) : pcg(s, b, x, max);
    *failed = it < 0;
    return it > 0;
}

int nl_linear_solve(nl_solver *s, const double *r, double *du, int fresh_tangent)
{
    tf_ctx *ctx = s->base.ctx;
    size_t n = s->k.n;
    tf_tangent_kind kind = s->base.opts.newton.tangent;
    double t0 = omp_get_wtime();
    double *b = s->rtrial; /* -r (fixed DOFs zero) */
    for (size_t i = 0; i < n; ++i) {
        b[i] = s->weak || !s->bc.fixed[i] ? -r[i] : 0;
    }
    int rc = 0;
    if (fresh_tangent == NL_TANGENT_PATCH) {
        /* the block of the factor near the contact: the old one stays when
         * the new is not positive definite (an iterate far from
         * equilibrium; BFGS's refresh rule still watches the progress).
         * BFGS's pairs are kept: a changing initial matrix, as in L-BFGS
         * with a scaled one; forgetting them at each update (as at a
         * refactorisation) took 42 iterations and 4 factorisations at
         * 21 x 21 x 5 against 26 and 2 (docs/validation.md §13). */
        (void)nl_patch_update(s);
        fresh_tangent = NL_TANGENT_NONE;
    }
    if (fresh_tangent) {
        nl_eliminate(s);
    }
    /* Krylov refactorises a fresh tangent only when its factor is no
     * preconditioner of it: none, shifted, or the LDL^T of an earlier
     * indefinite one (kept, it led a solve started past stability to
     * invert the body: test_indefinite.c) */
    if (fresh_tangent &&
        (kind != TF_TANGENT_KRYLOV || !s->chol_ok || s->shifted || s->use_ldl)) {
        rc = nl_factor(s); /* full Newton; modified and BFGS assemble only to refactorise */
    } else if (!s->chol_ok) {
        rc = 1;
    }
    if (rc != 0) {
        s->st.t_solve += omp_get_wtime() - t0;
        return rc;
    }
    int done = 0, failed = 0;
    /* (a shifted factor is used as it is: the tangent it stands for is
     * indefinite, where CG has no descent to offer) */
    if (fresh_tangent && !s->use_ldl && !s->shifted &&
        (kind == TF_TANGENT_KRYLOV || s->kskew != NULL)) {
        done = krylov(s, b, du, &failed);
        if (!done && !failed && kind == TF_TANGENT_KRYLOV) {
            /* the old factor no longer helps: refactorise and try again */
            rc = nl_factor(s);
            done = rc == 0 && krylov(s, b, du, &failed);
        }
    } else if ((kind == TF_TANGENT_BFGS || kind == TF_TANGENT_PATCH) && s->qn > 0) {
        failed = bfgs(s, b, du) != 0;
        done = !failed;
    } else {
        failed = tf_chol_solve(ctx, factor_of(s), b, du, 1) != 0;
        done = !failed;
    }
    s->st.t_solve += omp_get_wtime() - t0;
    if (failed) {
        return -1;
    }
    if (rc > 0 || !done) {
        return rc > 0 ? rc : 1;
    }
    for (size_t i = 0; !s->weak && i < n; ++i) {
        du[i] = s->bc.fixed[i] ? 0 : du[i];
    }
    return 0;
}
