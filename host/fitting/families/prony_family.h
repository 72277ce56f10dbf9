/*
 * prony_family.h — the prony family's pieces that tests, studies and the
 * pipeline use beside the registry's operations (prony.c): the number of
 * terms by cross-validation, the tick a model's terms need, and the Q31
 * form's held-out error.  What it shares with the resonant family (the
 * data of the terms' fit, the fit loop, the held-out histories) is in
 * stateful_family.h.
 */
#ifndef TF_PRONY_FAMILY_H
#define TF_PRONY_FAMILY_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/families/stateful_family.h"
#include "fitting/histories.h"
#include "fitting/plan.h"
#include "fitting/prony_terms.h"
#include "model/model.h"

/* Terms the order search tries: K = 0 .. this. */
#define TF_PRONY_SEARCH_TERMS 4

/* K = 0 .. TF_PRONY_SEARCH_TERMS by cross-validation over the histories of
 * d (tf_stateful_select_terms): cv[K] the validation RMS of h, *best the
 * cheapest K within 2 % of the best, terms fitted with it on every
 * history.  Returns 0, or -1 with a message. */
int tf_prony_select_terms(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h,
                          const tf_fit_plan *plan, double *cv, int *best, tf_prony_terms *terms);

/* 0 when every time constant of t is within TF_PRONY_MAX_TAU_TICKS ticks
 * of h (model/forms/prony.h); else -1 with a message naming the tick it
 * needs. */
int tf_prony_tick_allows(tf_ctx *ctx, const tf_prony_terms *t, const tf_histories *h);

/* The largest error of a prony model's Q31 form (q31-format.md §8) over
 * the held-out histories, each stepped from rest with the forces as Q31
 * words, against the solves; NAN when the model has no Q31 form or there
 * are no histories. */
double tf_prony_q31_heldout(const tf_model *m, const tf_cases *c);

#endif /* TF_PRONY_FAMILY_H */
