/*
 * tfit_q31_eval.c — the Q31 basis, rows and entry points
 * (docs/q31-format.md §4-§5).
 *
 * q = input map (13 words) | per output row o (node-major, as the float
 * nodal layout): s_o, c_o[0], ..., c_o[T-1].
 *   phi (Q30): phi_0 = 2^30, phi_k = round(g_v phi_parent / 2^30), the
 *              float basis's recurrence and order (header-format.md §5.1)
 *   acc      = sum_t c_o[t] phi_t, exact in 64 bits
 *   out[o]   = round(acc / 2^s_o) = floor((hi(acc) + 2^(s_o - 33)) / 2^(s_o - 32)),
 *              33 <= s_o <= 62: only the high word of acc matters.
 */
#include "tfit_q31_internal.h"

void tfit_q31_basis(uint32_t p, const int32_t g[3], int32_t *phi)
{
    uint32_t prev = 0u, n_prev = 1u, k = 1u;
    phi[0] = TFIT_Q31_ONE;
    for (uint32_t d = 1u; d <= p; ++d) {
        for (uint32_t i = 0u; i < n_prev; ++i) {
            phi[k++] = (int32_t)q_shr64_lo(q_smul(g[0], phi[prev + i]) + (1u << 29), 30u);
        }
        for (uint32_t i = n_prev - d; i < n_prev; ++i) {
            phi[k++] = (int32_t)q_shr64_lo(q_smul(g[1], phi[prev + i]) + (1u << 29), 30u);
        }
        phi[k++] = (int32_t)q_shr64_lo(q_smul(g[2], phi[prev + n_prev - 1u]) + (1u << 29), 30u);
        prev += n_prev;
        n_prev += d + 1u;
    }
}

static int32_t row(const int32_t *r, const int32_t *phi, uint32_t n_terms)
{
    const uint32_t s = (uint32_t)r[0];
    const int32_t *c = r + 1;
    uint64_t acc = q_smul(c[0], phi[0]);
    for (uint32_t t = 1u; t < n_terms; ++t) {
        acc += q_smul(c[t], phi[t]);
    }
    return q_sra32(q_hi(acc) + (1u << (s - 33u)), s - 32u);
}

static tfit_status evaluate_q31(const tfit_model_q31 *m, const int32_t in[3], int32_t *out)
{
    int32_t g[3];
    int32_t phi[TFIT_Q31_MAX_TERMS];
    const uint32_t n_terms = q_terms(m->degree);
    const int32_t *r = m->q + TFIT_Q31_MAP_WORDS;
    const uint32_t clamped = tfit_q31_input_map(m->q, in, g);

    tfit_q31_basis(m->degree, g, phi);
    for (uint32_t o = 0u; o < 3u * m->n_out; ++o) {
        out[o] = row(r, phi, n_terms);
        r += n_terms + 1u;
    }
    return (tfit_status)(int)(clamped & 1u);
}

tfit_status tfit_displacements_q31(const tfit_model_q31 *m, const int32_t force[3], int32_t *out)
{
    if (m == 0 || m->q == 0 || force == 0 || out == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->family != (uint32_t)TFIT_FAMILY_NODAL) {
        return TFIT_ERR_FAMILY;
    }
    return evaluate_q31(m, force, out);
}

tfit_status tfit_contact_force_q31(const tfit_model_q31 *m, const int32_t disp[3],
                                   int32_t force[3])
{
    if (m == 0 || m->q == 0 || disp == 0 || force == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->family != (uint32_t)TFIT_FAMILY_CONTACT) {
        return TFIT_ERR_FAMILY;
    }
    return evaluate_q31(m, disp, force);
}
