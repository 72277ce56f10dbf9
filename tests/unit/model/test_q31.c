/*
 * test_q31.c — the Q31 path: target code (target/src/tfit_q31_*.c) against
 * the host's independent integer reference (host/model/q31_ref.c) on random
 * models and inputs, the Armv6-M multiply decomposition against native
 * 64-bit products, the model check's rejections, and the error the
 * quantisation adds.
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

#define TFIT_Q31_PORTABLE_MUL /* the Armv6-M helpers, on this machine */
#include "target/src/tfit_q31_internal.h"

#include "fitting/families/family.h"
#include "model/q31.h"
#include "random_model.h"
#include "model/target_view.h"

static void portable_multiplies_are_exact(void **state)
{
    (void)state;
    tf_rng r = {31};
    const uint32_t edges[] = {0u, 1u, 0xffffu, 0x10000u, 0x7fffffffu, 0x80000000u, 0xffffffffu};
    for (int i = 0; i < 200000; ++i) {
        uint32_t a = i < 49 ? edges[i % 7] : (uint32_t)tf_rng_next(&r);
        uint32_t b = i < 49 ? edges[i / 7] : (uint32_t)tf_rng_next(&r);
        assert_true(q_umul(a, b) == (uint64_t)a * b);
        assert_true(q_smul((int32_t)a, (int32_t)b) ==
                    (uint64_t)((int64_t)(int32_t)a * (int64_t)(int32_t)b));
        if ((b >> 31) == 0 || (a & 0x7fffffffu) < (1u << 30)) {
            assert_true(q_sumul((int32_t)a, b) == (uint64_t)((int64_t)(int32_t)a * (int64_t)b));
        }
    }
    for (int i = 0; i < 100000; ++i) { /* bit length over every magnitude */
        uint32_t x = ((uint32_t)tf_rng_next(&r) | 0x80000000u) >> (i % 32), n = 0, v = x;
        while (v != 0) {
            ++n, v >>= 1;
        }
        assert_int_equal(q_bit_length(x), n);
    }
    for (uint32_t k = 0; k < 32; ++k) {
        assert_int_equal(q_sra32(0x80000000u, k), INT32_MIN >> k);
        assert_int_equal(q_sra32(12345u, k), 12345 >> k);
    }
}

/* Target and reference agree on every word, for every input kind. */
static void target_matches_reference(void **state)
{
    (void)state;
    tf_rng r = {2026};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int models = 0, refused = 0;
    int64_t inputs = 0, clamped = 0;
    int32_t gmax = 0;
    for (int i = 0; i < 400; ++i) {
        char name[32];
        snprintf(name, sizeof name, "m%d", i);
        /* one in four full size (up to 400 points, p up to 8) */
        tf_model *m = tf_random_model(&r, name, i % 3 ? TFIT_FAMILY_NODAL : TFIT_FAMILY_CONTACT,
                                      i % 4 != 0);
        assert_non_null(m);
        tf_q31 *q = tf_q31_quantise(&ctx, m);
        if (q == NULL) { /* only a too elongated envelope may refuse */
            assert_non_null(strstr(ctx.err, "elongated"));
            ++refused;
            tf_model_free(m);
            continue;
        }
        tfit_model_q31 t;
        tf_target_view_q31(q, &t);
        assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
        int32_t *a = malloc(3 * m->n_out * sizeof *a), *b = malloc(3 * m->n_out * sizeof *b);
        int32_t golden[TF_Q31_GOLDEN_MAX][3];
        size_t ng = tf_q31_golden_inputs(q, m, (uint64_t)i, golden);
        for (size_t v = 0; v < ng + 40; ++v) {
            int32_t x[3], g[3];
            for (int k = 0; k < 3; ++k) {
                x[k] = v < ng ? golden[v][k] : tf_random_q31_word(&r);
            }
            tfit_status st = m->family == TFIT_FAMILY_CONTACT ? tfit_contact_force_q31(&t, x, a)
                                                              : tfit_displacements_q31(&t, x, a);
            assert_int_equal(st, tf_q31_ref_eval(q, x, b, g));
            assert_memory_equal(a, b, 3 * m->n_out * sizeof *a);
            for (int k = 0; k < 3; ++k) {
                gmax = abs(g[k]) > gmax ? abs(g[k]) : gmax;
            }
            clamped += st == TFIT_CLAMPED;
            ++inputs;
        }
        free(a);
        free(b);
        tf_q31_free(q);
        tf_model_free(m);
        ++models;
    }
    printf("q31: %d models (%d refused), %lld inputs (%lld clamped): target == reference; "
           "largest |g| %d (1.0 = %d)\n",
           models, refused, (long long)inputs, (long long)clamped, gmax, 1 << 30);
    assert_true(models > 350 && clamped > inputs / 10);
    /* the projection lands on the unit ball to a few units in the last place */
    assert_true(gmax <= (1 << 30) + 16);
}

