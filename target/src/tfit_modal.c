/*
 * tfit_modal.c — modal family: r spatial modes times polynomial amplitudes.
 *
 * coef = input map (12) | A[r][T] | U[3 n_out][r]
 *   a_k    = A[k][0] + A[k][1] phi1 + ... (left to right)
 *   out[o] = U[o][0] a_0 + U[o][1] a_1 + ... (left to right)
 * The modes are evaluated one output point (three rows) per iteration,
 * sharing each amplitude; the output mask is applied as each word is stored.
 * On Cortex-M4F/M7 ranks 1 .. 8 reconstruct in assembly
 * (tfit_modal_armv7em.c, the same operations in the same order).
 */
#include "tfit_internal.h"

void tfit_eval_modal(const tfit_model *m, const float g[3], uint32_t keep, float *out)
{
    float phi[TFIT_MAX_TERMS];
    float a[TFIT_MAX_RANK];
    const uint32_t p = m->dims[0];
    const uint32_t r = m->dims[1];
    const uint32_t n_terms = TFIT_TERMS(p);
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    /* U ends the table (amp + r T for a whole model): counted from the end,
     * a view of output point j alone (n_out = 1, n_coef shortened) finds
     * U's row j, as tfit_model_check's self-test needs */
    const float *u = m->coef + (m->n_coef - 3u * r * m->n_out);

    tfit_basis(p, g, phi);
    for (uint32_t k = 0u; k < r; ++k) {
        /* masked: +0.0f for a NaN/Inf input (the assembly's zero rows need
         * it; the C rows mask their outputs anyway) */
        a[k] = tfit_masked(tfit_row(amp + k * n_terms, phi, n_terms), keep);
    }
#if TFIT_DEGREE1_ASM
    if (r <= TFIT_MODAL_ASM_MAX_RANK) {
        tfit_modal_rows_asm(r, u, a, m->n_out, keep, out);
        return;
    }
#endif
    tfit_modal_rows_c(u, a, r, m->n_out, keep, out);
}
