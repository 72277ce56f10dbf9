/*
 * target_view.h — a tfit_model descriptor pointing into a host tf_model's
 * tables, so the host can run the target library on host-built models:
 * the tests compare it with the reference evaluator, and `tissuefit sweep`
 * times it.  Expected bits never come from here (docs/architecture.md).
 */
#ifndef TF_TARGET_VIEW_H
#define TF_TARGET_VIEW_H

#include "model/model.h"
#include "model/q31.h"
#include "tfit.h"
#include "tfit_q31.h"

/* Fills *t to describe m (tables shared, not copied), CRC included. */
void tf_target_view(const tf_model *m, tfit_model *t);

/* The same for a Q31 form. */
void tf_target_view_q31(const tf_q31 *q, tfit_model_q31 *t);

#endif /* TF_TARGET_VIEW_H */
