/*
 * tfit_modal_q15_armv7em.c — the modal_q15 family (docs/header-format.md
 * §5.9) on Armv7E-M with a single-precision FPU (Cortex-M4F, Cortex-M7),
 * in inline assembly.  The C of tfit_modal_q15.c (every other target and
 * -DTFIT_PORTABLE) is the reference: the same operations, bit for bit
 * (check-qemu, check-qemu-portable).
 *
 * Why (docs/tradeoff.md §5): a float32 product and sum costs at least 3
 * cycles per mode coefficient on the M4F (no fused multiply-add), 52 us for
 * block48_nh's 2,904 at 168 MHz.  SMLAD multiplies two pairs of signed
 * 16-bit halves and adds both products to a 32-bit accumulator in one
 * cycle, and LDM brings a row's 4 words in 5: a point's three rows of 8
 * modes cost 3 LDM, 3 SMLAD chains, 3 VMOV, 3 VCVT, 3 VMUL and one VSTM
 * (about 42 cycles, against 80 in float).  The amplitudes are summed term
 * by term (At is stored transposed), the eight sums staying in s16-s23:
 * one VLDM of 8 words and one of phi_t per term instead of two VLDR and a
 * loop per product.
 *
 * Output mask (§5.5): for a NaN/Inf input every word of c (the amplitude
 * pairs and the bias) is and-ed with keep = 0, so every sum is 0 and every
 * output (+0) * S = +0.0f.
 */
#include "tfit_internal.h"

#if TFIT_Q15_ASM

/* r0 At, r1 phi + 1, r2 terms left (n_terms >= 2: p >= 1), r3 v, r4 keep,
 * r5 c.  After the loop the products a_k v_k are converted (VCVT rounds
 * toward zero, saturating), saturated to 14 bits (SSAT), packed in pairs
 * (PKHBT) in r0, r2, r7, r9, and the bias -16384 (c1 + c3 + c5 + c7) formed
 * in r10. */
void tfit_q15_amp_asm(const float *at, const float *phi, uint32_t n_terms, const float *v,
                      uint32_t keep, uint32_t c[5])
{
    register const float *r0 __asm__("r0") = at;
    register const float *r1 __asm__("r1") = phi + 1;
    register uint32_t r2 __asm__("r2") = n_terms - 1u;
    register const float *r3 __asm__("r3") = v;
    register uint32_t r4 __asm__("r4") = keep;
    register uint32_t *r5 __asm__("r5") = c;
    __asm__ volatile("\tvldm r0!, {s16-s23}\n"
                     "1:\n"
                     "\tvldm r1!, {s0}\n"
                     "\tvldm r0!, {s8-s15}\n"
                     "\tvmul.f32 s8, s8, s0\n"
                     "\tvmul.f32 s9, s9, s0\n"
                     "\tvmul.f32 s10, s10, s0\n"
                     "\tvmul.f32 s11, s11, s0\n"
                     "\tvmul.f32 s12, s12, s0\n"
                     "\tvmul.f32 s13, s13, s0\n"
                     "\tvmul.f32 s14, s14, s0\n"
                     "\tvmul.f32 s15, s15, s0\n"
                     "\tvadd.f32 s16, s16, s8\n"
                     "\tvadd.f32 s17, s17, s9\n"
                     "\tvadd.f32 s18, s18, s10\n"
                     "\tvadd.f32 s19, s19, s11\n"
                     "\tvadd.f32 s20, s20, s12\n"
                     "\tvadd.f32 s21, s21, s13\n"
                     "\tvadd.f32 s22, s22, s14\n"
                     "\tvadd.f32 s23, s23, s15\n"
                     "\tsubs r2, r2, #1\n"
                     "\tbne 1b\n"
                     "\tvldm r3, {s8-s15}\n"
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
                     "\tadd r1, r1, r6\n"
                     "\tadd r8, r8, r10\n"
                     "\tadd r10, r1, r8\n"
                     "\trsb r10, r10, #0\n"
                     "\tlsl r10, r10, #14\n"
                     "\tand r0, r0, r4\n"
                     "\tand r2, r2, r4\n"
                     "\tand r7, r7, r4\n"
                     "\tand r9, r9, r4\n"
                     "\tand r10, r10, r4\n"
                     "\tstm r5, {r0, r2, r7, r9, r10}\n"
                     : "+r"(r0), "+r"(r1), "+r"(r2)
                     : "r"(r3), "r"(r4), "r"(r5)
                     : "r6", "r7", "r8", "r9", "r10", "s0", "s8", "s9", "s10", "s11", "s12", "s13",
                       "s14", "s15", "s16", "s17", "s18", "s19", "s20", "s21", "s22", "s23", "cc",
                       "memory");
}

