/*
 * oscillator.h — one damped mode of a resonant model (docs/header-format.md
 * §5.8) as numbers, without the model object: the unit-gain oscillator
 *
 *     y'' + 2 zeta w y' + w^2 y = w^2 g
 *
 * stepped over a tick T with the input held (zero-order hold) by the
 * transition matrix F = exp(T w [[0, 1], [-1, -2 zeta]]) of the scaled
 * state (y, y'/w), computed by GSL's scaling and squaring (Moler and Van
 * Loan 1978) and rounded to float once by the model (model/forms/resonant.h).
 *
 * The float recursion keeps its state finite and its error bounded only
 * when the rounded F still contracts: its spectral norm (in double, of the
 * float entries) must be at most 1 - 2^-20.  For the exact F, 1 - |F|_2 is
 * about (2/3) zeta (w T)^3 for small w T, so a slow, lightly damped mode
 * at a fast tick is refused (measured: make resonant-study,
 * docs/fitting.md §8.3), with the tick it would need.  A mode faster than
 * TF_RESONANT_MAX_WT / T is not resolved by the tick (fewer than
 * 2 pi / 1.5 = 4.2 ticks per period) and is refused too.
 */
#ifndef TF_OSCILLATOR_H
#define TF_OSCILLATOR_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"

#define TF_RESONANT_MIN_MARGIN 0x1p-20 /* 1 - |F|_2 at least this */
#define TF_RESONANT_MAX_WT 1.5        /* omega T at most this */
#define TF_RESONANT_MAX_ZETA 2.0      /* zeta at most this */

/* F = exp(T w [[0, 1], [-1, -2 zeta]]) in double, row-major f[4]. */
void tf_resonant_transition(double omega_t, double zeta, double f[4]);

/* The spectral norm of a 2 x 2 matrix (row-major), in double. */
double tf_resonant_norm2(const double f[4]);

/* 0 when a mode omega (rad/s), zeta at tick (s) is one the float
 * recursion carries (w T <= TF_RESONANT_MAX_WT, the rounded F's norm at
 * most 1 - TF_RESONANT_MIN_MARGIN); else 1 with a message naming the
 * mode, its frequency and damping and what the tick would have to be. */
int tf_resonant_params_check(tf_ctx *ctx, double omega, double zeta, double tick);

/* 0 when a mode's seven table floats {f11, f12, f21, f22, w0, w1, w2} are
 * ones the device carries (|F_ij| <= 1, |w| <= 2^10, 1 - |F|_2 >= 2^-20);
 * else 1 with a message naming model `name` and mode k. */
int tf_resonant_floats_check(tf_ctx *ctx, const float pt[7], const char *name, uint32_t k);

#endif /* TF_OSCILLATOR_H */
