/*
 * test_resonant.c — the resonant family (docs/header-format.md §5.8): the
 * transition matrix against its closed form; the device's update against
 * the exact step response of a damped oscillator under a held force; the
 * target's step against the host reference, bit for bit, state included;
 * what a NaN tick, reset and the model check do; the refusal of modes the
 * float recursion cannot carry, with the tick they need; the operation
 * counts.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "force_sequence.h"
#include "model/ref_eval.h"
#include "model/forms/resonant.h"
#include "model/target_view.h"
#include "random_model.h"

/* exp(theta [[0, 1], [-1, -2 zeta]]) in closed form: e^{-zeta theta}
 * (C I + S (M + zeta I)), C = cos or cosh (beta theta), S = sin or sinh
 * (beta theta) / beta, beta = sqrt|1 - zeta^2|. */
static void closed_form(double theta, double zeta, double f[4])
{
    const double beta = sqrt(fabs(1 - zeta * zeta)), e = exp(-zeta * theta);
    const double c = zeta < 1 ? cos(beta * theta) : cosh(beta * theta);
    const double s = zeta < 1 ? sin(beta * theta) / beta : sinh(beta * theta) / beta;
    f[0] = e * (c + zeta * s);
    f[1] = e * s;
    f[2] = -e * s;
    f[3] = e * (c - zeta * s);
}

static void transition_is_the_matrix_exponential(void **state)
{
    (void)state;
    const double cases[][2] = {{0.3, 0.05}, {1.4, 0.002}, {0.01, 0.5}, {0.7, 1.5}, {1e-3, 0.9}};
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        double f[4], g[4];
        tf_resonant_transition(cases[i][0], cases[i][1], f);
        closed_form(cases[i][0], cases[i][1], g);
        for (int j = 0; j < 4; ++j) {
            assert_true(fabs(f[j] - g[j]) < 1e-14);
        }
        assert_true(tf_resonant_norm2(f) < 1.0);
    }
}

/* A one-point model of degree 1 with K modes whose static map is the
 * identity (out = h), its input map the unit ball at the origin. */
static tf_model *identity_model(uint32_t modes, uint32_t tick_ns)
{
    const uint32_t dims[TFIT_RESONANT_DIMS] = {1, 0, modes, tick_ns};
    const double origin[3] = {0, 0, 0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "i", TFIT_FAMILY_RESONANT, 1, dims, TFIT_RESONANT_DIMS);
    tf_model_set_ball(m, origin, 1.0);
    float *rows = tf_model_tables(m) + 7 * modes;
    for (int c = 0; c < 3; ++c) {
        rows[4 * c + 1 + c] = 1.0f;
    }
    return m;
}

/* A force stepped to 0.5 at tick 0 and held: tick n outputs the
 * oscillator at time (n + 1) T (the tick's end, zero-order hold),
 * 0.5 (1 - e^{-zeta w t} (cos w_d t + zeta / beta sin w_d t)), within float
 * rounding over 4000 ticks (60 periods); a first-order hold or the output
 * at the tick's start would differ by O(w T). */
static void step_response_is_exact_at_the_ticks(void **state)
{
    (void)state;
    tf_model *m = identity_model(1, 1000000);
    const double omega = 2 * 3.14159265358979 * 15, zeta = 0.03, w[3] = {1, 1, 1};
    tf_resonant_set_mode(m, 0, omega, zeta, w);
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float st[TFIT_RESONANT_MAX_STATE], out[3];
    assert_int_equal(tfit_resonant_reset(&t, st), TFIT_OK);
    const float f[3] = {0.5f, 0, 0};
    const double beta = sqrt(1 - zeta * zeta);
    double worst = 0, worst_start = 0, peak = 0;
    for (int n = 0; n < 4000; ++n) {
        assert_int_equal(tfit_resonant_step(&t, st, f, out), TFIT_OK);
        const double te = (n + 1) * 1e-3, ts = n * 1e-3;
        const double ye = 0.5 * (1 - exp(-zeta * omega * te) *
                                         (cos(beta * omega * te) + zeta / beta * sin(beta * omega * te)));
        const double ys = 0.5 * (1 - exp(-zeta * omega * ts) *
                                         (cos(beta * omega * ts) + zeta / beta * sin(beta * omega * ts)));
        worst = fmax(worst, fabs((double)out[0] - ye));
        worst_start = fmax(worst_start, fabs((double)out[0] - ys));
        peak = fmax(peak, (double)out[0]);
    }
    print_message("step: peak %.4f (overshoot), worst |device - exact| %.2e, against the "
                  "tick's start %.2e\n", peak, worst, worst_start);
    assert_true(peak > 0.9);       /* it rings: nearly twice the static 0.5 */
    assert_true(worst < 2e-6);
    assert_true(worst_start > 1e4 * worst);
    tf_model_free(m);
}

