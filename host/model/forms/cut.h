/*
 * cut.h — the cut form's evaluation at a cut progress (forms/cut.c,
 * docs/header-format.md §5.7).
 */
#ifndef TF_CUT_FORM_H
#define TF_CUT_FORM_H

#include "model/model.h"

/* A cut model at the raw force in[3] and cut progress s, as
 * tfit_displacements_cut(): the status, outputs into out[3 n_out], the
 * operations added to ops (may be NULL). */
tfit_status tf_cut_ref_eval(const tf_model *m, const float in[3], float s, float *out,
                            tf_opcount *ops);

#endif /* TF_CUT_FORM_H */
