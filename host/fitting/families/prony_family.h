/*
 * prony_family.h — the prony family's pieces that tests and studies use
 * beside the registry's operations (prony.c): the data of the terms' fit
 * from a static map and histories, the number of terms by
 * cross-validation, and the errors of a model stepped through histories.
 */
#ifndef TF_PRONY_FAMILY_H
#define TF_PRONY_FAMILY_H

#include <stddef.h>

#include "fitting/histories.h"
#include "fitting/plan.h"
#include "fitting/prony_terms.h"
#include "model/model.h"

/* Terms the order search tries: K = 0 .. this. */
#define TF_PRONY_SEARCH_TERMS 4

/* The terms' data (prony_terms.h) of static map s on a history set: g as
 * the device projects each tick's force, h the input at which s gives the
 * tick's true displacements (least squares, Gauss-Newton from the last
 * tick's).  Returns 0, or -1 with a message; free with tf_prony_data_free. */
int tf_prony_data_build(const tf_model *s, const tf_history_set *set, double tick,
                        tf_prony_data *d, char *err, size_t errlen);
void tf_prony_data_free(tf_prony_data *d);

/* K = 0 .. TF_PRONY_SEARCH_TERMS by cross-validation over the histories of
 * d (plan->folds folds of whole histories): cv[K] the validation RMS of h,
 * *best the cheapest K within 2 % of the best, terms fitted with it on
 * every history.  Returns 0, or -1 with a message. */
int tf_prony_select_terms(const tf_prony_data *d, const tf_histories *h, const tf_fit_plan *plan,
                          double *cv, int *best, tf_prony_terms *terms, char *err, size_t errlen);

/* 0 when every time constant of t is within TF_PRONY_MAX_TAU_TICKS ticks
 * of h (model/forms/prony.h); else -1 with a message naming the tick it needs. */
int tf_prony_tick_allows(const tf_prony_terms *t, const tf_histories *h, char *err,
                         size_t errlen);

/* The float32 model m (prony or resonant) stepped through every history of
 * set from rest (tf_stateful_step), against the true displacements: the largest and RMS
 * error and the largest |displacement| (mm).  Returns 0, or -1 when out of
 * memory. */
int tf_prony_history_errors(const tf_model *m, const tf_history_set *set, double *max,
                            double *rms, double *peak);

/* What the stateful families (prony, resonant) share in the registry:
 * the held-out errors of the float32 model stepped through the cases'
 * held-out histories (rel_max over the largest displacement there), and
 * the orders as "p=1 [r=3] K=2 [tick=1000000ns]". */
/* The largest error of a prony model's Q31 form (q31-format.md §8) over
 * the held-out histories, each stepped from rest with the forces as Q31
 * words, against the solves; NAN when the model has no Q31 form or there
 * are no histories. */
double tf_prony_q31_heldout(const tf_model *m, const tf_cases *c);

int tf_stateful_heldout(const tf_model *m, const tf_cases *c, double *max, double *rms,
                        double *rel_max, uint32_t *n);
void tf_stateful_orders_text(const tf_model *m, int style, char *buf, size_t n);

#endif /* TF_PRONY_FAMILY_H */
