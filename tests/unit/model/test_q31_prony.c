/*
 * test_q31_prony.c — the prony family's Q31 form (docs/q31-format.md §8):
 * the target step (target/src/tfit_q31_prony.c) against the host's integer
 * reference (host/model/q31_ref.c) word for word, status, outputs and
 * state, on random models and force words; the state bound of §8 on the
 * worst history for it; the model check's and the quantiser's refusals;
 * the error Q31 adds against the exact model.
 */
#include <limits.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "target/src/tfit_q31_internal.h"

#include "model/q31.h"
#include "model/target_view.h"
#include "random_model.h"

#define MAX_STATE TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)

/* A prony model with a nodal static map of degree p, n_out points, and K
 * terms of decay a (float) and weight w each. */
static tf_model *prony_model(tf_rng *r, uint32_t p, uint32_t n_out, uint32_t terms, float a,
                             double w)
{
    const uint32_t dims[TFIT_PRONY_DIMS] = {p, 0, terms, 1000000u};
    tf_model *m = tf_random_model_of(r, "creep", TFIT_FAMILY_PRONY, dims, TFIT_PRONY_DIMS, n_out);
    assert_non_null(m);
    float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < terms; ++k) {
        pt[2 * k] = a;
        pt[2 * k + 1] = (float)(w * (1.0 - (double)a) / -log((double)a));
    }
    return m;
}

/* Target and reference agree on status, outputs and state at every tick. */
static void target_matches_reference(void **state)
{
    (void)state;
    tf_rng r = {1414};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int models = 0, refused = 0;
    long ticks = 0, clamped = 0;
    for (int i = 0; i < 600; ++i) {
        tf_model *m = tf_random_model(&r, "p", TFIT_FAMILY_PRONY, i % 4 != 0);
        assert_non_null(m);
        tf_q31 *q = tf_q31_quantise(&ctx, m);
        if (q == NULL) { /* a modal static map, a term beyond §8's range, an elongated envelope */
            assert_true(strstr(ctx.err, "modal static map") || strstr(ctx.err, "outside 0 <= a") ||
                        strstr(ctx.err, "elongated"));
            ++refused;
            tf_model_free(m);
            continue;
        }
        tfit_model_q31 t;
        tf_target_view_q31(q, &t);
        assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
        const uint32_t words = TFIT_PRONY_Q31_STATE_WORDS(q->terms);
        int32_t sa[MAX_STATE], sb[MAX_STATE];
        assert_int_equal(tfit_prony_reset_q31(&t, sa), TFIT_OK);
        tf_q31_ref_prony_reset(q, sb);
        assert_memory_equal(sa, sb, words * sizeof *sa);
        int32_t *a = malloc(3 * m->n_out * sizeof *a), *b = malloc(3 * m->n_out * sizeof *b);
        int32_t golden[TF_Q31_GOLDEN_MAX][3];
        size_t ng = tf_q31_golden_inputs(q, m, (uint64_t)i, golden);
        for (size_t v = 0; v < ng + 200; ++v) {
            int32_t x[3];
            for (int k = 0; k < 3; ++k) {
                x[k] = v < ng ? golden[v][k] : tf_random_q31_word(&r);
            }
            tfit_status st = tfit_prony_step_q31(&t, sa, x, a);
            assert_int_equal(st, tf_q31_ref_prony_step(q, sb, x, b));
            assert_memory_equal(a, b, 3 * m->n_out * sizeof *a);
            assert_memory_equal(sa, sb, words * sizeof *sa);
            clamped += st == TFIT_CLAMPED;
            ++ticks;
        }
        free(a);
        free(b);
        tf_q31_free(q);
        tf_model_free(m);
        ++models;
    }
    printf("q31 prony: %d models (%d refused), %ld ticks (%ld clamped): target == reference\n",
           models, refused, ticks, clamped);
    assert_true(models > 150 && clamped > ticks / 10);
}

