/*
 * test_cut_model.c — the cut family's evaluation (docs/header-format.md
 * §5.7): the target's tfit_displacements_cut against the host reference,
 * bit for bit, over random models, forces and cut progress values; the
 * knots, the interpolation between them, the clamp of s and the rejection
 * of NaN/Inf; the arguments; tfit_model_check's sizes; the operation
 * counts.
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

#include "model/forms/cut.h"
#include "model/ref_eval.h"
#include "model/target_view.h"
#include "random_model.h"

static uint32_t bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

/* Cut progress values that exercise every branch-free selection. */
static float pick_s(tf_rng *r, int k)
{
    static const float special[] = {0.0f, 1.0f, -0.0f, 0.5f, 0x1p-149f, 1.0f - 0x1p-24f,
                                    1.0f + 0x1p-23f, -0x1p-149f, -1e30f, 1e30f, FLT_MAX,
                                    NAN, INFINITY, -INFINITY, 0.999999f, 1e-30f};
    if (k % 3 == 0) {
        return special[(size_t)k / 3 % (sizeof special / sizeof special[0])];
    }
    return (float)tf_rng_range(r, -0.25, 1.25);
}

static void target_agrees_with_reference(void **state)
{
    (void)state;
    tf_rng r = {0xc07};
    unsigned long bad = 0, calls = 0;
    for (int i = 0; i < 80; ++i) {
        tf_model *m = tf_random_model(&r, "c", TFIT_FAMILY_CUT, i % 2);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        const size_t n = 3 * (size_t)m->n_out;
        float *want = malloc(n * sizeof *want), *got = malloc(n * sizeof *got);
        for (int k = 0; k < 200; ++k) {
            const double scale = k % 7 == 0 ? 1e30 : 1.0 / fabs((double)m->coef[3]);
            const float f[3] = {(float)tf_rng_range(&r, -scale, scale),
                                (float)tf_rng_range(&r, -scale, scale),
                                k % 11 == 0 ? NAN : (float)tf_rng_range(&r, -scale, scale)};
            const float s = pick_s(&r, k);
            tfit_status s1 = tf_cut_ref_eval(m, f, s, want, NULL);
            tfit_status s2 = tfit_displacements_cut(&t, f, s, got);
            bad += s1 != s2 || memcmp(want, got, n * sizeof *got) != 0;
            calls++;
        }
        free(want);
        free(got);
        tf_model_free(m);
    }
    print_message("cut: %lu of %lu evaluations differ from the reference\n", bad, calls);
    assert_int_equal(bad, 0);
}

/* One output point, degree 1, K = 4, input map the unit ball: at knot k
 * the rows are ux = k, uy = g0, uz = -k g2. */
static tf_model *ramp(void)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const uint32_t dims[2] = {1, 4};
    tf_model *m = tf_model_new(&ctx, "ramp", TFIT_FAMILY_CUT, 1, dims, 2);
    assert_non_null(m);
    const double c[3] = {0, 0, 0};
    tf_model_set_ball(m, c, 1.0);
    float *tab = tf_model_tables(m);
    for (int k = 0; k <= 4; ++k) {
        float *row = tab + 12 * k;
        row[0] = (float)k;     /* ux: 1, g0, g1, g2 */
        row[4 + 1] = 1.0f;     /* uy = g0 */
        row[8 + 3] = (float)-k; /* uz = -k g2 */
    }
    return m;
}

static void knots_interpolation_and_clamp(void **state)
{
    (void)state;
    tf_model *m = ramp();
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float u[3];
    const float f[3] = {0.5f, 0.0f, 0.25f};
    for (int k = 0; k <= 4; ++k) { /* on a knot: that knot's rows exactly */
        assert_int_equal(tfit_displacements_cut(&t, f, (float)k / 4.0f, u), TFIT_OK);
        assert_true(u[0] == (float)k && u[1] == 0.5f && u[2] == -0.25f * (float)k);
    }
    /* between knots: linear (exact in these binary fractions) */
    assert_int_equal(tfit_displacements_cut(&t, f, 0.375f, u), TFIT_OK);
    assert_true(u[0] == 1.5f && u[2] == -0.375f);
    /* s outside [0, 1]: clamped, flagged */
    assert_int_equal(tfit_displacements_cut(&t, f, -0.5f, u), TFIT_CLAMPED);
    assert_true(u[0] == 0.0f && u[1] == 0.5f);
    assert_int_equal(tfit_displacements_cut(&t, f, 7.0f, u), TFIT_CLAMPED);
    assert_true(u[0] == 4.0f && u[2] == -1.0f);
    assert_int_equal(tfit_displacements_cut(&t, f, -FLT_MAX, u), TFIT_CLAMPED);
    assert_true(u[0] == 0.0f);
    /* the force outside its envelope: clamped too */
    const float far[3] = {3.0f, 0.0f, 0.0f};
    assert_int_equal(tfit_displacements_cut(&t, far, 0.5f, u), TFIT_CLAMPED);
    assert_true(u[0] == 2.0f && u[1] == 1.0f);
    /* NaN or Inf in s or in the force: rejected, every output +0.0f */
    const float bad_s[] = {NAN, -NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad_s / sizeof bad_s[0]; ++i) {
        u[0] = u[1] = u[2] = 9.0f;
        assert_int_equal(tfit_displacements_cut(&t, f, bad_s[i], u), TFIT_ERR_INPUT);
        assert_true(bits(u[0]) == 0 && bits(u[1]) == 0 && bits(u[2]) == 0);
    }
    const float nan_f[3] = {0.1f, NAN, 0.0f};
    u[0] = 9.0f;
    assert_int_equal(tfit_displacements_cut(&t, nan_f, 0.5f, u), TFIT_ERR_INPUT);
    assert_true(bits(u[0]) == 0 && bits(u[1]) == 0 && bits(u[2]) == 0);
    tf_model_free(m);
}

