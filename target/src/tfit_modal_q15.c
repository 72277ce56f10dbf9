/*
 * tfit_modal_q15.c — the modal_q15 family (docs/header-format.md §5.9):
 * modal at rank 8 with its modes in Q15 and the products summed in
 * integers.
 *
 * coef = input map (12) | At[T][8] | v[8] | S | rows[3 n_out][4 words]
 *   a_k = ((At[0][k] + At[1][k] phi1) + At[2][k] phi2) + ...  (float, as modal)
 *   c_k = trunc(a_k v_k) saturated to [-8192, 8191]
 *   out[o] = (float)(sum_k q[o][k] c_k) * S
 * Each row word holds two modes' q in [-16255, 16255]: the low half q[2j],
 * the high half q[2j+1] + 16384 (so that no word is the bit pattern of a
 * NaN or Inf: the table stays a finite float table for the CRC, the range
 * check and the emitter); the bias word -16384 (c_1 + c_3 + c_5 + c_7)
 * starts every sum.  |sum| <= 8 * 16255 * 8192 < 2^31: no overflow
 * (every partial sum is taken modulo 2^32, and the total fits).
 * On Cortex-M4F/M7 both steps run in assembly (tfit_modal_q15_armv7em.c,
 * SMLAD: two 16-bit products a cycle); this C is every other target's,
 * and the reference both follow, bit for bit.  Branch-free, as every
 * evaluator: the same instructions for every input.
 */
#include "tfit_internal.h"

#if !TFIT_Q15_ASM
/* The signed halves of a word, without an implementation-defined cast. */
static int32_t half_lo(uint32_t w)
{
    return (int32_t)((w & 0xffffu) ^ 0x8000u) - 0x8000;
}

static int32_t half_hi(uint32_t w)
{
    return (int32_t)((w >> 16) ^ 0x8000u) - 0x8000;
}

/* A 32-bit sum taken modulo 2^32 back to its signed value. */
static int32_t as_signed(uint32_t acc)
{
    const int32_t neg = (int32_t)(acc >> 31);
    return ((int32_t)(acc & 0x7fffffffu) - 0x40000000 * neg) - 0x40000000 * neg;
}

/* trunc(x) saturated to [-8192, 8191], as VCVT.S32.F32 then SSAT #14 */
static int32_t to_q(float x)
{
    const float hi = tfit_select(tfit_mask(x >= 8191.0f), 8191.0f, x);
    return (int32_t)tfit_select(tfit_mask(hi <= -8192.0f), -8192.0f, hi);
}

static void amplitudes_c(const float *at, const float *phi, uint32_t n_terms, const float *v,
                         uint32_t keep, uint32_t c[5])
{
    int32_t q[TFIT_MODAL_Q15_RANK];
    for (uint32_t k = 0u; k < TFIT_MODAL_Q15_RANK; ++k) {
        float a = at[k];
        for (uint32_t t = 1u; t < n_terms; ++t) {
            a = a + at[t * TFIT_MODAL_Q15_RANK + k] * phi[t];
        }
        q[k] = to_q(a * v[k]);
    }
    int32_t odd = 0;
    for (uint32_t j = 0u; j < TFIT_MODAL_Q15_WORDS; ++j) {
        c[j] = (((uint32_t)q[2u * j] & 0xffffu) | ((uint32_t)q[2u * j + 1u] << 16)) & keep;
        odd += q[2u * j + 1u];
    }
    c[4] = ((uint32_t)(-odd) << 14) & keep;
}

static void rows_c(const float *rows, const uint32_t c[5], uint32_t n_out, float scale, float *out)
{
    for (uint32_t o = 0u; o < 3u * n_out; ++o) {
        uint32_t acc = c[4];
        for (uint32_t j = 0u; j < TFIT_MODAL_Q15_WORDS; ++j) {
            const uint32_t w = tfit_bits(rows[j]);
            acc += (uint32_t)(half_lo(w) * half_lo(c[j]));
            acc += (uint32_t)(half_hi(w) * half_hi(c[j]));
        }
        out[o] = (float)as_signed(acc) * scale;
        rows += TFIT_MODAL_Q15_WORDS;
    }
}

#endif

void tfit_eval_modal_q15(const tfit_model *m, const float g[3], uint32_t keep, float *out)
{
    float phi[TFIT_MAX_TERMS];
    uint32_t c[5];
    const uint32_t n_terms = TFIT_TERMS(m->dims[0]);
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + TFIT_MODAL_Q15_RANK * n_terms;
    /* the rows end the table: counted from the end, a view of output
     * point j alone (n_out = 1, n_coef shortened) finds row j, as
     * tfit_model_check's self-test needs */
    const float *rows = m->coef + (m->n_coef - 3u * TFIT_MODAL_Q15_WORDS * m->n_out);

    tfit_basis(m->dims[0], g, phi);
#if TFIT_Q15_ASM
    tfit_q15_amp_asm(at, phi, n_terms, v, keep, c);
    tfit_q15_rows_asm(rows, c, m->n_out, v[TFIT_MODAL_Q15_RANK], out);
#else
    amplitudes_c(at, phi, n_terms, v, keep, c);
    rows_c(rows, c, m->n_out, v[TFIT_MODAL_Q15_RANK], out);
#endif
}