/* §8's bound, |z| <= 2^30 + 16 + 2^16 in Q29 from rest, on the history that
 * drives z hardest: the force jumping between opposite points of the
 * envelope's boundary and held until the terms have settled, with |D| at
 * its largest and the slowest decay the check accepts. */
static void state_within_its_bound(void **state)
{
    (void)state;
    tf_rng r = {17};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const float slow = 1.0f - 0x1p-17f; /* word 2^31 - 2^14, the largest */
    const struct {
        float a;
        double w;
        uint32_t hold;
    } cases[] = {{0.5f, 1.0, 64}, {0.999f, 1.0, 20000}, {slow, 1.0, 1u << 20}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        tf_model *m = prony_model(&r, 1, 2, 1, cases[c].a, cases[c].w);
        tf_q31 *q = tf_q31_quantise(&ctx, m);
        assert_non_null(q);
        tfit_model_q31 t;
        tf_target_view_q31(q, &t);
        assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
        int32_t s[MAX_STATE], out[6];
        int64_t zmax = 0;
        tfit_prony_reset_q31(&t, s);
        for (uint32_t n = 0; n < 6 * cases[c].hold; ++n) {
            const int32_t v = (n / cases[c].hold) % 2 ? INT32_MAX : INT32_MIN;
            const int32_t x[3] = {v, v, v};
            tfit_prony_step_q31(&t, s, x, out);
            for (int i = 3; i < 6; ++i) {
                zmax = llabs((long long)s[i]) > zmax ? llabs((long long)s[i]) : zmax;
            }
        }
        printf("q31 prony: a = %.9g, D word %d: largest |z| = 2^30 %+lld units (bound 2^30 + "
               "16 + 2^16)\n",
               (double)cases[c].a, q->q[TFIT_Q31_MAP_WORDS + 2], (long long)(zmax - (1 << 30)));
        assert_true(zmax <= (1 << 30) + 16 + (1 << 16));
        /* the jump between opposite boundary points moves some g_i by at
         * least 2/sqrt(3): z (Q29) reaches D (Q30) / sqrt(3) */
        assert_true(zmax > q->q[TFIT_Q31_MAP_WORDS + 2] / 2);
        tf_q31_free(q);
        tf_model_free(m);
    }
}

/* A damaged state is no undefined behaviour: the filtered input is
 * saturated, the outputs stay within the rows' range proof. */
static void damaged_state_is_defined(void **state)
{
    (void)state;
    tf_rng r = {23};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = prony_model(&r, 2, 3, 3, 0.99f, 0.3);
    tf_q31 *q = tf_q31_quantise(&ctx, m);
    assert_non_null(q);
    tfit_model_q31 t;
    tf_target_view_q31(q, &t);
    int32_t sa[MAX_STATE], sb[MAX_STATE], a[9], b[9];
    const uint32_t words = TFIT_PRONY_Q31_STATE_WORDS(3);
    for (int trial = 0; trial < 2000; ++trial) {
        for (uint32_t w = 0; w < words; ++w) {
            sa[w] = sb[w] = tf_random_q31_word(&r);
        }
        const int32_t x[3] = {tf_random_q31_word(&r), tf_random_q31_word(&r),
                              tf_random_q31_word(&r)};
        assert_int_equal(tfit_prony_step_q31(&t, sa, x, a), tf_q31_ref_prony_step(q, sb, x, b));
        assert_memory_equal(a, b, sizeof a);
        assert_memory_equal(sa, sb, words * sizeof *sa);
    }
    tf_q31_free(q);
    tf_model_free(m);
}