static tf_model *ball_model(tfit_family f, uint32_t p, double radius, uint64_t seed)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    uint32_t dims[1] = {p};
    tf_model *m = tf_model_new(&ctx, "ball", f, f == TFIT_FAMILY_CONTACT ? 1 : 5, dims, 1);
    const double centre[3] = {0.1 * radius, -0.2 * radius, 0.05 * radius};
    tf_model_set_ball(m, centre, radius);
    tf_rng r = {seed};
    float *c = tf_model_tables(m);
    for (uint32_t i = 0; i < m->n_coef - TFIT_INPUT_MAP_FLOATS; ++i) {
        c[i] = (float)tf_rng_range(&r, -3, 3);
    }
    return m;
}

static void check_rejects_damage(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = ball_model(TFIT_FAMILY_NODAL, 2, 1.0, 1);
    tf_q31 *q = tf_q31_quantise(&ctx, m);
    assert_non_null(q);
    tfit_model_q31 t;
    tf_target_view_q31(q, &t);
    assert_int_equal(tfit_model_check_q31(&t), TFIT_OK);
    assert_int_equal(tfit_model_check_q31(NULL), TFIT_ERR_ARG);
    t.api_version = 1; /* the monomial Q31 basis of API 2 */
    assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_VERSION);
    tf_target_view_q31(q, &t);
    t.family = TFIT_FAMILY_MODAL;
    assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_FAMILY);
    tf_target_view_q31(q, &t);
    t.n_words -= 1;
    assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_CORRUPT); /* no longer q_end - q */
    t.q_end -= 1;
    assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_SIZE);
    /* a flipped bit in a table pointer: caught by its end, never read through */
    for (int b = 0; b < 32; ++b) {
        tf_target_view_q31(q, &t);
        t.q = (const int32_t *)((uintptr_t)t.q ^ ((uintptr_t)1 << b));
        assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_CORRUPT);
        tf_target_view_q31(q, &t);
        t.node_ids_end = (const uint32_t *)((uintptr_t)t.node_ids_end ^ ((uintptr_t)1 << b));
        assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_CORRUPT);
    }
    tf_target_view_q31(q, &t);
    q->q[20] ^= 1 << 7; /* a flipped bit */
    assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_CORRUPT);
    q->q[20] ^= 1 << 7;
    /* out-of-range values with a matching CRC: the range proof refuses them */
    const struct {
        uint32_t index;
        int32_t value;
    } bad[] = {{12, 15}, {12, 1}, {3, (1 << 30) + 1}, {0, (1 << 29) + 1},
               {TFIT_Q31_MAP_WORDS, 32}, {TFIT_Q31_MAP_WORDS, 63}, {TFIT_Q31_MAP_WORDS + 1, INT32_MIN}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        int32_t keep = q->q[bad[i].index];
        q->q[bad[i].index] = bad[i].value;
        tf_target_view_q31(q, &t);
        assert_int_equal(tfit_model_check_q31(&t), TFIT_ERR_RANGE);
        q->q[bad[i].index] = keep;
    }
    tf_q31_free(q);
    tf_model_free(m);
    /* the quantiser takes exactly the families whose registry entry
     * declares a Q31 form */
    tf_rng r = {5};
    for (size_t i = 0; i < tf_family_count(); ++i) {
        const tf_family *f = tf_family_at(i);
        tf_model *any = tf_random_model(&r, f->name, f->id, 1);
        tf_q31 *form = tf_q31_quantise(&ctx, any);
        if (f->id == TFIT_FAMILY_PRONY && form == NULL) { /* a modal static map, a slow term */
            assert_non_null(strstr(ctx.err, "no Q31 form"));
            assert_null(strstr(ctx.err, "no Q31 form for family"));
            tf_model_free(any);
            continue;
        }
        assert_int_equal(form != NULL, f->q31 != NULL);
        if (form == NULL) {
            assert_non_null(strstr(ctx.err, "no Q31 form for family"));
        }
        tf_q31_free(form);
        tf_model_free(any);
    }
}

/* The added error is a few output units in the last place: far below any
 * fit error, and the measurement sees a broken quantisation. */