/* One output point: three rows of 4 words against the amplitude words in
 * r3-r6, each sum started from the bias in lr (SMLAD, then three more),
 * the sums x, y, z in r7, r8, r9 (each row's first loaded word) converted,
 * scaled by s0 and stored. */
#define TFIT_Q15_POINT                                                                             \
    "\tldm r0!, {r7, r8, r9, r10}\n"                                                               \
    "\tsmlad r7, r7, r3, lr\n"                                                                     \
    "\tsmlad r7, r8, r4, r7\n"                                                                     \
    "\tsmlad r7, r9, r5, r7\n"                                                                     \
    "\tsmlad r7, r10, r6, r7\n"                                                                    \
    "\tldm r0!, {r8, r9, r10, r11}\n"                                                              \
    "\tsmlad r8, r8, r3, lr\n"                                                                     \
    "\tsmlad r8, r9, r4, r8\n"                                                                     \
    "\tsmlad r8, r10, r5, r8\n"                                                                    \
    "\tsmlad r8, r11, r6, r8\n"                                                                    \
    "\tldm r0!, {r9, r10, r11, r12}\n"                                                             \
    "\tsmlad r9, r9, r3, lr\n"                                                                     \
    "\tsmlad r9, r10, r4, r9\n"                                                                    \
    "\tsmlad r9, r11, r5, r9\n"                                                                    \
    "\tsmlad r9, r12, r6, r9\n"                                                                    \
    "\tvmov s1, r7\n"                                                                              \
    "\tvmov s2, r8\n"                                                                              \
    "\tvmov s3, r9\n"                                                                              \
    "\tvcvt.f32.s32 s1, s1\n"                                                                      \
    "\tvcvt.f32.s32 s2, s2\n"                                                                      \
    "\tvcvt.f32.s32 s3, s3\n"                                                                      \
    "\tvmul.f32 s1, s1, s0\n"                                                                      \
    "\tvmul.f32 s2, s2, s0\n"                                                                      \
    "\tvmul.f32 s3, s3, s0\n"                                                                      \
    "\tvstm r1!, {s1-s3}\n"

/* r0 rows, r1 out, r2 points (then pairs) left, r3-r6 the amplitude words,
 * lr the bias, s0 the scale S.  An odd point first, then two points per
 * iteration (the loop's subs and taken branch shared by two points). */
void tfit_q15_rows_asm(const float *rows, const uint32_t c[5], uint32_t n_out, float scale,
                       float *out)
{
    register const float *r0 __asm__("r0") = rows;
    register float *r1 __asm__("r1") = out;
    register uint32_t r2 __asm__("r2") = n_out;
    register uint32_t r3 __asm__("r3") = c[0];
    register uint32_t r4 __asm__("r4") = c[1];
    register uint32_t r5 __asm__("r5") = c[2];
    register uint32_t r6 __asm__("r6") = c[3];
    register uint32_t lr __asm__("lr") = c[4];
    register float s0 __asm__("s0") = scale;
    __asm__ volatile("\ttst r2, #1\n"
                     "\tbeq 2f\n" TFIT_Q15_POINT "2:\n"
                     "\tlsrs r2, r2, #1\n"
                     "\tbeq 3f\n"
                     "1:\n" TFIT_Q15_POINT TFIT_Q15_POINT "\tsubs r2, r2, #1\n"
                     "\tbne 1b\n"
                     "3:\n"
                     : "+r"(r0), "+r"(r1), "+r"(r2)
                     : "r"(r3), "r"(r4), "r"(r5), "r"(r6), "r"(lr), "t"(s0)
                     : "r7", "r8", "r9", "r10", "r11", "r12", "s1", "s2", "s3", "cc", "memory");
}

#else
typedef int tfit_modal_q15_armv7em_unused; /* ISO C forbids an empty translation unit */
#endif
