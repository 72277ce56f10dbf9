/*
 * prony.h — the prony form (forms/prony.c, paired with
 * target/src/tfit_prony.c): a stateful form (stateful.h) whose filter is K
 * exponential terms, viscoelastic creep (docs/header-format.md §5.6).  Its
 * terms from their continuous-time description: time constant tau_k and
 * weight w_k of the normalised creep function
 *
 *     J(t) / J(inf) = 1 - sum_k w_k exp(-t / tau_k),   w_k >= 0, sum w_k <= 1,
 *
 * at the header's tick period T.  Each term is the exact first-order-hold
 * update of e = g - x, tau x' = g - x, over one tick:
 *
 *     e[n] = a e[n-1] + ((1 - a) / r) (g[n] - g[n-1]),   r = T / tau, a = exp(-r),
 *
 * stored as a_k and D_k = w_k (1 - a_k) / r_k.  a_k is rounded to float once,
 * and the time constant the device then realises, tau' = -T / ln(a_k), is
 * what the fit uses (tf_prony_realised_tau): the float rounding of a moves
 * the decay rate by up to 2^-25 / r relative, which is not small for slow
 * terms, so the host fits with the rate the device has rather than the one
 * it asked for.
 */
#ifndef TF_PRONY_FORM_H
#define TF_PRONY_FORM_H

#include <stdint.h>

#include "model/forms/stateful.h"
#include "model/model.h"

/* The slowest time constant a model may have, in ticks: beyond it the
 * float32 update of a term loses more than 0.1 % of the peak response over
 * 10^6 ticks (measured: make prony-study, docs/fitting.md §7). */
#define TF_PRONY_MAX_TAU_TICKS 1e5

/* The float decay a = exp(-T / tau) rounded to nearest, and the time
 * constant it realises.  tick and tau in seconds, tau > 0. */
float tf_prony_decay(double tick, double tau);
double tf_prony_realised_tau(double tick, float decay);

/* (1 - a) / r for the float decay a, with r = -ln(a) (the realised
 * T / tau), accurate for every a in (0, 1): the first-order-hold gain of a
 * unit weight. */
double tf_prony_hold_gain(float decay);

/* Sets term k of m: a_k from tau (s), D_k = w (1 - a_k) / r_k at the
 * model's tick (dims[3] ns).  Returns the realised time constant (s). */
double tf_prony_set_term(tf_model *m, uint32_t k, double tau, double weight);

/* Term k of m as the device realises it: its time constant (s) and its
 * weight in the normalised creep function. */
void tf_prony_get_term(const tf_model *m, uint32_t k, double *tau, double *weight);

#endif /* TF_PRONY_FORM_H */
