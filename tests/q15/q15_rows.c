/*
 * q15_rows.c — the Q15 rows prototype (q15_rows.h): C reference and the
 * Armv7E-M assembly, which must agree bit for bit (q15_qemu.c under QEMU
 * M4F and M7).  Cost per point on the M4F (cycle table of
 * host/cost/cycles.c, upper bound): 3 LDM of 4 words, 12 SMUAD/SMLAD,
 * 3 VMOV, 3 VCVT, 3 VMUL, one VSTM of 3 words and the loop.
 */
#include "q15_rows.h"

static int32_t lo16(uint32_t w)
{
    return (int32_t)(int16_t)(uint16_t)(w & 0xffffu);
}

static int32_t hi16(uint32_t w)
{
    return (int32_t)(int16_t)(uint16_t)(w >> 16);
}

void q15_amplitudes(const float *a, const float *v, uint32_t c[Q15_WORDS])
{
    for (uint32_t j = 0u; j < Q15_WORDS; ++j) {
        uint32_t half[2];
        for (uint32_t h = 0u; h < 2u; ++h) {
            const float x = a[2u * j + h] * v[2u * j + h];
            /* trunc, saturated as VCVT + SSAT #14 do */
            const int32_t k = x >= (float)Q15_C_MAX   ? Q15_C_MAX
                              : x <= (float)Q15_C_MIN ? Q15_C_MIN
                                                      : (int32_t)x;
            half[h] = (uint32_t)k & 0xffffu;
        }
        c[j] = half[0] | (half[1] << 16);
    }
}

void q15_rows_c(const uint32_t *rows, const uint32_t c[Q15_WORDS], uint32_t n_out, float scale,
                float *out)
{
    for (uint32_t o = 0u; o < 3u * n_out; ++o) {
        int32_t acc = 0;
        for (uint32_t j = 0u; j < Q15_WORDS; ++j) {
            acc += lo16(rows[j]) * lo16(c[j]) + hi16(rows[j]) * hi16(c[j]);
        }
        out[o] = (float)acc * scale;
        rows += Q15_WORDS;
    }
}

void q15_amp_terms_c(const float *at, const float *phi, uint32_t n_terms, float a[Q15_RANK])
{
    for (uint32_t k = 0u; k < Q15_RANK; ++k) {
        a[k] = at[k];
    }
    for (uint32_t t = 1u; t < n_terms; ++t) {
        for (uint32_t k = 0u; k < Q15_RANK; ++k) {
            a[k] = a[k] + at[t * Q15_RANK + k] * phi[t];
        }
    }
}

void q15_amp_c(const float *at, const float *phi, uint32_t n_terms, const float *v, uint32_t keep,
               uint32_t c[Q15_WORDS])
{
    float a[Q15_RANK];
    q15_amp_terms_c(at, phi, n_terms, a);
    q15_amplitudes(a, v, c);
    for (uint32_t j = 0u; j < Q15_WORDS; ++j) {
        c[j] &= keep;
    }
}

#if defined(__ARM_FEATURE_DSP) && defined(__ARM_FP)
/* The term loop of q15_amp_terms_asm and q15_amp_asm (sums in s16-s23). */
#define Q15_TERMS                                                                                  \
    "\tvldm r0!, {s16-s23}\n"                                                                     \
    "1:\n"                                                                                         \
    "\tvldm r1!, {s0}\n"                                                                          \
    "\tvldm r0!, {s8-s15}\n"                                                                      \
    "\tvmul.f32 s8, s8, s0\n"                                                                     \
    "\tvmul.f32 s9, s9, s0\n"                                                                     \
    "\tvmul.f32 s10, s10, s0\n"                                                                   \
    "\tvmul.f32 s11, s11, s0\n"                                                                   \
    "\tvmul.f32 s12, s12, s0\n"                                                                   \
    "\tvmul.f32 s13, s13, s0\n"                                                                   \
    "\tvmul.f32 s14, s14, s0\n"                                                                   \
    "\tvmul.f32 s15, s15, s0\n"                                                                   \
    "\tvadd.f32 s16, s16, s8\n"                                                                   \
    "\tvadd.f32 s17, s17, s9\n"                                                                   \
    "\tvadd.f32 s18, s18, s10\n"                                                                  \
    "\tvadd.f32 s19, s19, s11\n"                                                                  \
    "\tvadd.f32 s20, s20, s12\n"                                                                  \
    "\tvadd.f32 s21, s21, s13\n"                                                                  \
    "\tvadd.f32 s22, s22, s14\n"                                                                  \
    "\tvadd.f32 s23, s23, s15\n"                                                                  \
    "\tsubs r2, r2, #1\n"                                                                         \
    "\tbne 1b\n"

