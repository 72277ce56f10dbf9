/*
 * cycles.h — estimated cycles of one evaluation on Cortex-M4F and Cortex-M7
 * (docs/firmware.md, "Cycle estimates").
 *
 * The estimate is instruction mix x cycles per instruction class.  The mix
 * comes from the structure of the compiled evaluator (arm-none-eabi-gcc -O2):
 * per loop iteration and per call, instructions counted by class from
 * arm-none-eabi-objdump (tests/firmware/insn_mix.c checks that the compiled
 * code still has exactly these mixes, and the QEMU runs check the total
 * instruction count per call).  The cycles per class come from the Cortex-M4
 * technical reference manual (Arm DDI 0439B, table 3-1 "Cortex-M4
 * instruction set summary" and table 7-1 "FPU instruction set"); the
 * Cortex-M7 manual (Arm DDI 0489) gives no such table, so its costs are a
 * stated dual-issue model with a wider uncertainty.
 */
#ifndef TF_CYCLES_H
#define TF_CYCLES_H

#include <stddef.h>
#include <stdint.h>

#include "model/model.h"

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

/* The instructions one call executes, by class (the model's prediction of
 * what QEMU traces). */
void tf_cycles_mix(const tf_model *m, tf_core core, tf_insn_mix *mix);

/* Cycles of a given instruction mix (e.g. one traced under QEMU). */
tf_cycles tf_cycles_of_mix(const tf_insn_mix *mix, tf_core core);

/* Estimate for one evaluation of m (tfit_displacements or
 * tfit_contact_force, including the call from C). */
tf_cycles tf_cycles_estimate(const tf_model *m, tf_core core);

/* The loop mixes the estimate assumes, one line per loop in the format of
 * tests/firmware/insn_mix.c ("FUNCTION loop K depth D: mix"), for the
 * objdump cross-check.  Writes at most n bytes; returns the length needed. */
size_t tf_cycles_loop_table(tf_core core, char *buf, size_t n);

#endif /* TF_CYCLES_H */
