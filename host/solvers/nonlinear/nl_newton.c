/*
 * nl_newton.c — Newton-Raphson with load stepping, step cutting and a line
 * search (nl_internal.h).
 *
 * A load step goes from the state's target to a fraction of the way to the
 * next one (load factor, contact force, and for the Kelvin laws the time,
 * all linear in between).  Each step iterates
 *     K(d) du = -r(d),  d <- d + eta du
 * until the residual is small against the internal forces AND the energy
 * of the correction |du . r| is small against the step's first one (both
 * criteria of e.g. Bathe, Finite Element Procedures, §8.4.3).  eta = 1
 * unless s(eta) = du . r(d + eta du) has not fallen to half of s(0): then
 * secant steps on s (Bonet & Wood, Nonlinear Continuum Mechanics for FEA,
 * §7.4.4).  A step that does not converge within the iterations, inverts a
 * point (J <= 0) or meets a tangent that is not positive definite is
 * halved, down to the first step size / 2^max_cuts; a step that converges
 * in three iterations or fewer lets the next one double.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/progress.h"
#include "solvers/nonlinear/nl_internal.h"

/* Seconds between progress lines of one force's load steps. */
#define NL_PROGRESS_S 5.0
#define LS_RATIO 0.5
#define LS_TRIALS 6
/* Rounding floor: a tiny load (the small-load limit) leaves a residual of
 * about 1e-8 of the forces that no iteration removes (J - 1 from det F in
 * the laws, times a bulk modulus fifty times the shear one).  Once the
 * correction's energy is below ROUNDING_ENERGY of the first and the
 * residual has stopped falling, the iteration has converged as far as the
 * arithmetic allows: with the residual within the tolerance, when it fell
 * by less than half in the last iteration; above it, only when it has not
 * come below the smallest of the step's earlier iterations
 * STALL_ITERATIONS times in a row (BFGS with an older factor converges
 * linearly with bumps, and the first rule alone stopped it at 1.2e-7 of
 * the forces). */
#define ROUNDING_ENERGY 1e-14
#define STALL_ITERATIONS 3

enum { WHY_ITER = 1, WHY_INVERTED, WHY_INDEFINITE };

/* Why the last step failed, for the message. */
typedef struct step_fail {
    int why;
    nl_fault fault;
    double rnorm, ref;
    size_t node;
} step_fail;

static double norm(const double *v, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += v[i] * v[i];
    }
    return sqrt(s);
}

static double dot(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; ++i) {
        s += a[i] * b[i];
    }
    return s;
}

void nl_reset(nl_solver *s)
{
    size_t n3 = 3 * s->sh.cloud->n;
    memset(s->d, 0, n3 * sizeof *s->d);
    memset(s->hist, 0, s->ncell * s->np * s->hb * sizeof *s->hist);
    memset(s->bhist, 0, s->bnd.n * s->nh * sizeof *s->bhist);
    s->at = (nl_target){0, -1, {0, 0, 0}};
    s->eager = 0;
    s->rest_guess = 0;
    s->shift = 0; /* (a case depends on its own start alone: nonlinear.c, solve) */
}

/* Residual r(d) = internal + boundary - external, fixed DOFs zeroed; the
 * reference |forces| in *ref.  Returns as nl_assemble. */
static int residual(nl_solver *s, const double *d, const nl_target *t, double dt, int tangent,
                    const double *fext, double *r, double *ref, nl_fault *fault)
{
    size_t n3 = 3 * s->sh.cloud->n;
    int rc = nl_assemble(s, d, t, dt, tangent, r, s->fint, fault);
    if (rc != 0) {
        return rc;
    }
    for (size_t i = 0; i < n3; ++i) {
        r[i] -= fext[i];
        if (!s->weak && s->bc.fixed[i]) {
            r[i] = 0;
        }
    }
    *ref = fmax(norm(fext, n3), norm(s->fint, n3));
    return 0;
}

/* Line search along du from d with s0 = du . r(d) < 0; leaves the accepted
 * point in s->dtrial and its residual in rt (the last evaluated).  Returns
 * 0, 1 (every trial inverts a point), -1. */
