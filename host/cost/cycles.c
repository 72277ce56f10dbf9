/*
 * cycles.c — see cycles.h.
 */
#include "cost/cycles.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const class_names[TF_INSN_CLASSES] = {
    "alu", "mul", "mla", "div", "load", "store", "ldm", "ldm_pc", "stm", "words",
    "fload", "fstore", "fldm", "fstm", "fwords", "fadd", "fmul", "fdiv", "fmac", "fother",
    "fmov", "branch", "nbranch"};

void tf_insn_mix_format(const tf_insn_mix *mix, char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = '\0';
    for (int c = 0; c < TF_INSN_CLASSES && k < n; ++c) {
        if (mix->n[c] != 0) {
            k += (size_t)snprintf(buf + k, n - k, "%s%s=%u", k ? " " : "", class_names[c],
                                  mix->n[c]);
        }
    }
}

int tf_insn_mix_parse(const char *text, tf_insn_mix *mix)
{
    memset(mix, 0, sizeof *mix);
    const char *p = text;
    while (*p != '\0') {
        while (*p == ' ' || *p == '\n' || *p == '\t') {
            ++p;
        }
        if (*p == '\0') {
            break;
        }
        size_t len = strcspn(p, "=");
        int c = 0;
        while (c < TF_INSN_CLASSES &&
               !(strlen(class_names[c]) == len && strncmp(p, class_names[c], len) == 0)) {
            ++c;
        }
        if (c == TF_INSN_CLASSES || p[len] != '=') {
            return -1;
        }
        char *end;
        unsigned long v = strtoul(p + len + 1, &end, 10);
        if (end == p + len + 1) {
            return -1;
        }
        mix->n[c] = (unsigned)v;
        p = end;
    }
    return 0;
}

uint64_t tf_insn_mix_count(const tf_insn_mix *mix)
{
    uint64_t n = 0;
    for (int c = 0; c < TF_INSN_CLASSES; ++c) {
        if (c != TF_INSN_WORDS && c != TF_INSN_FWORDS) {
            n += mix->n[c];
        }
    }
    return n;
}

/* ------------------------------------------------------------------------
 * Blocks: a call's mix is the sum of the blocks it runs, each times the
 * number of times it runs, which depends only on the model's form, orders
 * and n_out (model/forms/).  Loop blocks are checked against objdump of the
 * compiled library; whole sums against the instructions QEMU executes per
 * call (tests/firmware, make check-cycles).
 */

static void add_mix(tf_insn_mix *total, const char *text, uint64_t times)
{
    tf_insn_mix m;
    if (tf_insn_mix_parse(text, &m) != 0) {
        fprintf(stderr, "cycles.c: bad mix '%s'\n", text);
        abort();
    }
    for (int c = 0; c < TF_INSN_CLASSES; ++c) {
        total->n[c] += (unsigned)(m.n[c] * times);
    }
}

void tf_insn_add(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t times)
{
    add_mix(t, b->mix[core], times);
}

void tf_insn_sub(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t times)
{
    tf_insn_mix m;
    tf_insn_mix_parse(b->mix[core], &m);
    for (int c = 0; c < TF_INSN_CLASSES; ++c) {
        t->n[c] -= (unsigned)(m.n[c] * times);
    }
}

void tf_insn_falls_through(tf_insn_mix *t, uint64_t n)
{
    add_mix(t, "nbranch=1", n);
    t->n[TF_INSN_BRANCH] -= (unsigned)n;
}

void tf_insn_taken(tf_insn_mix *t, uint64_t n)
{
    add_mix(t, "branch=1", n);
    t->n[TF_INSN_NBRANCH] -= (unsigned)n;
}

void tf_insn_loop(tf_insn_mix *t, const tf_block *b, tf_core core, uint64_t n)
{
    tf_insn_add(t, b, core, n);
    if (n > 0) {
        tf_insn_falls_through(t, 1);
    }
}

size_t tf_insn_loop_lines(const tf_block *blocks, size_t n, tf_core core, char *buf, size_t len,
                          size_t at)
{
    size_t k = at;
    for (size_t b = 0; b < n; ++b) {
        if (blocks[b].loop > 0) {
            /* objdump cannot tell a taken branch from one that falls through */
            tf_insn_mix m;
            char text[512];
            tf_insn_mix_parse(blocks[b].mix[core], &m);
            m.n[TF_INSN_BRANCH] += m.n[TF_INSN_NBRANCH];
            m.n[TF_INSN_NBRANCH] = 0;
            tf_insn_mix_format(&m, text, sizeof text);
            int w = snprintf(buf + (k < len ? k : len), k < len ? len - k : 0,
                             "%s loop %d depth %d: %s\n", blocks[b].function, blocks[b].loop,
                             blocks[b].depth, text);
            k += (size_t)w;
        }
    }
    return k;
}

