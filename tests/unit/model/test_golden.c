/*
 * test_golden.c — the golden input design covers every class the contract
 * names, and the reference evaluator gives each its status.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "model/golden.h"
#include "random_model.h"
#include "model/ref_eval.h"

static void covers_every_input_class(void **state)
{
    (void)state;
    tf_rng r = {8};
    for (int family = 1; family <= 4; ++family) {
        tf_model *m = tf_random_model(&r, "g", (tfit_family)family, 1);
        float in[TF_GOLDEN_MAX][3];
        size_t n = tf_golden_inputs(m, 77, in);
        int zero = 0, nan = 0, pinf = 0, ninf = 0, subnormal = 0, huge = 0, on_edge = 0;
        int status_seen[3] = {0, 0, 0};
        float *out = malloc(3 * m->n_out * sizeof *out);
        assert_true(n >= 60 && n <= TF_GOLDEN_MAX);
        for (size_t v = 0; v < n; ++v) {
            for (int i = 0; i < 3; ++i) {
                float x = in[v][i];
                nan += isnan(x);
                pinf += isinf(x) && x > 0;
                ninf += isinf(x) && x < 0;
                subnormal += fpclassify(x) == FP_SUBNORMAL;
                huge += fabsf(x) >= 1e38f && isfinite(x);
            }
            zero += in[v][0] == 0 && in[v][1] == 0 && in[v][2] == 0;
            float g[3];
            int clamped, bad;
            tf_ref_input(m, in[v], g, &clamped, &bad, NULL);
            double gn = sqrt((double)g[0] * g[0] + (double)g[1] * g[1] + (double)g[2] * g[2]);
            on_edge += !bad && fabs(gn - 1.0) < 1e-6;
            tfit_status s = tf_ref_eval(m, in[v], out, NULL);
            status_seen[s == TFIT_OK ? 0 : (s == TFIT_CLAMPED ? 1 : 2)]++;
            for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
                assert_true(isfinite(out[o]));
            }
        }
        assert_true(zero >= 1);
        assert_true(nan >= 4);
        assert_true(pinf >= 2 && ninf >= 2);
        assert_true(subnormal >= 3);
        assert_true(huge >= 3);
        assert_true(on_edge >= 14);
        assert_true(status_seen[0] >= 20 && status_seen[1] >= 10 && status_seen[2] == 8);
        free(out);
        tf_model_free(m);
    }
}

static void deterministic_for_a_seed(void **state)
{
    (void)state;
    tf_rng r = {9};
    tf_model *m = tf_random_model(&r, "g", TFIT_FAMILY_MODAL, 1);
    float a[TF_GOLDEN_MAX][3], b[TF_GOLDEN_MAX][3];
    size_t na = tf_golden_inputs(m, 5, a), nb = tf_golden_inputs(m, 5, b);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, na * sizeof a[0]);
    size_t nc = tf_golden_inputs(m, 6, b);
    assert_int_equal(na, nc);
    assert_true(memcmp(a[2], b[2], sizeof a[2]) != 0); /* random part follows the seed */
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(covers_every_input_class),
        cmocka_unit_test(deterministic_for_a_seed),
    };
    return cmocka_run_group_tests_name("golden", tests, NULL, NULL);
}
