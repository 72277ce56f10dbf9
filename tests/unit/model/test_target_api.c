/*
 * test_target_api.c — the target library's contract, through its public
 * API: statuses, zeroed outputs on NaN/Inf, clamping, argument and family
 * errors, and every rejection tfit_model_check() promises.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "random_model.h"
#include "model/golden.h"
#include "model/target_view.h"
#include "tfit.h"

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, 4);
    return u;
}

static tfit_status eval(const tfit_model *t, const float in[3], float *out)
{
    return t->family == TFIT_FAMILY_CONTACT ? tfit_contact_force(t, in, out)
                                            : tfit_displacements(t, in, out);
}

/* Nodal p=1 model of n nodes: u = A f with a fixed, known A; envelope R. */
static tf_model *linear_model(uint32_t n, double radius)
{
    const uint32_t dims[1] = {1};
    char err[256];
    tf_model *m = tf_model_new("lin", TFIT_FAMILY_NODAL, n, dims, 1, err, sizeof err);
    const double centre[3] = {0, 0, 0};
    tf_model_set_ball(m, centre, radius);
    float *c = tf_model_tables(m);
    for (uint32_t o = 0; o < 3 * n; ++o) {
        for (int k = 0; k < 3; ++k) {
            c[o * 4 + 1 + (uint32_t)k] = (float)((double)(o + 1) * (k + 1) * 0.25 * radius);
        }
    }
    return m;
}

static void nonfinite_inputs_give_zero_outputs(void **state)
{
    (void)state;
    const float bad[][3] = {{NAN, 0, 0}, {0, INFINITY, 0}, {0, 0, -INFINITY}, {1, NAN, INFINITY}};
    tf_rng r = {11};
    for (int family = 1; family <= 4; ++family) {
        tf_model *m = tf_random_model(&r, "m", (tfit_family)family, 1);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        float *out = malloc(3 * m->n_out * sizeof *out);
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
            for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
                out[o] = 1234.5f;
            }
            assert_int_equal(eval(&t, bad[i], out), TFIT_ERR_INPUT);
            for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
                assert_int_equal(bits(out[o]), 0u); /* +0.0f exactly */
            }
        }
        free(out);
        tf_model_free(m);
    }
}

static void inside_is_exact_outside_is_clamped(void **state)
{
    (void)state;
    tf_model *m = linear_model(4, 2.0);
    tfit_model t;
    tf_target_view(m, &t);
    float out[12], edge[12];

    const float inside[3] = {0.5f, -1.0f, 0.25f}; /* |f| < 2 */
    assert_int_equal(tfit_displacements(&t, inside, out), TFIT_OK);
    for (uint32_t o = 0; o < 12; ++o) {
        double expect = 0;
        for (int k = 0; k < 3; ++k) {
            expect += (o + 1) * (k + 1) * 0.25 * inside[k];
        }
        assert_true(fabs((double)out[o] - expect) <= 1e-6 * fabs(expect) + 1e-12);
    }

    /* 10x and 1e30x beyond the envelope land on its boundary, in the same direction. */
    const float dir[3] = {0.6f, -0.8f, 0.0f};
    const float on_edge[3] = {2 * dir[0], 2 * dir[1], 2 * dir[2]};
    assert_int_equal(tfit_displacements(&t, on_edge, edge), TFIT_OK);
    for (int scale = 0; scale < 3; ++scale) {
        const double s = scale == 0 ? 20.0 : (scale == 1 ? 1e30 : 3e38);
        const float far[3] = {(float)(s * dir[0]), (float)(s * dir[1]), 0.0f};
        assert_int_equal(tfit_displacements(&t, far, out), TFIT_CLAMPED);
        for (uint32_t o = 0; o < 12; ++o) {
            assert_true(isfinite(out[o]));
            assert_true(fabsf(out[o] - edge[o]) <= 1e-5f * (fabsf(edge[o]) + 1.0f));
        }
    }
    tf_model_free(m);
}

