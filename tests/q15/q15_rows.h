/*
 * q15_rows.h — prototype of the Q15 modal reconstruction proposed for
 * issue 14 acceptance 1 (docs/reports/block48_nh_q15.md): rank 8, one
 * output point (three rows) per iteration.  Not part of libtfit yet.
 *
 *   rows: 3 n_out rows of 4 words, word j = q[2j] (low half) | q[2j+1] << 16,
 *         q int16 in [-32767, 32767]
 *   c:    the amplitudes as 4 words packed the same way, c_k in [-8192, 8191]
 *   out[o] = (float)(sum_k q[o][k] c_k) * scale
 * |sum| <= 8 * 32767 * 8192 = 2147418112 < 2^31: no overflow by construction.
 */
#ifndef Q15_ROWS_H
#define Q15_ROWS_H

#include <stdint.h>

#define Q15_RANK 8u
#define Q15_WORDS (Q15_RANK / 2u)
#define Q15_C_MIN (-8192)
#define Q15_C_MAX 8191

/* c_k = trunc(a_k v_k) saturated to [-8192, 8191] (VCVT.S32.F32 then SSAT #14
 * on Armv7E-M), packed in pairs. */
void q15_amplitudes(const float *a, const float *v, uint32_t c[Q15_WORDS]);

/* The reference in C, any target. */
void q15_rows_c(const uint32_t *rows, const uint32_t c[Q15_WORDS], uint32_t n_out, float scale,
                float *out);

#if defined(__ARM_FEATURE_DSP) && defined(__ARM_FP)
/* The same in Armv7E-M assembly (SMUAD/SMLAD, dual 16-bit MACs). */
int32_t q15_sat_asm(float x); /* one c_k: VCVT.S32.F32, SSAT #14 */
void q15_rows_asm(const uint32_t *rows, const uint32_t c[Q15_WORDS], uint32_t n_out, float scale,
                  float *out);
#endif

#endif /* Q15_ROWS_H */

/* The r = 8 amplitudes term by term (the proposed layout: A transposed,
 * At[t][k] = A[k][t]): a_k = ((At[0][k] + At[1][k] phi_1) + At[2][k] phi_2)
 * + ..., the operations of tfit_row() for each mode in the same order, so
 * bit-identical to the float modal family's amplitudes (header-format.md
 * §5.3); n_terms >= 2.  In C, and in Armv7E-M assembly with the eight sums
 * in s16-s23 (one VLDM of 8 words and one phi load per term). */
void q15_amp_terms_c(const float *at, const float *phi, uint32_t n_terms, float a[Q15_RANK]);
/* The whole amplitude step: q15_amp_terms_c, q15_amplitudes, each word
 * and-ed with keep (all ones, or 0 for a NaN/Inf input: every sum 0, every
 * output +0.0f).  In C, and fused in Armv7E-M assembly (the sums never
 * leave s16-s23: VMUL by v, VCVT.S32.F32, VMOV, SSAT #14, PKHBT). */
void q15_amp_c(const float *at, const float *phi, uint32_t n_terms, const float *v, uint32_t keep,
               uint32_t c[Q15_WORDS]);
#if defined(__ARM_FEATURE_DSP) && defined(__ARM_FP)
void q15_amp_terms_asm(const float *at, const float *phi, uint32_t n_terms, float a[Q15_RANK]);
void q15_amp_asm(const float *at, const float *phi, uint32_t n_terms, const float *v, uint32_t keep,
                 uint32_t c[Q15_WORDS]);
#endif
