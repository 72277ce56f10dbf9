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
 * The compiled evaluator, block by block.
 *
 * Each block is a piece of tfit_displacements()/tfit_contact_force() as
 * arm-none-eabi-gcc 12.2 -O2 compiles it (target/target.mk): a loop body
 * ("loop K" of FUNCTION, K counted by address as tests/firmware/insn_mix.c
 * numbers them; its own instructions, without nested loops) or a path
 * through code outside loops (loop 0).  The estimate adds blocks times the
 * number of times each runs, which depends only on the model's family,
 * orders and n_out.  Loop blocks are checked against objdump of the
 * compiled library; the whole sum is checked against the instructions QEMU
 * executes per call (tests/firmware, make check-cycles).
 */
typedef enum block_id {
    ENTRY_FORWARD,  /* tfit_displacements: argument and family checks, tail call */
    ENTRY_DIMS1,    /* ... a family other than nodal with dims[0] = 1 tests the family too */
    ENTRY_CONTACT,  /* tfit_contact_force, p != 1: the same */
    D1_ENTRY_FORWARD, /* tfit_displacements, nodal p = 1: checks, tail call */
    D1_ENTRY_CONTACT, /* tfit_contact_force, p = 1: the same */
    D1_ONE,         /* tfit_degree1_one_asm(): the whole contact p = 1 evaluation */
    D1_PATH,        /* tfit_degree1_asm() outside its loops and the odd point */
    D1_MAIN,        /* loop 1: eight pairs of output points */
    D1_REM,         /* loop 2: one pair of output points */
    D1_POINT,       /* the odd output point */
    EVAL_NODAL,     /* evaluate(): input map call, family switch, status */
    EVAL_MODAL,
    EVAL_ZHOU,
    MASK_WORD,      /* evaluate() loop 1: the output mask after zhou2017 */
    INPUT_PATH,     /* tfit_input_map(): straight-line code */
    BASIS_PATH,     /* tfit_basis() outside its loops, p >= 2 */
    BASIS_PATH_LOW, /* tfit_basis() outside its loops, p <= 1 (no T recurrence) */
    BASIS_T_STEP,   /* loop 1: one recurrence step T_i of the three variables, i = 2..p */
    BASIS_T_ENTRY,  /* ... minus what its first pass skips (M4F: entered mid-body) */
    BASIS_DEGREE,   /* loop 2: one degree d = 0..p */
    BASIS_E,        /* loop 3: one inner degree e = b + c = 0..d */
    BASIS_TERM,     /* loop 4: one term T_a(g0) (T_b(g1) T_c(g2)) */
    NODAL_PATH,     /* outside loops, p != 1 */
    NODAL_NODE,     /* loop 1: one output point, any p */
    NODAL_P0_SKIP,  /* ... minus the inner-loop set-up that p = 0 skips */
    NODAL_TERM,     /* loop 2: one basis term of the three rows */
    MODAL_PATH,     /* outside loops, r <= 8: the rows in assembly */
    MODAL_PATH_C,   /* outside loops, r > 8: the rows in C (loops 3, 4) */
    MODAL_AMP,      /* loop 1: one amplitude a_k */
    MODAL_AMP_P0_SKIP,
    MODAL_AMP_TERM, /* loop 2: one term of it */
    MODAL_NODE,     /* loop 3: one output point (r > 8) */
    MODAL_MODE,     /* loop 4: one mode of the three rows */
    MR_DISPATCH,    /* tfit_modal_rows_asm(): the rank's function, tail call */
    MR_PATH,        /* tfit_modal_rows_rR() outside its loop, without the r amplitude words */
    MR_POINT_1,     /* tfit_modal_rows_rR() loop 1: one output point at rank R */
    MR_POINT_2,
    MR_POINT_3,
    MR_POINT_4,
    MR_POINT_5,
    MR_POINT_6,
    MR_POINT_7,
    MR_POINT_8,
    ZHOU_PATH,
    ZHOU_AXIS,      /* loop 1: contact displacement of one force axis */
    ZHOU_AXIS_STEP, /* loop 2: one Clenshaw step of it (lambda_a of them) */
    ZHOU_AXIS_SETUP, /* ... the loop set-up in loop 1's body, which lambda_a = 0 skips */
    ZHOU_AXIS_STUB, /* ... the out-of-line code lambda_a = 0 runs instead */
    ZHOU_SURF_AXIS, /* loop 3: one force axis of the surfaces */
    ZHOU_PAIR,      /* loop 4: one (axis, component) pair */
    ZHOU_ROW,       /* loop 5: one surface coefficient p_i(t) */
    ZHOU_ROW_STEP,  /* loop 6: one Clenshaw step of it (k of them) */
    ZHOU_ROW_SETUP, /* ... its set-up in loop 5's body, which k = 0 skips */
    ZHOU_ROW_STUB,  /* ... the out-of-line code k = 0 runs instead */
    ZHOU_NODE,      /* loop 7: one output point of one surface, every part */
    ZHOU_X_STEP,    /* loop 8: one Clenshaw step in X (A of them) */
    ZHOU_X_SETUP,   /* ... its set-up in loop 7's body, which A = 0 skips */
    ZHOU_X_STUB,    /* ... the out-of-line code A = 0 runs instead */
    ZHOU_Y_STEP,    /* loop 9: one Clenshaw step in Y (B of them) */
    ZHOU_Y_PART,    /* ... the Y tail in loop 7's body outside loop 9 (B = 0 skips it) */
    ZHOU_SUM,       /* ... the superposition in loop 7's body (force axis x skips it) */
    STEP_ENTRY,     /* a Clenshaw loop is entered past its first instruction */
    STATEFUL_NODAL, /* one tick of a stateful model outside its filter and static map:
                     * tfit_prony_step or tfit_resonant_step (checks, tail call),
                     * tfit_stateful_step (projection and filter calls, the static
                     * map's view, status), tfit_stateful_eval to tfit_eval_nodal (p != 1) */
    STATEFUL_ROWS,  /* ... to tfit_degree1_rows_asm (nodal p = 1) */
    STATEFUL_MODAL, /* ... to tfit_eval_modal */
    PRONY_DISPATCH, /* tfit_stateful_step's call of the prony filter */
    PRONY_FILTER,   /* tfit_prony_filter() outside its loop, K >= 1 */
    PRONY_FILTER_SETUP, /* ... the loop's set-up and exit load, which K = 0 skips */
    PRONY_FILTER_STUB,  /* ... the out-of-line code K = 0 runs instead */
    PRONY_TERM,     /* loop 1: one term, three axes */
    RESONANT_DISPATCH, /* tfit_stateful_step's call of the resonant filter */
    RESONANT_FILTER, /* tfit_resonant_filter() outside its loop, K >= 1 (K = 0, no test
                      * model, would skip the loop's set-up: not modelled) */
    RESONANT_MODE,  /* tfit_resonant_filter loop 1: one mode, three axes */
    D1R_PATH,       /* tfit_degree1_rows_asm() outside its loops and the odd point */
    D1R_MAIN,       /* loop 1: eight pairs of output points */
    D1R_REM,        /* loop 2: one pair */
    CUT_ENTRY,      /* tfit_displacements_cut: checks, the calls, the status */
    CUT_PROGRESS,   /* tfit_cut_progress(): straight-line code */
    CUT_ROWS_D1,    /* tfit_cut_rows() outside its loops, p = 1 */
    CUT_D1_POINT,   /* loop 3: one output point at p = 1, both knots */
    CUT_ROWS_PATH,  /* tfit_cut_rows() outside its loops, p != 1 */
    CUT_POINT,      /* loop 1: one output point, any p */
    CUT_P0_SKIP,    /* ... minus the inner-loop set-up that p = 0 skips */
    CUT_TERM,       /* loop 2: one basis term of the six rows */
    EVAL_MODAL_Q15, /* evaluate(): the modal_q15 case */
    MQ_PATH,        /* tfit_eval_modal_q15(): the basis, the two assembly calls */
    MQA_PATH,       /* tfit_q15_amp_asm() outside its loop: set-up, conversion, packing */
    MQA_TERM,       /* loop 1: one basis term of the eight amplitudes */
    MQR_PATH,       /* tfit_q15_rows_asm() outside its loop, without the odd point */
    MQR_POINT,      /* the odd output point */
    MQR_PAIR,       /* loop 1: two output points */
    N_BLOCKS
} block_id;

