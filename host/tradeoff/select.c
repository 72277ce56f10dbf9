/*
 * select.c — see select.h.
 */
#include "tradeoff/select.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tf_mcu_parse(tf_ctx *ctx, const char *text, tf_mcu *mcu)
{
    char core[32];
    const char *at = strchr(text, '@');
    size_t len = at ? (size_t)(at - text) : strlen(text);
    snprintf(mcu->name, sizeof mcu->name, "%s", text);
    if (len >= sizeof core) {
        len = sizeof core - 1;
    }
    memcpy(core, text, len);
    core[len] = '\0';
    if (strcmp(core, "cortex-m4f") == 0 || strcmp(core, "cortex-m4") == 0) {
        mcu->core = TF_CORE_M4F;
    } else if (strcmp(core, "cortex-m7") == 0) {
        mcu->core = TF_CORE_M7;
    } else {
        return tf_fail(ctx,
                       "--mcu '%s': cycle estimates exist for cortex-m4f and cortex-m7 "
                       "(e.g. cortex-m4f@168)",
                       text);
    }
    mcu->mhz = tf_core_mhz(mcu->core);
    if (at != NULL) {
        char *end;
        mcu->mhz = strtod(at + 1, &end);
        if (*end != '\0' || !(mcu->mhz > 0) || !isfinite(mcu->mhz)) {
            return tf_fail(ctx, "--mcu '%s': the clock after @ is a positive number of MHz", text);
        }
    }
    return 0;
}

double tf_candidate_us(const tf_candidate *c, const tf_mcu *mcu)
{
    double us_at_default = mcu->core == TF_CORE_M4F ? c->us_m4f : c->us_m7;
    return us_at_default * tf_core_mhz(mcu->core) / mcu->mhz;
}

static int usable(const tf_candidate *c)
{
    return c->precision == TF_PREC_F32 && c->set == TF_SET_SCENE && c->model != NULL;
}

/* The contact inverse: the cheapest passive candidate within tol (N,
 * held-out max); when none is (a nonlinear contact law, whose best fit is
 * far above a tolerance made for linear scenes), the most accurate passive
 * one, as the order search would ship.  *within says which. */
static const tf_candidate *pick_contact(const tf_sweep *sw, const tf_mcu *mcu, double tol,
                                        int *within)
{
    const tf_candidate *best = NULL, *closest = NULL;
    for (size_t i = 0; i < sw->n; ++i) {
        const tf_candidate *c = &sw->c[i];
        if (!usable(c) || c->family->kind != TF_FAMILY_INVERSE || !c->passive) {
            continue;
        }
        const double us = tf_candidate_us(c, mcu);
        if (c->heldout_max <= tol && (best == NULL || us < tf_candidate_us(best, mcu))) {
            best = c;
        }
        if (closest == NULL || c->heldout_max < closest->heldout_max ||
            (c->heldout_max == closest->heldout_max && us < tf_candidate_us(closest, mcu))) {
            closest = c;
        }
    }
    *within = best != NULL;
    return best != NULL ? best : closest;
}

/* The fastest and the most accurate forward candidates, for messages. */
static void extremes(const tf_sweep *sw, const tf_mcu *mcu, const tf_candidate **fast,
                     const tf_candidate **accurate)
{
    *fast = *accurate = NULL;
    for (size_t i = 0; i < sw->n; ++i) {
        const tf_candidate *c = &sw->c[i];
        if (!usable(c) || c->family->kind == TF_FAMILY_INVERSE) {
            continue;
        }
        if (*fast == NULL || tf_candidate_us(c, mcu) < tf_candidate_us(*fast, mcu)) {
            *fast = c;
        }
        if (*accurate == NULL || c->heldout_max < (*accurate)->heldout_max ||
            (c->heldout_max == (*accurate)->heldout_max &&
             tf_candidate_us(c, mcu) < tf_candidate_us(*accurate, mcu))) {
            *accurate = c;
        }
    }
}

double tf_select_total(const tf_candidate *c, double disc_mm)
{
    return c->heldout_max + (isnan(disc_mm) ? 0 : disc_mm);
}

