/*
 * ref_eval.c — reference evaluator (see ref_eval.h): each model by its
 * form (model/forms/form.h).
 */
#include "model/ref_eval.h"

#include "model/forms/form.h"
#include "model/ref_arith.h"

tfit_status tf_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    return tf_form_of(m->family)->ref_eval(m, in, out, ops);
}

void tf_ref_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status, float *out)
{
    tf_form_of(m->family)->golden_run(m, in, n, status, out);
}

void tf_ref_input(const tf_model *m, const float in[3], float g[3], int *clamped, int *bad,
                  tf_opcount *ops)
{
    tf_arith c = {{0, 0, 0}};
    tf_ref_project(&c, m, in, g, clamped, bad);
    tf_ref_count(ops, &c);
}
