/*
 * tfit_modal.c — modal family: r spatial modes times polynomial amplitudes.
 *
 * coef = input map (12) | A[r][T] | U[3 n_out][r]
 *   a_k    = A[k][0] + A[k][1] phi1 + ... (left to right)
 *   out[o] = U[o][0] a_0 + U[o][1] a_1 + ... (left to right)
 */
#include "tfit_internal.h"

void tfit_eval_modal(const tfit_model *m, const float g[3], float *out)
{
    float phi[TFIT_MAX_TERMS];
    float a[TFIT_MAX_RANK];
    const uint32_t p = m->dims[0];
    const uint32_t r = m->dims[1];
    const uint32_t n_terms = TFIT_TERMS(p);
    const uint32_t n_rows = 3u * m->n_out;
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *modes = amp + r * n_terms;

    tfit_basis(p, g, phi);
    for (uint32_t k = 0u; k < r; ++k) {
        a[k] = tfit_row(amp + k * n_terms, phi, n_terms);
    }
    for (uint32_t o = 0u; o < n_rows; ++o) {
        out[o] = tfit_dot(modes + o * r, a, r);
    }
}
