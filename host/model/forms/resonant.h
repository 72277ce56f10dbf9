/*
 * resonant.h — the resonant form (forms/resonant.c, paired with
 * target/src/tfit_resonant.c): a stateful form (stateful.h) whose filter is
 * K damped modes, a body with inertia (docs/header-format.md §5.8).  The
 * modes in its table: angular frequency omega_k, damping ratio zeta_k and
 * per-axis weights w_k of the unit-gain oscillators (model/oscillator.h)
 *
 *     y'' + 2 zeta w y' + w^2 y = w^2 g,   h = g + sum_k w_k (y_k - g),
 *
 * at the header's tick T, the input held over each tick (zero-order hold,
 * as tf_solver_history applies a history's forces; tfit_resonant.c gives
 * the update): F rounded to float once, then the weights.
 */
#ifndef TF_RESONANT_FORM_H
#define TF_RESONANT_FORM_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "model/forms/stateful.h"
#include "model/model.h"
#include "model/oscillator.h"

/* Sets mode k of m (dims[3] ns tick): F rounded to float, the weights.
 * omega in rad/s. */
void tf_resonant_set_mode(tf_model *m, uint32_t k, double omega, double zeta,
                          const double w[3]);

/* The mode's omega (rad/s) and zeta as the rounded F realises them (from
 * its eigenvalues), and its weights. */
void tf_resonant_get_mode(const tf_model *m, uint32_t k, double *omega, double *zeta,
                          double w[3]);

/* tf_resonant_floats_check (oscillator.h) of mode k of m. */
int tf_resonant_mode_check(tf_ctx *ctx, const tf_model *m, uint32_t k);

#endif /* TF_RESONANT_FORM_H */
