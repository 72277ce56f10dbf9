/*
 * test_lm_step.c — the trial step of the Levenberg–Marquardt solver: only
 * a bound makes a step "projected" (rounding of p + step does not).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "base/rng.h"
#include "numerics/lm_box.h"

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rounding_is_no_projection),
        cmocka_unit_test(only_a_bound_projects),
    };
    return cmocka_run_group_tests_name("lm_step", tests, NULL, NULL);
}
