/*
 * test_lm.c — the Levenberg–Marquardt core's stopping rules and guards:
 * a trial with a NaN residual, a step across a valley with no gain, a flat
 * valley where the relative reduction is small but the model was wrong, a
 * wall of non-finite residuals, budgets and callbacks; and box bounds.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "assert_close.h"
#include "numerics/lsfit.h"
#include "numerics/lm.h"
#include "numerics/lsq.h"
#include "base/rng.h"

/* A one-parameter problem with a trace of the points it was evaluated at. */
typedef struct trace {
    double k;          /* constant residual added as r[1] when m = 2 */
    double target;
    double b[256];     /* evaluation points, in order */
    double cost[256];
    size_t n;
    size_t nonfinite;  /* evaluations that returned a non-finite residual */
    size_t fail_after; /* callback returns 1 after this many calls (0: never) */
} trace;

static void record(trace *t, double b, const double *r, size_t m)
{
    double c = 0;
    for (size_t i = 0; i < m; ++i) {
        c += r[i] * r[i];
    }
    if (t->n < 256) {
        t->b[t->n] = b;
        t->cost[t->n] = c;
    }
    ++t->n;
    t->nonfinite += !isfinite(c);
}

/* r = sqrt(b) - sqrt(target): NaN for b < 0. */
static int sqrt_residual(void *ctx, const double *b, double *r)
{
    trace *t = ctx;
    r[0] = sqrt(b[0]) - sqrt(t->target);
    record(t, b[0], r, 1);
    return 0;
}

static int sqrt_jacobian(void *ctx, const double *b, double *j)
{
    (void)ctx;
    j[0] = 0.5 / sqrt(b[0]);
    return 0;
}

static tf_lm_options options(double factor)
{
    tf_lm_options o;
    tf_lm_default_options(&o, 1);
    o.factor = factor;
    return o;
}

/* Solves a one-parameter problem of m residuals from *b with a first trust
 * region `factor` and ftol (0: the default). */
static tf_lm_result solve1(size_t m, tf_lm_residual_fn r, tf_lm_jacobian_fn j, trace *t,
                           double factor, double ftol, double *b)
{
    tf_lm_problem pb = {m, 1, r, j, t, NULL, NULL, 0};
    tf_lm_options o = options(factor);
    if (ftol > 0) {
        o.ftol = ftol;
    }
    tf_lm_result res = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, b, &res), 0);
    return res;
}

static void nan_trial_is_rejected(void **state)
{
    (void)state;
    /* From b = 4 the Gauss-Newton step lands at b = -2 (factor 100 lets the
     * first trial be the full step): sqrt(-2) is NaN. */
    trace t = {.target = 0.25};
    double b = 4;
    tf_lm_result res = solve1(1, sqrt_residual, sqrt_jacobian, &t, 100, 0, &b);
    assert_true(t.nonfinite >= 1);
    assert_close(t.b[1], -2.0, 1e-12);
    assert_true(tf_stop_converged(res.stop));
    assert_close(b, 0.25, 1e-12);
    assert_true(isfinite(res.rss) && res.rss < 1e-24);
}

/* r = b + 1 on b >= 0, NaN below: the least-squares minimum lies beyond the
 * edge of the model's domain. */
static int wall_residual(void *ctx, const double *b, double *r)
{
    trace *t = ctx;
    r[0] = b[0] >= 0 ? b[0] + 1 : NAN;
    record(t, b[0], r, 1);
    return 0;
}

static void nonfinite_wall_is_not_convergence(void **state)
{
    (void)state;
    trace t = {0};
    double b = 1;
    /* A small first region (factor 0.01) so that the fit walks up to the
     * wall in many accepted steps, and a loose ftol: near the wall the
     * non-finite trials squeeze the trust region, every accepted step is
     * then small, with a small predicted and actual reduction and a perfect
     * ratio (r is linear).  Only the Gauss-Newton reduction (here 1: r is
     * parallel to J) shows that this is no minimum. */
    tf_lm_result res = solve1(1, wall_residual, NULL, &t, 0.01, 1e-3, &b);
    assert_int_equal(res.stop, TF_STOP_NONFINITE);
    assert_false(tf_stop_converged(res.stop));
    assert_true(t.nonfinite >= 2 && res.iterations >= 5);
    assert_true(b >= 0 && b < 1e-6); /* the best finite point, at the edge */
    assert_true(res.evals < options(1).max_evals); /* stopped by itself */
}

