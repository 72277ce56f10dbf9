/*
 * test_forms.c — the form table (model/forms/form.h): every family id from
 * TFIT_FAMILY_FIRST to TFIT_FAMILY_LAST has its form, found by that id and
 * by no other; each form agrees with the family that fits it, its random
 * models have the size it gives and pass the host's and the target's
 * checks, and its loop blocks are in the table check-cycles compares with
 * objdump.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "fitting/families/family.h"
#include "model/forms/form.h"
#include "model/golden.h"
#include "model/target_view.h"
#include "random_model.h"

static void every_id_has_its_form(void **state)
{
    (void)state;
    assert_null(tf_form_of((tfit_family)(TFIT_FAMILY_FIRST - 1)));
    assert_null(tf_form_of((tfit_family)(TFIT_FAMILY_LAST + 1)));
    tf_rng r = {31};
    for (int id = TFIT_FAMILY_FIRST; id <= TFIT_FAMILY_LAST; ++id) {
        const tf_form *f = tf_form_of((tfit_family)id);
        assert_non_null(f);
        assert_int_equal(f->id, id);
        /* a family fits it, under the same name, offering its Q31 form */
        const tf_family *fam = tf_family_of(f->id);
        assert_non_null(fam);
        assert_string_equal(fam->name, f->name);
        assert_int_equal(fam->q31 != NULL, f->q31 != NULL);
        /* a stateless form evaluated at the projected input has its part */
        assert_true(f->ref_eval != tf_form_ref_eval || f->ref_map != NULL);
        /* stateful exactly when its golden vectors are a tick sequence */
        assert_int_equal(f->filter != NULL, f->golden_inputs == tf_golden_ticks);
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        tf_model *m = tf_random_model(&r, f->name, f->id, 1);
        assert_non_null(m);
        assert_int_equal(m->n_dims, f->n_dims);
        assert_int_equal(tf_model_ncoef(f->id, m->n_out, m->dims, m->n_dims), m->n_coef);
        assert_int_equal(tf_model_validate(&ctx, m), 0);
        tfit_model t;
        tf_target_view(m, &t);
        assert_int_equal(tfit_model_check(&t), TFIT_OK);
        tf_model_free(m);
    }
}

/* Each form's loop blocks, and no other, are lines of the loop table. */
static void loop_table_has_every_forms_loops(void **state)
{
    (void)state;
    static char table[32768];
    for (int core = 0; core < TF_CORES; ++core) {
        const size_t n = tf_form_loop_table((tf_core)core, table, sizeof table);
        assert_true(n < sizeof table);
        size_t loops = 0;
        for (int id = TFIT_FAMILY_FIRST; id <= TFIT_FAMILY_LAST; ++id) {
            const tf_form *f = tf_form_of((tfit_family)id);
            for (size_t b = 0; b < f->n_blocks; ++b) {
                char line[256];
                if (f->blocks[b].loop == 0) {
                    continue;
                }
                snprintf(line, sizeof line, "%s loop %d depth %d: ", f->blocks[b].function,
                         f->blocks[b].loop, f->blocks[b].depth);
                assert_non_null(strstr(table, line));
                ++loops;
            }
        }
        assert_true(loops > 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_id_has_its_form),
        cmocka_unit_test(loop_table_has_every_forms_loops),
    };
    return cmocka_run_group_tests_name("forms", tests, NULL, NULL);
}
