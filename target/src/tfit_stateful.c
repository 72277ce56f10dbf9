/*
 * tfit_stateful.c — what the stateful families (prony, resonant) share: the
 * static map after their own terms as a nodal or modal model, and its
 * evaluation at the filtered input h (docs/header-format.md §5.6, §5.8).
 */
#include "tfit_internal.h"

void tfit_stateful_static(const tfit_model *m, uint32_t skip, tfit_model *v)
{
    v->family = m->dims[1] == 0u ? TFIT_FAMILY_NODAL : TFIT_FAMILY_MODAL;
    v->n_out = m->n_out;
    v->n_dims = m->dims[1] == 0u ? TFIT_NODAL_DIMS : TFIT_MODAL_DIMS;
    v->dims = m->dims;
    v->coef = m->coef + skip;
    v->n_coef = m->n_coef - skip;
    v->node_ids = m->node_ids;
}

/* The static map of a p = 1 model: the assembly of tfit_degree1_armv7em.c
 * on Cortex-M4F/M7, else the same operations in C. */
static void degree1_rows(const float *rows, const float h[3], uint32_t n_out, uint32_t keep,
                         float *out)
{
#if TFIT_DEGREE1_ASM
    tfit_degree1_rows_asm(rows, h, n_out, keep, out);
#else
    tfit_rows_degree1(rows, h, n_out, keep, out);
#endif
}

void tfit_stateful_eval(const tfit_model *v, const float h[3], uint32_t keep, float *out)
{
    if (v->family == TFIT_FAMILY_MODAL) {
        tfit_eval_modal(v, h, keep, out);
    } else if (v->dims[0] != 1u) {
        tfit_eval_nodal(v, h, keep, out);
    } else { /* p = 1: rows of {1, h0, h1, h2} (docs/firmware.md §5.4) */
        degree1_rows(v->coef + TFIT_INPUT_MAP_FLOATS, h, v->n_out, keep, out);
    }
}