static void nonfinite_start_is_reported(void **state)
{
    (void)state;
    trace t = {0};
    double b = -1;
    tf_lm_result res = solve1(1, wall_residual, NULL, &t, 1, 0, &b);
    assert_int_equal(res.stop, TF_STOP_BAD_START);
    assert_true(isnan(res.rss));
    assert_int_equal(res.evals, 1);
}

/* ------------------------------------------------------------------------ */
/* r = [sin b] or [k, sin b].  From b0 with tan b0 = 2 b0 the Gauss-Newton
 * step b0 - tan b0 lands exactly on -b0, across the valley at b = 0, with
 * the same cost: an actual reduction of 0. */

static int sin_residual(void *ctx, const double *b, double *r)
{
    trace *t = ctx;
    size_t m = t->k != 0 ? 2 : 1;
    r[0] = sin(b[0]);
    if (m == 2) {
        r[1] = t->k;
    }
    record(t, b[0], r, m);
    return 0;
}

static int sin_jacobian(void *ctx, const double *b, double *j)
{
    trace *t = ctx;
    j[0] = cos(b[0]);
    if (t->k != 0) {
        j[1] = 0;
    }
    return 0;
}

static double mirror_point(void)
{
    double b = 1.2;
    for (int i = 0; i < 60; ++i) {
        double c = cos(b);
        b -= (tan(b) - 2 * b) / (1 / (c * c) - 2);
    }
    return b;
}

static void step_across_valley_is_not_convergence(void **state)
{
    (void)state;
    const double b0 = mirror_point();
    trace t = {0};
    double b = b0;
    tf_lm_result res = solve1(1, sin_residual, sin_jacobian, &t, 100, 0, &b);
    /* The set-up: the first trial is the mirror point, with no gain. */
    assert_close(t.b[1], -b0, 1e-12);
    assert_true(fabs(t.cost[1] - t.cost[0]) <= 1e-14);
    /* The solver went on to the minimum. */
    assert_true(tf_stop_converged(res.stop));
    assert_true(fabs(b) < 1e-8);
    assert_true(res.iterations >= 2);
}

static void flat_valley_needs_a_sane_ratio(void **state)
{
    (void)state;
    /* With a large constant residual k the valley in sin(b) is flat: the
     * predicted relative reduction of the first (across-the-valley) step is
     * sin^2 b0 / k^2 ~ 8e-9, below ftol, and its actual reduction is 0.  A
     * rule without the ratio guard stops there, at b0, after no progress. */
    const double b0 = mirror_point();
    trace t = {.k = 1e4};
    double b = b0;
    tf_lm_result res = solve1(2, sin_residual, sin_jacobian, &t, 100, 1e-6, &b);
    assert_close(t.b[1], -b0, 1e-12);
    assert_true(fabs(t.cost[1] - t.cost[0]) <= 1e-6);
    assert_int_equal(res.stop, TF_STOP_REDUCTION);
    assert_true(res.iterations >= 1);
    assert_true(sin(b) * sin(b) < 0.5 * sin(b0) * sin(b0)); /* real progress */
}

/* ------------------------------------------------------------------------ */
/* Rosenbrock: r = (10 (b2 - b1^2), 1 - b1). */

static int rosenbrock(void *ctx, const double *b, double *r)
{
    trace *t = ctx;
    ++t->n;
    if (t->fail_after != 0 && t->n > t->fail_after) {
        return 1;
    }
    r[0] = 10 * (b[1] - b[0] * b[0]);
    r[1] = 1 - b[0];
    return 0;
}

/* Rosenbrock from (-1.2, 1) by forward differences, with a budget. */
static tf_lm_result solve_rosenbrock(trace *t, size_t max_evals, double *b)
{
    tf_lm_problem pb = {2, 2, rosenbrock, NULL, t, NULL, NULL, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 2);
    o.max_evals = max_evals;
    tf_lm_result res = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    b[0] = -1.2;
    b[1] = 1;
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, b, &res), 0);
    return res;
}

