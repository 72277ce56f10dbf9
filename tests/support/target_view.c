/*
 * target_view.c — see target_view.h.
 */
#include "target_view.h"

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