static void api_arguments(void **state)
{
    (void)state;
    tf_model *m = ramp();
    tf_rng r = {5};
    tf_model *n = tf_random_model(&r, "n", TFIT_FAMILY_NODAL, 1);
    tfit_model t, v;
    tf_target_view(m, &t);
    tf_target_view(n, &v);
    float out[3 * 64];
    const float f[3] = {0, 0, 0};
    assert_int_equal(tfit_displacements_cut(NULL, f, 0.5f, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements_cut(&t, NULL, 0.5f, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements_cut(&t, f, 0.5f, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements_cut(&v, f, 0.5f, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_displacements(&t, f, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_contact_force(&t, f, out), TFIT_ERR_FAMILY);
    t.coef = NULL;
    assert_int_equal(tfit_displacements_cut(&t, f, 0.5f, out), TFIT_ERR_ARG);
    tf_model_free(m);
    tf_model_free(n);
}

/* tfit_model_check refuses shapes the evaluator cannot run: K = 0, K
 * beyond TFIT_CUT_MAX_INTERVALS, a third dim, a table of another size;
 * the host refuses the same shapes. */
static void check_refuses_bad_shapes(void **state)
{
    (void)state;
    tf_model *m = ramp();
    tfit_model t;
    tf_target_view(m, &t);
    uint32_t dims[3] = {1, 4, 0};
    t.dims = dims;
    t.dims_end = dims + 2;
    assert_int_equal(tfit_model_check(&t), TFIT_OK); /* the same dims elsewhere */
    const uint32_t bad[][2] = {{1, 0}, {1, TFIT_CUT_MAX_INTERVALS + 1}, {1, 3}, {2, 4}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        dims[0] = bad[i][0];
        dims[1] = bad[i][1];
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    }
    t.n_dims = 3;
    t.dims_end = dims + 3;
    dims[0] = 1;
    dims[1] = 4;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const uint32_t zero[2] = {1, 0}, big[2] = {1, TFIT_CUT_MAX_INTERVALS + 1};
    assert_null(tf_model_new(&ctx, "x", TFIT_FAMILY_CUT, 1, zero, 2));
    assert_null(tf_model_new(&ctx, "x", TFIT_FAMILY_CUT, 1, big, 2));
    tf_model_free(m);
}

static void op_counts_match_formulas(void **state)
{
    (void)state;
    tf_rng r = {77};
    for (int i = 0; i < 100; ++i) {
        tf_model *m = tf_random_model(&r, "c", TFIT_FAMILY_CUT, i % 2);
        tf_opcount want = tf_model_ops(m);
        float *out = malloc(3 * m->n_out * sizeof *out);
        const float inputs[][3] = {{0, 0, 0}, {1e30f, 0, 0}, {NAN, 1, 1}, {0.1f, 0.2f, 0.3f}};
        const float s[] = {0.3f, 2.0f, NAN, 1.0f};
        for (int k = 0; k < 4; ++k) {
            tf_opcount got = {0, 0, 0};
            tf_cut_ref_eval(m, inputs[k], s[k], out, &got);
            assert_int_equal(got.add, want.add);
            assert_int_equal(got.mul, want.mul);
        }
        free(out);
        tf_model_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(target_agrees_with_reference),
        cmocka_unit_test(knots_interpolation_and_clamp),
        cmocka_unit_test(api_arguments),
        cmocka_unit_test(check_refuses_bad_shapes),
        cmocka_unit_test(op_counts_match_formulas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
