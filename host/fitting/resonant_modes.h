/*
 * resonant_modes.h — the damped modes of a resonant model (docs/fitting.md
 * §8), fitted to force histories.
 *
 * The data are those of the prony family (prony_terms.h, tf_prony_data):
 * per history and tick the projected input g the device computes and the
 * target h, the input at which the static map gives the true displacements.
 * The model is the device's filter in double (model/forms/resonant.h, zero-order
 * hold), per axis i:
 *
 *     h_i[n] = g_i[n] + sum_k w_ki s_ki[n],
 *     (s, v)_k[n] = F_k ((s, v)_k[n-1] - (g_i[n] - g_i[n-1], 0)),
 *     F_k = exp(T w_k [[0, 1], [-1, -2 zeta_k]]),  s = v = 0, g = g_rest before tick 0.
 *
 * Linear in the weights, nonlinear in (w_k, zeta_k): the Levenberg-Marquardt
 * core (numerics/lm.h) moves ln w_k and ln zeta_k inside bounds, and at
 * every step the weights of each axis are the least-squares solution for
 * those modes (variable projection; Golub and Pereyra 1973; LAPACK dgels).
 * Modes are added one at a time: K modes start from the K - 1 fitted ones
 * and a new one tried at TF_RESONANT_STARTS frequencies spread log-evenly
 * over the bounds (the best after LM on all of them is kept), because the
 * residual is far from convex in a frequency.  Weights beyond
 * TF_RESONANT_MAX_WEIGHT in magnitude are outside the domain.
 */
#ifndef TF_RESONANT_MODES_H
#define TF_RESONANT_MODES_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/prony_terms.h"
#include "model/model.h"

#define TF_RESONANT_STARTS 8
/* A weight beyond this marks modes that cancel each other (a slow creep
 * fitted by a near-static mode times 10^7, say), not a body's ringing: the
 * point is outside the model's domain (non-finite residual) for the LM. */
#define TF_RESONANT_MAX_WEIGHT 8.0

typedef struct tf_resonant_modes {
    int n;
    double omega[TFIT_RESONANT_MAX_MODES]; /* rad/s, increasing */
    double zeta[TFIT_RESONANT_MAX_MODES];
    double w[TFIT_RESONANT_MAX_MODES][3];  /* per input axis */
    double rms; /* of h - target over the histories fitted */
} tf_resonant_modes;

/* Bounds of the search: omega in [omega_lo, omega_hi] rad/s, zeta in
 * [zeta_lo, zeta_hi]. */
typedef struct tf_resonant_bounds {
    double omega_lo, omega_hi, zeta_lo, zeta_hi;
} tf_resonant_bounds;

/* K modes (0 <= K <= TFIT_RESONANT_MAX_MODES) on histories idx[0..n) (idx
 * NULL: all).  Returns 0, or -1 with a message (TF_FAMILY_UNDETERMINED first
 * when the histories cannot determine K modes). */
int tf_resonant_fit_modes(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n, int k,
                          const tf_resonant_bounds *b, tf_resonant_modes *out);

/* The same from n_starts frequencies for each new mode (cheaper, for
 * cross-validation's many fits). */
int tf_resonant_fit_modes_from(tf_ctx *ctx, const tf_prony_data *d, const size_t *idx, size_t n,
                               int k, const tf_resonant_bounds *b, int n_starts,
                               tf_resonant_modes *out);

/* RMS of h - target over histories idx[0..n) (idx NULL: all). */
double tf_resonant_modes_rms(const tf_prony_data *d, const size_t *idx, size_t n,
                             const tf_resonant_modes *t);

#endif /* TF_RESONANT_MODES_H */
