/*
 * target_view.c — see target_view.h.
 */
#include "model/target_view.h"

#include <stdlib.h>

#include "model/golden.h"

void tf_target_view(const tf_model *m, tfit_model *t)
{
    t->api_version = TFIT_API_VERSION;
    t->family = (uint32_t)m->family;
    t->n_out = m->n_out;
    t->n_dims = m->n_dims;
    t->n_coef = m->n_coef;
    t->dims = m->dims;
    t->coef = m->coef;
    t->node_ids = m->node_ids;
    t->dims_end = m->dims + m->n_dims;
    t->coef_end = m->coef + m->n_coef;
    t->node_ids_end = m->node_ids + m->n_out;
    if (tf_check_vector(m, t->check) != 0) {
        abort(); /* out of memory for 3 n_out floats */
    }
    t->crc32 = tf_model_crc32_checked(m, t->check);
}

void tf_target_view_q31(const tf_q31 *q, tfit_model_q31 *t)
{
    t->api_version = TFIT_Q31_API_VERSION;
    t->family = (uint32_t)q->family;
    t->n_out = q->n_out;
    t->degree = q->degree;
    t->n_words = q->n_words;
    t->q = q->q;
    t->node_ids = q->node_ids;
    t->q_end = q->q + q->n_words;
    t->node_ids_end = q->node_ids + q->n_out;
    t->crc32 = tf_q31_crc32(q);
}