static int line_search(nl_solver *s, const double *d, const double *du, double s0,
                       const nl_target *t, double dt, const double *fext, double *rt,
                       double *ref, nl_fault *fault)
{
    size_t n3 = 3 * s->sh.cloud->n;
    double eta = 1, best_eta = 1, best = INFINITY, prev_eta = 0, prev_s = s0;
    for (int trial = 0; trial < LS_TRIALS; ++trial) {
        for (size_t i = 0; i < n3; ++i) {
            s->dtrial[i] = d[i] + eta * du[i];
        }
        int rc = residual(s, s->dtrial, t, dt, 0, fext, rt, ref, fault);
        if (rc < 0) {
            return -1;
        }
        if (rc == 1) { /* inverted: shorter */
            eta *= 0.5;
            continue;
        }
        double se = dot(du, rt, n3);
        if (fabs(se) < best) {
            best = fabs(se);
            best_eta = eta;
        }
        if (fabs(se) <= LS_RATIO * fabs(s0)) {
            return 0;
        }
        /* secant on s(eta) through the last two points, kept in (0.05, 1] */
        double next = se != prev_s ? eta - se * (eta - prev_eta) / (se - prev_s) : 0.5 * eta;
        prev_eta = eta;
        prev_s = se;
        eta = fmin(1.0, fmax(0.05, next));
    }
    if (!isfinite(best)) {
        return 1;
    }
    for (size_t i = 0; i < n3; ++i) {
        s->dtrial[i] = d[i] + best_eta * du[i];
    }
    return residual(s, s->dtrial, t, dt, 0, fext, rt, ref, fault);
}

/* BFGS refactorises BFGS_PATIENCE iterations after its last factorisation
 * at the earliest, and only when the correction's energy fell by less than
 * a factor BFGS_STALL in the last iteration.  On the 3 N neo-Hookean
 * block48 case (docs/validation.md §13) a tangent assembly and
 * factorisation cost about as much as 10 (21 x 21 x 5) to 35 (41 x 41 x 9)
 * BFGS iterations, so a refresh must save that many; measured (patience,
 * stall): (4, 0.5) 3 factorisations and 22 iterations at 21 x 21 x 5, 4 and
 * 34 at 31 x 31 x 7; (10, 0.9) 2 and 30, 3 and 33.  Once a step of the
 * case has failed (a cut), the quicker rule (4, 0.5) again: the patient
 * one failed test_homogeneous.c's cubes, whose steps are cut near a limit
 * point. */
#define BFGS_PATIENCE 10
#define BFGS_STALL 0.9
/* From a guess on the rest tangent's factor (nl_factor_for_rest), a tangent
 * at the iterate after this many iterations: the pairs there may converge
 * steadily but linearly (the liver with its nodule, 15,222 nodes: 14 to 30
 * iterations to the energy tolerance, some cases beyond the 50 allowed,
 * then solved again from rest).  A tangent and its factorisation cost
 * there as much as about 18 iterations (46 s against 2.5 s; on the liver
 * without the nodule 40), so a tangent at 10 iterations cost more than it
 * saved. */
#define BFGS_GUESS_PATIENCE 25

/* Does this iteration assemble a tangent?  Full Newton and Krylov always.
 * Modified Newton and BFGS keep their factorisation while it pays: they
 * assemble (and refactorise) when they have none, or when, at least
 * `patience` iterations after the last one, the correction's energy fell
 * by less than `rate` in the last iteration (the residual itself is no
 * guide: far from the solution it may grow while the energy falls).  BFGS
 * learns the change of the tangent from its steps and is more patient, but
 * not past a limit point: its updates assume a positive definite tangent,
 * so while the factorisation is the LDL^T of an indefinite one it takes
 * full Newton steps (St. Venant-Kirchhoff compressed to half its length
 * missed the closed form by 2e-8 otherwise, above test_homogeneous.c's
 * 1e-9).  An indefinite tangent met while a Cholesky factor is held does
 * not get that LDL^T at once (nl_linear.c: keeps_factor). */