static void rosenbrock_converges(void **state)
{
    (void)state;
    trace t = {0};
    double b[2];
    tf_lm_result res = solve_rosenbrock(&t, 1000, b);
    assert_true(tf_stop_converged(res.stop));
    assert_close(b[0], 1, 1e-9);
    assert_close(b[1], 1, 1e-9);
    assert_int_equal(res.evals, t.n);
}

static void evaluation_budget_is_kept(void **state)
{
    (void)state;
    trace t = {0};
    double b[2];
    tf_lm_result res = solve_rosenbrock(&t, 7, b);
    assert_int_equal(res.stop, TF_STOP_MAX_EVALS);
    assert_false(tf_stop_converged(res.stop));
    /* The budget is checked after each trial; one Jacobian by differences
     * (2 evaluations) can run over it. */
    assert_true(res.evals >= 7 && res.evals <= 7 + 2);
}

static void failing_callback_stops_the_fit(void **state)
{
    (void)state;
    trace t = {.fail_after = 4};
    double b[2];
    tf_lm_result res = solve_rosenbrock(&t, 1000, b);
    assert_int_equal(res.stop, TF_STOP_CALLBACK);
    assert_true(isfinite(b[0]) && isfinite(b[1]));
}

static void bad_problems_are_refused(void **state)
{
    (void)state;
    trace t = {0};
    double b[2] = {0, 0}, lo[2] = {0, 1}, hi[2] = {1, 0}, nan_lo[2] = {NAN, 0};
    tf_lm_problem pb = {2, 2, rosenbrock, NULL, &t, lo, hi, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 2);
    tf_lm_result res = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, b, &res), -1);
    assert_non_null(strstr(ctx.err, "parameter 1"));
    pb.lower = nan_lo;
    pb.upper = NULL;
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, b, &res), -1);
    pb.lower = NULL;
    pb.n = 0;
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, b, &res), -1);
    assert_int_equal(t.n, 0);
}

/* ------------------------------------------------------------------------ */
/* Bounds: y = a exp(-b x), data from a = 2, b = 0.5 with a small fixed
 * perturbation; the box holds b away from 0.5. */

#define NB 12
typedef struct decay {
    double x[NB], y[NB];
    const double *lower, *upper;
    int outside; /* evaluations outside the box */
} decay;

static void decay_data(decay *d)
{
    for (int i = 0; i < NB; ++i) {
        d->x[i] = 0.5 * i;
        d->y[i] = 2 * exp(-0.5 * d->x[i]) + 0.01 * ((i * 7) % 5 - 2);
    }
}

static void check_inside(decay *d, const double *p)
{
    for (int j = 0; j < 2; ++j) {
        if ((d->lower && p[j] < d->lower[j]) || (d->upper && p[j] > d->upper[j])) {
            d->outside++;
        }
    }
}

static int decay_value(void *ctx, const double *p, double *f)
{
    decay *d = ctx;
    check_inside(d, p);
    for (int i = 0; i < NB; ++i) {
        f[i] = p[0] * exp(-p[1] * d->x[i]);
    }
    return 0;
}

static int decay_jacobian(void *ctx, const double *p, double *j)
{
    decay *d = ctx;
    check_inside(d, p);
    for (int i = 0; i < NB; ++i) {
        double e = exp(-p[1] * d->x[i]);
        j[i] = e;
        j[i + NB] = -p[0] * d->x[i] * e;
    }
    return 0;
}

/* The best a for a fixed b: linear least squares in closed form. */
static double best_a(const decay *d, double b)
{
    double num = 0, den = 0;
    for (int i = 0; i < NB; ++i) {
        double e = exp(-b * d->x[i]);
        num += d->y[i] * e;
        den += e * e;
    }
    return num / den;
}