static void added_error_is_small(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    for (uint32_t p = 0; p <= 4; ++p) {
        tf_model *m = ball_model(p % 2 ? TFIT_FAMILY_NODAL : TFIT_FAMILY_CONTACT, p, 2.5, p);
        tf_q31 *q = tf_q31_quantise(&ctx, m);
        assert_non_null(q);
        tf_q31_measure(q, m, 7, 2000);
        double lsb = ldexp(1.0, q->out_exp - 31);
        printf("q31 p=%u: added error %.3g (%.1f output LSB), float32 path %.3g\n", p,
               q->added_error, q->added_error / lsb, q->float_error);
        assert_true(q->added_error <= 8 * lsb);
        assert_true(q->float_error < 1e-4 && (p == 0 || q->float_error > 0));
        /* one coefficient off by 2^-14 of the row scale: the error must show it */
        q->q[TFIT_Q31_MAP_WORDS + 1] += 1 << 16;
        tf_q31_measure(q, m, 7, 2000);
        assert_true(q->added_error > 100 * lsb);
        tf_q31_free(q);
        tf_model_free(m);
    }
}

/* Degree-d term T_d(g0) T_0 T_0 of tfit_q31_basis's graded order: the
 * first of degree d, index C(d + 2, 3). */
static uint32_t first_of_degree(uint32_t d)
{
    return d * (d + 1u) * (d + 2u) / 6u;
}

/* q30 Chebyshev recurrence (q31-format.md §4): for |g| up to 2^30 + 2^4
 * (the projection's worst), |T_k| <= 2^30 + 2^11 and |T_k - 2^30
 * T_k(g / 2^30)| < 14 units, k <= 8 — the bound the rows' overflow proof
 * uses — and |phi| <= 2^30 + 2^13 for any three such components.  Every g
 * within 2^16 of +-1 (where T_k is steepest), then a stride through the
 * rest. */
static void chebyshev_q30_within_its_bound(void **state)
{
    (void)state;
    const int32_t edge = TFIT_Q31_ONE + 16;
    const uint32_t p = TFIT_Q31_MAX_DEGREE;
    int32_t phi[165];
    double worst_err = 0;
    int64_t worst_t = 0;
    for (int64_t i = -(int64_t)edge; i <= edge; i += (llabs(i) >= TFIT_Q31_ONE - 65536 ? 1 : 997)) {
        const int32_t g[3] = {(int32_t)i, 0, 0};
        tfit_q31_basis(p, g, phi);
        const long double x = (long double)i / TFIT_Q31_ONE;
        long double tm = 1, t = x; /* T_{k-1}, T_k in long double */
        for (uint32_t k = 1; k <= p; ++k) {
            if (k > 1) {
                const long double tn = 2 * x * t - tm;
                tm = t, t = tn;
            }
            const int64_t q = phi[first_of_degree(k)];
            worst_t = llabs(q) > worst_t ? llabs(q) : worst_t;
            const double err = (double)fabsl((long double)q - t * TFIT_Q31_ONE);
            worst_err = err > worst_err ? err : worst_err;
        }
    }
    tf_rng r = {30};
    int64_t worst_phi = 0;
    for (int i = 0; i < 20000; ++i) {
        int32_t g[3];
        for (int j = 0; j < 3; ++j) {
            g[j] = (int32_t)(edge - (int64_t)tf_rng_below(&r, i % 2 ? 2u * (uint32_t)edge + 1u : 64u));
            g[j] = tf_rng_below(&r, 2) ? g[j] : -g[j];
        }
        tfit_q31_basis(p, g, phi);
        for (uint32_t k = 0; k < 165; ++k) {
            worst_phi = llabs(phi[k]) > worst_phi ? llabs(phi[k]) : worst_phi;
        }
    }
    printf("q31 Chebyshev, |g| <= 2^30 + 16: max |T_k| = 2^30 + %lld, max error %.2f units; "
           "max |phi| = 2^30 + %lld\n",
           (long long)(worst_t - TFIT_Q31_ONE), worst_err, (long long)(worst_phi - TFIT_Q31_ONE));
    assert_true(worst_t <= TFIT_Q31_ONE + (1 << 11));
    assert_true(worst_err < 14);
    assert_true(worst_phi <= TFIT_Q31_ONE + (1 << 13));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(portable_multiplies_are_exact),
        cmocka_unit_test(target_matches_reference),
        cmocka_unit_test(check_rejects_damage),
        cmocka_unit_test(added_error_is_small),
        cmocka_unit_test(chebyshev_q30_within_its_bound),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
