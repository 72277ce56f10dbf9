/*
 * tfit_q31_golden.c — runs a Q31 model's golden vectors (NAME_golden.h) and
 * counts mismatching words, on the device as on the host.
 */
#include "tfit_q31_internal.h"

uint32_t tfit_golden_run_q31(const tfit_golden_q31 *gv, int32_t *scratch)
{
    if (gv == 0 || gv->model == 0 || gv->in == 0 || gv->status == 0 || gv->out == 0 ||
        scratch == 0) {
        return UINT32_MAX;
    }
    const tfit_model_q31 *m = gv->model;
    const uint32_t n = 3u * m->n_out;
    const int prony = m->family == (uint32_t)TFIT_FAMILY_PRONY;
    int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    uint32_t mismatches = 0u;
    if (prony && (m->n_words <= TFIT_Q31_PRONY_K_WORD || m->q[TFIT_Q31_PRONY_K_WORD] < 0 ||
                  m->q[TFIT_Q31_PRONY_K_WORD] > (int32_t)TFIT_PRONY_MAX_TERMS)) {
        return UINT32_MAX;
    }
    if (prony) { /* the vectors are one tick sequence from rest */
        (void)tfit_prony_reset_q31(m, state);
    }
    for (uint32_t v = 0u; v < gv->n_vec; ++v) {
        const int32_t *x = gv->in + 3u * v;
        tfit_status s = prony ? tfit_prony_step_q31(m, state, x, scratch)
                        : m->family == (uint32_t)TFIT_FAMILY_CONTACT
                            ? tfit_contact_force_q31(m, x, scratch)
                            : tfit_displacements_q31(m, x, scratch);
        mismatches += (uint32_t)((int32_t)s != gv->status[v]);
        for (uint32_t o = 0u; o < n; ++o) {
            mismatches += (uint32_t)(scratch[o] != gv->out[v * n + o]);
        }
    }
    return mismatches;
}
