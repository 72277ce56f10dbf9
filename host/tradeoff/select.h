/*
 * select.h — choosing models for a budget (docs/tradeoff.md): the most
 * accurate forward model whose estimated time, with the contact inverse's,
 * fits a servo budget on a given microcontroller; or the cheapest one within
 * an error bound.
 */
#ifndef TF_SELECT_H
#define TF_SELECT_H

#include <stddef.h>

#include "base/context.h"
#include "cost/cycles.h"
#include "tradeoff/sweep.h"

typedef struct tf_mcu {
    tf_core core;
    double mhz;
    char name[48]; /* as given: "cortex-m4f@168" */
} tf_mcu;

/* "cortex-m4f@168", "cortex-m7@480" (MHz after @; the default clock when
 * omitted).  Returns 0, or -1 with a message. */
int tf_mcu_parse(tf_ctx *ctx, const char *text, tf_mcu *mcu);

/* Estimated microseconds of a float32 candidate on mcu (upper bound). */
double tf_candidate_us(const tf_candidate *c, const tf_mcu *mcu);

typedef struct tf_selection {
    const tf_candidate *forward, *contact;
    int contact_within_tol; /* 0: no passive contact was within contact_tol; the closest is taken */
} tf_selection;

/* Among the float32 candidates of the scene's outputs: the contact inverse
 * is the cheapest passive one within contact_tol (N, held-out max), else the
 * most accurate passive one (contact_within_tol says which); the forward model is
 * the most accurate whose time plus the contact's fits budget_us, or (when
 * budget_us is NAN) the cheapest within max_error_mm; with both, the
 * cheapest within the error that fits the budget.  Returns 0, or -1 with a
 * message that states the best achievable on each axis. */
int tf_select(tf_ctx *ctx, const tf_sweep *sw, const tf_mcu *mcu, double budget_us,
              double max_error_mm, double contact_tol, tf_selection *sel);

#endif /* TF_SELECT_H */