static void arguments_and_families(void **state)
{
    (void)state;
    tf_rng r = {5};
    tf_model *nodal = tf_random_model(&r, "n", TFIT_FAMILY_NODAL, 1);
    tf_model *contact = tf_random_model(&r, "c", TFIT_FAMILY_CONTACT, 1);
    tfit_model tn, tc;
    tf_target_view(nodal, &tn);
    tf_target_view(contact, &tc);
    float in[3] = {0, 0, 0}, out[3 * 8];

    assert_int_equal(tfit_displacements(NULL, in, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements(&tn, NULL, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements(&tn, in, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_contact_force(NULL, in, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_displacements(&tc, in, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_contact_force(&tn, in, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_model_check(NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_model_crc32(NULL), 0u);
    assert_int_equal(tfit_golden_run(NULL, out), UINT32_MAX);

    /* An unchecked model with NULL tables: an argument error, as the Q31
     * entry points return, never a read through NULL (every degree, both
     * entry points, each table). */
    for (uint32_t p = 0; p <= 2; ++p) {
        for (int table = 0; table < 2; ++table) {
            const uint32_t dims[1] = {p};
            char err[256];
            tf_model *n = tf_model_new("n", TFIT_FAMILY_NODAL, 3, dims, 1, err, sizeof err);
            tf_model *c = tf_model_new("c", TFIT_FAMILY_CONTACT, 1, dims, 1, err, sizeof err);
            tfit_model v[2];
            tf_target_view(n, &v[0]);
            tf_target_view(c, &v[1]);
            for (int k = 0; k < 2; ++k) {
                if (table == 0) {
                    v[k].coef = NULL;
                } else {
                    v[k].dims = NULL;
                }
            }
            assert_int_equal(tfit_displacements(&v[0], in, out), TFIT_ERR_ARG);
            assert_int_equal(tfit_contact_force(&v[1], in, out), TFIT_ERR_ARG);
            tf_model_free(n);
            tf_model_free(c);
        }
    }
    tfit_model_q31 q = {0};
    q.family = TFIT_FAMILY_NODAL;
    q.n_out = 1;
    const int32_t qin[3] = {0, 0, 0};
    int32_t qout[3];
    assert_int_equal(tfit_displacements_q31(&q, qin, qout), TFIT_ERR_ARG);
    q.family = TFIT_FAMILY_CONTACT;
    assert_int_equal(tfit_contact_force_q31(&q, qin, qout), TFIT_ERR_ARG);
    tf_model_free(nodal);
    tf_model_free(contact);
}

/* Every check: the view is fixed up (CRC recomputed where the test wants
 * the check to get past the CRC). */
static void check_rejections(void **state)
{
    (void)state;
    tf_model *m = linear_model(2, 1.0);
    tfit_model t;

    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    assert_int_equal(tfit_model_crc32(&t), tf_model_crc32_checked(m, t.check));

    t.api_version = TFIT_API_VERSION + 1;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_VERSION);

    tf_target_view(m, &t);
    t.family = 0;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_FAMILY);
    t.family = TFIT_FAMILY_REGION_SURFACE + 1; /* the first id no family has */
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_FAMILY);

    tf_target_view(m, &t);
    t.n_coef -= 1;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT); /* no longer coef_end - coef */
    t.coef_end -= 1;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    tf_target_view(m, &t);
    t.family = TFIT_FAMILY_CONTACT; /* contact needs exactly one output point */
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);

    const uint32_t too_high[1] = {TFIT_MAX_DEGREE + 1};
    tf_target_view(m, &t);
    t.dims = too_high;
    t.dims_end = too_high + 1;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);

    /* a table pointer that no longer matches its end is never read through */
    const uintptr_t one = 1;
    for (int b = 0; b < 8 * (int)sizeof(uintptr_t); ++b) {
        tf_target_view(m, &t);
        t.coef = (const float *)((uintptr_t)t.coef ^ (one << b));
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);
        tf_target_view(m, &t);
        t.dims = (const uint32_t *)((uintptr_t)t.dims ^ (one << b));
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);
        tf_target_view(m, &t);
        t.node_ids_end = (const uint32_t *)((uintptr_t)t.node_ids_end ^ (one << b));
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);
    }

    /* the self-test: results that differ from the carried ones, with a
     * model CRC that matches, are an arithmetic failure, not damage */
    for (int b = 0; b < 32; ++b) {
        tf_target_view(m, &t);
        t.check[TFIT_CHECK_WORDS - 1] ^= 1u << b;
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);
        t.crc32 = tfit_model_crc32(&t);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_ARITH);
    }

    tf_target_view(m, &t);
    t.crc32 ^= 1u;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);

    float keep = m->coef[TFIT_INPUT_MAP_FLOATS + 5];
    const float poison[] = {NAN, INFINITY, 1e38f};
    for (int i = 0; i < 3; ++i) {
        m->coef[TFIT_INPUT_MAP_FLOATS + 5] = poison[i];
        tf_target_view(m, &t); /* CRC matches the poisoned table */
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    }
    m->coef[TFIT_INPUT_MAP_FLOATS + 5] = keep;
    m->coef[3] = 1e30f; /* W entry beyond the safe range */
    tf_target_view(m, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    tf_model_free(m);
}

