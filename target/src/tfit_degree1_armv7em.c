/*
 * tfit_degree1_armv7em.c — degree-1 models (nodal and contact, p = 1) on
 * Armv7E-M with a single-precision FPU (Cortex-M4F, Cortex-M7), in inline
 * assembly.  The portable C path (tfit_input_map + tfit_rows_degree1, used
 * on every other target and with -DTFIT_PORTABLE) is the reference: both
 * perform exactly the operations of docs/header-format.md §4 and §5.2, in
 * that order, and both run every golden vector (check-qemu: this file on
 * the M4F and M7 boards; check-qemu-portable: the C path on the same
 * boards).
 *
 * Why assembly (docs/firmware.md §5.4): GCC never merges float loads into
 * VLDM, and on the Cortex-M4 a VLDR costs 2 cycles where VLDM costs 1 per
 * word.  A p = 1 output point is 12 coefficients, 9 multiplications and 9
 * additions: 12 + 18 cycles of loads and arithmetic at best, so the load
 * instruction decides between ~48 and ~34 cycles per point.  Here:
 *
 *   - two output points per VLDM (24 words) and per VSTM (6 words);
 *   - eight pairs per loop iteration, then a loop of single pairs and one
 *     odd point, so the loop branch is paid once per 16 points;
 *   - the six sums of a pair interleaved, so that no float result is used
 *     by the next instruction (the M7's FPU has a multi-cycle latency);
 *   - the output mask of §5.5 without a per-word operation: for a NaN/Inf
 *     input the rows are read from a block of +0.0f instead of the model
 *     (tfit_zero_coef; g is finite, so every output is +0 + (+0 * g) ... =
 *     +0.0f, the same bits as the mask), rewound once per iteration;
 *   - the projection with its integer selections as conditional moves.
 *
 * tfit_degree1_rows_asm() runs the rows alone, at a g the caller projected
 * and filtered (a stateful model's static map at p = 1, tfit_stateful.c).
 *
 * Registers: g in s0-s2, a pair in s3-s26 (s16-s26 are callee-saved: the
 * compiler saves them, because they are clobbered); core r0 rows pointer,
 * r2 out, r3 n_out, r4-r6, r12 and lr scratch.  The cycle model
 * (host/cost/cycles.c) describes these instruction streams block by block,
 * and check-cycles compares it with objdump and QEMU traces.
 */
#include "tfit_internal.h"

#if TFIT_DEGREE1_ASM

/* Rows of zeros read instead of the model's for a NaN/Inf input: one main
 * loop iteration (8 pairs of points, 192 floats) covers the remainder loop
 * and the odd point too, because the pointer is rewound after each
 * iteration.  Named like the generated tables so that the linker scripts
 * put it in zero-wait-state RAM with them (linker/sections.ld). */
static const float tfit_zero_coef[192];

/* §4, the input projection.  In: r0 coef (the map), r1 input, r12 the
 * zero rows.  Out: g in s0-s2; r0 the rows, or the zero rows for a NaN/Inf
 * input; lr keep (all ones, or 0 for NaN/Inf); r12 the status.  Each
 * numbered step is the one of header-format.md §4. */
