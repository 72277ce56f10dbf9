/*
 * test_pod.c — the POD recovers a known low-rank structure: data built from
 * three orthonormal modes has three non-zero singular values, its modes span
 * the same space, and the rank for a tolerance is the right one.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "numerics/pod.h"
#include "base/rng.h"

#define M 60
#define N 25

static void recovers_rank_three(void **state)
{
    (void)state;
    static double q[M][3], data[N][M];
    tf_rng r = {4};
    /* three orthonormal columns by Gram-Schmidt */
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < M; ++i) {
            q[i][c] = tf_rng_range(&r, -1, 1);
        }
        for (int p = 0; p < c; ++p) {
            double d = 0;
            for (int i = 0; i < M; ++i) {
                d += q[i][c] * q[i][p];
            }
            for (int i = 0; i < M; ++i) {
                q[i][c] -= d * q[i][p];
            }
        }
        double n = 0;
        for (int i = 0; i < M; ++i) {
            n += q[i][c] * q[i][c];
        }
        for (int i = 0; i < M; ++i) {
            q[i][c] /= sqrt(n);
        }
    }
    const double scale[3] = {100.0, 10.0, 0.5};
    for (int j = 0; j < N; ++j) {
        double w[3] = {tf_rng_range(&r, -1, 1), tf_rng_range(&r, -1, 1), tf_rng_range(&r, -1, 1)};
        for (int i = 0; i < M; ++i) {
            data[j][i] = 0;
            for (int c = 0; c < 3; ++c) {
                data[j][i] += scale[c] * w[c] * q[i][c];
            }
        }
    }
    tf_pod pod;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_pod_compute(&ctx, &data[0][0], M, N, &pod), 0);
    assert_int_equal(pod.k, N);
    assert_true(pod.sigma[2] > 0.1);
    assert_true(pod.sigma[3] < 1e-12 * pod.sigma[0]);
    for (int c = 0; c < 3; ++c) { /* each true mode lies in the span of the first three */
        double proj = 0;
        for (int k = 0; k < 3; ++k) {
            double d = 0;
            for (int i = 0; i < M; ++i) {
                d += q[i][c] * pod.modes[k * M + i];
            }
            proj += d * d;
        }
        assert_true(fabs(proj - 1.0) < 1e-10);
    }
    assert_int_equal(tf_pod_rank_for(&pod, 1e-9), 3);
    assert_int_equal(tf_pod_rank_for(&pod, pod.sigma[2] * 1.5), 2);
    tf_pod_free(&pod);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(recovers_rank_three)};
    return cmocka_run_group_tests_name("pod", tests, NULL, NULL);
}
