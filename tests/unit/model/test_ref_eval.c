/*
 * test_ref_eval.c — the host reference evaluator against first principles:
 * operation counts equal the documented formulas, the basis order is the
 * documented one, the projection lands on the envelope boundary in the
 * input's direction, and the target library agrees with it bit for bit.
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

#include "random_model.h"
#include "model/basis.h"
#include "model/ref_eval.h"
#include "model/target_view.h"

static void op_counts_match_formulas(void **state)
{
    (void)state;
    tf_rng r = {3};
    const float inputs[][3] = {{0, 0, 0}, {0.1f, 0.2f, 0.3f}, {1e30f, 0, 0}, {NAN, 1, 1}};
    for (int i = 0; i < 200; ++i) {
        tf_model *m = tf_random_model(&r, "m", 0, 0);
        tf_opcount want = tf_model_ops(m);
        float *out = malloc(3 * m->n_out * sizeof *out);
        for (size_t k = 0; k < 4; ++k) {
            tf_opcount got = {0, 0, 0};
            tf_ref_eval(m, inputs[k], out, &got);
            assert_int_equal(got.add, want.add);
            assert_int_equal(got.mul, want.mul);
            assert_int_equal(got.div, want.div);
        }
        free(out);
        tf_model_free(m);
    }
}

/* Row t of a nodal model with C[o][t] = (o == t) returns phi_t exactly. */
static void basis_order_is_graded_lexicographic(void **state)
{
    (void)state;
    const uint32_t p = 4, n_terms = 35, dims[1] = {p};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "b", TFIT_FAMILY_NODAL, 12, dims, 1);
    float *c = tf_model_tables(m);
    for (uint32_t o = 0; o < n_terms; ++o) {
        c[o * n_terms + o] = 1.0f;
    }
    const float g[3] = {0.5f, -0.25f, 0.125f}; /* T_k of these need <= 12 bits: no rounding */
    float out[36];
    assert_int_equal(tf_ref_eval(m, g, out, NULL), TFIT_OK);
    double t0[5], t1[5], t2[5];
    tf_chebyshev(p, 0.5, t0);
    tf_chebyshev(p, -0.25, t1);
    tf_chebyshev(p, 0.125, t2);
    uint32_t t = 0;
    for (int d = 0; d <= (int)p; ++d) {
        for (int a = d; a >= 0; --a) {
            for (int b = d - a; b >= 0; --b, ++t) {
                double want = t0[a] * t1[b] * t2[d - a - b];
                assert_true((double)out[t] == want);
            }
        }
    }
    assert_int_equal(t, n_terms);
    tf_model_free(m);
}

static void projection_is_radial(void **state)
{
    (void)state;
    const uint32_t dims[1] = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "p", TFIT_FAMILY_NODAL, 1, dims, 1);
    const double centre[3] = {1.0, -2.0, 0.5};
    tf_model_set_ball(m, centre, 0.75);
    tf_rng r = {17};
    for (int i = 0; i < 2000; ++i) {
        double d[3], n = 0;
        for (int k = 0; k < 3; ++k) {
            d[k] = tf_rng_range(&r, -1, 1);
            n += d[k] * d[k];
        }
        n = sqrt(n);
        double s = pow(10.0, tf_rng_range(&r, -3, 30));
        float x[3], g[3];
        for (int k = 0; k < 3; ++k) {
            x[k] = (float)(centre[k] + 0.75 * s * d[k] / n);
        }
        int clamped, bad;
        tf_ref_input(m, x, g, &clamped, &bad, NULL);
        assert_false(bad);
        double gn = sqrt((double)g[0] * g[0] + (double)g[1] * g[1] + (double)g[2] * g[2]);
        if (s > 1.001) {
            assert_true(clamped);
            assert_true(fabs(gn - 1.0) < 4 * FLT_EPSILON);
            for (int k = 0; k < 3; ++k) { /* same direction */
                assert_true(fabs((double)g[k] - d[k] / n) < 1e-5 + (s < 1e3 ? 1e-4 : 0.0));
            }
        } else if (s < 0.999) {
            assert_false(clamped);
            assert_true(fabs(gn - s) < 1e-5);
        }
    }
    tf_model_free(m);
}

static void target_agrees_with_reference(void **state)
{
    (void)state;
    tf_rng r = {23};
    unsigned long mismatches = 0, compared = 0;
    for (int i = 0; i < 150; ++i) {
        tf_model *m = tf_random_model(&r, "m", 0, 0);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        float *want = malloc(3 * m->n_out * sizeof *want);
        float *got = malloc(3 * m->n_out * sizeof *got);
        for (int k = 0; k < 20; ++k) {
            float x[3];
            for (int j = 0; j < 3; ++j) {
                x[j] = (float)(tf_rng_range(&r, -2, 2) * pow(10.0, tf_rng_range(&r, -4, 4)));
            }
            tfit_status s1 = tf_ref_eval(m, x, want, NULL);
            tfit_status s2 = m->family == TFIT_FAMILY_CONTACT ? tfit_contact_force(&t, x, got)
                                                              : tfit_displacements(&t, x, got);
            mismatches += s1 != s2;
            mismatches += memcmp(want, got, 3 * m->n_out * sizeof *got) != 0;
            compared++;
        }
        free(want);
        free(got);
        tf_model_free(m);
    }
    assert_int_equal(mismatches, 0);
    assert_int_equal(compared, 3000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(op_counts_match_formulas),
        cmocka_unit_test(basis_order_is_graded_lexicographic),
        cmocka_unit_test(projection_is_radial),
        cmocka_unit_test(target_agrees_with_reference),
    };
    return cmocka_run_group_tests_name("ref_eval", tests, NULL, NULL);
}