static void zhou_and_modal_rejections(void **state)
{
    (void)state;
    tf_rng r = {99};
    tf_model *z = tf_random_model(&r, "z", TFIT_FAMILY_ZHOU2017, 1);
    tfit_model t;
    z->coef[z->n_coef - 1] = 1.5f; /* a node coordinate outside [-1, 1] */
    tf_target_view(z, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    tf_model_free(z);

    tf_model *md = tf_random_model(&r, "md", TFIT_FAMILY_MODAL, 1);
    tf_target_view(md, &t);
    uint32_t dims[2] = {md->dims[0], 0};
    t.dims = dims; /* rank 0 */
    t.dims_end = dims + 2;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    dims[1] = TFIT_MAX_RANK + 1;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    tf_model_free(md);
}

/* modal_q15 (header-format.md §5.9): a valid random model passes; a row
 * word with a half beyond +-16255 (sums that could overflow), a
 * non-finite scale v_k, a negative S, p = 0 or a rank other than 8 are
 * refused by the target and by the host's validation. */
static void modal_q15_rejections(void **state)
{
    (void)state;
    tf_rng r = {7};
    tf_model *q = tf_random_model(&r, "q", TFIT_FAMILY_MODAL_Q15, 1);
    char err[256];
    tfit_model t;
    tf_target_view(q, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_OK);
    float *v = tf_model_tables(q) + TFIT_MODAL_Q15_RANK * tf_terms(q->dims[0]);
    float *row = v + TFIT_MODAL_Q15_RANK + 1;
    const float keep_row = row[0], keep_v = v[3], keep_s = v[TFIT_MODAL_Q15_RANK];
    static const uint32_t bad_words[] = {
        (16256u & 0xffffu) | (16384u << 16),          /* low half 16256 */
        ((uint32_t)-16256 & 0xffffu) | (16384u << 16), /* low half -16256 */
        (16384u + 16256u) << 16,                       /* high half 16256 */
        (16384u - 16256u) << 16,                       /* high half -16256 */
        0x7f800000u,                                   /* +Inf's bits */
    };
    for (size_t i = 0; i < sizeof bad_words / sizeof bad_words[0]; ++i) {
        memcpy(&row[0], &bad_words[i], sizeof bad_words[i]);
        tf_target_view(q, &t); /* CRC matches the altered table */
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
        assert_int_not_equal(tf_model_validate(q, err, sizeof err), 0);
    }
    const uint32_t edge = (16255u & 0xffffu) | ((16384u - 16255u) << 16); /* +-16255: valid */
    memcpy(&row[0], &edge, sizeof edge);
    tf_target_view(q, &t);
    assert_int_not_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    row[0] = keep_row;
    v[3] = INFINITY;
    tf_target_view(q, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    v[3] = keep_v;
    v[TFIT_MODAL_Q15_RANK] = -keep_s;
    tf_target_view(q, &t);
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
    v[TFIT_MODAL_Q15_RANK] = keep_s;
    tf_target_view(q, &t);
    uint32_t dims[2] = {0, TFIT_MODAL_Q15_RANK};
    t.dims = dims; /* p = 0 */
    t.dims_end = dims + 2;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    dims[0] = q->dims[0];
    dims[1] = 7;
    assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
    tf_model_free(q);
}

static void golden_run_counts_mismatches(void **state)
{
    (void)state;
    tf_model *m = linear_model(1, 1.0);
    tfit_model t;
    tf_target_view(m, &t);
    uint32_t in[3] = {bits(0.5f), 0, 0};
    uint32_t out[3];
    int32_t status[1] = {TFIT_OK};
    float scratch[3];
    assert_int_equal(tfit_displacements(&t, (const float[3]){0.5f, 0, 0}, scratch), TFIT_OK);
    for (int i = 0; i < 3; ++i) {
        out[i] = bits(scratch[i]);
    }
    tfit_golden g = {&t, 1, in, status, out};
    assert_int_equal(tfit_golden_run(&g, scratch), 0u);
    out[1] ^= 1u; /* one ulp */
    assert_int_equal(tfit_golden_run(&g, scratch), 1u);
    status[0] = TFIT_CLAMPED;
    assert_int_equal(tfit_golden_run(&g, scratch), 2u);
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nonfinite_inputs_give_zero_outputs),
        cmocka_unit_test(inside_is_exact_outside_is_clamped),
        cmocka_unit_test(arguments_and_families),
        cmocka_unit_test(check_rejections),
        cmocka_unit_test(zhou_and_modal_rejections),
        cmocka_unit_test(modal_q15_rejections),
        cmocka_unit_test(golden_run_counts_mismatches),
    };
    return cmocka_run_group_tests_name("target_api", tests, NULL, NULL);
}