/* ------------------------------------------------------------------------
 * Cycles per instruction class.
 *
 * Cortex-M4 (Arm DDI 0439B, table 3-1 and table 7-1), zero wait states:
 * data processing, MUL and the 32x32->64 multiplies 1; MLA 2; SDIV/UDIV
 * 2..12; LDR/STR 2, or 1 when pipelined behind another load/store; LDM/STM/
 * PUSH/POP/LDRD 1+N; a branch 1+P, P = 1..3 (pipeline refill), 1 when not
 * taken; POP {pc} 1+N+P; VLDR/VSTR 2; VLDM/VSTM 1+N; VADD, VSUB, VMUL, VCMP,
 * VMOV 1; VDIV 14; VMLA/VFMA 3.  "high" takes the slow end of every range
 * (every branch taken with P = 3, no load pipelining): an upper bound for
 * the instruction stream; "low" the fast end.
 *
 * Cortex-M7 (Arm DDI 0489): an in-order dual-issue pipeline with a 64-bit
 * load/store path, branch prediction and one single-precision FPU pipeline;
 * the manual lists no cycle counts.  The model: a data-processing
 * instruction issues beside another (1/2), a load, store or FPU instruction
 * takes one issue slot (1), multiple transfers move two words per cycle,
 * VDIV.F32 14, predicted branches 1 (high: a mispredict every fourth
 * branch, 8-cycle refill).  Expect +-30 %.
 */
typedef struct cost_table {
    double c[TF_INSN_CLASSES];
} cost_table;

enum { ALU, MUL, MLA, DIV, LOAD, STORE, LDM, LDM_PC, STM, WORDS, FLOAD, FSTORE, FLDM, FSTM,
       FWORDS, FADD, FMUL, FDIV, FMAC, FOTHER, FMOV, BRANCH, NBRANCH };

static const cost_table costs[TF_CORES][2] = {
    [TF_CORE_M4F] = {
        /* high */ {{[ALU] = 1, [MUL] = 1, [MLA] = 2, [DIV] = 12, [LOAD] = 2, [STORE] = 2,
                     [LDM] = 1, [LDM_PC] = 4, [STM] = 1, [WORDS] = 1, [FLOAD] = 2, [FSTORE] = 2,
                     [FLDM] = 1, [FSTM] = 1, [FWORDS] = 1, [FADD] = 1, [FMUL] = 1, [FDIV] = 14,
                     [FMAC] = 3, [FOTHER] = 1, [FMOV] = 1, [BRANCH] = 4, [NBRANCH] = 1}},
        /* low */ {{[ALU] = 1, [MUL] = 1, [MLA] = 2, [DIV] = 2, [LOAD] = 1, [STORE] = 1,
                    [LDM] = 1, [LDM_PC] = 2, [STM] = 1, [WORDS] = 1, [FLOAD] = 1, [FSTORE] = 1,
                    [FLDM] = 1, [FSTM] = 1, [FWORDS] = 1, [FADD] = 1, [FMUL] = 1, [FDIV] = 14,
                    [FMAC] = 3, [FOTHER] = 1, [FMOV] = 1, [BRANCH] = 2, [NBRANCH] = 1}},
    },
    [TF_CORE_M7] = {
        /* high */ {{[ALU] = 0.5, [MUL] = 1, [MLA] = 1, [DIV] = 12, [LOAD] = 1, [STORE] = 1,
                     [LDM] = 1, [LDM_PC] = 3, [STM] = 1, [WORDS] = 0.5, [FLOAD] = 1,
                     [FSTORE] = 1, [FLDM] = 1, [FSTM] = 1, [FWORDS] = 0.5, [FADD] = 1,
                     [FMUL] = 1, [FDIV] = 14, [FMAC] = 1, [FOTHER] = 1, [FMOV] = 1,
                     [BRANCH] = 3, [NBRANCH] = 3}},
        /* low */ {{[ALU] = 0.5, [MUL] = 0.5, [MLA] = 1, [DIV] = 2, [LOAD] = 0.5, [STORE] = 0.5,
                    [LDM] = 1, [LDM_PC] = 1, [STM] = 1, [WORDS] = 0.5, [FLOAD] = 0.5,
                    [FSTORE] = 0.5, [FLDM] = 1, [FSTM] = 1, [FWORDS] = 0.5, [FADD] = 1,
                    [FMUL] = 1, [FDIV] = 14, [FMAC] = 1, [FOTHER] = 1, [FMOV] = 1,
                    [BRANCH] = 1, [NBRANCH] = 1}},
    },
};

static double cost_of(const tf_insn_mix *mix, const cost_table *t)
{
    double c = 0;
    for (int k = 0; k < TF_INSN_CLASSES; ++k) {
        c += mix->n[k] * t->c[k];
    }
    return c;
}

double tf_core_mhz(tf_core core)
{
    return core == TF_CORE_M7 ? 480.0 : 168.0;
}

const char *tf_core_name(tf_core core)
{
    return core == TF_CORE_M7 ? "M7" : "M4F";
}

tf_cycles tf_cycles_of_mix(const tf_insn_mix *mix, tf_core core)
{
    tf_cycles r = {tf_insn_mix_count(mix), cost_of(mix, &costs[core][0]),
                   cost_of(mix, &costs[core][1])};
    return r;
}
