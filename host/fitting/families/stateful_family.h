/*
 * stateful_family.h — what the stateful families (prony, resonant;
 * docs/fitting.md §7, §8) share: one fit loop over a filter fit.
 *
 * A stateful family fits a static map (a nodal or modal model of the
 * static cases, which a time-dependent solver gives at equilibrium) and
 * then its filter's K terms to the cases' force histories: the data are,
 * per history and tick, the projected input g the device computes and the
 * target h, the input at which the static map gives the true displacements
 * (tf_prony_data, fitting/prony_terms.h).  The order search: p by the nodal
 * family's cross-validation on the static cases; K = 0 .. search by
 * cross-validation over the training histories (folds of whole histories,
 * the RMS of h), the cheapest within 2 % of the best.  Held-out errors are
 * those of the float32 model stepped through the held-out histories
 * (tf_stateful_step) against the truth.  What differs between the families
 * is a tf_filter_fit: how the terms are fitted and how a model is made of
 * them.
 */
#ifndef TF_STATEFUL_FAMILY_H
#define TF_STATEFUL_FAMILY_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/families/family.h"
#include "fitting/histories.h"
#include "fitting/plan.h"
#include "fitting/prony_terms.h"
#include "model/model.h"

/* K searched at most (a tf_filter_fit's search). */
#define TF_STATEFUL_MAX_SEARCH 8

/* A stateful family's fit of its filter's terms. */
typedef struct tf_filter_fit {
    const char *name;  /* the family's name, in messages and the model's */
    const char *terms; /* what K counts, in messages: "terms", "modes" */
    tfit_family id;    /* the form of its models */
    int search;        /* K = 0 .. search tried, at most TF_STATEFUL_MAX_SEARCH */
    size_t size;       /* bytes of the fitted terms (tf_prony_terms, ...) */
    /* K terms on histories idx[0..n) (idx NULL: all) of d, within what the
     * histories h allow, into terms; cv != 0: the cheaper fit of
     * cross-validation's folds.  Returns 0, or -1 with a message
     * (TF_FAMILY_UNDETERMINED first when the histories cannot determine K). */
    int (*fit)(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h, const size_t *idx,
               size_t n, int k, int cv, void *terms);
    /* RMS of h - target over histories idx[0..n) (idx NULL: all). */
    double (*rms)(const tf_prony_data *d, const size_t *idx, size_t n, const void *terms);
    /* The model of static map s and the fitted terms at the histories'
     * tick, or NULL with a message (terms the device cannot carry). */
    tf_model *(*assemble)(tf_ctx *ctx, const tf_model *s, const void *terms, const tf_histories *h);
} tf_filter_fit;

/* The filter's data (prony_terms.h) of static map s on a history set: g as
 * the device projects each tick's force, h the input at which s gives the
 * tick's true displacements (least squares, Gauss-Newton from the last
 * tick's).  Returns 0, or -1 with a message; free with tf_prony_data_free. */
int tf_prony_data_build(tf_ctx *ctx, const tf_model *s, const tf_history_set *set, double tick,
                        tf_prony_data *d);
void tf_prony_data_free(tf_prony_data *d);

/* K = 0 .. ff->search by cross-validation over the histories of d
 * (plan->folds folds of whole histories): cv[K] the validation RMS of h,
 * *best the cheapest K within 2 % of the best, the terms fitted with it on
 * every history.  Returns 0, or -1 with a message. */
int tf_stateful_select_terms(tf_ctx *ctx, const tf_filter_fit *ff, const tf_prony_data *d,
                             const tf_histories *h, const tf_fit_plan *plan, double *cv, int *best,
                             void *terms);

/* The family operations (family.h) of a stateful family with filter fit
 * ff: the model of orders {p, r, K, tick} (static map on the static cases
 * idx, terms on every training history), the order search, the sweep's
 * candidates (nodal static maps, every p and K the cases determine). */
tf_model *tf_stateful_fit(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                          const size_t *idx, size_t m, const uint32_t *orders);
int tf_stateful_select(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                       const tf_fit_plan *plan, tf_family_result *r);
int tf_stateful_candidates(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                           const tf_fit_plan *plan, tf_family_take take, void *arg);

/* The float32 model m (any stateful form) stepped through every history of
 * set from rest (tf_stateful_step), against the true displacements: the
 * largest and RMS error and the largest |displacement| (mm).  Returns 0,
 * or -1 when out of memory. */
int tf_stateful_history_errors(const tf_model *m, const tf_history_set *set, double *max,
                               double *rms, double *peak);

/* tf_family.heldout of every stateful family: the errors of the float32
 * model stepped through the cases' held-out histories (rel_max over the
 * largest displacement there); and its orders_text, "p=1 [r=3] K=2
 * [tick=1000000ns]". */
int tf_stateful_heldout(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max,
                        double *rms, double *rel_max, uint32_t *n);
void tf_stateful_orders_text(const tf_model *m, int style, char *buf, size_t n);

#endif /* TF_STATEFUL_FAMILY_H */