static void fit_decay(decay *d, const double *lo, const double *hi, const double *start,
                      int analytic, tf_lsfit_result *r)
{
    d->lower = lo;
    d->upper = hi;
    d->outside = 0;
    tf_lsfit_model m = {2, NULL, decay_value, analytic ? decay_jacobian : NULL, d};
    tf_lsfit_data data = {NB, 1, d->y, 0, NULL};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, 2);
    o.start = start;
    o.lower = lo;
    o.upper = hi;
    o.lm.ftol = o.lm.xtol = 1e-14;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lsfit(&ctx, &m, &data, &o, r), 0);
    assert_true(tf_stop_converged(r->stop));
    assert_int_equal(d->outside, 0);
}

static void bounds_hold_and_are_reported(void **state)
{
    (void)state;
    decay d;
    decay_data(&d);
    const double start[2] = {1, 0.1}, lo[2] = {-INFINITY, 0}, hi[2] = {INFINITY, 0.3};
    const double lo7[2] = {0, 0.7}, hi7[2] = {10, 5};
    for (int analytic = 0; analytic < 2; ++analytic) {
        tf_lsfit_result r;
        fit_decay(&d, lo, hi, start, analytic, &r);
        assert_true(r.par[1] == 0.3);
        assert_int_equal(r.state[1], TF_PAR_UPPER);
        assert_int_equal(r.state[0], TF_PAR_FREE);
        assert_true(isnan(r.se[1]) && r.cov[3] == 0 && r.cov[1] == 0);
        assert_true(isfinite(r.se[0]) && r.se[0] > 0);
        assert_close(r.par[0], best_a(&d, 0.3), 1e-9);
        assert_int_equal(r.rank, 1);
        tf_lsfit_result_free(&r);

        const double start7[2] = {1, 1};
        fit_decay(&d, lo7, hi7, start7, analytic, &r);
        assert_true(r.par[1] == 0.7);
        assert_int_equal(r.state[1], TF_PAR_LOWER);
        assert_close(r.par[0], best_a(&d, 0.7), 1e-9);
        tf_lsfit_result_free(&r);
    }
}

static void inactive_bounds_change_nothing(void **state)
{
    (void)state;
    decay d;
    decay_data(&d);
    const double start[2] = {1, 0.1}, lo[2] = {0, 0}, hi[2] = {10, 3};
    tf_lsfit_result free_fit, boxed;
    fit_decay(&d, NULL, NULL, start, 1, &free_fit);
    fit_decay(&d, lo, hi, start, 1, &boxed);
    assert_int_equal(boxed.state[0], TF_PAR_FREE);
    assert_int_equal(boxed.state[1], TF_PAR_FREE);
    for (int j = 0; j < 2; ++j) {
        assert_close(boxed.par[j], free_fit.par[j], 1e-10);
        assert_close(boxed.se[j], free_fit.se[j], 1e-8);
    }
    assert_close(free_fit.par[1], 0.5, 0.05);
    tf_lsfit_result_free(&free_fit);
    tf_lsfit_result_free(&boxed);
}

static void start_outside_the_box_is_clamped(void **state)
{
    (void)state;
    decay d;
    decay_data(&d);
    const double start[2] = {50, -3}, lo[2] = {0, 0}, hi[2] = {10, 0.3};
    tf_lsfit_result r;
    fit_decay(&d, lo, hi, start, 1, &r);
    assert_true(r.par[1] == 0.3);
    assert_close(r.par[0], best_a(&d, 0.3), 1e-9);
    tf_lsfit_result_free(&r);
}

/* ------------------------------------------------------------------------ */
/* Large residuals: y = 3 exp(-0.1 x) + 1 plus noise of size 0.5.  Near the
 * minimum the sum of squares stops resolving steps long before the
 * parameters are as good as double precision allows; the fit must still
 * end at the Gauss-Newton fixed point: a further Gauss-Newton step from the
 * returned point (by QR, lsq.c) must be negligible. */

#define NL 50
typedef struct noisy {
    double x[NL], y[NL];
} noisy;

static int noisy_residual(void *ctx, const double *p, double *r)
{
    const noisy *d = ctx;
    for (int i = 0; i < NL; ++i) {
        r[i] = p[0] * exp(-p[1] * d->x[i]) + p[2] - d->y[i];
    }
    return 0;
}

