/*
 * registry.c — every model family, by name (family.h), in the order the
 * pipeline fits them and the reports list them.
 *
 * Adding a family: a file in this folder that defines
 * `const tf_family tf_family_NAME`, and NAME in the list below.
 */
#include <stdio.h>
#include <string.h>

#include "fitting/families/family.h"

#define FAMILIES(X) X(nodal) X(modal) X(zhou2017) X(contact) X(prony) X(cut) X(resonant) X(modal_q15)

#define DECLARE(name) extern const tf_family tf_family_##name;
FAMILIES(DECLARE)
#define ENTRY(name) &tf_family_##name,
static const tf_family *const families[] = {FAMILIES(ENTRY)};

size_t tf_family_count(void)
{
    return sizeof families / sizeof families[0];
}

const tf_family *tf_family_at(size_t i)
{
    return i < tf_family_count() ? families[i] : NULL;
}

const tf_family *tf_family_find(const char *name)
{
    for (size_t i = 0; i < tf_family_count(); ++i) {
        if (strcmp(families[i]->name, name) == 0) {
            return families[i];
        }
    }
    return NULL;
}

const tf_family *tf_family_of(tfit_family id)
{
    for (size_t i = 0; i < tf_family_count(); ++i) {
        if (families[i]->id == id) {
            return families[i];
        }
    }
    return NULL;
}

void tf_family_names(tf_family_kind kind, char *out, size_t outlen)
{
    size_t k = 0;
    out[0] = '\0';
    for (size_t i = 0; i < tf_family_count() && k < outlen; ++i) {
        if (families[i]->kind == kind) {
            int n = snprintf(out + k, outlen - k, "%s%s", k ? ", " : "", families[i]->name);
            k += n > 0 ? (size_t)n : 0;
        }
    }
}

void tf_fit_plan_defaults(tf_fit_plan *p)
{
    *p = (tf_fit_plan){.family = tf_family_find("nodal"), .contact = 0, .n_train = 100,
                       .n_heldout = 50, .seed = 20170912, .folds = 5, .max_degree = 4,
                       .max_rank = 12, .tick_ns = 1000000, .hist_train = 12,
                       .hist_heldout = 6, .hist_ticks = 5000, .hist_solve_every = 1,
                       .cut_intervals = 0, .cut_heldout = 4};
}
