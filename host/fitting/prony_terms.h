/*
 * prony_terms.h — the time constants and weights of a prony model's creep
 * function, fitted to force histories (docs/fitting.md §7).
 *
 * The data are, per history and tick, the projected normalised input g the
 * device computes and the target h: the input at which the static map
 * gives the true displacements (for a p = 1 map the least-squares solution
 * of S(h) = u; prony.c).  The model is the device's filter in double:
 *
 *     h[n] = g[n] - sum_k w_k e_k[n],
 *     e_k[n] = a_k e_k[n-1] + ((1 - a_k) / r_k) (g[n] - g[n-1]),
 *     r_k = T / tau_k, a_k = exp(-r_k), e_k = 0 and g = g_rest before tick 0.
 *
 * It is linear in the weights and nonlinear in the time constants: the
 * Levenberg-Marquardt core (numerics/lm.h) moves ln tau_k inside bounds,
 * and at every step the weights are the least-squares solution for those
 * time constants (variable projection; Golub and Pereyra 1973), kept
 * non-negative by dropping a term whose weight comes out negative and
 * solving again.  Three starts, the time constants spread log-evenly
 * over the range and shifted by -0.3 and +0.3 of their spacing; the best
 * is kept.  Their sum must not exceed 1 (a creep function starts at
 * J(0) >= 0); a fit whose weights need more is refused as undetermined.
 */
#ifndef TF_PRONY_TERMS_H
#define TF_PRONY_TERMS_H

#include <stddef.h>

#include "base/context.h"
#include "model/model.h"

typedef struct tf_prony_data {
    size_t n_hist, n_ticks;
    const double *g;      /* n_hist x n_ticks x 3, history-major */
    const double *target; /* the same shape: the h to reproduce */
    double g_rest[3];     /* g of the zero force: the reset state */
    double tick;          /* s */
} tf_prony_data;

typedef struct tf_prony_terms {
    int n;
    double tau[TFIT_PRONY_MAX_TERMS]; /* s, increasing */
    double w[TFIT_PRONY_MAX_TERMS];
    double rms; /* of h - target over the histories fitted */
} tf_prony_terms;

/* K terms (0 <= K <= TFIT_PRONY_MAX_TERMS) on histories idx[0..n) (idx
 * NULL: all), time constants within [tau_lo, tau_hi] s.  Returns 0, or -1
 * with a message (TF_FAMILY_UNDETERMINED first when the histories cannot
 * determine K terms). */
int tf_prony_fit_terms(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                       double tau_lo, double tau_hi, tf_prony_terms *out);

/* The same from `starts` (1 to 3) starting points (cheaper, for
 * cross-validation's many fits). */
int tf_prony_fit_terms_from(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                            double tau_lo, double tau_hi, int starts, tf_prony_terms *out);

/* RMS of h - target over histories idx[0..n) (idx NULL: all). */
double tf_prony_terms_rms(const tf_prony_data *d, const size_t *idx, size_t n,
                          const tf_prony_terms *t);

#endif /* TF_PRONY_TERMS_H */
