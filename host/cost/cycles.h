/*
 * cycles.h — the cycle model of the compiled evaluator on Cortex-M4F and
 * Cortex-M7 (docs/firmware.md, "Cycle estimates"): instruction classes and
 * mixes, the blocks of the compiled code, and the cycles of a mix.
 *
 * The estimate is instruction mix x cycles per instruction class.  The mix
 * comes from the structure of the compiled evaluator (arm-none-eabi-gcc -O2):
 * per loop iteration and per call, instructions counted by class from
 * arm-none-eabi-objdump (tests/firmware/insn_mix.c checks that the compiled
 * code still has exactly these mixes, and the QEMU runs check the total
 * instruction count per call).  A block is a piece of the compiled code: a
 * loop body or a path outside loops.  The blocks several forms run are in
 * cost/evaluator.h; each form adds its own and composes a call's mix
 * from them (model/forms/form.h); nothing here knows a model.  The cycles per class come from the Cortex-M4
 * technical reference manual (Arm DDI 0439B, table 3-1 "Cortex-M4
 * instruction set summary" and table 7-1 "FPU instruction set"); the
 * Cortex-M7 manual (Arm DDI 0489) gives no such table, so its costs are a
 * stated dual-issue model with a wider uncertainty.
 */
#ifndef TF_CYCLES_H
#define TF_CYCLES_H

#include <stddef.h>
#include <stdint.h>

typedef enum tf_insn_class {
    TF_INSN_ALU,    /* data processing, moves, compares, IT */
    TF_INSN_MUL,    /* MUL, UMULL, SMULL, UMLAL, SMLAL */
    TF_INSN_MLA,    /* MLA, MLS */
    TF_INSN_DIV,    /* SDIV, UDIV */
    TF_INSN_LOAD,   /* LDR, LDRB, LDRH, ... one register */
    TF_INSN_STORE,  /* STR, STRB, STRH */
    TF_INSN_LDM,    /* LDM, POP without pc, LDRD */
    TF_INSN_LDM_PC, /* POP {..., pc}: returns */
    TF_INSN_STM,    /* STM, PUSH, STRD */
    TF_INSN_WORDS,  /* registers moved by LDM, LDM_PC and STM */
    TF_INSN_FLOAD,  /* VLDR */
    TF_INSN_FSTORE, /* VSTR */
    TF_INSN_FLDM,   /* VLDM, VPOP */
    TF_INSN_FSTM,   /* VSTM, VPUSH */
    TF_INSN_FWORDS, /* registers moved by FLDM and FSTM */
    TF_INSN_FADD,   /* VADD, VSUB */
    TF_INSN_FMUL,   /* VMUL, VNMUL */
    TF_INSN_FDIV,   /* VDIV, VSQRT */
    TF_INSN_FMAC,   /* VMLA, VFMA, ...: must never appear (-ffp-contract=off) */
    TF_INSN_FOTHER, /* VCMP, VCVT, VABS, VNEG, VMOV between FPU registers or of a constant */
    TF_INSN_FMOV,   /* VMOV between core and FPU registers, VMRS, VMSR */
    TF_INSN_BRANCH, /* B, BL, BX, and CBZ, CBNZ, B<cond> when taken */
    TF_INSN_NBRANCH, /* CBZ, CBNZ, B<cond> not taken (objdump cannot tell: "branch" there) */
    TF_INSN_CLASSES
} tf_insn_class;

typedef struct tf_insn_mix {
    unsigned n[TF_INSN_CLASSES];
} tf_insn_mix;

/* "alu=4 fload=12 ..." (non-zero classes in enum order). */
void tf_insn_mix_format(const tf_insn_mix *mix, char *buf, size_t n);
/* Parses that format; returns 0, or -1 on an unknown class or syntax. */
int tf_insn_mix_parse(const char *text, tf_insn_mix *mix);
/* Instructions in a mix (multiple transfers count once). */
uint64_t tf_insn_mix_count(const tf_insn_mix *mix);

typedef enum tf_core { TF_CORE_M4F, TF_CORE_M7, TF_CORES } tf_core;

typedef struct tf_cycles {
    uint64_t instructions; /* per call, as the compiled code executes them */
    double cycles;         /* estimate, zero-wait-state memory */
    double cycles_low;     /* same, most favourable end of the per-class ranges */
} tf_cycles;

/* Clock the header's microsecond macros assume (STM32F407: 168 MHz,
 * STM32H743: 480 MHz). */
double tf_core_mhz(tf_core core);
const char *tf_core_name(tf_core core); /* "M4F", "M7" */

/* Cycles of a given instruction mix (e.g. one traced under QEMU, or a
 * model's: tf_model_cycles, model/model.h). */
tf_cycles tf_cycles_of_mix(const tf_insn_mix *mix, tf_core core);

/* A block of the compiled evaluator: a loop body ("loop K" of FUNCTION, K
 * counted by address as tests/firmware/insn_mix.c numbers them, at nesting
 * depth D; its own instructions, without nested loops) or a path through
 * code outside loops (loop 0), with its mix on each core ("alu=4 fload=12
 * ...": the M4F build, the M7 build). */
typedef struct tf_block {
    const char *function;
    int loop, depth;
    const char *mix[TF_CORES];
} tf_block;
#define TF_SAME(s) {s, s} /* one mix on both cores */

/* Adds (subtracts) block b, run `times` times, to the mix t. */
void tf_insn_add(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t times);
void tf_insn_sub(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t times);
/* A loop block run n times: its back edge falls through the last time. */
void tf_insn_loop(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t n);
/* n conditional branches that fall through instead of being taken (a
 * loop's last back edge, a skip not taken), or the reverse. */
void tf_insn_falls_through(tf_insn_mix *t, uint64_t n);
void tf_insn_taken(tf_insn_mix *t, uint64_t n);

/* The loop blocks of blocks[0..n), one line each in the format of
 * tests/firmware/insn_mix.c ("FUNCTION loop K depth D: mix"), written at
 * buf + at (at most len bytes in all); returns at plus the length needed. */
size_t tf_insn_loop_lines(const tf_block *blocks, size_t n, tf_core core, char *buf, size_t len,
                          size_t at);

#endif /* TF_CYCLES_H */