#define TFIT_ASM_INPUT_MAP                                                                        \
    "ldm      r1, {r4, r5, r6}\n\t"   /* the input's bit patterns */                              \
    "vldm     r0!, {s3-s14}\n\t"      /* x0 in s3-s5, W in s6-s14; r0 -> rows */                  \
    "bic      r1, r4, #0x80000000\n\t" /* 1: max|in| as bit patterns */                          \
    "bic      lr, r5, #0x80000000\n\t"                                                            \
    "cmp      r1, lr\n\t"                                                                         \
    "it       lo\n\t"                                                                             \
    "movlo    r1, lr\n\t"                                                                         \
    "bic      lr, r6, #0x80000000\n\t"                                                            \
    "cmp      r1, lr\n\t"                                                                         \
    "it       lo\n\t"                                                                             \
    "movlo    r1, lr\n\t"                                                                         \
    "cmp      r1, #0x7f800000\n\t"    /* NaN/Inf: carry set */                                    \
    "sbc      lr, lr, lr\n\t"         /* keep = bad ? 0 : ~0 */                                   \
    "it       hs\n\t"                                                                             \
    "movhs    r0, r12\n\t"            /* bad: the zero rows (§5.5) */                             \
    "and      r4, r4, lr\n\t"         /* 2: x = bad ? +0 : in */                                  \
    "and      r5, r5, lr\n\t"                                                                     \
    "and      r6, r6, lr\n\t"                                                                     \
    "and      r1, r1, lr\n\t"         /* max|x| */                                                \
    "lsr      r12, r1, #23\n\t"       /* 3: 2^(64 - e(M)) when M > 2^64, else 1 */                \
    "rsb      r12, r12, #318\n\t"                                                                 \
    "lsl      r12, r12, #23\n\t"                                                                  \
    "cmp      r1, #0x5f800000\n\t"                                                                \
    "it       ls\n\t"                                                                             \
    "movls    r12, #0x3f800000\n\t"                                                               \
    "vmov     s15, r12\n\t"                                                                       \
    "vmov     s0, r4\n\t"                                                                         \
    "vmov     s1, r5\n\t"                                                                         \
    "vmov     s2, r6\n\t"                                                                         \
    "vmul.f32 s0, s0, s15\n\t"                                                                    \
    "vmul.f32 s1, s1, s15\n\t"                                                                    \
    "vmul.f32 s2, s2, s15\n\t"                                                                    \
    "vsub.f32 s0, s0, s3\n\t"         /* 4: d = x - x0 */                                         \
    "vsub.f32 s1, s1, s4\n\t"                                                                     \
    "vsub.f32 s2, s2, s5\n\t"                                                                     \
    "vmul.f32 s6, s6, s0\n\t"         /* 5: g_i = ((W_i0 d0 + W_i1 d1) + W_i2 d2) */              \
    "vmul.f32 s9, s9, s0\n\t"                                                                     \
    "vmul.f32 s12, s12, s0\n\t"                                                                   \
    "vmul.f32 s7, s7, s1\n\t"                                                                     \
    "vmul.f32 s10, s10, s1\n\t"                                                                   \
    "vmul.f32 s13, s13, s1\n\t"                                                                   \
    "vadd.f32 s6, s6, s7\n\t"                                                                     \
    "vmul.f32 s8, s8, s2\n\t"                                                                     \
    "vadd.f32 s9, s9, s10\n\t"                                                                    \
    "vmul.f32 s11, s11, s2\n\t"                                                                   \
    "vadd.f32 s12, s12, s13\n\t"                                                                  \
    "vmul.f32 s14, s14, s2\n\t"                                                                   \
    "vadd.f32 s6, s6, s8\n\t"         /* g0 */                                                    \
    "vadd.f32 s9, s9, s11\n\t"        /* g1 */                                                    \
    "vadd.f32 s12, s12, s14\n\t"      /* g2 */                                                    \
    "vmov     r4, s6\n\t"             /* 6: m = max|g| as bit patterns */                         \
    "vmov     r5, s9\n\t"                                                                         \
    "vmov     r6, s12\n\t"                                                                        \
    "bic      r4, r4, #0x80000000\n\t"                                                            \
    "bic      r5, r5, #0x80000000\n\t"                                                            \
    "bic      r6, r6, #0x80000000\n\t"                                                            \
    "cmp      r4, r5\n\t"                                                                         \
    "it       lo\n\t"                                                                             \
    "movlo    r4, r5\n\t"                                                                         \
    "cmp      r4, r6\n\t"                                                                         \
    "it       lo\n\t"                                                                             \
    "movlo    r4, r6\n\t"                                                                         \
    "lsr      r5, r4, #23\n\t"        /* 2^(-e(m)) when m > 1 (far), else 1 */                    \
    "rsb      r5, r5, #254\n\t"                                                                   \
    "lsl      r5, r5, #23\n\t"                                                                    \
    "mov      r12, #0\n\t"                                                                        \
    "cmp      r4, #0x3f800000\n\t"                                                                \
    "ite      ls\n\t"                                                                             \
    "movls    r5, #0x3f800000\n\t"                                                                \
    "movhi    r12, #0xffffffff\n\t"   /* r12 = far */                                             \
    "vmov     s15, r5\n\t"                                                                        \
    "vmul.f32 s6, s6, s15\n\t"                                                                    \
    "vmul.f32 s9, s9, s15\n\t"                                                                    \
    "vmul.f32 s12, s12, s15\n\t"                                                                  \
    "vmul.f32 s3, s6, s6\n\t"         /* 7: s = ((g0 g0) + (g1 g1)) + (g2 g2) */                  \
    "vmul.f32 s4, s9, s9\n\t"                                                                     \
    "vmul.f32 s5, s12, s12\n\t"                                                                   \
    "vmov.f32 s13, #3.0\n\t"                                                                      \
    "vadd.f32 s3, s3, s4\n\t"                                                                     \
    "vmov.f32 s14, #0.5\n\t"                                                                      \
    "vadd.f32 s3, s3, s5\n\t"                                                                     \
    "movw     r6, #0x59df\n\t"        /* 0x5f3759df */                                            \
    "movt     r6, #0x5f37\n\t"                                                                    \
    "vmov     r4, s3\n\t"             /* s >= +0: compared as a bit pattern */                    \
    "cmp      r4, #0x3f800000\n\t"                                                                \
    "ite      hi\n\t"                                                                             \
    "movhi    r12, #0xffffffff\n\t"   /* r12 = out = far or s > 1 */                              \
    "movls    r4, #0x3f800000\n\t"    /* s' = out ? s : 1 = max(s, 1): far implies s >= 1 */      \
    "sub      r6, r6, r4, lsr #1\n\t" /* 8: y = bits(0x5f3759df - (bits(s') >> 1)) */            \
    "vmov     s4, r4\n\t"                                                                         \
    "vmov     s5, r6\n\t"                                                                         \
    "vmul.f32 s7, s4, s5\n\t"         /* Newton 1: t = (s' y) y; t = 3 - t; y = (0.5 y) t */      \
    "vmul.f32 s8, s14, s5\n\t"                                                                    \
    "vmul.f32 s7, s7, s5\n\t"                                                                     \
    "vsub.f32 s7, s13, s7\n\t"                                                                    \
    "vmul.f32 s5, s8, s7\n\t"                                                                     \
    "vmul.f32 s7, s4, s5\n\t"         /* Newton 2 */                                              \
    "vmul.f32 s8, s14, s5\n\t"                                                                    \
    "vmul.f32 s7, s7, s5\n\t"                                                                     \
    "vsub.f32 s7, s13, s7\n\t"                                                                    \
    "vmul.f32 s5, s8, s7\n\t"                                                                     \
    "vmul.f32 s7, s4, s5\n\t"         /* Newton 3 */                                              \
    "vmul.f32 s8, s14, s5\n\t"                                                                    \
    "vmul.f32 s7, s7, s5\n\t"                                                                     \
    "vsub.f32 s7, s13, s7\n\t"                                                                    \
    "vmul.f32 s5, s8, s7\n\t"                                                                     \
    "cmp      r12, #0\n\t"            /* 9: g = g (out ? y : 1) */                                \
    "it       eq\n\t"                                                                             \
    "vmoveq.f32 s5, #1.0\n\t"                                                                     \
    "vmul.f32 s0, s6, s5\n\t"                                                                     \
    "vmul.f32 s1, s9, s5\n\t"                                                                     \
    "vmul.f32 s2, s12, s5\n\t"                                                                    \
    "and      r12, r12, #1\n\t"       /* status: bad ? -1 : out ? 1 : 0 */                        \
    "orn      r12, r12, lr\n\t"

