/*
 * resonant_family.h — the resonant family's pieces that tests and studies
 * use beside the registry's operations (resonant.c): the search bounds for
 * a set of histories, the number of modes by cross-validation, and the
 * model from a static map and fitted modes.
 */
#ifndef TF_RESONANT_FAMILY_H
#define TF_RESONANT_FAMILY_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/histories.h"
#include "fitting/plan.h"
#include "fitting/resonant_modes.h"
#include "model/model.h"

/* Modes the order search tries: K = 0 .. this; frequency starts per new
 * mode in its cross-validation's fits. */
#define TF_RESONANT_SEARCH_MODES 3
#define TF_RESONANT_CV_STARTS 3
#define TF_RESONANT_ZETA_LO 0.005

/* zeta from TF_RESONANT_ZETA_LO to 1; omega from two periods over the
 * history's length, or the lowest the float recursion carries at the
 * lowest zeta if higher (model/oscillator.h: at a 1 ms tick about 10 Hz),
 * to TF_RESONANT_MAX_WT / T: every mode in the box is one the device can
 * run. */
void tf_resonant_bounds_for(const tf_histories *h, tf_resonant_bounds *b);

/* K = 0 .. TF_RESONANT_SEARCH_MODES by cross-validation over the histories
 * of d (plan->folds folds of whole histories): cv[K] the validation RMS of
 * h, *best the cheapest K within 2 % of the best, modes fitted with it on
 * every history.  Returns 0, or -1 with a message. */
int tf_resonant_select_modes(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h,
                             const tf_fit_plan *plan, double *cv, int *best,
                             tf_resonant_modes *modes);

/* The resonant model of static map s (nodal or modal) and modes t at
 * tick_ns; NULL with a message when a mode is one the float recursion
 * cannot carry at that tick (tf_resonant_params_check). */
tf_model *tf_resonant_assemble(tf_ctx *ctx, const tf_model *s, const tf_resonant_modes *t,
                               uint32_t tick_ns);

#endif /* TF_RESONANT_FAMILY_H */
