/*
 * insn_class.h — classifies Arm Thumb-2 instructions from objdump's text
 * into the cost classes of host/cost/cycles.h; shared by insn_mix.c (static
 * mixes of loops) and trace_mix.c (mixes executed under QEMU).
 */
#ifndef TF_INSN_CLASS_H
#define TF_INSN_CLASS_H

#include <stddef.h>

#include "cost/cycles.h"

/* Class of one instruction ("vmul.f32", "s15, s15, s14"); *words is the
 * number of registers of a multiple transfer, else 0. */
int tf_classify_insn(const char *mnemonic, const char *operands, int *words);

/* True for a conditional branch mnemonic (beq, bne.n, cbz, cbnz, ...): the
 * branches that may fall through (TF_INSN_NBRANCH when they do). */
int tf_is_conditional_branch(const char *mnemonic);

/* Splits "   3c:\tvmul.f32\ts15, s15, s14" (objdump -d --no-show-raw-insn).
 * Returns 0 for an instruction line, -1 otherwise. */
int tf_parse_objdump_line(const char *line, unsigned long *addr, char *mn, size_t mn_len,
                          char *ops, size_t ops_len);

/* Adds one instruction of class cls moving words registers. */
void tf_insn_mix_add(tf_insn_mix *mix, int cls, int words);

#endif /* TF_INSN_CLASS_H */
