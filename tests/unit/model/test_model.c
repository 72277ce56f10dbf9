/*
 * test_model.c — host model tables: sizes, operation counts, and that the
 * host's validation accepts exactly what the target's check accepts.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "random_model.h"
#include "model/target_view.h"

static void sizes_follow_the_layout(void **state)
{
    (void)state;
    const uint32_t p1[1] = {1}, p3[1] = {3}, modal[2] = {2, 5};
    assert_int_equal(tf_terms(0), 1);
    assert_int_equal(tf_terms(1), 4);
    assert_int_equal(tf_terms(2), 10);
    assert_int_equal(tf_terms(8), 165);
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_NODAL, 121, p1, 1), 12 + 363 * 4);
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_CONTACT, 1, p3, 1), 12 + 3 * 20);
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_CONTACT, 2, p3, 1), 0);
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_MODAL, 10, modal, 2), 12 + 5 * 10 + 30 * 5);
    uint32_t z[TFIT_ZHOU2017_DIMS] = {1, 1, 1};
    for (int i = 3; i < TFIT_ZHOU2017_DIMS; i += 3) {
        z[i] = 4;     /* A */
        z[i + 1] = 4; /* B */
        z[i + 2] = 1; /* k */
    }
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_ZHOU2017, 121, z, 30), 12 + 3 * 3 + 9 * 18 + 242);
    z[5] = TFIT_MAX_DEGREE + 1;
    assert_int_equal(tf_model_ncoef(TFIT_FAMILY_ZHOU2017, 121, z, 30), 0);
}

static void block48_nodal_operation_count(void **state)
{
    (void)state;
    const uint32_t p1[1] = {1};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "b", TFIT_FAMILY_NODAL, 121, p1, 1);
    tf_opcount ops = tf_model_ops(m);
    /* projection 14 add, 33 mul, no division; the degree-1 Chebyshev basis
     * {1, g0, g1, g2} costs nothing (API 2 counted 3 products g_v * 1);
     * 363 rows of 3 mul + 3 add */
    assert_int_equal(ops.add, 14 + 363 * 3);
    assert_int_equal(ops.mul, 33 + 363 * 3);
    assert_int_equal(ops.div, 0);
    assert_int_equal(tf_model_table_bytes(m), 4 * (1464 + 1 + 121));
    tf_model_free(m);
}

static void host_validation_matches_target_check(void **state)
{
    (void)state;
    tf_rng r = {41};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int rejected = 0;
    for (int i = 0; i < 300; ++i) {
        tf_model *m = tf_random_model(&r, "v", 0, 0);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tf_model_validate(&ctx, m), 0);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        /* Blow one table entry up: both sides must refuse. */
        uint32_t k = TFIT_INPUT_MAP_FLOATS + tf_rng_below(&r, m->n_coef - TFIT_INPUT_MAP_FLOATS);
        m->coef[k] = (float)(tf_rng_below(&r, 2) ? NAN : 3e38);
        tf_target_view(m, &t);
        int host_bad = tf_model_validate(&ctx, m) != 0;
        int target_bad = tfit_model_check(&t) == TFIT_ERR_RANGE;
        assert_int_equal(host_bad, 1);
        assert_int_equal(target_bad, 1);
        rejected += host_bad;
        tf_model_free(m);
    }
    assert_int_equal(rejected, 300);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(sizes_follow_the_layout),
        cmocka_unit_test(block48_nodal_operation_count),
        cmocka_unit_test(host_validation_matches_target_check),
    };
    return cmocka_run_group_tests_name("model", tests, NULL, NULL);
}