static int wants_tangent(const nl_solver *s, unsigned since, double ratio_e)
{
    tf_tangent_kind k = s->base.opts.newton.tangent;
    if (k == TF_TANGENT_MODIFIED) {
        return !s->chol_ok || (since >= 2 && ratio_e > 0.25);
    }
    if (k == TF_TANGENT_BFGS || k == TF_TANGENT_PATCH) {
        int all;
        if (s->eager) { /* a step failed in this case: main's quicker rule */
            all = !s->chol_ok || s->use_ldl || (since >= 4 && ratio_e > 0.5);
        } else {
            all = !s->chol_ok || s->use_ldl ||
                  (since >= BFGS_PATIENCE && ratio_e > BFGS_STALL) ||
                  (s->rest_guess && since >= BFGS_GUESS_PATIENCE);
        }
        /* the patch tangent: the factor's block near the contact every
         * iteration that does not refactorise */
        if (s->patch.on && s->patch.base && !all) {
            return NL_TANGENT_PATCH;
        }
        return all ? NL_TANGENT_ALL : NL_TANGENT_NONE;
    }
    return NL_TANGENT_ALL;
}

/* Newton iterations for one load step from s->d.  Returns 0 (converged:
 * s->d updated, histories in the _new arrays), 1 (failed: f says why),
 * -1 (a message in the context). */
