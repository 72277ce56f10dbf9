/*
 * tfit_modal_armv7em.c — the modal family's reconstruction (the output
 * rows, docs/header-format.md §5.3) on Armv7E-M with a single-precision FPU
 * (Cortex-M4F, Cortex-M7), in inline assembly, for ranks 1 .. 8.  The
 * portable C loop of tfit_modal.c (every other target, -DTFIT_PORTABLE, and
 * ranks above 8) is the reference: both perform exactly the operations of
 * §5.3 in that order,
 *   out[o] = (((U[o][0] a_0) + U[o][1] a_1) + ...) + U[o][r-1] a_{r-1},
 * and both run every golden vector (check-qemu, check-qemu-portable).
 *
 * Why assembly (docs/firmware.md §5.4): the reconstruction is 3 r n_out
 * coefficients against r amplitudes, the bulk of a modal evaluation, and
 * GCC loads each coefficient with its own VLDR (2 cycles on the M4) and
 * keeps a[] in memory.  Here the r amplitudes stay in s0 .. s(r-1), one
 * output point's 3 r coefficients (x row, y row, z row) arrive with one
 * VLDM (1 cycle per word) into s8 .. s(8+3r-1), every product is formed in
 * place and summed into the row's first register, the three sums of a
 * point interleaved; the last three sums land in s8-s10 for one VSTM.  A
 * point costs 3r words, 3r multiplications, 3(r-1) additions, the store
 * and three loop instructions: 9r + 8 cycles (M4F upper bound), 3 per
 * coefficient, against about 19 per mode and 40 per point in C.
 *
 * The code of each rank is unrolled by the assembler macros below
 * (.altmacro evaluates %(expr) into register numbers); one function per
 * rank, chosen through tfit_modal_rows_asm[] by tfit_modal.c.
 *
 * Output mask (§5.5) without a per-word operation, as in the degree-1
 * assembly: for a NaN/Inf input the caller passes amplitudes of +0.0f and
 * the rows are read from a block of +0.0f instead of the model, rewound
 * after every point (rewind = 12 r bytes, else 0), so every output is
 * (+0 * +0) + ... = +0.0f, the bits of the mask.
 *
 * Registers: r0 rows, r1 amplitudes, r2 out, r3 points left, r12 rewind.
 * The cycle model (host/cost/cycles.c) describes each function's path and
 * loop, and check-cycles compares it with objdump and QEMU traces.
 */
#include "tfit_internal.h"

#if TFIT_DEGREE1_ASM

/* One mode slot's worth of zeros for each of the three rows at the largest
 * rank: a NaN/Inf input reads these instead of the model's rows.  Named
 * like the generated tables (linker/sections.ld). */
static const float tfit_modal_zero_coef[3u * TFIT_MODAL_ASM_MAX_RANK];

/* Assembler macros (GNU as, .altmacro for %(expr)), defined once for this
 * translation unit and left in .noaltmacro mode for the compiler's code.
 *   tfit_mr_op OP, D, A, B    OP sD, sA, sB
 *   tfit_mr_rows R            the whole rows loop of rank R */