static int noisy_jacobian(void *ctx, const double *p, double *j)
{
    const noisy *d = ctx;
    for (int i = 0; i < NL; ++i) {
        double e = exp(-p[1] * d->x[i]);
        j[i] = e;
        j[i + NL] = -p[0] * d->x[i] * e;
        j[i + 2 * NL] = 1;
    }
    return 0;
}

static void large_residual_fit_ends_at_the_gauss_newton_point(void **state)
{
    (void)state;
    noisy d;
    tf_rng g = {7};
    for (int i = 0; i < NL; ++i) {
        d.x[i] = i;
        d.y[i] = 3 * exp(-0.1 * i) + 1 + tf_rng_range(&g, -0.5, 0.5);
    }
    double p[3] = {1, 0.5, 0}, jac[3 * NL], r[NL], step[3];
    tf_lm_problem pb = {NL, 3, noisy_residual, noisy_jacobian, &d, NULL, NULL, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 3);
    o.ftol = o.xtol = 1e-15;
    tf_lm_result res = {.jac = jac};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, p, &res), 0);
    assert_true(tf_stop_converged(res.stop));
    assert_true(res.rss > 1); /* the residuals are large */
    noisy_residual(&d, p, r);
    tf_lsq *f = tf_lsq_factor(&ctx, NL, 3, jac, NL, NULL, 0);
    assert_non_null(f);
    assert_int_equal(tf_lsq_solve(&ctx, f, 1, r, NL, step, 3, NULL), 0);
    tf_lsq_free(f);
    for (int j = 0; j < 3; ++j) {
        assert_close(step[j], 0, 1e-12 * fabs(p[j]));
    }
}

/* Small residuals on an ill-conditioned model, Lanczos's three decaying
 * exponentials (rates 1, 3, 5 on x in [0, 1.15]) with data rounded to 4
 * decimals: residuals ~3e-5 on data of size 2.5.  The model adds a
 * deterministic jitter of 8 eps |y_i| (a function of the bits of p), as the
 * rounding of a model evaluation would, so that ||r||^2 is only known to
 * ~1e-10 relative: far above the rounding of the sum itself (5e-15), and
 * reached while the parameters are still ~1e-7 from the Gauss-Newton point.
 * tf_lsfit passes ||y|| to the solver, which then knows this floor and still
 * ends at the Gauss-Newton point. */
#define NZ 24
typedef struct lanczos {
    double x[NZ], y[NZ];
} lanczos;

static double jitter(const double *p, int i)
{
    uint64_t h = (uint64_t)(i + 1) * 0x9e3779b97f4a7c15ull;
    for (int j = 0; j < 6; ++j) {
        uint64_t bits;
        memcpy(&bits, &p[j], sizeof bits);
        h = (h ^ bits) * 0xbf58476d1ce4e5b9ull;
        h ^= h >> 31;
    }
    tf_rng g = {h};
    return tf_rng_range(&g, -1, 1);
}

static double lanczos_model(const double *p, double x)
{
    return p[0] * exp(-p[1] * x) + p[2] * exp(-p[3] * x) + p[4] * exp(-p[5] * x);
}

static int lanczos_value(void *ctx, const double *p, double *f)
{
    const lanczos *d = ctx;
    for (int i = 0; i < NZ; ++i) {
        f[i] = lanczos_model(p, d->x[i]) + 8 * DBL_EPSILON * d->y[i] * jitter(p, i);
    }
    return 0;
}

static int lanczos_jacobian(void *ctx, const double *p, double *j)
{
    const lanczos *d = ctx;
    for (int i = 0; i < NZ; ++i) {
        for (int k = 0; k < 3; ++k) {
            double e = exp(-p[2 * k + 1] * d->x[i]);
            j[i + 2 * k * NZ] = e;
            j[i + (2 * k + 1) * NZ] = -p[2 * k] * d->x[i] * e;
        }
    }
    return 0;
}

