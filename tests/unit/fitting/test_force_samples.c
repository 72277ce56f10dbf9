/*
 * test_force_samples.c — training and held-out forces: inside the envelope,
 * the axis points present, space-filling better than random, deterministic,
 * and the held-out set disjoint from training.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "fitting/force_samples.h"
#include "base/rng.h"

#define NT 100
#define NH 50

static void inside_and_axes(void **state)
{
    (void)state;
    const double c[3] = {0.5, -1.0, 2.0}, r = 3.0;
    double tr[NT][3], ho[NH][3];
    tf_force_samples(c, r, NT, NH, 42, tr, ho);
    for (int i = 0; i < NT + NH; ++i) {
        const double *p = i < NT ? tr[i] : ho[i - NT];
        double d = sqrt(pow(p[0] - c[0], 2) + pow(p[1] - c[1], 2) + pow(p[2] - c[2], 2));
        assert_true(d <= r * (1 + 1e-12));
    }
    for (int axis = 0; axis < 3; ++axis) { /* +-r e_axis are the first six */
        assert_true(tr[2 * axis][axis] == c[axis] + r);
        assert_true(tr[2 * axis + 1][axis] == c[axis] - r);
    }
    for (int i = 0; i < NT; ++i) {
        for (int j = 0; j < NH; ++j) {
            assert_true(memcmp(tr[i], ho[j], sizeof tr[i]) != 0);
        }
    }
}

static void space_filling_and_deterministic(void **state)
{
    (void)state;
    const double c[3] = {0, 0, 0};
    double a[NT][3], b[NT][3], ho[NH][3];
    tf_force_samples(c, 1.0, NT, NH, 7, a, ho);
    tf_force_samples(c, 1.0, NT, NH, 7, b, ho);
    assert_memory_equal(a, b, sizeof a);
    tf_force_samples(c, 1.0, NT, NH, 8, b, ho);
    assert_true(memcmp(a[10], b[10], sizeof a[10]) != 0);

    /* Low discrepancy keeps points apart: compare with i.i.d. uniform sets. */
    double d_design = tf_force_samples_min_distance((const double(*)[3])a, NT);
    tf_rng r = {1};
    double worse = 0;
    for (int trial = 0; trial < 20; ++trial) {
        double rnd[NT][3];
        for (int n = 0; n < NT;) {
            double u[3] = {tf_rng_range(&r, -1, 1), tf_rng_range(&r, -1, 1), tf_rng_range(&r, -1, 1)};
            if (u[0] * u[0] + u[1] * u[1] + u[2] * u[2] <= 1) {
                memcpy(rnd[n++], u, sizeof u);
            }
        }
        worse += tf_force_samples_min_distance((const double(*)[3])rnd, NT) < d_design;
    }
    assert_true(worse >= 18); /* the design beats random sets almost always */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(inside_and_axes),
        cmocka_unit_test(space_filling_and_deterministic),
    };
    return cmocka_run_group_tests_name("force_samples", tests, NULL, NULL);
}