__asm__(".altmacro\n"
        ".macro tfit_mr_op op, d, a, b\n"
        "\t\\op s\\d, s\\a, s\\b\n"
        ".endm\n"
        ".macro tfit_mr_lda last\n" /* the amplitudes: s0 .. s(r-1) */
        "\t.if \\last\n"
        "\tvldm r1, {s0-s\\last}\n"
        "\t.else\n"
        "\tvldm r1, {s0}\n"
        "\t.endif\n"
        ".endm\n"
        ".macro tfit_mr_ldu last\n" /* one point's rows: s8 .. s(8+3r-1) */
        "\tvldm r0!, {s8-s\\last}\n"
        ".endm\n"
        /* mode k of the three rows: products in place, then the sums; the
         * last mode's sums go to s8, s9, s10 (free by then: they held the
         * x row's first products, already summed) */
        ".macro tfit_mr_mode r, k\n"
        "\t.irp c, 0, 1, 2\n"
        "\ttfit_mr_op vmul.f32, %(8+\\c*\\r+\\k), %(8+\\c*\\r+\\k), %(\\k)\n"
        "\t.endr\n"
        "\t.if \\k\n"
        "\t.irp c, 0, 1, 2\n"
        "\t.if \\k == \\r - 1\n"
        "\ttfit_mr_op vadd.f32, %(8+\\c), %(8+\\c*\\r), %(8+\\c*\\r+\\k)\n"
        "\t.else\n"
        "\ttfit_mr_op vadd.f32, %(8+\\c*\\r), %(8+\\c*\\r), %(8+\\c*\\r+\\k)\n"
        "\t.endif\n"
        "\t.endr\n"
        "\t.endif\n"
        ".endm\n"
        ".macro tfit_mr_rows r\n"
        "\ttfit_mr_lda %(\\r-1)\n"
        "1:\n"
        "\ttfit_mr_ldu %(8+3*\\r-1)\n"
        "\t.set tfit_mr_k, 0\n"
        "\t.rept \\r\n"
        "\ttfit_mr_mode \\r, %tfit_mr_k\n"
        "\t.set tfit_mr_k, tfit_mr_k + 1\n"
        "\t.endr\n"
        "\tvstm r2!, {s8-s10}\n"
        "\tsub r0, r0, r12\n"
        "\tsubs r3, r3, #1\n"
        "\tbne 1b\n"
        ".endm\n"
        ".noaltmacro\n");

/* The rows of n_out >= 1 output points at rank R. */
#define TFIT_MODAL_ROWS(R)                                                                       \
    static void tfit_modal_rows_r##R(const float *rows, const float *a, uint32_t n_out,            \
                                     uint32_t rewind, float *out)                                  \
    {                                                                                              \
        register const float *r0 __asm__("r0") = rows;                                             \
        register const float *r1 __asm__("r1") = a;                                                \
        register float *r2 __asm__("r2") = out;                                                    \
        register uint32_t r3 __asm__("r3") = n_out;                                                \
        register uint32_t r12 __asm__("r12") = rewind;                                             \
        __asm__ volatile(".altmacro\n\ttfit_mr_rows " #R "\n\t.noaltmacro"                          \
                         : "+r"(r0), "+r"(r2), "+r"(r3)                                            \
                         : "r"(r1), "r"(r12)                                                       \
                         : "s0", "s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8", "s9", "s10",      \
                           "s11", "s12", "s13", "s14", "s15", "s16", "s17", "s18", "s19", "s20",   \
                           "s21", "s22", "s23", "s24", "s25", "s26", "s27", "s28", "s29", "s30",   \
                           "s31", "cc", "memory");                                                 \
    }

TFIT_MODAL_ROWS(1)
TFIT_MODAL_ROWS(2)
TFIT_MODAL_ROWS(3)
TFIT_MODAL_ROWS(4)
TFIT_MODAL_ROWS(5)
TFIT_MODAL_ROWS(6)
TFIT_MODAL_ROWS(7)
TFIT_MODAL_ROWS(8)

void tfit_modal_rows_asm(uint32_t r, const float *rows, const float *a, uint32_t n_out,
                         uint32_t keep, float *out)
{
    static void (*const by_rank[TFIT_MODAL_ASM_MAX_RANK])(const float *, const float *, uint32_t,
                                                          uint32_t, float *) = {
        tfit_modal_rows_r1, tfit_modal_rows_r2, tfit_modal_rows_r3, tfit_modal_rows_r4,
        tfit_modal_rows_r5, tfit_modal_rows_r6, tfit_modal_rows_r7, tfit_modal_rows_r8};
    /* keep all ones: the model's rows, no rewind; 0: the zero rows, rewound */
    const uintptr_t model = (uintptr_t)rows & keep;
    const uintptr_t zero = (uintptr_t)tfit_modal_zero_coef & ~keep;
    by_rank[r - 1u]((const float *)(model | zero), a, n_out, (12u * r) & ~keep, out);
}

#else
typedef int tfit_modal_armv7em_unused; /* ISO C forbids an empty translation unit */
#endif
