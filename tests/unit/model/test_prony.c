/*
 * test_prony.c — the prony family (docs/header-format.md §5.6): the target's
 * step against the host reference, bit for bit, state included, over long
 * force histories; the discrete update against the continuous creep
 * response it discretises; what a NaN tick, reset, the clamp and the model
 * check do; the operation counts.
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

#include "force_sequence.h"
#include "model/golden.h"
#include "model/forms/prony.h"
#include "model/ref_eval.h"
#include "model/target_view.h"
#include "random_model.h"

/* The force scale that puts the sequence's 2^23 at the envelope radius
 * (a power of two at or above it). */
static float sequence_scale(const tf_model *m)
{
    double w = fabs((double)m->coef[3]) + fabs((double)m->coef[7]) + fabs((double)m->coef[11]);
    return ldexpf(1.0f, (int)ceil(log2(3.0 / w)) - 23);
}

/* Steps target and reference through n ticks of the force sequence,
 * comparing status, outputs and every state word at each; returns the
 * mismatching ticks. */
static unsigned long compare_run(const tf_model *m, uint32_t seed, unsigned long n)
{
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    const size_t n_out = 3 * (size_t)m->n_out, words = TFIT_PRONY_STATE_WORDS(m->dims[2]);
    float *want = malloc(n_out * sizeof *want), *got = malloc(n_out * sizeof *got);
    float s_ref[TFIT_PRONY_MAX_STATE], s_dev[TFIT_PRONY_MAX_STATE];
    tf_stateful_reset(m, s_ref);
    assert_int_equal(tfit_prony_reset(&t, s_dev), TFIT_OK);
    assert_memory_equal(s_ref, s_dev, words * sizeof *s_ref);
    tf_force_seq q;
    tf_seq_init(&q, seed);
    const float scale = sequence_scale(m);
    unsigned long bad = 0;
    for (unsigned long k = 0; k < n; ++k) {
        float f[3];
        tf_seq_force(&q, scale, f);
        tfit_status s1 = tf_stateful_step(m, s_ref, f, want, NULL);
        tfit_status s2 = tfit_prony_step(&t, s_dev, f, got);
        bad += s1 != s2 || memcmp(want, got, n_out * sizeof *got) != 0 ||
               memcmp(s_ref, s_dev, words * sizeof *s_ref) != 0;
    }
    free(want);
    free(got);
    return bad;
}

static void target_agrees_with_reference_over_long_histories(void **state)
{
    (void)state;
    tf_rng r = {0x9e37};
    unsigned long bad = 0;
    for (int i = 0; i < 60; ++i) {
        tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
        bad += compare_run(m, 1000u + (uint32_t)i, 20000);
        tf_model_free(m);
    }
    assert_int_equal(bad, 0);
}

/* A one-point prony model of degree 1 with K terms whose static map is
 * the identity (out = h: rows x, y, z = (0, 1, 0, 0), ...), its input map
 * the ball of radius R around centre; terms not set. */
static tf_model *identity_model(uint32_t terms, const double centre[3], double radius)
{
    const uint32_t dims[TFIT_PRONY_DIMS] = {1, 0, terms, 1000000}; /* 1 ms */
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "i", TFIT_FAMILY_PRONY, 1, dims, TFIT_PRONY_DIMS);
    tf_model_set_ball(m, centre, radius);
    float *rows = tf_model_tables(m) + 2 * terms;
    for (int c = 0; c < 3; ++c) {
        rows[4 * c + 1 + c] = 1.0f;
    }
    return m;
}

/* Exact creep of one term for a piecewise-linear input (first-order hold):
 * tau x' = g - x over a tick where g goes from g0 to g1. */
static double exact_lag(double x, double g0, double g1, double tick, double tau)
{
    const double r = tick / tau, a = exp(-r), b = 1.0 - (1.0 - a) / r;
    return a * x + (1.0 - a) * g0 + (g1 - g0) * b;
}

/* The float update realises the continuous creep h = g - sum w_k (g - x_k)
 * of a ramp, hold and release: within float rounding, not the O(T) error a
 * zero-order hold or a forward Euler step would leave. */