static void small_residual_fit_ends_at_the_gauss_newton_point(void **state)
{
    (void)state;
    lanczos d;
    const double truth[6] = {0.0951, 1, 0.8607, 3, 1.5576, 5};
    for (int i = 0; i < NZ; ++i) {
        d.x[i] = 0.05 * i;
        d.y[i] = round(1e4 * lanczos_model(truth, d.x[i])) * 1e-4;
    }
    const double start[6] = {1.2, 0.3, 5.6, 5.5, 6.5, 7.6};
    tf_lsfit_model model = {6, NULL, lanczos_value, lanczos_jacobian, &d};
    tf_lsfit_data data = {NZ, 1, d.y, 0, NULL};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, 6);
    o.start = start;
    o.lm.ftol = o.lm.xtol = 1e-15;
    tf_lsfit_result res;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &res), 0);
    assert_true(tf_stop_converged(res.stop));
    assert_true(res.rss[0] < 1e-7); /* the residuals are small */
    double jac[6 * NZ], r[NZ], step[6];
    for (int i = 0; i < NZ; ++i) {
        r[i] = lanczos_model(res.par, d.x[i]) - d.y[i]; /* without the jitter */
    }
    lanczos_jacobian(&d, res.par, jac);
    tf_lsq *f = tf_lsq_factor(&ctx, NZ, 6, jac, NZ, NULL, 0);
    assert_non_null(f);
    assert_int_equal(tf_lsq_solve(&ctx, f, 1, r, NZ, step, 6, NULL), 0);
    tf_lsq_free(f);
    for (int j = 0; j < 6; ++j) {
        assert_close(step[j], 0, 1e-10 * fabs(res.par[j]));
    }
    tf_lsfit_result_free(&res);
}

/* Difference Jacobians against the analytic one: forward differences to
 * about half the digits of double precision, central ones to about two
 * thirds.  The residual f(p) - f(p*) is zero at the start p*, so the solver
 * stops there at once and returns the differenced Jacobian at p*. */
static const double p_star[2] = {1.7, 0.45};

static int decay_offset(void *ctx, const double *p, double *r)
{
    double f0[NB];
    decay_value(ctx, p, r);
    decay_value(ctx, p_star, f0);
    for (int i = 0; i < NB; ++i) {
        r[i] -= f0[i];
    }
    return 0;
}

static double difference_error(int central)
{
    decay d = {0};
    decay_data(&d);
    double p[2] = {p_star[0], p_star[1]}, fd[2 * NB], an[2 * NB], worst = 0;
    tf_lm_problem pb = {NB, 2, decay_offset, NULL, &d, NULL, NULL, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 2);
    o.central_diff = central;
    tf_lm_result res = {.jac = fd};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, p, &res), 0);
    assert_int_equal(res.stop, TF_STOP_ZERO_RESIDUAL);
    assert_true(p[0] == p_star[0] && p[1] == p_star[1]);
    assert_int_equal(res.evals, 1 + (central ? 4 : 2));
    decay_jacobian(&d, p, an);
    for (int i = 0; i < 2 * NB; ++i) {
        worst = fmax(worst, fabs(fd[i] - an[i]) / (1 + fabs(an[i])));
    }
    return worst;
}

static void finite_differences_match_the_jacobian(void **state)
{
    (void)state;
    double forward = difference_error(0), central = difference_error(1);
    assert_true(forward < 1e-7);
    assert_true(central < 1e-9);
    assert_true(central < 0.01 * forward);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nan_trial_is_rejected),
        cmocka_unit_test(nonfinite_wall_is_not_convergence),
        cmocka_unit_test(nonfinite_start_is_reported),
        cmocka_unit_test(step_across_valley_is_not_convergence),
        cmocka_unit_test(flat_valley_needs_a_sane_ratio),
        cmocka_unit_test(rosenbrock_converges),
        cmocka_unit_test(evaluation_budget_is_kept),
        cmocka_unit_test(failing_callback_stops_the_fit),
        cmocka_unit_test(bad_problems_are_refused),
        cmocka_unit_test(bounds_hold_and_are_reported),
        cmocka_unit_test(inactive_bounds_change_nothing),
        cmocka_unit_test(start_outside_the_box_is_clamped),
        cmocka_unit_test(large_residual_fit_ends_at_the_gauss_newton_point),
        cmocka_unit_test(small_residual_fit_ends_at_the_gauss_newton_point),
        cmocka_unit_test(finite_differences_match_the_jacobian),
    };
    return cmocka_run_group_tests_name("lm", tests, NULL, NULL);
}