static void realised_mode_is_the_asked_one(void **state)
{
    (void)state;
    tf_model *m = identity_model(2, 100000); /* 100 us */
    const double w[3] = {0.5, -0.25, 1};
    tf_resonant_set_mode(m, 0, 2000.0, 0.02, w);
    tf_resonant_set_mode(m, 1, 9000.0, 1.3, w);
    const double want[2][2] = {{2000.0, 0.02}, {9000.0, 1.3}};
    for (uint32_t k = 0; k < 2; ++k) {
        double omega, zeta, ww[3];
        tf_resonant_get_mode(m, k, &omega, &zeta, ww);
        print_message("mode %u: omega %.9g (asked %g), zeta %.9g (asked %g)\n", k, omega,
                      want[k][0], zeta, want[k][1]);
        assert_true(fabs(omega / want[k][0] - 1) < 1e-4);
        assert_true(fabs(zeta / want[k][1] - 1) < 1e-3);
        assert_true(ww[0] == 0.5 && ww[1] == -0.25 && ww[2] == 1);
    }
    tf_model_free(m);
}

/* A slow, lightly damped mode at a fast tick: the rounded F no longer
 * contracts by 2^-20 per tick; refused with the tick that would do, which
 * passes.  A mode the tick does not resolve is refused too. */
static void ticks_the_float_recursion_cannot_carry_are_refused(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const double omega = 2 * 3.14159265358979 * 20, zeta = 0.01;
    assert_int_equal(tf_resonant_params_check(&ctx, omega, zeta, 1e-3), 0);
    assert_int_equal(tf_resonant_params_check(&ctx, omega, zeta, 1e-5), 1);
    print_message("%s\n", ctx.err);
    const char *at = strstr(ctx.err, "fit with a tick of at least ");
    assert_non_null(at);
    const double need = 1e-6 * strtod(at + strlen("fit with a tick of at least "), NULL);
    assert_true(need > 1e-5 && need < 1e-3);
    assert_int_equal(tf_resonant_params_check(&ctx, omega, zeta, need), 0);
    assert_int_equal(tf_resonant_params_check(&ctx, omega, zeta, need * 0.75), 1);
    assert_int_equal(tf_resonant_params_check(&ctx, 2000.0, 0.1, 1e-3), 1);
    print_message("%s\n", ctx.err);
    assert_non_null(strstr(ctx.err, "does not resolve it"));
}

static unsigned long compare_run(const tf_model *m, uint32_t seed, unsigned long n)
{
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    const size_t n_out = 3 * (size_t)m->n_out, words = TFIT_RESONANT_STATE_WORDS(m->dims[2]);
    float *want = malloc(n_out * sizeof *want), *got = malloc(n_out * sizeof *got);
    float s_ref[TFIT_RESONANT_MAX_STATE], s_dev[TFIT_RESONANT_MAX_STATE];
    tf_stateful_reset(m, s_ref);
    assert_int_equal(tfit_resonant_reset(&t, s_dev), TFIT_OK);
    assert_memory_equal(s_ref, s_dev, words * sizeof *s_ref);
    tf_force_seq q;
    tf_seq_init(&q, seed);
    const double w = fabs((double)m->coef[3]) + fabs((double)m->coef[7]) + fabs((double)m->coef[11]);
    const float scale = ldexpf(1.0f, (int)ceil(log2(3.0 / w)) - 23);
    unsigned long bad = 0;
    for (unsigned long k = 0; k < n; ++k) {
        float f[3];
        tf_seq_force(&q, scale, f);
        tfit_status s1 = tf_stateful_step(m, s_ref, f, want, NULL);
        tfit_status s2 = tfit_resonant_step(&t, s_dev, f, got);
        bad += s1 != s2 || memcmp(want, got, n_out * sizeof *got) != 0 ||
               memcmp(s_ref, s_dev, words * sizeof *s_ref) != 0;
        for (size_t w2 = 0; w2 < words; ++w2) {
            bad += !isfinite(s_dev[w2]);
        }
    }
    free(want);
    free(got);
    return bad;
}

static void target_agrees_with_reference_over_long_histories(void **state)
{
    (void)state;
    tf_rng r = {0x7e50};
    unsigned long bad = 0;
    for (int i = 0; i < 40; ++i) {
        tf_model *m = tf_random_model(&r, "r", TFIT_FAMILY_RESONANT, 1);
        bad += compare_run(m, 2000u + (uint32_t)i, 10000);
        tf_model_free(m);
    }
    assert_int_equal(bad, 0);
}