static void update_is_the_exact_first_order_hold(void **state)
{
    (void)state;
    const double origin[3] = {0, 0, 0};
    tf_model *m = identity_model(2, origin, 1.0);
    const double tau_asked[2] = {0.004, 0.35}, w[2] = {0.3, 0.45};
    double tau[2];
    for (int k = 0; k < 2; ++k) {
        tau[k] = tf_prony_set_term(m, (uint32_t)k, tau_asked[k], w[k]);
        assert_true(fabs(tau[k] / tau_asked[k] - 1) < 1e-3);
    }
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float st[TFIT_PRONY_MAX_STATE], out[3];
    tfit_prony_reset(&t, st);
    double x[2] = {0, 0}, g_prev = 0, worst = 0, worst_zoh = 0, x_zoh[2] = {0, 0};
    for (int n = 0; n < 3000; ++n) {
        /* press over 50 ticks to 0.8, hold, release at 1500 over 20 */
        double g = n < 50 ? 0.8 * n / 50 : (n < 1500 ? 0.8 : (n < 1520 ? 0.8 * (1520 - n) / 20 : 0));
        float f[3] = {(float)g, 0, 0};
        assert_int_equal(tfit_prony_step(&t, st, f, out), TFIT_OK);
        double h = g, h_zoh = g;
        for (int k = 0; k < 2; ++k) {
            x[k] = exact_lag(x[k], g_prev, (double)f[0], 1e-3, tau[k]);
            x_zoh[k] = exp(-1e-3 / tau[k]) * x_zoh[k] + (1 - exp(-1e-3 / tau[k])) * (double)f[0];
            h -= w[k] * ((double)f[0] - x[k]);
            h_zoh -= w[k] * ((double)f[0] - x_zoh[k]);
        }
        g_prev = (double)f[0];
        worst = fmax(worst, fabs((double)out[0] - h));
        worst_zoh = fmax(worst_zoh, fabs((double)out[0] - h_zoh));
    }
    print_message("first-order hold: worst |device - exact| %.2e; a zero-order hold differs by %.2e\n",
                  worst, worst_zoh);
    assert_true(worst < 2e-6);
    assert_true(worst_zoh > 100 * worst);
    tf_model_free(m);
}

/* A NaN or Inf tick leaves every state bit and zeroes the outputs; the
 * next valid tick continues as if the bad one never came. */
static void bad_tick_leaves_the_state(void **state)
{
    (void)state;
    tf_rng r = {77};
    for (int i = 0; i < 40; ++i) {
        tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
        tfit_model t;
        tf_target_view(m, &t);
        const size_t words = TFIT_PRONY_STATE_WORDS(m->dims[2]);
        float a[TFIT_PRONY_MAX_STATE], b[TFIT_PRONY_MAX_STATE];
        float *out = malloc(3 * m->n_out * sizeof *out), *out2 = malloc(3 * m->n_out * sizeof *out);
        tfit_prony_reset(&t, a);
        tf_force_seq q;
        tf_seq_init(&q, (uint32_t)i);
        for (int k = 0; k < 500; ++k) {
            float f[3];
            tf_seq_force(&q, sequence_scale(m), f);
            tfit_prony_step(&t, a, f, out);
        }
        memcpy(b, a, sizeof a);
        const float nan3[][3] = {{NAN, 0, 0}, {0, INFINITY, 0}, {1, 1, -INFINITY}};
        for (int k = 0; k < 3; ++k) {
            assert_int_equal(tfit_prony_step(&t, a, nan3[k], out), TFIT_ERR_INPUT);
            assert_memory_equal(a, b, words * sizeof *a);
            for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
                uint32_t bits;
                memcpy(&bits, &out[o], 4);
                assert_int_equal(bits, 0);
            }
        }
        const float f[3] = {m->coef[0], m->coef[1], m->coef[2]};
        tfit_prony_step(&t, a, f, out);
        tfit_prony_step(&t, b, f, out2);
        assert_memory_equal(out, out2, 3 * m->n_out * sizeof *out);
        free(out);
        free(out2);
        tf_model_free(m);
    }
}

/* Reset: the projected zero force, then zeros; a held force then relaxes
 * to the static map at g (h -> g as every e_k decays). */
static void reset_and_relaxation(void **state)
{
    (void)state;
    const double centre[3] = {0.25, 0, 0};
    tf_model *m = identity_model(1, centre, 2.0);
    tf_prony_set_term(m, 0, 0.01, 0.6);
    tfit_model t;
    tf_target_view(m, &t);
    float st[TFIT_PRONY_MAX_STATE], out[3];
    assert_int_equal(tfit_prony_reset(&t, st), TFIT_OK);
    assert_true(st[0] == -0.125f && st[1] == 0.0f && st[2] == 0.0f); /* W (0 - x0) */
    for (int w = 3; w < 6; ++w) {
        assert_true(st[w] == 0.0f);
    }
    const float f[3] = {1.25f, 0, 0}; /* g = 0.5 */
    tfit_prony_step(&t, st, f, out);
    const double ramp = 0.6 * (1 - exp(-0.1)) / 0.1 * 0.625; /* the term's lag after the tick */
    assert_true(fabs((double)out[0] - (0.5 - ramp)) < 1e-6);
    for (int n = 0; n < 2000; ++n) {
        tfit_prony_step(&t, st, f, out);
    }
    assert_true(fabs((double)out[0] - 0.5) < 1e-6);
    tf_model_free(m);
}

