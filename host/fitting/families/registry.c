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

#define FAMILIES(X)                                                                               \
    X(nodal) X(modal) X(zhou2017) X(contact) X(prony) X(cut) X(resonant) X(modal_q15) X(region)    \
    X(region_surface)

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

const char *tf_family_suffix(const tf_family *f)
{
    return f->suffix != NULL ? f->suffix : f->kind == TF_FAMILY_FORWARD ? "forward" : "contact";
}

/* The forward family fitted from a contact region, or NULL. */
static const tf_family *region_family(void)
{
    for (size_t i = 0; i < tf_family_count(); ++i) {
        if (families[i]->region != NULL && families[i]->kind == TF_FAMILY_FORWARD) {
            return families[i];
        }
    }
    return NULL;
}

int tf_fit_plan_family_for_contact(tf_ctx *ctx, tf_fit_plan *plan, const tf_problem *p)
{
    const tf_contact *c = &p->contacts[plan->contact];
    const int region = c->region.kind != TF_CONTACT_REGION_NONE;
    const tf_family *fr = region_family();
    if (region == (plan->family->region != NULL)) {
        return 0;
    }
    if (region && !plan->family_asked && fr != NULL) {
        plan->family = fr;
        return 0;
    }
    if (region) {
        return tf_fail(ctx, "contact '%s' is a contact region: the %s family fits one contact "
                            "site's load cases and would emit a point model; a region's law and "
                            "surface are the %s family's (drop --family and fit.family, or name "
                            "%s)",
                       c->name, plan->family->name, fr ? fr->name : "(none)",
                       fr ? fr->name : "(none)");
    }
    return tf_fail(ctx, "the %s family fits a contact region (contact.K.region); contact '%s' is "
                        "a site (a forward family of a site: nodal, modal, ...)",
                   plan->family->name, c->name);
}

void tf_fit_plan_defaults(tf_fit_plan *p)
{
    *p = (tf_fit_plan){.family = tf_family_find("nodal"), .contact = 0, .n_train = 100,
                       .n_heldout = 50, .seed = 20170912, .folds = 5, .max_degree = 4,
                       .max_rank = 12, .tick_ns = 1000000, .hist_train = 12,
                       .hist_heldout = 6, .hist_ticks = 5000, .hist_solve_every = 1,
                       .cut_intervals = 0, .cut_heldout = 4};
}
