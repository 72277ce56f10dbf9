/*
 * test_neighbours.c — support queries against brute force.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "meshfree/neighbours.h"
#include "base/rng.h"

static void queries_match_brute_force(void **state)
{
    (void)state;
    enum { n = 2000 };
    double *xyz = malloc(3 * n * sizeof *xyz);
    uint32_t out[n], want[n];
    tf_rng r = {11};
    for (size_t i = 0; i < 3 * n; ++i) {
        xyz[i] = tf_rng_range(&r, 0, i % 3 == 2 ? 2 : 10);
    }
    const double radius[3] = {1.1, 0.7, 0.4};
    tf_nbr g;
    assert_int_equal(tf_nbr_build(&g, xyz, n, radius), 0);
    for (int t = 0; t < 200; ++t) {
        double x[3] = {tf_rng_range(&r, -1, 11), tf_rng_range(&r, -1, 11), tf_rng_range(&r, -1, 3)};
        size_t m = 0;
        for (size_t i = 0; i < n; ++i) {
            double s = 0;
            for (int a = 0; a < 3; ++a) {
                double d = (xyz[3 * i + a] - x[a]) / radius[a];
                s += d * d;
            }
            if (s <= 1) {
                want[m++] = (uint32_t)i;
            }
        }
        size_t got = tf_nbr_query(&g, x, out, n);
        assert_int_equal(got, m);
        for (size_t k = 0; k < m; ++k) {
            assert_int_equal(out[k], want[k]); /* ascending, the same nodes */
        }
        if (m > 1) {
            assert_int_equal(tf_nbr_query(&g, x, out, 1), m); /* reports the size it needs */
        }
    }
    tf_nbr_free(&g);
    free(xyz);
}

/* block48's grid with solver.support=1e-16: more bins per axis than an
 * unsigned holds were asked for (0 bins and a crash before); a support that
 * holds no node is an empty answer, with no buffer to sort. */
static void a_tiny_support_still_bins(void **state)
{
    (void)state;
    enum { nx = 11, ny = 11, nz = 3, n = nx * ny * nz };
    double *xyz = malloc(3 * n * sizeof *xyz);
    for (size_t i = 0; i < n; ++i) {
        xyz[3 * i] = 4.8 * (double)(i % nx);
        xyz[3 * i + 1] = 4.8 * (double)(i / nx % ny);
        xyz[3 * i + 2] = 3.0 * (double)(i / (nx * ny));
    }
    const double radius[3] = {4.8e-16, 4.8e-16, 3e-16};
    tf_nbr g;
    assert_int_equal(tf_nbr_build(&g, xyz, n, radius), 0);
    size_t bins = (size_t)g.dims[0] * g.dims[1] * g.dims[2];
    assert_true(bins >= 1 && bins <= 2 * n + 64);
    uint32_t one[4];
    for (size_t i = 0; i < n; i += 37) {
        assert_int_equal(tf_nbr_query(&g, xyz + 3 * i, one, 4), 1);
        assert_int_equal(one[0], i);
    }
    const double between[3] = {2.4, 2.4, 1.5};
    assert_int_equal(tf_nbr_query(&g, between, NULL, 0), 0);
    tf_nbr_free(&g);
    free(xyz);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(queries_match_brute_force),
                                       cmocka_unit_test(a_tiny_support_still_bins)};
    return cmocka_run_group_tests_name("neighbours", tests, NULL, NULL);
}