/* The chosen forward model renders too little of its peak to be of use. */
static int useless(tf_ctx *ctx, const tf_candidate *c, const tf_candidate *accurate,
                   const tf_mcu *mcu, double contact_us, double disc_mm, const char *what)
{
    const double total = tf_select_total(c, disc_mm);
    return tf_fail(ctx,
                   "only models off by %g %% of their peak or more fit %s on %s: the best of "
                   "them, %s, is off by %.3g mm (%.3g %% of the %.3g mm its held-out cases "
                   "reach%s).  Most accurate: %s, held-out max %.3g mm, %.2f us plus %.2f us",
                   100 * TF_SELECT_USELESS, what, mcu->name, c->label, total,
                   100 * total / c->peak, c->peak,
                   isnan(disc_mm) ? "" : ", with the solve's discretisation error",
                   accurate->label, accurate->heldout_max, tf_candidate_us(accurate, mcu),
                   contact_us);
}

int tf_select(tf_ctx *ctx, const tf_sweep *sw, const tf_mcu *mcu, double budget_us,
              double max_error_mm, double disc_mm, double contact_tol, tf_selection *sel)
{
    const tf_candidate *fast, *accurate;
    sel->contact = pick_contact(sw, mcu, contact_tol, &sel->contact_within_tol);
    sel->forward = NULL;
    extremes(sw, mcu, &fast, &accurate);
    if (sel->contact == NULL || fast == NULL) {
        return tf_fail(ctx, "no passive contact inverse, or no forward model");
    }
    const double contact_us = tf_candidate_us(sel->contact, mcu);
    for (size_t i = 0; i < sw->n; ++i) {
        const tf_candidate *c = &sw->c[i], *b = sel->forward;
        if (!usable(c) || c->family->kind == TF_FAMILY_INVERSE) {
            continue;
        }
        const double us = tf_candidate_us(c, mcu);
        if ((!isnan(budget_us) && us + contact_us > budget_us) ||
            (!isnan(max_error_mm) && tf_select_total(c, disc_mm) > max_error_mm)) {
            continue;
        }
        int better;
        if (!isnan(max_error_mm)) { /* cheapest within the error */
            better = b == NULL || us < tf_candidate_us(b, mcu) ||
                     (us == tf_candidate_us(b, mcu) && c->heldout_max < b->heldout_max);
        } else { /* most accurate within the budget, then cheapest */
            better = b == NULL || c->heldout_max < b->heldout_max ||
                     (c->heldout_max == b->heldout_max && us < tf_candidate_us(b, mcu));
        }
        if (better) {
            sel->forward = c;
        }
    }
    char what[128];
    if (!isnan(budget_us) && !isnan(max_error_mm)) {
        snprintf(what, sizeof what, "a %.4g us budget and a %.3g mm error", budget_us,
                 max_error_mm);
    } else if (!isnan(budget_us)) {
        snprintf(what, sizeof what, "a %.4g us budget", budget_us);
    } else {
        snprintf(what, sizeof what, "a %.3g mm error", max_error_mm);
    }
    const tf_candidate *f = sel->forward;
    if (f != NULL && f->peak > 0 && tf_select_total(f, disc_mm) >= TF_SELECT_USELESS * f->peak) {
        sel->forward = NULL;
        return useless(ctx, f, accurate, mcu, contact_us, disc_mm, what);
    }
    if (f != NULL) {
        return 0;
    }
    char physics[160] = "";
    if (!isnan(disc_mm) && !isnan(max_error_mm) && disc_mm >= max_error_mm) {
        snprintf(physics, sizeof physics,
                 "; the solve itself is off by %.3g mm against the physics",
                 disc_mm);
    }
    return tf_fail(ctx,
                   "no model fits %s on %s (estimated upper bounds%s).  Fastest: %s, %.2f us plus "
                   "%.2f us for the contact inverse, held-out max %.3g mm.  Most accurate: %s, "
                   "held-out max %.3g mm, %.2f us plus %.2f us",
                   what, mcu->name, physics, fast->label, tf_candidate_us(fast, mcu), contact_us,
                   fast->heldout_max, accurate->label, accurate->heldout_max,
                   tf_candidate_us(accurate, mcu), contact_us);
}
