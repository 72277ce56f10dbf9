/*
 * ref_eval.h — the host's reference evaluator for golden vectors.
 *
 * It implements docs/header-format.md §4–5 independently of target/src:
 * every arithmetic operation is carried out in double and rounded to float
 * immediately (GUIDE §4: double has more than 2*24+2 bits, so this equals
 * IEEE binary32 arithmetic exactly for +, -, *, /).  Expected output bits for
 * the golden vectors come from here, never from the target code.
 */
#ifndef TF_REF_EVAL_H
#define TF_REF_EVAL_H

#include <stddef.h>

#include "model/model.h"

/* Evaluates m at the raw input in[3] (N or mm) into out[3 m->n_out].
 * Returns the tfit_status the target must return.  When ops is not NULL the
 * operations performed are added to it.  A prony model gives its relaxed
 * response (the force held for ever: the state {g, 0}, then one tick), the
 * equilibrium a time-dependent solver's static solve gives; h = g there,
 * so it is its static map at g. */
tfit_status tf_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops);

/* A cut model (TFIT_FAMILY_CUT) at the raw force in[3] and cut progress s,
 * as tfit_displacements_cut() (docs/header-format.md §5.7). */
tfit_status tf_ref_eval_cut(const tf_model *m, const float in[3], float s, float *out,
                            tf_opcount *ops);

/* A prony model's state (TFIT_PRONY_STATE_WORDS(K) floats) at rest, and one
 * tick (§5.6): as tfit_prony_reset and tfit_prony_step. */
void tf_ref_prony_reset(const tf_model *m, float *state);
tfit_status tf_ref_prony_step(const tf_model *m, float *state, const float in[3], float *out,
                              tf_opcount *ops);

/* The same for either stateful family (prony, resonant: §5.8, as
 * tfit_resonant_reset and tfit_resonant_step); state of
 * TFIT_RESONANT_MAX_STATE floats at most. */
void tf_ref_stateful_reset(const tf_model *m, float *state);
tfit_status tf_ref_stateful_step(const tf_model *m, float *state, const float in[3], float *out,
                                 tf_opcount *ops);

/* Statuses and outputs (n x 3 n_out) of n inputs as the golden vectors
 * define them: each on its own, or for a prony model one tick sequence from
 * a reset state (tfit_golden_run). */
void tf_ref_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status, float *out);

/* The input projection alone: g on the unit ball; sets *clamped and *bad. */
void tf_ref_input(const tf_model *m, const float in[3], float g[3], int *clamped, int *bad,
                  tf_opcount *ops);

#endif /* TF_REF_EVAL_H */
