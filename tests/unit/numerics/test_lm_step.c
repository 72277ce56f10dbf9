/*
 * test_lm_step.c — the trial step of the Levenberg–Marquardt solver: only
 * a bound makes a step "projected" (rounding of p + step does not), and a
 * damped step that underflows is reported as such, not as a bad Jacobian.
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
#include "base/rng.h"
#include "numerics/lm.h"
#include "numerics/lm_box.h"
#include "numerics/lm_step.h"

/* Without bounds no step is projected, though (p + step) - p differs from
 * step for most of these (the old test flagged them, and the predicted
 * reduction then came from -2 s.g - |Js|^2, which cancels). */
static void rounding_is_no_projection(void **state)
{
    (void)state;
    tf_rng rng = {19};
    enum { N = 8, TRIALS = 1000 };
    size_t rounded = 0;
    for (int k = 0; k < TRIALS; ++k) {
        double p[N], step[N], pt[N];
        for (int j = 0; j < N; ++j) {
            p[j] = (tf_rng_uniform(&rng) - 0.5) * pow(10, 40 * tf_rng_uniform(&rng) - 20);
            step[j] = (tf_rng_uniform(&rng) - 0.5) * fabs(p[j]) * pow(10, -12 * tf_rng_uniform(&rng));
        }
        assert_int_equal(tf_lm_box_trial(N, NULL, NULL, p, step, pt), 0);
        for (int j = 0; j < N; ++j) {
            assert_true(pt[j] == p[j] + step[j]);
            rounded += (pt[j] - p[j]) != step[j];
        }
    }
    /* The cases are ones rounding changes: most of the 8000 steps. */
    assert_true(rounded > TRIALS * N / 2);
}

static void only_a_bound_projects(void **state)
{
    (void)state;
    const double p[3] = {0.1, 1, 5}, step[3] = {0.3, -0.7, 1e-9};
    const double wide_lo[3] = {-1, -1, -1}, wide_hi[3] = {10, 10, 10};
    const double lo[3] = {-1, 0.5, 5}, hi[3] = {0.2, 10, 5};
    double pt[3];
    assert_int_equal(tf_lm_box_trial(3, wide_lo, wide_hi, p, step, pt), 0);
    assert_true(pt[0] == p[0] + step[0] && pt[1] == p[1] + step[1]);
    /* p_1 + 0.3 passes its upper bound 0.2, p_2 - 0.7 its lower bound 0.5,
     * p_3 is held at lo = hi = 5. */
    assert_int_equal(tf_lm_box_trial(3, lo, hi, p, step, pt), 1);
    assert_true(pt[0] == 0.2 && pt[1] == 0.5 && pt[2] == 5);
    /* One-sided boxes (NULL for the other side). */
    assert_int_equal(tf_lm_box_trial(3, lo, NULL, p, step, pt), 1);
    assert_true(pt[0] == p[0] + step[0] && pt[1] == 0.5);
    const double zero[3] = {0, 0, 0};
    assert_int_equal(tf_lm_box_trial(3, lo, hi, p, zero, pt), 0);
}

/* ------------------------------------------------------------------------ */

/* One parameter, R = 1, Q^T r = 1e-300, D = 1e10, and the smallest trust
 * radius there is: the damped step is 5e-334, which is 0 in double.  Its
 * scaled norm divided 0 by 0 in the Newton denominator, LAPACK refused the
 * NaN (info -9) and the solver said "bad-jacobian". */
static void underflowed_damped_step_is_named(void **state)
{
    (void)state;
    const double r = 1, qtf = 1e-300, diag = 1e10;
    const lapack_int piv = 1;
    double work[16], step = -1;
    assert_true(tf_lmstep_work_size(1) <= sizeof work / sizeof work[0]);
    tf_lmstep s = {1, 1, &r, 1, &piv, 1, &qtf, &diag, work};
    assert_true(tf_lmstep_solve(&s, 4.9e-324, 0, &step) == TF_LMSTEP_UNDERFLOW);
    /* A radius the step can meet still works. */
    double par = tf_lmstep_solve(&s, 1e-292, 0, &step);
    assert_true(par > 0 && step < 0 && isfinite(step));
}

/* r = 1e-10 at p0 = 1e-310 and 1 anywhere else, J = 1e300: every trial
 * fails, the region shrinks ten-fold each time, and after 14 trials the
 * step (radius / 1e300) is below the smallest subnormal. */
static double p_start;

static int spike_residual(void *ctx, const double *p, double *res)
{
    (void)ctx;
    res[0] = p[0] == p_start ? 1e-10 : 1;
    return 0;
}

static int spike_jacobian(void *ctx, const double *p, double *jac)
{
    (void)ctx, (void)p;
    jac[0] = 1e300;
    return 0;
}

static void underflow_is_reported_as_such(void **state)
{
    (void)state;
    p_start = 1e-310;
    tf_lm_problem pb = {1, 1, spike_residual, spike_jacobian, NULL, NULL, NULL, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 1);
    o.ftol = o.xtol = 1e-15;
    tf_lm_result res = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double p = p_start;
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, &p, &res), 0);
    assert_int_equal(res.stop, TF_STOP_UNDERFLOW);
    assert_string_equal(tf_stop_name(res.stop), "underflow");
    assert_false(tf_stop_converged(res.stop));
    assert_true(p == p_start);
    assert_close(res.rss, 1e-20, 1e-35);
    assert_true(res.evals < 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rounding_is_no_projection),
        cmocka_unit_test(only_a_bound_projects),
        cmocka_unit_test(underflowed_damped_step_is_named),
        cmocka_unit_test(underflow_is_reported_as_such),
    };
    return cmocka_run_group_tests_name("lm_step", tests, NULL, NULL);
}