/* r0 at, r1 phi + 1, r2 terms left, r3 v, r4 keep, r5 c; after the loop
 * the eight products a_k v_k are converted and packed in r0-r2, r6-r10. */
void q15_amp_asm(const float *at, const float *phi, uint32_t n_terms, const float *v, uint32_t keep,
                 uint32_t c[Q15_WORDS])
{
    register const float *r0 __asm__("r0") = at;
    register const float *r1 __asm__("r1") = phi + 1;
    register uint32_t r2 __asm__("r2") = n_terms - 1u;
    register const float *r3 __asm__("r3") = v;
    register uint32_t r4 __asm__("r4") = keep;
    register uint32_t *r5 __asm__("r5") = c;
    __asm__ volatile(Q15_TERMS "\tvldm r3, {s8-s15}\n"
                               "\tvmul.f32 s16, s16, s8\n"
                               "\tvmul.f32 s17, s17, s9\n"
                               "\tvmul.f32 s18, s18, s10\n"
                               "\tvmul.f32 s19, s19, s11\n"
                               "\tvmul.f32 s20, s20, s12\n"
                               "\tvmul.f32 s21, s21, s13\n"
                               "\tvmul.f32 s22, s22, s14\n"
                               "\tvmul.f32 s23, s23, s15\n"
                               "\tvcvt.s32.f32 s16, s16\n"
                               "\tvcvt.s32.f32 s17, s17\n"
                               "\tvcvt.s32.f32 s18, s18\n"
                               "\tvcvt.s32.f32 s19, s19\n"
                               "\tvcvt.s32.f32 s20, s20\n"
                               "\tvcvt.s32.f32 s21, s21\n"
                               "\tvcvt.s32.f32 s22, s22\n"
                               "\tvcvt.s32.f32 s23, s23\n"
                               "\tvmov r0, s16\n"
                               "\tvmov r1, s17\n"
                               "\tvmov r2, s18\n"
                               "\tvmov r6, s19\n"
                               "\tvmov r7, s20\n"
                               "\tvmov r8, s21\n"
                               "\tvmov r9, s22\n"
                               "\tvmov r10, s23\n"
                               "\tssat r0, #14, r0\n"
                               "\tssat r1, #14, r1\n"
                               "\tssat r2, #14, r2\n"
                               "\tssat r6, #14, r6\n"
                               "\tssat r7, #14, r7\n"
                               "\tssat r8, #14, r8\n"
                               "\tssat r9, #14, r9\n"
                               "\tssat r10, #14, r10\n"
                               "\tpkhbt r0, r0, r1, lsl #16\n"
                               "\tpkhbt r2, r2, r6, lsl #16\n"
                               "\tpkhbt r7, r7, r8, lsl #16\n"
                               "\tpkhbt r9, r9, r10, lsl #16\n"
                               "\tand r0, r0, r4\n"
                               "\tand r2, r2, r4\n"
                               "\tand r7, r7, r4\n"
                               "\tand r9, r9, r4\n"
                               "\tstm r5, {r0, r2, r7, r9}\n"
                     : "+r"(r0), "+r"(r1), "+r"(r2)
                     : "r"(r3), "r"(r4), "r"(r5)
                     : "r6", "r7", "r8", "r9", "r10", "s0", "s8", "s9", "s10", "s11", "s12", "s13",
                       "s14", "s15", "s16", "s17", "s18", "s19", "s20", "s21", "s22", "s23", "cc",
                       "memory");
}

/* r0 at, r1 phi + 1, r2 terms left, r3 a; s0 phi_t, s8-s15 one term's
 * products, s16-s23 the sums (callee-saved: listed as clobbers) */
