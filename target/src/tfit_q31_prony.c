/*
 * tfit_q31_prony.c — the prony family in Q31 (docs/q31-format.md §8): the
 * float step of tfit_prony.c in integers, one fixed-cost step per tick with
 * a caller-owned int32 state.
 *
 * q = input map (13) | K | K pairs {a_k (Q31), D_k (Q30)} | nodal rows.
 * state = gp[3] (the previous tick's projected input, Q30) | z[K][3] (Q29).
 *
 * One tick, force word x:
 *   g = the Q31 projection of x (§3), status TFIT_CLAMPED when projected
 *   z_ki <- round((a_k z_ki + D_k g_i - D_k gp_i) / 2^31)   (Q60 -> Q29)
 *   h_i  = g_i - 2 sum_k z_ki, in 64 bits, saturated to [-2^30, 2^30]
 *   out  = the nodal rows at h (§4-§5); gp <- g
 * The sum is exact in 64 bits for any state words (|a z| < 2^62,
 * |D g| <= 2^60 + 2^34, |D gp| <= 2^61); the new z is the low word of the
 * rounded quotient, which §8's bound keeps exact for every state reached
 * from tfit_prony_reset_q31() (modulo 2^32 for a damaged state: defined,
 * and h's saturation keeps the rows inside their range proof either way).
 * No branch on the input or the state.
 */
#include "tfit_q31_internal.h"

#define Q30_ONE 0x40000000u

/* The int32 word z as a 64-bit two's complement value. */
static uint64_t widen(uint32_t z)
{
    return q_words(q_negative(z), z);
}

/* v (a 64-bit value with |v| < 2^62) saturated to [-2^30, 2^30]. */
static int32_t saturate_q30(uint64_t v)
{
    const uint32_t over = q_negative(q_hi(q_words(0u, Q30_ONE) - v));  /* v > 2^30 */
    const uint32_t under = q_negative(q_hi(v + q_words(0u, Q30_ONE))); /* v < -2^30 */
    return (int32_t)q_select(over, Q30_ONE, q_select(under, 0u - Q30_ONE, q_lo(v)));
}

/* The terms' update and the filtered input h (Q30). */
static void filter_q31(const int32_t *q, const int32_t g[3], int32_t *state, int32_t h[3])
{
    const uint32_t terms = (uint32_t)q[TFIT_Q31_PRONY_K_WORD];
    const int32_t *pt = q + TFIT_Q31_PRONY_K_WORD + 1;
    uint64_t hs[3] = {widen((uint32_t)g[0]), widen((uint32_t)g[1]), widen((uint32_t)g[2])};
    int32_t *z = state + 3;

    for (uint32_t k = 0u; k < terms; ++k, pt += 2, z += 3) {
        for (uint32_t i = 0u; i < 3u; ++i) {
            uint64_t acc = q_smul(pt[0], z[i]);
            acc += q_smul(pt[1], g[i]);
            acc -= q_smul(pt[1], state[i]);
            const uint32_t zn = q_shr64_lo(acc + (1u << 30), 31u);
            z[i] = (int32_t)zn;
            hs[i] -= widen(zn) + widen(zn);
        }
    }
    for (uint32_t i = 0u; i < 3u; ++i) {
        h[i] = saturate_q30(hs[i]);
        state[i] = g[i];
    }
}

static int usable(const tfit_model_q31 *m)
{
    return m != 0 && m->q != 0;
}

tfit_status tfit_prony_reset_q31(const tfit_model_q31 *m, int32_t *state)
{
    if (!usable(m) || state == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->family != (uint32_t)TFIT_FAMILY_PRONY) {
        return TFIT_ERR_FAMILY;
    }
    static const int32_t zero[3] = {0, 0, 0};
    /* volatile: GCC would make the zeroing loop a call to memset, which a
     * freestanding library cannot make (check-freestanding: nm -u) */
    volatile int32_t *z = state + 3;
    (void)tfit_q31_input_map(m->q, zero, state); /* the projected zero force */
    for (uint32_t w = 0u; w < 3u * (uint32_t)m->q[TFIT_Q31_PRONY_K_WORD]; ++w) {
        z[w] = 0;
    }
    return TFIT_OK;
}

tfit_status tfit_prony_step_q31(const tfit_model_q31 *m, int32_t *state, const int32_t force[3],
                                int32_t *out)
{
    if (!usable(m) || state == 0 || force == 0 || out == 0) {
        return TFIT_ERR_ARG;
    }
    if (m->family != (uint32_t)TFIT_FAMILY_PRONY) {
        return TFIT_ERR_FAMILY;
    }
    int32_t g[3], h[3];
    const uint32_t clamped = tfit_q31_input_map(m->q, force, g);
    filter_q31(m->q, g, state, h);
    tfit_q31_rows(m, q_prony_rows(m->q, (uint32_t)m->q[TFIT_Q31_PRONY_K_WORD]), h, out);
    return (tfit_status)(int)(clamped & 1u);
}
