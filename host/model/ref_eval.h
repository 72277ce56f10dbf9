/*
 * ref_eval.h — the host's reference evaluator for golden vectors.
 *
 * It implements docs/header-format.md §4–5 independently of target/src:
 * every arithmetic operation is carried out in double and rounded to float
 * immediately (GUIDE §4: double has more than 2*24+2 bits, so this equals
 * IEEE binary32 arithmetic exactly for +, -, *, /).  Expected output bits for
 * the golden vectors come from here, never from the target code.  Each
 * form evaluates its own part (model/forms/: ref_map, ref_eval), with the
 * pieces of model/ref_arith.h; a cut model at a given progress is
 * forms/cut.h's, a stateful model's tick forms/stateful.h's.
 */
#ifndef TF_REF_EVAL_H
#define TF_REF_EVAL_H

#include <stddef.h>

#include "model/model.h"

/* Evaluates m at the raw input in[3] (N or mm) into out[3 m->n_out].
 * Returns the tfit_status the target must return.  When ops is not NULL the
 * operations performed are added to it.  A cut model is evaluated fully
 * cut (s = 1, as the scene's other cases); a stateful model gives its
 * relaxed response (the force held for ever), the equilibrium a
 * time-dependent solver's static solve gives. */
tfit_status tf_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops);

/* Statuses and outputs (n x 3 n_out) of n inputs as the golden vectors
 * define them (tfit_golden_run): each on its own, a cut model's at the
 * golden progress of each vector, a stateful model's as one tick sequence
 * from a reset state. */
void tf_ref_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status, float *out);

/* The input projection alone: g on the unit ball; sets *clamped and *bad. */
void tf_ref_input(const tf_model *m, const float in[3], float g[3], int *clamped, int *bad,
                  tf_opcount *ops);

#endif /* TF_REF_EVAL_H */