static int newton(nl_solver *s, const nl_target *t, double dt, unsigned *iters, step_fail *f)
{
    size_t n3 = 3 * s->sh.cloud->n;
    const tf_newton_opts *o = &s->base.opts.newton;
    double *fext = malloc(n3 * sizeof *fext), *d = malloc(n3 * sizeof *d);
    double *rt = malloc(n3 * sizeof *rt), *qs = NULL, *qy = NULL;
    int quasi = o->tangent == TF_TANGENT_BFGS || o->tangent == TF_TANGENT_PATCH;
    if (quasi) {
        qs = malloc(n3 * sizeof *qs);
        qy = malloc(n3 * sizeof *qy);
    }
    if (!fext || !d || !rt || (quasi && (!qs || !qy))) {
        free(fext);
        free(d);
        free(rt);
        free(qs);
        free(qy);
        return tf_fail(s->base.ctx, "out of memory");
    }
    nl_external(s, t, fext);
    memcpy(d, s->d, n3 * sizeof *d);
    for (size_t i = 0; !s->weak && i < n3; ++i) {
        if (s->bc.fixed[i]) {
            d[i] = t->scale * s->bc.ubar[i];
        }
    }
    double e0 = 0, e = 0, e_prev = 0, ref = 0, rn = 0, least = INFINITY;
    unsigned since = 0, flat = 0;
    int have_r = 0, rc = 0, conv = 0;
    unsigned it;
    tf_progress pr; /* one load step of an organ's finest clouds can take minutes */
    tf_progress_start(&pr, s->base.ctx, NL_PROGRESS_S);
    for (it = 0; it <= o->max_iter; ++it) {
        int tangent = it < o->max_iter ? wants_tangent(s, since, e_prev > 0 ? e / e_prev : 0)
                                       : NL_TANGENT_NONE;
        double before = rn;
        least = it > 0 ? fmin(least, rn) : least; /* of the earlier iterations */
        /* (the rest tangent's factor kept for this case counts as made now) */
        since = tangent == NL_TANGENT_ALL || (it == 0 && s->rest_factor) ? 0 : since + 1;
        s->rest_factor = 0;
        if (!have_r || tangent == NL_TANGENT_ALL) {
            rc = residual(s, d, t, dt, tangent == NL_TANGENT_ALL, fext, s->r, &ref, &f->fault);
        } else {
            memcpy(s->r, rt, n3 * sizeof *rt);
        }
        if (rc != 0) {
            f->why = WHY_INVERTED;
            break;
        }
        rn = norm(s->r, n3);
        tf_progress_line(&pr, "newton: iteration %u, residual %.3g (tolerance %.3g)", it, rn,
                         o->rtol * ref);
        int at_floor = it >= 2 && e <= ROUNDING_ENERGY * e0;
        flat = at_floor && rn >= least ? flat + 1 : 0;
        int stalled = at_floor && ((rn <= o->rtol * ref && rn > 0.5 * before) ||
                                   flat >= STALL_ITERATIONS);
        if ((rn <= o->rtol * ref && (it == 0 || e <= o->etol * e0)) || stalled) {
            conv = 1;
            break;
        }
        if (it == o->max_iter) {
            break;
        }
        rc = tangent == NL_TANGENT_PATCH ? nl_assemble_patch(s, d, dt, &f->fault) : 0;
        if (rc != 0) {
            f->why = WHY_INVERTED;
            break;
        }
        rc = nl_linear_solve(s, s->r, s->du, tangent);
        if (rc != 0) {
            f->why = WHY_INDEFINITE;
            break;
        }
        /* a new factor for the patch tangent: its cells' tangent at d */
        rc = s->patch.want_k0 ? nl_patch_k0(s, d, dt, &f->fault) : 0;
        if (rc != 0) {
            f->why = WHY_INVERTED;
            break;
        }
        double s0 = dot(s->du, s->r, n3);
        e_prev = it > 0 ? e : 0;
        e = fabs(s0);
        if (it == 0 || e0 == 0) {
            e0 = e;
        }
        if (e <= ROUNDING_ENERGY * e0) { /* no line search in the rounding noise */
            for (size_t i = 0; i < n3; ++i) {
                s->dtrial[i] = d[i] + s->du[i];
            }
            rc = residual(s, s->dtrial, t, dt, 0, fext, rt, &ref, &f->fault);
        } else {
            rc = line_search(s, d, s->du, s0, t, dt, fext, rt, &ref, &f->fault);
        }
        if (rc != 0) {
            f->why = WHY_INVERTED;
            break;
        }
        for (size_t i = 0; qs && i < n3; ++i) {
            qs[i] = s->dtrial[i] - d[i];
            qy[i] = rt[i] - s->r[i];
        }
        if (qs) {
            nl_qn_update(s, qs, qy);
        }
        memcpy(d, s->dtrial, n3 * sizeof *d);
        have_r = 1;
        s->st.iterations++;
    }
    *iters = it;
    if (conv) {
        memcpy(s->d, d, n3 * sizeof *d);
    } else if (rc >= 0) {
        if (f->why == 0 || rc == 0) {
            f->why = WHY_ITER;
        }
        f->rnorm = rn;
        f->ref = ref;
        size_t worst = 0;
        for (size_t i = 0; i < n3; ++i) {
            worst = fabs(s->r[i]) > fabs(s->r[worst]) ? i : worst;
        }
        f->node = worst / 3;
        rc = 1;
    }
    free(fext);
    free(d);
    free(rt);
    free(qs);
    free(qy);
    return conv ? 0 : rc;
}

static void commit(nl_solver *s, const nl_target *t)
{
    double *h = s->hist;
    s->hist = s->hist_new;
    s->hist_new = h;
    h = s->bhist;
    s->bhist = s->bhist_new;
    s->bhist_new = h;
    s->at = *t;
}

static nl_target between(const nl_target *a, const nl_target *b, double th)
{
    nl_target t = {a->scale + th * (b->scale - a->scale), b->contact, {0, 0, 0}};
    for (int k = 0; k < 3; ++k) {
        t.force[k] = a->force[k] + th * (b->force[k] - a->force[k]);
    }
    return t;
}

