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

/* A forward model off by this fraction of the displacement it renders (its
 * held-out max plus the solve's discretisation error, against the held-out
 * cases' peak) or more is not chosen: a budget only such models meet is
 * refused (docs/tradeoff.md, "Choosing for a budget"). */
#define TF_SELECT_USELESS 0.25

typedef struct tf_selection {
    const tf_candidate *forward, *contact;
    int contact_within_tol; /* 0: no passive contact was within contact_tol; the closest is taken */
} tf_selection;

/* Among the float32 candidates of the scene's outputs: the contact inverse
 * is the cheapest passive one within contact_tol (N, held-out max), else the
 * most accurate passive one (contact_within_tol says which); the forward model is
 * the most accurate whose time plus the contact's fits budget_us, or (when
 * budget_us is NAN) the cheapest whose total error (held-out max plus
 * disc_mm, the solve's error against the physics; NAN: not measured,
 * counted as 0) is within max_error_mm; with both, the cheapest within the
 * error that fits the budget.  A forward model whose total error is
 * TF_SELECT_USELESS of its peak or more is refused.  Returns 0, or -1 with
 * a message that states the best achievable on each axis. */
int tf_select(tf_ctx *ctx, const tf_sweep *sw, const tf_mcu *mcu, double budget_us,
              double max_error_mm, double disc_mm, double contact_tol, tf_selection *sel);

/* A candidate's total error: held-out max plus disc_mm (NAN: not measured). */
double tf_select_total(const tf_candidate *c, double disc_mm);

#endif /* TF_SELECT_H */