void q15_amp_terms_asm(const float *at, const float *phi, uint32_t n_terms, float a[Q15_RANK])
{
    register const float *r0 __asm__("r0") = at;
    register const float *r1 __asm__("r1") = phi + 1;
    register uint32_t r2 __asm__("r2") = n_terms - 1u;
    register float *r3 __asm__("r3") = a;
    __asm__ volatile(Q15_TERMS "\tvstm r3, {s16-s23}\n"
                     : "+r"(r0), "+r"(r1), "+r"(r2)
                     : "r"(r3)
                     : "s0", "s8", "s9", "s10", "s11", "s12", "s13", "s14", "s15", "s16", "s17",
                       "s18", "s19", "s20", "s21", "s22", "s23", "cc", "memory");
}

int32_t q15_sat_asm(float x)
{
    int32_t k;
    __asm__("vcvt.s32.f32 %1, %1\n\tvmov %0, %1\n\tssat %0, #14, %0" : "=r"(k), "+t"(x));
    return k;
}

/* One output point: its three rows of 4 words against the amplitude words
 * in r3-r6 (SMUAD, then three SMLAD each), the sums x, y, z in r7, r8, r9
 * (each row's first loaded word), converted, scaled by s0 and stored. */
#define Q15_POINT                                                                                  \
    "\tldm r0!, {r7, r8, r9, r10}\n"                                                              \
    "\tsmuad r7, r7, r3\n"                                                                        \
    "\tsmlad r7, r8, r4, r7\n"                                                                    \
    "\tsmlad r7, r9, r5, r7\n"                                                                    \
    "\tsmlad r7, r10, r6, r7\n"                                                                   \
    "\tldm r0!, {r8, r9, r10, r11}\n"                                                             \
    "\tsmuad r8, r8, r3\n"                                                                        \
    "\tsmlad r8, r9, r4, r8\n"                                                                    \
    "\tsmlad r8, r10, r5, r8\n"                                                                   \
    "\tsmlad r8, r11, r6, r8\n"                                                                   \
    "\tldm r0!, {r9, r10, r11, r12}\n"                                                            \
    "\tsmuad r9, r9, r3\n"                                                                        \
    "\tsmlad r9, r10, r4, r9\n"                                                                   \
    "\tsmlad r9, r11, r5, r9\n"                                                                   \
    "\tsmlad r9, r12, r6, r9\n"                                                                   \
    "\tvmov s1, r7\n"                                                                             \
    "\tvmov s2, r8\n"                                                                             \
    "\tvmov s3, r9\n"                                                                             \
    "\tvcvt.f32.s32 s1, s1\n"                                                                     \
    "\tvcvt.f32.s32 s2, s2\n"                                                                     \
    "\tvcvt.f32.s32 s3, s3\n"                                                                     \
    "\tvmul.f32 s1, s1, s0\n"                                                                     \
    "\tvmul.f32 s2, s2, s0\n"                                                                     \
    "\tvmul.f32 s3, s3, s0\n"                                                                     \
    "\tvstm r1!, {s1-s3}\n"

/* r0 rows, r1 out, r2 points (then pairs) left, r3-r6 the amplitude
 * words, s0 scale.  An odd point first, then two points per iteration
 * (the loop's subs and taken branch, 5 cycles, shared by two points). */
void q15_rows_asm(const uint32_t *rows, const uint32_t c[Q15_WORDS], uint32_t n_out, float scale,
                  float *out)
{
    register const uint32_t *r0 __asm__("r0") = rows;
    register float *r1 __asm__("r1") = out;
    register uint32_t r2 __asm__("r2") = n_out;
    register uint32_t r3 __asm__("r3") = c[0];
    register uint32_t r4 __asm__("r4") = c[1];
    register uint32_t r5 __asm__("r5") = c[2];
    register uint32_t r6 __asm__("r6") = c[3];
    register float s0 __asm__("s0") = scale;
    __asm__ volatile("\ttst r2, #1\n"
                     "\tbeq 2f\n" Q15_POINT "2:\n"
                     "\tlsrs r2, r2, #1\n"
                     "\tbeq 3f\n"
                     "1:\n" Q15_POINT Q15_POINT "\tsubs r2, r2, #1\n"
                     "\tbne 1b\n"
                     "3:\n"
                     : "+r"(r0), "+r"(r1), "+r"(r2)
                     : "r"(r3), "r"(r4), "r"(r5), "r"(r6), "t"(s0)
                     : "r7", "r8", "r9", "r10", "r11", "r12", "s1", "s2", "s3", "cc", "memory");
}
#endif
