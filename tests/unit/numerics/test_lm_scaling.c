/*
 * test_lm_scaling.c — the Levenberg–Marquardt solver does not depend on the
 * units of the parameters (docs/lm.md §2): a column of J 1e16 times larger
 * than another does not make the other look dependent, a start at p = 0
 * gets a first trust region in the units of r, and a column norm times
 * ||r|| that overflows is no gradient stop.  The whole Moré–Garbow–
 * Hillstrom set with rescaled parameters is in test_lm_mgh.c.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "assert_close.h"
#include "numerics/lm.h"

/* r_i = S (p_1 - 2) + (p_2 - 3) t_i + e_i, t_i = 1..10, e_i = -+1/2
 * alternating: linear, with the least-squares solution p_1 = 2 - (mean of
 * e - slope * mean of t) / S, p_2 = 3 - cov(t, e) / var(t) = 3 - 0.25 /
 * 8.25, whatever S is. */
#define NL 10

static int line_residual(void *ctx, const double *p, double *r)
{
    const double s = *(const double *)ctx;
    for (int i = 0; i < NL; ++i) {
        double t = i + 1, e = i % 2 ? 0.5 : -0.5;
        r[i] = s * (p[0] - 2) + (p[1] - 3) * t + e;
    }
    return 0;
}

static int line_jacobian(void *ctx, const double *p, double *jac)
{
    (void)p;
    const double s = *(const double *)ctx;
    for (int i = 0; i < NL; ++i) {
        jac[i] = s;
        jac[i + NL] = i + 1;
    }
    return 0;
}

static const double slope_fit = 3 - 0.25 / 8.25;

/* From (p1, p2), for S = 1 to 1e20: converged at the least-squares slope
 * (RSS 2.42, or 2.70 where p_1 = 2 - 1.7e-17 / S rounds to 2). */
static void fits_the_line_from(double p1, double p2)
{
    const double scales[] = {1, 1e10, 1e15, 1e16, 1e20};
    for (size_t k = 0; k < sizeof scales / sizeof scales[0]; ++k) {
        double s = scales[k], p[2] = {p1, p2};
        tf_lm_problem pb = {NL, 2, line_residual, line_jacobian, &s, NULL, NULL, 0};
        tf_lm_options o;
        tf_lm_default_options(&o, 2);
        tf_lm_result res = {0};
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        assert_int_equal(tf_lm_solve(&ctx, &pb, &o, p, &res), 0);
        assert_true(tf_stop_converged(res.stop));
        assert_close(p[1], slope_fit, 1e-9);
        assert_true(res.rss < 3 && res.evals <= 10);
    }
}

/* With S = 1e16 the unscaled R_00 is 3e16, and the rank tolerance
 * max(m, n) eps |R_00| = 70 exceeded |R_11| = 9: the second column was
 * declared dependent, the Gauss–Newton step left p_2 at its start and the
 * fit stopped "converged" (step) at p_2 = 1, RSS 367 instead of 2.70. */
static void one_large_column_does_not_hide_the_others(void **state)
{
    (void)state;
    fits_the_line_from(1, 1);
}

/* From p = 0, ||D p0|| = 0 and the first region was the absolute value
 * factor = 1: with S = 1e15 that is 1e-15 of ||r0|| = 6e15, below what
 * double resolves, and the fit stopped at the start ("precision", RSS
 * 4e31) claiming convergence. */
static void zero_start_gets_a_region_in_the_units_of_r(void **state)
{
    (void)state;
    fits_the_line_from(0, 0);
}

/* r = 1e200 (p - 1/2): at p = 1 the column norm times ||r|| is 5e399, which
 * overflows; the cosine came out 0 (or NaN, which fmax dropped) and the fit
 * stopped at its start with "gradient". */
static int huge_residual(void *ctx, const double *p, double *r)
{
    (void)ctx;
    r[0] = 1e200 * (p[0] - 0.5);
    return 0;
}

static int huge_jacobian(void *ctx, const double *p, double *jac)
{
    (void)ctx, (void)p;
    jac[0] = 1e200;
    return 0;
}

static void overflowing_cosine_is_no_gradient_stop(void **state)
{
    (void)state;
    tf_lm_problem pb = {1, 1, huge_residual, huge_jacobian, NULL, NULL, NULL, 0};
    tf_lm_options o;
    tf_lm_default_options(&o, 1);
    tf_lm_result res = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double p = 1;
    assert_int_equal(tf_lm_solve(&ctx, &pb, &o, &p, &res), 0);
    assert_true(tf_stop_converged(res.stop));
    assert_int_not_equal(res.stop, TF_STOP_GRADIENT);
    assert_close(p, 0.5, 1e-15);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_large_column_does_not_hide_the_others),
        cmocka_unit_test(zero_start_gets_a_region_in_the_units_of_r),
        cmocka_unit_test(overflowing_cosine_is_no_gradient_stop),
    };
    return cmocka_run_group_tests_name("lm_scaling", tests, NULL, NULL);
}