/* A NaN or Inf tick leaves every state bit and zeroes the outputs. */
static void bad_tick_leaves_the_state(void **state)
{
    (void)state;
    tf_rng r = {78};
    for (int i = 0; i < 30; ++i) {
        tf_model *m = tf_random_model(&r, "r", TFIT_FAMILY_RESONANT, 1);
        tfit_model t;
        tf_target_view(m, &t);
        const size_t words = TFIT_RESONANT_STATE_WORDS(m->dims[2]);
        float a[TFIT_RESONANT_MAX_STATE], b[TFIT_RESONANT_MAX_STATE];
        float *out = malloc(3 * m->n_out * sizeof *out);
        tfit_resonant_reset(&t, a);
        const float push[3] = {m->coef[0] + 0.5f / m->coef[3], m->coef[1], m->coef[2]};
        for (int k = 0; k < 50; ++k) {
            tfit_resonant_step(&t, a, push, out);
        }
        memcpy(b, a, sizeof a);
        const float nan3[][3] = {{NAN, 0, 0}, {0, INFINITY, 0}, {1, 1, -INFINITY}};
        for (int k = 0; k < 3; ++k) {
            assert_int_equal(tfit_resonant_step(&t, a, nan3[k], out), TFIT_ERR_INPUT);
            assert_memory_equal(a, b, words * sizeof *a);
            for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
                uint32_t bits;
                memcpy(&bits, &out[o], 4);
                assert_int_equal(bits, 0);
            }
        }
        free(out);
        tf_model_free(m);
    }
}

/* Held long enough, the response settles at the static map (h -> g). */
static void settles_at_the_static_map(void **state)
{
    (void)state;
    tf_model *m = identity_model(2, 1000000);
    const double w[3] = {0.7, 0.7, 0.7}, w2[3] = {0.3, -0.2, 0.3};
    tf_resonant_set_mode(m, 0, 90.0, 0.05, w);
    tf_resonant_set_mode(m, 1, 700.0, 0.2, w2);
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float st[TFIT_RESONANT_MAX_STATE], out[3];
    tfit_resonant_reset(&t, st);
    const float f[3] = {0.3f, -0.2f, 0.1f};
    for (int n = 0; n < 5000; ++n) {
        tfit_resonant_step(&t, st, f, out);
    }
    for (int c = 0; c < 3; ++c) {
        assert_true(fabs((double)out[c] - (double)f[c]) < 1e-6);
    }
    tf_model_free(m);
}

static void check_refuses_what_could_overflow(void **state)
{
    (void)state;
    tf_model *m = identity_model(1, 1000000);
    const double w[3] = {1, 1, 1};
    tf_resonant_set_mode(m, 0, 90.0, 0.05, w);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_model_validate(&ctx, m), 0);
    float *pt = tf_model_tables(m);
    const float keep = pt[0];
    pt[0] = 1.0f + 0x1p-10f; /* beyond the device's magnitude limit */
    assert_int_not_equal(tf_model_validate(&ctx, m), 0);
    tfit_model t;
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    pt[0] = keep;
    pt[3] = 1.0f; /* within magnitude, but F no longer contracts: the host refuses */
    assert_int_not_equal(tf_model_validate(&ctx, m), 0);
    print_message("%s\n", ctx.err);
    assert_non_null(strstr(ctx.err, "keep the state finite"));
    pt[3] = tf_model_tables(m)[3];
    pt[4] = 0x1p11f;
    assert_int_not_equal(tf_model_validate(&ctx, m), 0);
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    tf_model_free(m);
}

static void api_arguments(void **state)
{
    (void)state;
    tf_rng r = {9};
    tf_model *m = tf_random_model(&r, "r", TFIT_FAMILY_RESONANT, 1);
    tf_model *p = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, 1);
    tfit_model t, u;
    tf_target_view(m, &t);
    tf_target_view(p, &u);
    float st[TFIT_RESONANT_MAX_STATE], out[3 * 8];
    const float f[3] = {0, 0, 0};
    assert_int_equal(tfit_resonant_reset(NULL, st), TFIT_ERR_ARG);
    assert_int_equal(tfit_resonant_reset(&t, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_resonant_reset(&u, st), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_prony_reset(&t, st), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_resonant_reset(&t, st), TFIT_OK);
    assert_int_equal(tfit_resonant_step(&t, NULL, f, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_resonant_step(&t, st, NULL, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_resonant_step(&t, st, f, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_resonant_step(&u, st, f, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_displacements(&t, f, out), TFIT_ERR_FAMILY);
    tf_model_free(m);
    tf_model_free(p);
}

static void op_counts_match_formulas(void **state)
{
    (void)state;
    tf_rng r = {32};
    for (int i = 0; i < 60; ++i) {
        tf_model *m = tf_random_model(&r, "r", TFIT_FAMILY_RESONANT, i % 2);
        tf_opcount want = tf_model_ops(m);
        float st[TFIT_RESONANT_MAX_STATE];
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
        cmocka_unit_test(transition_is_the_matrix_exponential),
        cmocka_unit_test(step_response_is_exact_at_the_ticks),
        cmocka_unit_test(realised_mode_is_the_asked_one),
        cmocka_unit_test(ticks_the_float_recursion_cannot_carry_are_refused),
        cmocka_unit_test(target_agrees_with_reference_over_long_histories),
        cmocka_unit_test(bad_tick_leaves_the_state),
        cmocka_unit_test(settles_at_the_static_map),
        cmocka_unit_test(check_refuses_what_could_overflow),
        cmocka_unit_test(api_arguments),
        cmocka_unit_test(op_counts_match_formulas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