static void check_and_quantiser_refuse(void **state)
{
    (void)state;
    tf_rng r = {31};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = prony_model(&r, 2, 4, 2, 0.9f, 0.4);
    tf_q31 *q = tf_q31_quantise(&ctx, m);
    assert_non_null(q);
    tfit_model_q31 t;
    tf_target_view_q31(q, &t);
    assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
    int32_t s[MAX_STATE], out[12];
    const int32_t x[3] = {0, 0, 0};
    assert_int_equal(tfit_prony_step_q31(NULL, s, x, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_step_q31(&t, NULL, x, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_prony_reset_q31(&t, NULL), TFIT_ERR_ARG);
    /* a prony table is no nodal model, and the reverse */
    assert_int_equal(tfit_displacements_q31(&t, x, out), TFIT_ERR_FAMILY);
    t.family = TFIT_FAMILY_NODAL;
    assert_int_equal(tfit_prony_step_q31(&t, s, x, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_prony_reset_q31(&t, s), TFIT_ERR_FAMILY);
    /* terms outside §8's range, with a matching CRC */
    const uint32_t ka = TFIT_Q31_MAP_WORDS + 1, kd = TFIT_Q31_MAP_WORDS + 2;
    const struct {
        uint32_t index;
        int32_t value;
        tfit_status want;
    } bad[] = {{ka, TFIT_Q31_PRONY_MAX_A + 1, TFIT_ERR_RANGE},
               {ka, -1, TFIT_ERR_RANGE},
               {kd, (1 << 30) + 1, TFIT_ERR_RANGE},
               {kd, -(1 << 30) - 1, TFIT_ERR_RANGE},
               {TFIT_Q31_MAP_WORDS, 3, TFIT_ERR_SIZE},
               {TFIT_Q31_MAP_WORDS, TFIT_PRONY_MAX_TERMS + 1, TFIT_ERR_SIZE},
               {TFIT_Q31_MAP_WORDS, -1, TFIT_ERR_SIZE}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        const int32_t keep = q->q[bad[i].index];
        q->q[bad[i].index] = bad[i].value;
        tf_target_view_q31(q, &t);
        assert_int_equal(tfit_model_check_q31(&t), bad[i].want);
        q->q[bad[i].index] = keep;
    }
    tf_target_view_q31(q, &t);
    assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
    tf_q31_free(q);
    /* a term slower than the bound allows, a weight beyond 1: refused */
    m->coef[TFIT_INPUT_MAP_FLOATS] = 1.0f - 0x1p-19f;
    assert_null(tf_q31_quantise(&ctx, m));
    assert_non_null(strstr(ctx.err, "outside 0 <= a"));
    m->coef[TFIT_INPUT_MAP_FLOATS] = 0.9f;
    m->coef[TFIT_INPUT_MAP_FLOATS + 1] = 1.5f;
    assert_null(tf_q31_quantise(&ctx, m));
    tf_model_free(m);
}

/* What Q31 adds against the exact model over a press-hold-release history
 * is a few output units in the last place; a term's decay off by one unit
 * of its word shows. */
static void added_error_is_small(void **state)
{
    (void)state;
    tf_rng r = {41};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = prony_model(&r, 2, 8, 2, 0.999f, 0.3);
    tf_q31 *q = tf_q31_quantise(&ctx, m);
    assert_non_null(q);
    tf_q31_measure(q, m, 7, 2000);
    const double lsb = ldexp(1.0, q->out_exp - 31);
    printf("q31 prony: added error %.3g (%.1f output LSB) over %u ticks, float32 path %.3g\n",
           q->added_error, q->added_error / lsb, q->error_cases, q->float_error);
    assert_int_equal(q->error_cases, 2000 * TF_Q31_PRONY_TICKS_PER_CASE);
    assert_true(q->added_error <= 64 * lsb && q->float_error > 0);
    q->q[TFIT_Q31_MAP_WORDS + 1] -= 1 << 12; /* tau 0.2 % short */
    tf_q31_measure(q, m, 7, 2000);
    assert_true(q->added_error > 1000 * lsb);
    tf_q31_free(q);
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(target_matches_reference),
        cmocka_unit_test(state_within_its_bound),
        cmocka_unit_test(damaged_state_is_defined),
        cmocka_unit_test(check_and_quantiser_refuse),
        cmocka_unit_test(added_error_is_small),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
