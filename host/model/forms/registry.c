/*
 * registry.c — every form the target evaluates, by its family id
 * (form.h), and the loop blocks of the compiled evaluator.
 *
 * Adding a form: a file in this folder that defines `const tf_form
 * tf_form_NAME`, and NAME in the list below at its id's place (the list
 * runs from TFIT_FAMILY_FIRST to TFIT_FAMILY_LAST; a form at another place
 * is never found, and test_forms.c fails).
 */
#include "model/forms/form.h"

#include "cost/evaluator.h"
#include "model/forms/stateful.h"

#define FORMS(X)                                                                                   \
    X(nodal) X(modal) X(zhou2017) X(contact) X(prony) X(cut) X(resonant) X(modal_q15) X(region)   \
        X(region_surface)

#define DECLARE(name) extern const tf_form tf_form_##name;
FORMS(DECLARE)
#define ENTRY(name) &tf_form_##name,
static const tf_form *const forms[] = {FORMS(ENTRY)};

const tf_form *tf_form_of(tfit_family id)
{
    const size_t n = sizeof forms / sizeof forms[0];
    const size_t i = (size_t)id - (size_t)TFIT_FAMILY_FIRST;
    if (id < TFIT_FAMILY_FIRST || i >= n || forms[i]->id != id) {
        return NULL;
    }
    return forms[i];
}

size_t tf_form_loop_table(tf_core core, char *buf, size_t n)
{
    size_t k = tf_insn_loop_lines(tf_insn_shared, tf_insn_n_shared, core, buf, n, 0);
    k = tf_insn_loop_lines(tf_stateful_blocks, tf_stateful_n_blocks, core, buf, n, k);
    for (size_t i = 0; i < sizeof forms / sizeof forms[0]; ++i) {
        k = tf_insn_loop_lines(forms[i]->blocks, forms[i]->n_blocks, core, buf, n, k);
    }
    return k;
}