/* One output point (§5.2): its 12 coefficients in s3-s14 (x row s3-s6, y
 * row s7-s10, z row s11-s14); x = ((c0 + c1 g0) + c2 g1) + c3 g2 ends in s3,
 * y in s4, z in s5. */
#define TFIT_ASM_POINT                                                                            \
    "vldm     r0, {s3-s14}\n\t"                                                                   \
    "vmul.f32 s4, s4, s0\n\t"                                                                     \
    "vmul.f32 s8, s8, s0\n\t"                                                                     \
    "vmul.f32 s12, s12, s0\n\t"                                                                   \
    "vadd.f32 s3, s3, s4\n\t"                                                                     \
    "vadd.f32 s7, s7, s8\n\t"                                                                     \
    "vadd.f32 s11, s11, s12\n\t"                                                                  \
    "vmul.f32 s5, s5, s1\n\t"                                                                     \
    "vmul.f32 s9, s9, s1\n\t"                                                                     \
    "vmul.f32 s13, s13, s1\n\t"                                                                   \
    "vadd.f32 s3, s3, s5\n\t"                                                                     \
    "vadd.f32 s7, s7, s9\n\t"                                                                     \
    "vadd.f32 s11, s11, s13\n\t"                                                                  \
    "vmul.f32 s6, s6, s2\n\t"                                                                     \
    "vmul.f32 s10, s10, s2\n\t"                                                                   \
    "vmul.f32 s14, s14, s2\n\t"                                                                   \
    "vadd.f32 s3, s3, s6\n\t"                                                                     \
    "vadd.f32 s4, s7, s10\n\t"                                                                    \
    "vadd.f32 s5, s11, s14\n\t"                                                                   \
    "vstm     r2, {s3-s5}\n\t"

