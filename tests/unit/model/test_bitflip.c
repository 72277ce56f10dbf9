/*
 * test_bitflip.c — acceptance: every single-bit flip in a small model's
 * tables (dims, coefficients, node ids) and in every field of its
 * descriptor (scalars, the six table pointers, the self-test vector, the
 * CRC) is caught by tfit_model_check(), for every form from
 * TFIT_FAMILY_FIRST to TFIT_FAMILY_LAST (model/forms/form.h), without a
 * read through a damaged pointer (the pointers are checked against their
 * ends first; a fault here would crash the test).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "model/forms/form.h"
#include "model/target_view.h"
#include "random_model.h"

/* Flips each bit of a pointer field (its bytes, memcpy'd) in turn; returns
 * how many flips passed the check. */
static unsigned flip_pointer(tfit_model *t, void *field, unsigned *tried)
{
    unsigned missed = 0;
    unsigned char keep[sizeof(void *)];
    memcpy(keep, field, sizeof keep);
    for (size_t b = 0; b < 8 * sizeof keep; ++b) {
        ((unsigned char *)field)[b / 8] ^= (unsigned char)(1u << (b % 8));
        missed += tfit_model_check(t) == TFIT_OK;
        memcpy(field, keep, sizeof keep);
        ++*tried;
    }
    return missed;
}

/* Flips each bit of words[0..n) in turn; returns how many flips passed the check. */
static unsigned flip_all(tfit_model *t, uint32_t *words, uint32_t n, unsigned *tried)
{
    unsigned missed = 0;
    for (uint32_t w = 0; w < n; ++w) {
        for (int b = 0; b < 32; ++b) {
            words[w] ^= 1u << b;
            missed += tfit_model_check(t) == TFIT_OK;
            words[w] ^= 1u << b;
            ++*tried;
        }
    }
    return missed;
}

static void every_flip_is_caught(void **state)
{
    (void)state;
    tf_rng r = {2026};
    for (int id = TFIT_FAMILY_FIRST; id <= TFIT_FAMILY_LAST; ++id) {
        const tf_form *f = tf_form_of((tfit_family)id);
        assert_non_null(f); /* every id has its form */
        tf_model *m = tf_random_model(&r, "small", f->id, 1);
        assert_non_null(m);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        unsigned tried = 0, missed = 0;
        missed += flip_all(&t, m->dims, m->n_dims, &tried);
        missed += flip_all(&t, (uint32_t *)(void *)m->coef, m->n_coef, &tried);
        missed += flip_all(&t, m->node_ids, m->n_out, &tried);
        uint32_t *scalars[] = {&t.api_version, &t.family, &t.n_out, &t.n_dims, &t.n_coef, &t.crc32};
        for (size_t i = 0; i < sizeof scalars / sizeof scalars[0]; ++i) {
            missed += flip_all(&t, scalars[i], 1, &tried);
        }
        missed += flip_all(&t, t.check, TFIT_CHECK_WORDS, &tried);
        void *pointers[] = {&t.dims, &t.coef, &t.node_ids, &t.dims_end, &t.coef_end,
                            &t.node_ids_end};
        for (size_t i = 0; i < sizeof pointers / sizeof pointers[0]; ++i) {
            missed += flip_pointer(&t, pointers[i], &tried);
        }
        printf("%-9s (family %d): %u coefficients, %u single-bit flips, %u missed\n", f->name, id,
               m->n_coef, tried, missed);
        assert_int_equal(missed, 0);
        assert_int_equal(tfit_model_check(&t), TFIT_OK); /* restored */
        tf_model_free(m);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(every_flip_is_caught)};
    return cmocka_run_group_tests_name("bitflip", tests, NULL, NULL);
}