typedef struct block {
    const char *function;
    int loop, depth;           /* 0: a path outside loops */
    const char *mix[TF_CORES]; /* M4F build, M7 build */
} block;

#define SAME(s) {s, s}

static const block blocks[N_BLOCKS] = {
    /* dims[0] != 1; a model of another family with dims[0] = 1 adds ENTRY_DIMS1 */
    [ENTRY_FORWARD] = {"tfit_displacements", 0, 0,
                       SAME("alu=12 load=2 ldm=2 stm=1 words=8 branch=2 nbranch=5")},
    [ENTRY_DIMS1] = {"tfit_displacements", 0, 0, SAME("alu=1 nbranch=1")},
    [ENTRY_CONTACT] = {"tfit_contact_force", 0, 0,
                       SAME("alu=5 load=2 ldm=2 stm=1 words=6 branch=1 nbranch=6")},
    [D1_ENTRY_FORWARD] = {"tfit_displacements", 0, 0,
                          SAME("alu=8 load=2 ldm=2 stm=1 words=8 branch=1 nbranch=6")},
    [D1_ENTRY_CONTACT] = {"tfit_contact_force", 0, 0,
                          SAME("alu=5 load=2 ldm=2 stm=1 words=6 branch=2 nbranch=5")},
    /* (objdump counts one more alu: the nop before its literal pool) */
    [D1_ONE] = {"tfit_degree1_one_asm", 0, 0,
                SAME("alu=52 load=2 ldm=1 ldm_pc=1 stm=1 words=11 fldm=2 fstm=1 fwords=27 "
                     "fadd=23 fmul=42 fother=3 fmov=11")},
    /* the three skips (no main iteration, no remaining pair, no odd point)
     * counted as falling through; d1_mix turns each one taken */
    [D1_PATH] = {"tfit_degree1_asm", 0, 0,
                 SAME("alu=58 load=3 ldm=1 ldm_pc=1 stm=1 words=11 fldm=2 fstm=1 fwords=36 "
                      "fadd=14 fmul=33 fother=3 fmov=11 nbranch=3")},
    [D1_MAIN] = {"tfit_degree1_asm", 1, 1,
                 SAME("alu=2 fldm=8 fstm=8 fwords=240 fadd=144 fmul=144 branch=1")},
    [D1_REM] = {"tfit_degree1_asm", 2, 1,
                SAME("alu=1 fldm=1 fstm=1 fwords=30 fadd=18 fmul=18 branch=1")},
    [D1_POINT] = {"tfit_degree1_asm", 0, 0, SAME("fldm=1 fstm=1 fwords=15 fadd=9 fmul=9")},
    [EVAL_NODAL] = {"evaluate", 0, 0, SAME("alu=18 load=4 ldm_pc=1 stm=1 words=10 branch=2 nbranch=2")},
    [EVAL_MODAL] = {"evaluate", 0, 0, SAME("alu=17 load=4 ldm_pc=1 stm=1 words=10 branch=4")},
    [EVAL_ZHOU] = {"evaluate", 0, 0, SAME("alu=21 load=5 ldm_pc=1 stm=1 words=10 branch=4 nbranch=2")},
    [MASK_WORD] = {"evaluate", 1, 1, SAME("alu=3 load=1 store=1 branch=1")},
    [INPUT_PATH] = {"tfit_input_map", 0, 0,
                    {"alu=81 load=2 store=1 ldm=1 ldm_pc=1 stm=1 words=8 fload=12 fstore=3 "
                     "fldm=1 fstm=1 fwords=4 fadd=14 fmul=33 fother=4 fmov=14",
                     "alu=81 load=2 store=1 ldm=1 ldm_pc=1 stm=1 words=12 fload=12 fstore=3 "
                     "fldm=1 fstm=1 fwords=4 fadd=14 fmul=33 fother=4 fmov=14"}},
    [BASIS_PATH] = {"tfit_basis", 0, 0, /* the M4F enters loop 1 with a branch */
                    {"alu=14 ldm_pc=1 stm=1 words=14 fload=3 fstore=6 fadd=3 fother=3 branch=1 "
                     "nbranch=1",
                     "alu=14 ldm_pc=1 stm=1 words=14 fload=3 fstore=6 fadd=3 fother=3 nbranch=1"}},
    [BASIS_PATH_LOW] = {"tfit_basis", 0, 0,
                        SAME("alu=10 ldm_pc=1 stm=1 words=14 fload=3 fstore=6 fadd=3 fother=1 "
                             "branch=2")},
    [BASIS_T_STEP] = {"tfit_basis", 1, 1,
                      SAME("alu=1 fstm=3 fwords=3 fadd=3 fmul=3 fother=6 branch=1")},
    [BASIS_T_ENTRY] = {"tfit_basis", 0, 0, {"fother=2", ""}},
    [BASIS_DEGREE] = {"tfit_basis", 2, 1, SAME("alu=6 branch=1")},
    [BASIS_E] = {"tfit_basis", 3, 2, SAME("alu=8 fldm=1 fwords=1 branch=1")},
    [BASIS_TERM] = {"tfit_basis", 4, 3, SAME("alu=1 fldm=2 fstm=1 fwords=3 fmul=2 branch=1")},
    [NODAL_PATH] = {"tfit_eval_nodal", 0, 0,
                    SAME("alu=21 mul=2 mla=1 load=5 store=1 ldm_pc=1 stm=1 words=18 branch=1 "
                         "nbranch=1")},
    [NODAL_NODE] = {"tfit_eval_nodal", 1, 1, SAME("alu=17 load=1 store=3 fload=3 fmov=3 branch=1 "
                                                          "nbranch=1")},
    [NODAL_P0_SKIP] = {"tfit_eval_nodal", 0, 0, SAME("alu=5")},
    [NODAL_TERM] = {"tfit_eval_nodal", 2, 2, SAME("alu=2 fldm=4 fwords=4 fadd=3 fmul=3 branch=1")},
    [MODAL_PATH] = {"tfit_eval_modal", 0, 0,
                    SAME("alu=23 mul=3 mla=1 load=6 store=2 ldm=2 ldm_pc=1 stm=2 words=24 branch=3 "
                         "nbranch=1")},
    [MODAL_PATH_C] = {"tfit_eval_modal", 0, 0,
                      SAME("alu=31 mul=3 mla=1 load=6 ldm=2 ldm_pc=1 stm=2 words=24 fload=1 "
                           "branch=1 nbranch=3")},
    [MODAL_AMP] = {"tfit_eval_modal", 1, 1,
                   SAME("alu=7 store=1 fload=1 fmov=1 branch=1 nbranch=1")},
    [MODAL_AMP_P0_SKIP] = {"tfit_eval_modal", 0, 0, SAME("alu=3")},
    [MODAL_AMP_TERM] = {"tfit_eval_modal", 2, 2,
                        SAME("alu=2 fldm=2 fwords=2 fadd=1 fmul=1 branch=1")},
    [MODAL_NODE] = {"tfit_eval_modal", 3, 1, SAME("alu=14 store=3 fload=3 fmul=3 fmov=3 branch=1")},
    [MODAL_MODE] = {"tfit_eval_modal", 4, 2, SAME("alu=1 fldm=4 fwords=4 fadd=3 fmul=3 branch=1")},
    /* (objdump counts one more alu in each: the nop before the literal
     * pool, or after the return) */
    [MR_DISPATCH] = {"tfit_modal_rows_asm", 0, 0,
                     {"alu=12 load=5 store=1 ldm=1 stm=1 words=6 branch=1",
                      "alu=12 load=5 store=1 ldm=1 stm=1 words=4 branch=1"}},
    [MR_PATH] = {"tfit_modal_rows_rR", 0, 0,
                 SAME("alu=3 load=2 stm=1 words=1 fldm=2 fstm=1 fwords=32")},
    /* 3r words in, 3 out; 3r multiplications, 3(r - 1) additions */
    [MR_POINT_1] = {"tfit_modal_rows_r1", 1, 1, SAME("alu=2 fldm=1 fstm=1 fwords=6 fmul=3 branch=1")},
    [MR_POINT_2] = {"tfit_modal_rows_r2", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=9 fadd=3 fmul=6 branch=1")},
    [MR_POINT_3] = {"tfit_modal_rows_r3", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=12 fadd=6 fmul=9 branch=1")},
    [MR_POINT_4] = {"tfit_modal_rows_r4", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=15 fadd=9 fmul=12 branch=1")},
    [MR_POINT_5] = {"tfit_modal_rows_r5", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=18 fadd=12 fmul=15 branch=1")},
    [MR_POINT_6] = {"tfit_modal_rows_r6", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=21 fadd=15 fmul=18 branch=1")},
    [MR_POINT_7] = {"tfit_modal_rows_r7", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=24 fadd=18 fmul=21 branch=1")},
    [MR_POINT_8] = {"tfit_modal_rows_r8", 1, 1,
                    SAME("alu=2 fldm=1 fstm=1 fwords=27 fadd=21 fmul=24 branch=1")},
    [ZHOU_PATH] = {"tfit_eval_zhou2017", 0, 0,
                   {"alu=16 load=3 store=5 ldm=1 ldm_pc=1 stm=1 words=20 fload=2",
                    "alu=17 load=3 store=5 ldm=1 ldm_pc=1 stm=1 words=20 fload=2"}},
    [ZHOU_AXIS] = {"tfit_eval_zhou2017", 1, 1,
                   SAME("alu=6 load=1 fload=1 fldm=2 fstm=1 fwords=3 fadd=3 fmul=2 fother=2 "
                        "branch=2 nbranch=1")},
    [ZHOU_AXIS_STEP] = {"tfit_eval_zhou2017", 2, 2,
                        SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_AXIS_SETUP] = {"tfit_eval_zhou2017", 0, 0, SAME("alu=3 fother=2 branch=1")},
    [ZHOU_AXIS_STUB] = {"tfit_eval_zhou2017", 0, 0, SAME("alu=1 fload=1 fother=1 branch=1")},
    [ZHOU_SURF_AXIS] = {"tfit_eval_zhou2017", 3, 1, SAME("alu=8 load=2 store=2 branch=1")},
    [ZHOU_PAIR] = {"tfit_eval_zhou2017", 4, 2,
                   SAME("alu=25 mla=1 load=9 store=3 ldm=1 words=2 fload=2 fadd=1 branch=1 "
                        "nbranch=2")},
    [ZHOU_ROW] = {"tfit_eval_zhou2017", 5, 3,
                  SAME("alu=4 fload=1 fstm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=2 "
                       "nbranch=1")},
    [ZHOU_ROW_STEP] = {"tfit_eval_zhou2017", 6, 4,
                       SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_ROW_SETUP] = {"tfit_eval_zhou2017", 0, 0, SAME("alu=1 fother=2 branch=1")},
    [ZHOU_ROW_STUB] = {"tfit_eval_zhou2017", 0, 0, SAME("fother=2 branch=1")},
    [ZHOU_NODE] = {"tfit_eval_zhou2017", 7, 3,
                   SAME("alu=7 fload=3 fstore=1 fadd=7 fmul=2 fother=4 branch=3 nbranch=3")},
    [ZHOU_X_STEP] = {"tfit_eval_zhou2017", 8, 4,
                     SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_X_SETUP] = {"tfit_eval_zhou2017", 0, 0, SAME("alu=1 fother=2 branch=1")},
    [ZHOU_X_STUB] = {"tfit_eval_zhou2017", 0, 0, SAME("fother=2 branch=1")},
    [ZHOU_Y_STEP] = {"tfit_eval_zhou2017", 9, 4,
                     SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_Y_PART] = {"tfit_eval_zhou2017", 0, 0,
                     SAME("alu=1 fload=1 fadd=3 fmul=1 fother=2 branch=1")},
    [ZHOU_SUM] = {"tfit_eval_zhou2017", 0, 0, SAME("fload=1 fadd=1")},
    [STEP_ENTRY] = {"tfit_eval_zhou2017", 0, 0, SAME("fother=1")},
    /* measured as the QEMU trace less the projection, the filter and the
     * static map's evaluator, the same for every stateful test model of
     * each kind of static map */
    [STATEFUL_NODAL] = {"tfit_stateful_step", 0, 0,
                        {"alu=53 mul=1 load=23 store=6 ldm=3 ldm_pc=1 stm=5 words=28 branch=6 nbranch=7",
                         "alu=53 mul=1 load=23 store=8 ldm=3 ldm_pc=1 stm=4 words=24 branch=6 nbranch=7"}},
    [STATEFUL_ROWS] = {"tfit_stateful_step", 0, 0,
                       {"alu=56 mul=1 load=25 store=7 ldm=2 ldm_pc=2 stm=5 words=28 branch=7 nbranch=6",
                        "alu=56 mul=1 load=25 store=9 ldm=2 ldm_pc=2 stm=4 words=24 branch=7 nbranch=6"}},
    [STATEFUL_MODAL] = {"tfit_stateful_step", 0, 0,
                        {"alu=51 mul=1 load=21 store=6 ldm=3 ldm_pc=1 stm=5 words=28 branch=7 nbranch=5",
                         "alu=51 mul=1 load=21 store=8 ldm=3 ldm_pc=1 stm=4 words=24 branch=7 nbranch=5"}},
    /* the family test falls through to the prony filter's call, and
     * branches to the resonant one's and back */
    [PRONY_DISPATCH] = {"tfit_stateful_step", 0, 0, SAME("branch=1 nbranch=1")},
    [PRONY_FILTER] = {"tfit_prony_filter", 0, 0,
                      SAME("alu=52 load=4 store=5 ldm=1 ldm_pc=1 stm=1 words=10 fload=7 fstore=1 "
                           "fadd=3 fmov=3 nbranch=1")},
    [PRONY_FILTER_SETUP] = {"tfit_prony_filter", 0, 0, SAME("alu=6 fload=1")},
    [PRONY_FILTER_STUB] = {"tfit_prony_filter", 0, 0, SAME("fother=1 branch=1")},
    [PRONY_TERM] = {"tfit_prony_filter", 1, 1,
                    SAME("alu=5 fload=5 fstore=3 fadd=6 fmul=6 branch=1")},
    [RESONANT_DISPATCH] = {"tfit_stateful_step", 0, 0, SAME("branch=3")},
    [RESONANT_FILTER] = {"tfit_resonant_filter", 0, 0,
                         SAME("alu=52 load=4 store=5 ldm=1 ldm_pc=1 stm=1 words=10 fload=7 "
                              "fstore=1 fldm=1 fstm=1 fwords=8 fadd=3 fmov=3 nbranch=1")},
    [RESONANT_MODE] = {"tfit_resonant_filter", 1, 1,
                       SAME("alu=5 fload=13 fstore=6 fadd=12 fmul=15 branch=1")},
    [D1R_PATH] = {"tfit_degree1_rows_asm", 0, 0,
                  SAME("alu=12 load=2 ldm_pc=1 stm=1 words=8 fldm=2 fstm=1 fwords=27 nbranch=3")},
    [D1R_MAIN] = {"tfit_degree1_rows_asm", 1, 1,
                  SAME("alu=2 fldm=8 fstm=8 fwords=240 fadd=144 fmul=144 branch=1")},
    [D1R_REM] = {"tfit_degree1_rows_asm", 2, 1,
                 SAME("alu=1 fldm=1 fstm=1 fwords=30 fadd=18 fmul=18 branch=1")},
    [CUT_ENTRY] = {"tfit_displacements_cut", 0, 0,
                   {"alu=33 load=9 store=4 ldm=1 ldm_pc=1 stm=1 words=16 fload=1 fldm=1 fstm=1 "
                    "fwords=4 fother=2 branch=4 nbranch=5",
                    "alu=33 load=9 store=4 ldm=1 ldm_pc=1 stm=1 words=16 fload=1 fldm=1 fstm=1 "
                    "fwords=4 fother=2 branch=4 nbranch=5"}},
    [CUT_PROGRESS] = {"tfit_cut_progress", 0, 0,
                      SAME("alu=31 load=1 store=2 ldm_pc=1 stm=1 words=8 fstore=2 fadd=1 fmul=1 "
                           "fother=6 fmov=8")},
    [CUT_ROWS_D1] = {"tfit_cut_rows", 0, 0,
                     {"alu=15 mul=4 mla=2 load=10 store=2 ldm_pc=1 stm=1 words=18 fload=3 fldm=1 "
                      "fstm=1 fwords=16 branch=1 nbranch=1",
                      "alu=15 mul=4 mla=2 load=10 store=2 ldm_pc=1 stm=1 words=18 fload=3 fldm=1 "
                      "fstm=1 fwords=12 branch=1 nbranch=1"}},
    [CUT_D1_POINT] = {"tfit_cut_rows", 3, 1,
                      SAME("alu=8 store=3 fload=24 fadd=24 fmul=21 fmov=3 branch=1")},
    [CUT_ROWS_PATH] = {"tfit_cut_rows", 0, 0,
                       {"alu=28 mul=4 mla=2 load=8 store=10 ldm_pc=1 stm=1 words=18 fldm=1 fstm=1 "
                        "fwords=16 nbranch=2",
                        "alu=28 mul=4 mla=2 load=8 store=10 ldm_pc=1 stm=1 words=18 fldm=1 fstm=1 "
                        "fwords=12 nbranch=2"}},
    [CUT_POINT] = {"tfit_cut_rows", 1, 1,
                   SAME("alu=22 load=11 store=4 fload=6 fadd=6 fmul=3 fmov=3 branch=1 nbranch=1")},
    [CUT_P0_SKIP] = {"tfit_cut_rows", 0, 0, SAME("alu=8 load=5")},
    [CUT_TERM] = {"tfit_cut_rows", 2, 2, SAME("alu=2 fldm=7 fwords=7 fadd=6 fmul=6 branch=1")},
    /* modal_q15 (tfit_modal_q15.c, tfit_modal_q15_armv7em.c); objdump
     * counts one more alu in each path: the nop after the return */
    /* forward_other() instead of evaluate(), reached by the branch of
     * tfit_displacements' family test that families 1-3 fall through */
    [EVAL_MODAL_Q15] = {"forward_other", 0, 0, SAME("alu=16 load=4 ldm_pc=1 stm=1 words=8 branch=3")},
    [MQ_PATH] = {"tfit_eval_modal_q15", 0, 0,
                 {"alu=22 mul=2 mla=1 load=7 store=2 ldm_pc=1 stm=1 words=16 fload=1 branch=3",
                  "alu=22 mul=2 mla=1 load=7 store=2 ldm_pc=1 stm=1 words=18 fload=1 branch=3"}},
    [MQA_PATH] = {"tfit_q15_amp_asm", 0, 0,
                  SAME("alu=24 ldm=2 stm=2 words=21 fldm=3 fstm=1 fwords=32 fmul=8 fother=9 "
                       "fmov=7 branch=1")},
    [MQA_TERM] = {"tfit_q15_amp_asm", 1, 1, SAME("alu=1 fldm=2 fwords=9 fadd=8 fmul=8 branch=1")},
    /* both skips (no odd point, no pair) counted as falling through */
    [MQR_PATH] = {"tfit_q15_rows_asm", 0, 0,
                  SAME("alu=4 load=1 ldm=2 ldm_pc=1 stm=1 words=22 nbranch=2")},
    [MQR_POINT] = {"tfit_q15_rows_asm", 0, 0,
                   SAME("alu=12 ldm=3 words=12 fstm=1 fwords=3 fmul=3 fother=3 fmov=3")},
    [MQR_PAIR] = {"tfit_q15_rows_asm", 1, 1,
                  SAME("alu=25 ldm=6 words=24 fstm=2 fwords=6 fmul=6 fother=6 fmov=6 branch=1")},
};

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

static void add_block(tf_insn_mix *total, tf_core core, block_id b, uint64_t times)
{
    add_mix(total, blocks[b].mix[core], times);
}

static void sub_block(tf_insn_mix *total, tf_core core, block_id b, uint64_t times)
{
    tf_insn_mix m;
    tf_insn_mix_parse(blocks[b].mix[core], &m);
    for (int c = 0; c < TF_INSN_CLASSES; ++c) {
        total->n[c] -= (unsigned)(m.n[c] * times);
    }
}

/* n conditional branches that fall through instead of being taken (a
 * loop's last back edge, a skip not taken), or the reverse. */
static void falls_through(tf_insn_mix *t, uint64_t n)
{
    add_mix(t, "nbranch=1", n);
    t->n[TF_INSN_BRANCH] -= (unsigned)n;
}

static void taken(tf_insn_mix *t, uint64_t n)
{
    add_mix(t, "branch=1", n);
    t->n[TF_INSN_NBRANCH] -= (unsigned)n;
}

/* A loop block run n times: its back edge falls through the last time. */
static void add_loop(tf_insn_mix *t, tf_core core, block_id b, uint64_t n)
{
    add_block(t, core, b, n);
    if (n > 0) {
        falls_through(t, 1);
    }
}

/* Degree 1 (tfit_degree1_armv7em.c): n_out / 16 iterations of eight
 * pairs, then (n_out / 2) mod 8 single pairs, then the odd point; each
 * part skipped by a taken branch when empty.  path, main and rem: the
 * blocks of tfit_degree1_asm or of tfit_degree1_rows_asm (the same loops). */
static void d1_loops(tf_insn_mix *t, tf_core core, uint32_t n_out, block_id path, block_id main,
                     block_id rem)
{
    add_block(t, core, path, 1);
    const uint32_t iterations = n_out >> 4, pairs = (n_out >> 1) & 7u;
    add_loop(t, core, main, iterations);
    add_loop(t, core, rem, pairs);
    taken(t, (iterations == 0) + (pairs == 0) + !(n_out & 1u));
    if (n_out & 1u) {
        add_block(t, core, D1_POINT, 1);
    }
}

static void d1_mix(tf_insn_mix *t, tf_core core, uint32_t n_out)
{
    d1_loops(t, core, n_out, D1_PATH, D1_MAIN, D1_REM);
}

static void basis_mix(tf_insn_mix *t, tf_core core, uint32_t p)
{
    if (p <= 1) {
        add_block(t, core, BASIS_PATH_LOW, 1);
    } else {
        add_block(t, core, BASIS_PATH, 1);
        add_loop(t, core, BASIS_T_STEP, p - 1);
        sub_block(t, core, BASIS_T_ENTRY, 1);
    }
    add_loop(t, core, BASIS_DEGREE, p + 1);
    /* loop 3 entered once per degree, loop 4 once per (degree, e) */
    add_block(t, core, BASIS_E, (uint64_t)(p + 1) * (p + 2) / 2);
    falls_through(t, p + 1);
    add_block(t, core, BASIS_TERM, tf_terms(p));
    falls_through(t, (uint64_t)(p + 1) * (p + 2) / 2);
}

/* tfit_eval_nodal, called by evaluate() or tfit_stateful_eval */
static void nodal_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    uint32_t p = m->dims[0], terms = tf_terms(p);
    basis_mix(t, core, p);
    add_block(t, core, NODAL_PATH, 1);
    add_loop(t, core, NODAL_NODE, m->n_out);
    add_block(t, core, NODAL_TERM, (uint64_t)m->n_out * (terms - 1));
    if (p == 0) { /* the term loop is skipped, by a taken branch */
        sub_block(t, core, NODAL_P0_SKIP, m->n_out);
        taken(t, m->n_out);
    } else {
        falls_through(t, m->n_out);
    }
}

/* Ranks whose rows run in assembly: TFIT_MODAL_ASM_MAX_RANK of
 * target/src/tfit_internal.h. */
#define MODAL_ASM_MAX_RANK 8u

/* The rows of a modal model of rank r <= 8 in assembly
 * (tfit_modal_armv7em.c): the dispatch, the rank's function (its path loads
 * the r amplitudes with one VLDM) and its loop over the output points. */
static void modal_rows_asm_mix(tf_insn_mix *t, tf_core core, uint32_t r, uint32_t n_out)
{
    add_block(t, core, MR_DISPATCH, 1);
    add_block(t, core, MR_PATH, 1);
    t->n[TF_INSN_FWORDS] += r;
    add_loop(t, core, (block_id)(MR_POINT_1 + (r - 1)), n_out);
}

/* tfit_eval_modal, called by evaluate() or tfit_stateful_eval: the basis, the
 * r amplitudes (loops 1, 2), then the rows in assembly (r <= 8) or in C
 * (loops 3, 4: r > 8, so the mode loop always runs) */
static void modal_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    uint32_t p = m->dims[0], r = m->dims[1], terms = tf_terms(p);
    basis_mix(t, core, p);
    add_block(t, core, r <= MODAL_ASM_MAX_RANK ? MODAL_PATH : MODAL_PATH_C, 1);
    add_loop(t, core, MODAL_AMP, r);
    add_block(t, core, MODAL_AMP_TERM, (uint64_t)r * (terms - 1));
    if (p == 0) { /* skipped by a taken branch */
        sub_block(t, core, MODAL_AMP_P0_SKIP, r);
        taken(t, r);
    } else {
        falls_through(t, r);
    }
    if (r <= MODAL_ASM_MAX_RANK) {
        modal_rows_asm_mix(t, core, r, m->n_out);
        return;
    }
    add_loop(t, core, MODAL_NODE, m->n_out);
    add_block(t, core, MODAL_MODE, (uint64_t)m->n_out * (r - 1));
    falls_through(t, m->n_out);
}

/* tfit_eval_modal_q15: the basis (p >= 1), the amplitudes term by term
 * (T - 1 iterations), then the rows: the odd point, then n_out / 2 pairs,
 * each part skipped by a taken branch when empty. */
static void modal_q15_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    const uint32_t p = m->dims[0], pairs = m->n_out >> 1;
    basis_mix(t, core, p);
    add_block(t, core, MQ_PATH, 1);
    add_block(t, core, MQA_PATH, 1);
    add_loop(t, core, MQA_TERM, tf_terms(p) - 1);
    add_block(t, core, MQR_PATH, 1);
    if (m->n_out & 1u) {
        add_block(t, core, MQR_POINT, 1);
    }
    add_loop(t, core, MQR_PAIR, pairs);
    taken(t, !(m->n_out & 1u) + (pairs == 0));
}

/* One inlined Clenshaw series of order n (tfit_cheb): the enclosing loop
 * body holds the set-up of its step loop; n >= 1 runs n steps, entering the
 * loop past its first instruction (a register move); n = 0 branches past
 * the set-up and the loop to an out-of-line stub and back (the test that
 * falls through for n >= 1 is then taken). */
static void clenshaw_mix(tf_insn_mix *t, tf_core core, uint32_t n, uint64_t times, block_id step,
                         block_id setup, block_id stub)
{
    if (n == 0) {
        sub_block(t, core, setup, times);
        add_block(t, core, stub, times);
        taken(t, times);
        return;
    }
    add_block(t, core, step, times * n);
    sub_block(t, core, STEP_ENTRY, times);
    falls_through(t, times);
}

static void zhou_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    const uint32_t *d = m->dims;
    const uint64_t n = m->n_out;
    add_block(t, core, EVAL_ZHOU, 1);
    add_loop(t, core, MASK_WORD, 3 * n);
    add_block(t, core, ZHOU_PATH, 1);
    add_loop(t, core, ZHOU_AXIS, 3);
    add_loop(t, core, ZHOU_SURF_AXIS, 3);
    for (int a = 0; a < 3; ++a) {
        clenshaw_mix(t, core, d[a], 1, ZHOU_AXIS_STEP, ZHOU_AXIS_SETUP, ZHOU_AXIS_STUB);
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = d[3 + 3 * pair], by = d[4 + 3 * pair], k = d[5 + 3 * pair];
        uint64_t rows = (uint64_t)ax + by + 1;
        add_block(t, core, ZHOU_PAIR, 1);
        if (pair % 3 == 2) { /* the pair loop's back edge, once per force axis */
            falls_through(t, 1);
        }
        add_loop(t, core, ZHOU_ROW, rows);
        clenshaw_mix(t, core, k, rows, ZHOU_ROW_STEP, ZHOU_ROW_SETUP, ZHOU_ROW_STUB);
        add_loop(t, core, ZHOU_NODE, n);
        clenshaw_mix(t, core, ax, n, ZHOU_X_STEP, ZHOU_X_SETUP, ZHOU_X_STUB);
        if (by == 0) { /* the Y part skipped by a taken branch */
            sub_block(t, core, ZHOU_Y_PART, n);
            taken(t, n);
        } else {
            add_block(t, core, ZHOU_Y_STEP, n * by);
            sub_block(t, core, STEP_ENTRY, n);
            falls_through(t, n);
        }
        if (pair < 3) { /* force axis x stores instead of adding: a taken branch */
            sub_block(t, core, ZHOU_SUM, n);
            taken(t, n);
        }
    }
}

/* One tick of a stateful model (tfit_stateful.c): the entry point and the
 * step's path for its static map's kind, the projection, the filter (the
 * dispatch, its function's path and loop), then the static map's
 * evaluator, or at p = 1 the rows of tfit_degree1_rows_asm. */
static void stateful_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    const tf_model v = tf_stateful_static_view(m);
    const uint32_t terms = m->dims[2];
    add_block(t, core, INPUT_PATH, 1);
    if (m->family == TFIT_FAMILY_PRONY) {
        add_block(t, core, PRONY_DISPATCH, 1);
        add_block(t, core, PRONY_FILTER, 1);
        add_loop(t, core, PRONY_TERM, terms);
        if (terms == 0) {
            sub_block(t, core, PRONY_FILTER_SETUP, 1);
            add_block(t, core, PRONY_FILTER_STUB, 1);
            taken(t, 1);
        }
    } else {
        add_block(t, core, RESONANT_DISPATCH, 1);
        add_block(t, core, RESONANT_FILTER, 1);
        add_loop(t, core, RESONANT_MODE, terms);
    }
    if (v.family == TFIT_FAMILY_MODAL) {
        add_block(t, core, STATEFUL_MODAL, 1);
        modal_mix(t, core, &v);
    } else if (v.dims[0] != 1) {
        add_block(t, core, STATEFUL_NODAL, 1);
        nodal_mix(t, core, &v);
    } else {
        add_block(t, core, STATEFUL_ROWS, 1);
        d1_loops(t, core, v.n_out, D1R_PATH, D1R_MAIN, D1R_REM);
    }
}

/* A cut model (tfit_cut.c): the entry, the projection, the progress, the
 * basis, then the rows of both knots per output point: at p = 1 loop 3,
 * else loop 1 with its term loop (which p = 0 skips by a taken branch). */
static void cut_mix(tf_insn_mix *t, tf_core core, const tf_model *m)
{
    const uint32_t p = m->dims[0], terms = tf_terms(p);
    add_block(t, core, CUT_ENTRY, 1);
    add_block(t, core, INPUT_PATH, 1);
    add_block(t, core, CUT_PROGRESS, 1);
    basis_mix(t, core, p);
    if (p == 1) {
        add_block(t, core, CUT_ROWS_D1, 1);
        add_loop(t, core, CUT_D1_POINT, m->n_out);
        return;
    }
    add_block(t, core, CUT_ROWS_PATH, 1);
    add_loop(t, core, CUT_POINT, m->n_out);
    if (p == 0) {
        sub_block(t, core, CUT_P0_SKIP, m->n_out);
        taken(t, m->n_out);
    } else {
        add_block(t, core, CUT_TERM, (uint64_t)m->n_out * (terms - 1));
        falls_through(t, m->n_out);
    }
}

void tf_cycles_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    memset(mix, 0, sizeof *mix);
    if (m->family == TFIT_FAMILY_CUT) {
        cut_mix(mix, core, m);
        return;
    }
    if (m->family == TFIT_FAMILY_PRONY || m->family == TFIT_FAMILY_RESONANT) {
        stateful_mix(mix, core, m);
        return;
    }
    const int contact = m->family == TFIT_FAMILY_CONTACT;
    if ((contact || m->family == TFIT_FAMILY_NODAL) && m->dims[0] == 1) {
        /* the degree-1 fast paths, tfit_eval.c */
        add_block(mix, core, contact ? D1_ENTRY_CONTACT : D1_ENTRY_FORWARD, 1);
        if (contact) {
            add_block(mix, core, D1_ONE, 1);
        } else {
            d1_mix(mix, core, m->n_out);
        }
        return;
    }
    add_block(mix, core, INPUT_PATH, 1);
    add_block(mix, core, contact ? ENTRY_CONTACT : ENTRY_FORWARD, 1);
    if (!contact && m->dims[0] == 1) {
        add_block(mix, core, ENTRY_DIMS1, 1);
    }
    switch (m->family) {
    case TFIT_FAMILY_MODAL:
        add_block(mix, core, EVAL_MODAL, 1);
        modal_mix(mix, core, m);
        break;
    case TFIT_FAMILY_ZHOU2017:
        zhou_mix(mix, core, m);
        break;
    case TFIT_FAMILY_MODAL_Q15:
        add_block(mix, core, EVAL_MODAL_Q15, 1);
        modal_q15_mix(mix, core, m);
        break;
    default:
        add_block(mix, core, EVAL_NODAL, 1);
        nodal_mix(mix, core, m);
        break;
    }
}

size_t tf_cycles_loop_table(tf_core core, char *buf, size_t n)
{
    size_t k = 0;
    for (int b = 0; b < N_BLOCKS; ++b) {
        if (blocks[b].loop > 0) {
            /* objdump cannot tell a taken branch from one that falls through */
            tf_insn_mix m;
            char text[512];
            tf_insn_mix_parse(blocks[b].mix[core], &m);
            m.n[TF_INSN_BRANCH] += m.n[TF_INSN_NBRANCH];
            m.n[TF_INSN_NBRANCH] = 0;
            tf_insn_mix_format(&m, text, sizeof text);
            int w = snprintf(buf + (k < n ? k : n), k < n ? n - k : 0, "%s loop %d depth %d: %s\n",
                             blocks[b].function, blocks[b].loop, blocks[b].depth, text);
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

tf_cycles tf_cycles_estimate(const tf_model *m, tf_core core)
{
    tf_insn_mix mix;
    tf_cycles_mix(m, core, &mix);
    return tf_cycles_of_mix(&mix, core);
}