/* Two output points A (s3-s14) and B (s15-s26), their six sums
 * interleaved; results x, y, z of A then of B in s3-s8, stored with one
 * VSTM.  Each result register is free when written: s4, s5, s8 held
 * products already added, s6 and s7 are read by A's last sums first. */
#define TFIT_ASM_PAIR                                                                             \
    "vldm     r0!, {s3-s26}\n\t"                                                                  \
    "vmul.f32 s4, s4, s0\n\t"                                                                     \
    "vmul.f32 s8, s8, s0\n\t"                                                                     \
    "vmul.f32 s12, s12, s0\n\t"                                                                   \
    "vmul.f32 s16, s16, s0\n\t"                                                                   \
    "vmul.f32 s20, s20, s0\n\t"                                                                   \
    "vmul.f32 s24, s24, s0\n\t"                                                                   \
    "vadd.f32 s3, s3, s4\n\t"                                                                     \
    "vadd.f32 s7, s7, s8\n\t"                                                                     \
    "vadd.f32 s11, s11, s12\n\t"                                                                  \
    "vadd.f32 s15, s15, s16\n\t"                                                                  \
    "vadd.f32 s19, s19, s20\n\t"                                                                  \
    "vadd.f32 s23, s23, s24\n\t"                                                                  \
    "vmul.f32 s5, s5, s1\n\t"                                                                     \
    "vmul.f32 s9, s9, s1\n\t"                                                                     \
    "vmul.f32 s13, s13, s1\n\t"                                                                   \
    "vmul.f32 s17, s17, s1\n\t"                                                                   \
    "vmul.f32 s21, s21, s1\n\t"                                                                   \
    "vmul.f32 s25, s25, s1\n\t"                                                                   \
    "vadd.f32 s3, s3, s5\n\t"                                                                     \
    "vadd.f32 s7, s7, s9\n\t"                                                                     \
    "vadd.f32 s11, s11, s13\n\t"                                                                  \
    "vadd.f32 s15, s15, s17\n\t"                                                                  \
    "vadd.f32 s19, s19, s21\n\t"                                                                  \
    "vadd.f32 s23, s23, s25\n\t"                                                                  \
    "vmul.f32 s6, s6, s2\n\t"                                                                     \
    "vmul.f32 s10, s10, s2\n\t"                                                                   \
    "vmul.f32 s14, s14, s2\n\t"                                                                   \
    "vmul.f32 s18, s18, s2\n\t"                                                                   \
    "vmul.f32 s22, s22, s2\n\t"                                                                   \
    "vmul.f32 s26, s26, s2\n\t"                                                                   \
    "vadd.f32 s3, s3, s6\n\t"                                                                     \
    "vadd.f32 s4, s7, s10\n\t"                                                                    \
    "vadd.f32 s5, s11, s14\n\t"                                                                   \
    "vadd.f32 s6, s15, s18\n\t"                                                                   \
    "vadd.f32 s7, s19, s22\n\t"                                                                   \
    "vadd.f32 s8, s23, s26\n\t"                                                                   \
    "vstm     r2!, {s3-s8}\n\t"

/* The rows of n_out output points (r3) at g (s0-s2), from r0 on, into r2:
 * n_out / 16 passes of eight pairs, (n_out / 2) mod 8 single pairs, the odd
 * point.  lr is keep: for a NaN/Inf input (lr = 0) r0 points at the zero
 * rows, rewound by 768 bytes after each pass. */
