/*
 * target_view.c — see target_view.h.
 */
#include "model/target_view.h"

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
    t->crc32 = tf_model_crc32(m);
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
    t->crc32 = tf_q31_crc32(q);
}
