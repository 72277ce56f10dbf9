/*
 * resonant.h — the modes of a resonant model (docs/header-format.md §5.7)
 * from their continuous-time description: angular frequency omega_k,
 * damping ratio zeta_k and per-axis weights w_k of the unit-gain oscillator
 *
 *     y'' + 2 zeta w y' + w^2 y = w^2 g,   h = g + sum_k w_k (y_k - g),
 *
 * at the header's tick T, the input held over each tick (zero-order hold,
 * as tf_solver_history applies a history's forces; tfit_resonant.c gives
 * the update).  The transition
 * matrix F = exp(T w [[0, 1], [-1, -2 zeta]]) of the scaled state
 * (y, y'/w) is the matrix exponential (GSL's scaling and squaring, Moler
 * and Van Loan 1978), rounded to float once.
 *
 * The float recursion keeps its state finite and its error bounded only
 * when the rounded F still contracts: its spectral norm (in double, of the
 * float entries) must be at most 1 - 2^-20.  For the exact F, 1 - |F|_2 is
 * about (2/3) zeta (w T)^3 for small w T (the energy y^2 + (y'/w)^2 a tick
 * loses at least), so a slow, lightly damped mode at a fast tick is refused
 * (measured: make resonant-study, docs/fitting.md §8.3), with the tick it
 * would need.  A mode faster than TF_RESONANT_MAX_WT / T is not resolved by
 * the tick (fewer than 2 pi / 1.5 = 4.2 ticks per period) and is refused
 * too.
 */
#ifndef TF_RESONANT_H
#define TF_RESONANT_H

#include <stddef.h>
#include <stdint.h>

#include "model/model.h"

#define TF_RESONANT_MIN_MARGIN 0x1p-20 /* 1 - |F|_2 at least this */
#define TF_RESONANT_MAX_WT 1.5        /* omega T at most this */
#define TF_RESONANT_MAX_ZETA 2.0      /* the device's limit: z = 2 zeta <= 4 */

/* F = exp(T w [[0, 1], [-1, -2 zeta]]) in double, row-major f[4]. */
void tf_resonant_transition(double omega_t, double zeta, double f[4]);

/* The spectral norm of a 2 x 2 matrix (row-major), in double. */
double tf_resonant_norm2(const double f[4]);

/* Sets mode k of m (dims[3] ns tick): F rounded to float, the weights.
 * omega in rad/s. */
void tf_resonant_set_mode(tf_model *m, uint32_t k, double omega, double zeta,
                          const double w[3]);

/* The mode's omega (rad/s) and zeta as the rounded F realises them (from
 * its eigenvalues), and its weights. */
void tf_resonant_get_mode(const tf_model *m, uint32_t k, double *omega, double *zeta,
                          double w[3]);

/* 0 when mode k of m is one the float recursion carries (the device's
 * magnitude limits, w T <= TF_RESONANT_MAX_WT, and the rounded F's norm at
 * most 1 - TF_RESONANT_MIN_MARGIN); else 1 with a message naming the mode,
 * its frequency and damping and what the tick would have to be. */
int tf_resonant_mode_check(const tf_model *m, uint32_t k, char *err, size_t errlen);

/* The same for a mode not yet written: omega (rad/s), zeta at tick (s). */
int tf_resonant_params_check(double omega, double zeta, double tick, char *err, size_t errlen);

/* The tick of m in seconds. */
double tf_resonant_tick(const tf_model *m);

#endif /* TF_RESONANT_H */