#define TFIT_ASM_ROWS                                                                             \
    "mov      r5, #768\n\t" /* rewind per iteration: 0, or 768 for NaN/Inf */                     \
    "bic      r5, r5, lr\n\t"                                                                      \
    "lsrs     r4, r3, #4\n\t" /* iterations of 8 pairs */                                          \
    "beq      2f\n"                                                                                \
    "1:\n\t" TFIT_ASM_PAIR TFIT_ASM_PAIR TFIT_ASM_PAIR TFIT_ASM_PAIR TFIT_ASM_PAIR TFIT_ASM_PAIR     \
        TFIT_ASM_PAIR TFIT_ASM_PAIR                                                               \
    "sub      r0, r0, r5\n\t"                                                                      \
    "subs     r4, r4, #1\n\t"                                                                      \
    "bne      1b\n"                                                                                \
    "2:\n\t"                                                                                       \
    "lsr      r4, r3, #1\n\t" /* the remaining pairs */                                            \
    "ands     r4, r4, #7\n\t"                                                                      \
    "beq      4f\n"                                                                                \
    "3:\n\t" TFIT_ASM_PAIR                                                                         \
    "subs     r4, r4, #1\n\t"                                                                      \
    "bne      3b\n"                                                                                \
    "4:\n\t"                                                                                       \
    "tst      r3, #1\n\t" /* the odd point */                                                      \
    "beq      5f\n\t" TFIT_ASM_POINT                                                               \
    "5:\n\t"

#define TFIT_ASM_CLOBBER_LOW                                                                      \
    "r4", "r5", "r6", "lr", "s0", "s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9", "s10",    \
        "s11", "s12", "s13", "s14", "s15", "cc", "memory"

tfit_status tfit_degree1_one_asm(const tfit_model *m, const float in[3], float *out)
{
    register const float *r0 __asm__("r0") = m->coef;
    register const float *r1 __asm__("r1") = in;
    register float *r2 __asm__("r2") = out;
    register uintptr_t r12 __asm__("r12") = (uintptr_t)tfit_zero_coef;
    __asm__ volatile(TFIT_ASM_INPUT_MAP TFIT_ASM_POINT
                     : "+r"(r0), "+r"(r1), "+r"(r12)
                     : "r"(r2)
                     : TFIT_ASM_CLOBBER_LOW);
    return (tfit_status)(int32_t)r12;
}

tfit_status tfit_degree1_asm(const tfit_model *m, const float in[3], float *out)
{
    register uint32_t r3 __asm__("r3") = m->n_out;
    register const float *r0 __asm__("r0") = m->coef;
    register const float *r1 __asm__("r1") = in;
    register float *r2 __asm__("r2") = out;
    register uintptr_t r12 __asm__("r12") = (uintptr_t)tfit_zero_coef;
    __asm__ volatile(TFIT_ASM_INPUT_MAP TFIT_ASM_ROWS
                     : "+r"(r0), "+r"(r1), "+r"(r2), "+r"(r12)
                     : "r"(r3)
                     : TFIT_ASM_CLOBBER_LOW, "s16", "s17", "s18", "s19", "s20", "s21", "s22",
                       "s23", "s24", "s25", "s26");
    return (tfit_status)(int32_t)r12;
}

void tfit_degree1_rows_asm(const float *rows, const float g[3], uint32_t n_out, uint32_t keep,
                           float *out)
{
    register const float *r0 __asm__("r0") = rows;
    register float *r2 __asm__("r2") = out;
    register uint32_t r3 __asm__("r3") = n_out;
    register uintptr_t r12 __asm__("r12") = (uintptr_t)tfit_zero_coef;
    __asm__ volatile("vldm     %[g], {s0-s2}\n\t" /* g */
                     "movs     lr, %[keep]\n\t"   /* keep: all ones, or 0 for NaN/Inf */
                     "it       eq\n\t"
                     "moveq    r0, r12\n\t"       /* bad: the zero rows (header-format §5.5) */
                     TFIT_ASM_ROWS
                     : "+r"(r0), "+r"(r2)
                     : "r"(r3), "r"(r12), [g] "r"(g), [keep] "r"(keep)
                     : "r4", "r5", "lr", "s0", "s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9",
                       "s10", "s11", "s12", "s13", "s14", "s15", "s16", "s17", "s18", "s19", "s20",
                       "s21", "s22", "s23", "s24", "s25", "s26", "cc", "memory");
}

#else
typedef int tfit_degree1_armv7em_unused; /* ISO C forbids an empty translation unit */
#endif