/* Gains beyond a physical creep function drive h out of [-1, 1]: the clamp
 * holds it there (the reference agrees), and no output is NaN or Inf. */
static void clamp_keeps_h_on_the_cube(void **state)
{
    (void)state;
    const uint32_t dims[TFIT_PRONY_DIMS] = {8, 0, 1, 1000};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "k", TFIT_FAMILY_PRONY, 1, dims, TFIT_PRONY_DIMS);
    float *pt = tf_model_tables(m);
    pt[0] = 1.0f - 0x1p-19f;
    pt[1] = -0x1p40f;
    float *rows = pt + 2;
    for (uint32_t i = 0; i < 3 * tf_terms(8); ++i) {
        rows[i] = 1.0f;
    }
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float st[TFIT_PRONY_MAX_STATE], out[3], want[3], sr[TFIT_PRONY_MAX_STATE];
    tfit_prony_reset(&t, st);
    tf_stateful_reset(m, sr);
    const float f[2][3] = {{1, 0, 0}, {-1, 0.5f, 0}};
    for (int n = 0; n < 200; ++n) {
        tfit_prony_step(&t, st, f[n % 2], out);
        tf_stateful_step(m, sr, f[n % 2], want, NULL);
        assert_memory_equal(out, want, sizeof out);
        for (int c = 0; c < 3; ++c) {
            assert_true(isfinite(out[c]) && fabsf(out[c]) <= (float)tf_terms(8));
        }
    }
    tf_model_free(m);
}

static void check_refuses_what_could_overflow(void **state)
{
    (void)state;
    tf_rng r = {5};
    tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
    while (m->dims[2] == 0) {
        tf_model_free(m);
        m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    float *pt = tf_model_tables(m);
    const float keep = pt[0];
    const float bad_decays[] = {1.0f, 1.0f - 0x1p-21f, -0x1p-30f, NAN};
    for (size_t i = 0; i < sizeof bad_decays / sizeof *bad_decays; ++i) {
        pt[0] = bad_decays[i];
        assert_int_not_equal(tf_model_validate(&ctx, m), 0);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    }
    pt[0] = keep;
    pt[1] = 0x1p65f;
    assert_int_not_equal(tf_model_validate(&ctx, m), 0);
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    tf_model_free(m);
}

static void api_arguments(void **state)
{
    (void)state;
    tf_rng r = {8};
    tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
    tf_model *n = tf_random_model(&r, "n", TFIT_FAMILY_NODAL, 1);
    tfit_model t, u;
    tf_target_view(m, &t);
    tf_target_view(n, &u);
    float st[TFIT_PRONY_MAX_STATE], out[3 * 8];
    const float f[3] = {0, 0, 0};
    assert_int_equal(tfit_prony_reset(NULL, st), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_reset(&t, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_reset(&u, st), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_prony_reset(&t, st), TFIT_OK);
    assert_int_equal(tfit_prony_step(&t, NULL, f, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_step(&t, st, NULL, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_step(&t, st, f, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_step(&u, st, f, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_displacements(&t, f, out), TFIT_ERR_FAMILY);
    t.coef = NULL;
    assert_int_equal(tfit_prony_step(&t, st, f, out), TFIT_ERR_ARG);
    tf_model_free(m);
    tf_model_free(n);
}

static void op_counts_match_formulas(void **state)
{
    (void)state;
    tf_rng r = {31};
    for (int i = 0; i < 100; ++i) {
        tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, i % 2);
        tf_opcount want = tf_model_ops(m);
        float st[TFIT_PRONY_MAX_STATE];
        float *out = malloc(3 * m->n_out * sizeof *out);
        tf_stateful_reset(m, st);
        const float inputs[][3] = {{0, 0, 0}, {1e30f, 0, 0}, {NAN, 1, 1}, {0.1f, 0.2f, 0.3f}};
        for (int k = 0; k < 4; ++k) {
            tf_opcount got = {0, 0, 0};
            tf_stateful_step(m, st, inputs[k], out, &got);
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
        cmocka_unit_test(target_agrees_with_reference_over_long_histories),
        cmocka_unit_test(update_is_the_exact_first_order_hold),
        cmocka_unit_test(bad_tick_leaves_the_state),
        cmocka_unit_test(reset_and_relaxation),
        cmocka_unit_test(clamp_keeps_h_on_the_cube),
        cmocka_unit_test(check_refuses_what_could_overflow),
        cmocka_unit_test(api_arguments),
        cmocka_unit_test(op_counts_match_formulas),
    };
    return cmocka_run_group_tests_name("prony", tests, NULL, NULL);
}
