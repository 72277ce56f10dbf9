/*
 * tfit_q31_eval.c — the Q31 basis, rows and entry points
 * (docs/q31-format.md §4-§5).
 *
 * q = input map (13 words) | per output row o (node-major, as the float
 * nodal layout): s_o, c_o[0], ..., c_o[T-1].
 *   phi (Q30): the Chebyshev terms T_a(g0) T_b(g1) T_c(g2) of the float
 *              basis (header-format.md §5.1), each product rounded to Q30
 *   acc      = sum_t c_o[t] phi_t, exact in 64 bits
 *   out[o]   = round(acc / 2^s_o) = floor((hi(acc) + 2^(s_o - 33)) / 2^(s_o - 32)),
 *              33 <= s_o <= 62: only the high word of acc matters.
 */
#include "tfit_q31_internal.h"

/* round(a b / 2^30), the product of two Q30 words in Q30. */
static int32_t q30_mul(int32_t a, int32_t b)
{
    return (int32_t)q_shr64_lo(q_smul(a, b) + (1u << 29), 30u);
}

/* t[k] = T_k(g) in Q30, k = 0..p: t[0] = 2^30, t[1] = g,
 * t[k] = round(g t[k-1] / 2^29) - t[k-2] (q31-format.md §4).  The rounded
 * product 2 g t can reach 2^31 and wraps in 32 bits; the difference is
 * |T_k| <= 2^30 + 2^14 and comes out exact, because uint32_t arithmetic is
 * modulo 2^32. */
static inline void chebyshev_q30(uint32_t p, int32_t g, int32_t *t)
{
    t[0] = TFIT_Q31_ONE;
    t[1] = g;
    for (uint32_t k = 2u; k <= p; ++k) {
        const uint32_t h = q_shr64_lo(q_smul(g, t[k - 1u]) + (1u << 28), 29u);
        t[k] = (int32_t)(h - (uint32_t)t[k - 2u]);
    }
}

/* phi = round(T_a(g0) round(T_b(g1) T_c(g2) / 2^30) / 2^30), the float
 * basis's order (tfit_basis.c: the inner products by b + c, then one
 * product per term).  Products by T_0 = 2^30 are exact. */
void tfit_q31_basis(uint32_t p, const int32_t g[3], int32_t *phi)
{
    int32_t t0[TFIT_Q31_MAX_DEGREE + 1u], t1[TFIT_Q31_MAX_DEGREE + 1u], t2[TFIT_Q31_MAX_DEGREE + 1u];
    int32_t q[((TFIT_Q31_MAX_DEGREE + 1u) * (TFIT_Q31_MAX_DEGREE + 2u)) / 2u];
    uint32_t k = 0u;

    /* No early return for p = 0 (the loops then give phi[0] = 2^30 from
     * exact products by 2^30): GCC would split the function into a
     * ".part" clone that the stack table (linker/firmware.mk) cannot see. */
    chebyshev_q30(p, g[0], t0);
    chebyshev_q30(p, g[1], t1);
    chebyshev_q30(p, g[2], t2);
    for (uint32_t e = 0u; e <= p; ++e) {
        for (uint32_t b = e + 1u; b-- > 0u;) {
            q[k++] = q30_mul(t1[b], t2[e - b]);
        }
    }
    k = 0u;
    for (uint32_t d = 0u; d <= p; ++d) {
        uint32_t base = 0u;
        for (uint32_t e = 0u; e <= d; ++e) {
            const int32_t ta = t0[d - e];
            for (uint32_t j = 0u; j <= e; ++j) {
                phi[k++] = q30_mul(ta, q[base + j]);
            }
            base += e + 1u;
        }
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

void tfit_q31_rows(const tfit_model_q31 *m, const int32_t *r, const int32_t g[3], int32_t *out)
{
    int32_t phi[TFIT_Q31_MAX_TERMS];
    const uint32_t n_terms = q_terms(m->degree);

    tfit_q31_basis(m->degree, g, phi);
    for (uint32_t o = 0u; o < 3u * m->n_out; ++o) {
        out[o] = row(r, phi, n_terms);
        r += n_terms + 1u;
    }
}

static tfit_status evaluate_q31(const tfit_model_q31 *m, const int32_t in[3], int32_t *out)
{
    int32_t g[3];
    const uint32_t clamped = tfit_q31_input_map(m->q, in, g);

    tfit_q31_rows(m, m->q + TFIT_Q31_MAP_WORDS, g, out);
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