static int give_up(nl_solver *s, const step_fail *f, size_t step, double th,
                   const nl_target *t)
{
    char where[160] = "";
    if (t->contact >= 0) {
        snprintf(where, sizeof where, ", force (%g, %g, %g) N at %s", t->force[0], t->force[1],
                 t->force[2], s->base.problem->contacts[t->contact].name);
    }
    unsigned cuts = s->base.opts.newton.max_cuts;
    if (f->why == WHY_INVERTED) {
        return tf_fail(s->base.ctx,
                       "%s: load step %zu (%.4g of the way, load factor %g%s): J = %.3g <= 0 at "
                       "the quadrature point (%g, %g, %g) mm after %u step cuts: the body "
                       "inverts there",
                       s->base.problem->name, step, th, t->scale, where, f->fault.j,
                       f->fault.x[0], f->fault.x[1], f->fault.x[2], cuts);
    }
    if (f->why == WHY_INDEFINITE) {
        return tf_fail(s->base.ctx,
                       "%s: load step %zu (%.4g of the way, load factor %g%s): the tangent "
                       "stiffness is not positive definite after %u step cuts (a limit point, "
                       "buckling, or a body not held)",
                       s->base.problem->name, step, th, t->scale, where, cuts);
    }
    return tf_fail(s->base.ctx,
                   "%s: load step %zu (%.4g of the way, load factor %g%s): Newton's method did "
                   "not converge in %u iterations after %u step cuts (residual %.3g N against "
                   "forces of %.3g N, largest at node %zu)",
                   s->base.problem->name, step, th, t->scale, where,
                   s->base.opts.newton.max_iter, cuts, f->rnorm, f->ref,
                   (size_t)tf_problem_node_number(s->base.problem, f->node));
}

int nl_advance(nl_solver *s, const nl_target *to, double dt)
{
    const tf_newton_opts *o = &s->base.opts.newton;
    size_t n3 = 3 * s->sh.cloud->n;
    nl_target from = s->at;
    if (from.contact != to->contact) {
        from.contact = to->contact; /* (the state's force acts at another site only if 0) */
    }
    double *saved = malloc(n3 * sizeof *saved);
    if (saved == NULL) {
        return tf_fail(s->base.ctx, "out of memory");
    }
    double th = 0, step = 1.0 / (o->steps > 0 ? o->steps : 1);
    double smallest = ldexp(step, -(int)o->max_cuts);
    size_t k = 0, halved = 0;
    int rc = 0;
    tf_progress pr; /* one force's load steps can take minutes (a soft law near its limit) */
    tf_progress_start(&pr, s->base.ctx, NL_PROGRESS_S);
    while (th < 1 && rc == 0) {
        double dth = fmin(step, 1 - th);
        if (1 - (th + dth) < 1e-12) {
            dth = 1 - th;
        }
        nl_target t = between(&from, to, th + dth);
        double sdt = dt < 0 ? s->dt_relaxed : dth * dt;
        step_fail f = {0};
        unsigned iters = 0;
        memcpy(saved, s->d, n3 * sizeof *saved);
        rc = newton(s, &t, sdt, &iters, &f);
        k++;
        if (rc == 0) {
            commit(s, &t);
            th += dth;
            s->st.steps++;
            step = iters <= 3 ? fmin(2 * dth, 1.0) : dth;
        } else if (rc == 1 && 0.5 * dth >= smallest * (1 - 1e-12)) {
            memcpy(s->d, saved, n3 * sizeof *saved);
            s->eager = 1;
            if (s->indef_kept) {
                /* the kept factor did not lead to equilibrium: the next try
                 * factorises its first tangent afresh (LDL^T if indefinite) */
                s->chol_ok = 0;
            }
            s->st.cuts++;
            halved++;
            step = 0.5 * dth;
            rc = 0;
        } else if (rc == 1) {
            memcpy(s->d, saved, n3 * sizeof *saved);
            rc = give_up(s, &f, k, th + dth, &t);
        }
        if (rc == 0) {
            tf_progress_line(&pr, "newton: %.4g of the load reached after %zu load steps tried (%zu halved)",
                             th, k, halved);
        }
    }
    free(saved);
    return rc;
}

int nl_polish(nl_solver *s, const nl_target *t, double dt)
{
    step_fail f = {0};
    unsigned iters = 0;
    int rc = newton(s, t, dt < 0 ? s->dt_relaxed : dt, &iters, &f);
    if (rc == 0) {
        commit(s, t);
        s->st.steps++;
    }
    return rc;
}
