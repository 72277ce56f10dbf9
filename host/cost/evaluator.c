/*
 * evaluator.c — see evaluator.h.  Each block is a piece of the library as
 * arm-none-eabi-gcc 12.2 -O2 compiles it (target/target.mk), its mix
 * counted from objdump (loops) or measured from the QEMU traces (paths).
 */
#include "cost/evaluator.h"

typedef enum block_id {
    ENTRY_FORWARD,  /* tfit_displacements: argument and family checks, tail call */
    ENTRY_DIMS1,    /* ... a family other than nodal with dims[0] = 1 tests the family too */
    EVAL_NODAL,     /* evaluate(): input map call, family switch, status */
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
    D1_PATH,        /* tfit_degree1_asm() outside its loops and the odd point */
    D1_MAIN,        /* loop 1: eight pairs of output points */
    D1_REM,         /* loop 2: one pair of output points */
    D1_POINT,       /* the odd output point */
    D1R_PATH,       /* tfit_degree1_rows_asm() outside its loops and the odd point */
    D1R_MAIN,       /* loop 1: eight pairs of output points */
    D1R_REM,        /* loop 2: one pair */
    N_BLOCKS
} block_id;

const tf_block tf_insn_shared[N_BLOCKS] = {
    /* dims[0] != 1; a model of another family with dims[0] = 1 adds ENTRY_DIMS1 */
    [ENTRY_FORWARD] = {"tfit_displacements", 0, 0,
                       TF_SAME("alu=12 load=2 ldm=2 stm=1 words=8 branch=2 nbranch=5")},
    [ENTRY_DIMS1] = {"tfit_displacements", 0, 0, TF_SAME("alu=1 nbranch=1")},
    [EVAL_NODAL] = {"evaluate", 0, 0, TF_SAME("alu=18 load=4 ldm_pc=1 stm=1 words=10 branch=2 nbranch=2")},
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
                        TF_SAME("alu=10 ldm_pc=1 stm=1 words=14 fload=3 fstore=6 fadd=3 fother=1 "
                             "branch=2")},
    [BASIS_T_STEP] = {"tfit_basis", 1, 1,
                      TF_SAME("alu=1 fstm=3 fwords=3 fadd=3 fmul=3 fother=6 branch=1")},
    [BASIS_T_ENTRY] = {"tfit_basis", 0, 0, {"fother=2", ""}},
    [BASIS_DEGREE] = {"tfit_basis", 2, 1, TF_SAME("alu=6 branch=1")},
    [BASIS_E] = {"tfit_basis", 3, 2, TF_SAME("alu=8 fldm=1 fwords=1 branch=1")},
    [BASIS_TERM] = {"tfit_basis", 4, 3, TF_SAME("alu=1 fldm=2 fstm=1 fwords=3 fmul=2 branch=1")},
    [NODAL_PATH] = {"tfit_eval_nodal", 0, 0,
                    TF_SAME("alu=21 mul=2 mla=1 load=5 store=1 ldm_pc=1 stm=1 words=18 branch=1 "
                         "nbranch=1")},
    [NODAL_NODE] = {"tfit_eval_nodal", 1, 1, TF_SAME("alu=17 load=1 store=3 fload=3 fmov=3 branch=1 "
                                                          "nbranch=1")},
    [NODAL_P0_SKIP] = {"tfit_eval_nodal", 0, 0, TF_SAME("alu=5")},
    [NODAL_TERM] = {"tfit_eval_nodal", 2, 2, TF_SAME("alu=2 fldm=4 fwords=4 fadd=3 fmul=3 branch=1")},
    [MODAL_PATH] = {"tfit_eval_modal", 0, 0,
                    TF_SAME("alu=23 mul=3 mla=1 load=6 store=2 ldm=2 ldm_pc=1 stm=2 words=24 branch=3 "
                         "nbranch=1")},
    [MODAL_PATH_C] = {"tfit_eval_modal", 0, 0,
                      TF_SAME("alu=31 mul=3 mla=1 load=6 ldm=2 ldm_pc=1 stm=2 words=24 fload=1 "
                           "branch=1 nbranch=3")},
    [MODAL_AMP] = {"tfit_eval_modal", 1, 1,
                   TF_SAME("alu=7 store=1 fload=1 fmov=1 branch=1 nbranch=1")},
    [MODAL_AMP_P0_SKIP] = {"tfit_eval_modal", 0, 0, TF_SAME("alu=3")},
    [MODAL_AMP_TERM] = {"tfit_eval_modal", 2, 2,
                        TF_SAME("alu=2 fldm=2 fwords=2 fadd=1 fmul=1 branch=1")},
    [MODAL_NODE] = {"tfit_eval_modal", 3, 1, TF_SAME("alu=14 store=3 fload=3 fmul=3 fmov=3 branch=1")},
    [MODAL_MODE] = {"tfit_eval_modal", 4, 2, TF_SAME("alu=1 fldm=4 fwords=4 fadd=3 fmul=3 branch=1")},
    /* (objdump counts one more alu in each: the nop before the literal
     * pool, or after the return) */
    [MR_DISPATCH] = {"tfit_modal_rows_asm", 0, 0,
                     {"alu=12 load=5 store=1 ldm=1 stm=1 words=6 branch=1",
                      "alu=12 load=5 store=1 ldm=1 stm=1 words=4 branch=1"}},
    [MR_PATH] = {"tfit_modal_rows_rR", 0, 0,
                 TF_SAME("alu=3 load=2 stm=1 words=1 fldm=2 fstm=1 fwords=32")},
    /* 3r words in, 3 out; 3r multiplications, 3(r - 1) additions */
    [MR_POINT_1] = {"tfit_modal_rows_r1", 1, 1, TF_SAME("alu=2 fldm=1 fstm=1 fwords=6 fmul=3 branch=1")},
    [MR_POINT_2] = {"tfit_modal_rows_r2", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=9 fadd=3 fmul=6 branch=1")},
    [MR_POINT_3] = {"tfit_modal_rows_r3", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=12 fadd=6 fmul=9 branch=1")},
    [MR_POINT_4] = {"tfit_modal_rows_r4", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=15 fadd=9 fmul=12 branch=1")},
    [MR_POINT_5] = {"tfit_modal_rows_r5", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=18 fadd=12 fmul=15 branch=1")},
    [MR_POINT_6] = {"tfit_modal_rows_r6", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=21 fadd=15 fmul=18 branch=1")},
    [MR_POINT_7] = {"tfit_modal_rows_r7", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=24 fadd=18 fmul=21 branch=1")},
    [MR_POINT_8] = {"tfit_modal_rows_r8", 1, 1,
                    TF_SAME("alu=2 fldm=1 fstm=1 fwords=27 fadd=21 fmul=24 branch=1")},
    /* the three skips (no main iteration, no remaining pair, no odd point)
     * counted as falling through; d1_mix turns each one taken */
    [D1_PATH] = {"tfit_degree1_asm", 0, 0,
                 TF_SAME("alu=58 load=3 ldm=1 ldm_pc=1 stm=1 words=11 fldm=2 fstm=1 fwords=36 "
                      "fadd=14 fmul=33 fother=3 fmov=11 nbranch=3")},
    [D1_MAIN] = {"tfit_degree1_asm", 1, 1,
                 TF_SAME("alu=2 fldm=8 fstm=8 fwords=240 fadd=144 fmul=144 branch=1")},
    [D1_REM] = {"tfit_degree1_asm", 2, 1,
                TF_SAME("alu=1 fldm=1 fstm=1 fwords=30 fadd=18 fmul=18 branch=1")},
    [D1_POINT] = {"tfit_degree1_asm", 0, 0, TF_SAME("fldm=1 fstm=1 fwords=15 fadd=9 fmul=9")},
    [D1R_PATH] = {"tfit_degree1_rows_asm", 0, 0,
                  TF_SAME("alu=12 load=2 ldm_pc=1 stm=1 words=8 fldm=2 fstm=1 fwords=27 nbranch=3")},
    [D1R_MAIN] = {"tfit_degree1_rows_asm", 1, 1,
                  TF_SAME("alu=2 fldm=8 fstm=8 fwords=240 fadd=144 fmul=144 branch=1")},
    [D1R_REM] = {"tfit_degree1_rows_asm", 2, 1,
                 TF_SAME("alu=1 fldm=1 fstm=1 fwords=30 fadd=18 fmul=18 branch=1")},
};

const size_t tf_insn_n_shared = N_BLOCKS;

/* Terms of the total-degree-p basis in 3 variables. */
static uint64_t terms(uint32_t p)
{
    return (uint64_t)(p + 1) * (p + 2) * (p + 3) / 6;
}

static void add(tf_insn_mix *t, tf_core core, block_id b, uint64_t times)
{
    tf_insn_add(t, &tf_insn_shared[b], core, times);
}

static void sub(tf_insn_mix *t, tf_core core, block_id b, uint64_t times)
{
    tf_insn_sub(t, &tf_insn_shared[b], core, times);
}

static void loop(tf_insn_mix *t, tf_core core, block_id b, uint64_t n)
{
    tf_insn_loop(t, &tf_insn_shared[b], core, n);
}

void tf_insn_input(tf_insn_mix *t, tf_core core)
{
    add(t, core, INPUT_PATH, 1);
}

void tf_insn_displacements(tf_insn_mix *t, tf_core core, uint32_t dims0)
{
    add(t, core, ENTRY_FORWARD, 1);
    if (dims0 == 1) {
        add(t, core, ENTRY_DIMS1, 1);
    }
}

void tf_insn_evaluate_nodal(tf_insn_mix *t, tf_core core)
{
    add(t, core, EVAL_NODAL, 1);
}

/* Degree 1 (tfit_degree1_armv7em.c): n_out / 16 iterations of eight
 * pairs, then (n_out / 2) mod 8 single pairs, then the odd point; each
 * part skipped by a taken branch when empty.  path, main and rem: the
 * blocks of tfit_degree1_asm or of tfit_degree1_rows_asm (the same loops). */
static void d1_loops(tf_insn_mix *t, tf_core core, uint32_t n_out, block_id path, block_id main,
                     block_id rem)
{
    add(t, core, path, 1);
    const uint32_t iterations = n_out >> 4, pairs = (n_out >> 1) & 7u;
    loop(t, core, main, iterations);
    loop(t, core, rem, pairs);
    tf_insn_taken(t, (iterations == 0) + (pairs == 0) + !(n_out & 1u));
    if (n_out & 1u) {
        add(t, core, D1_POINT, 1);
    }
}

void tf_insn_degree1(tf_insn_mix *t, tf_core core, uint32_t n_out)
{
    d1_loops(t, core, n_out, D1_PATH, D1_MAIN, D1_REM);
}

void tf_insn_degree1_rows(tf_insn_mix *t, tf_core core, uint32_t n_out)
{
    d1_loops(t, core, n_out, D1R_PATH, D1R_MAIN, D1R_REM);
}

void tf_insn_basis(tf_insn_mix *t, tf_core core, uint32_t p)
{
    if (p <= 1) {
        add(t, core, BASIS_PATH_LOW, 1);
    } else {
        add(t, core, BASIS_PATH, 1);
        loop(t, core, BASIS_T_STEP, p - 1);
        sub(t, core, BASIS_T_ENTRY, 1);
    }
    loop(t, core, BASIS_DEGREE, p + 1);
    /* loop 3 entered once per degree, loop 4 once per (degree, e) */
    add(t, core, BASIS_E, (uint64_t)(p + 1) * (p + 2) / 2);
    tf_insn_falls_through(t, p + 1);
    add(t, core, BASIS_TERM, terms(p));
    tf_insn_falls_through(t, (uint64_t)(p + 1) * (p + 2) / 2);
}

void tf_insn_nodal(tf_insn_mix *t, tf_core core, uint32_t p, uint32_t n_out)
{
    tf_insn_basis(t, core, p);
    add(t, core, NODAL_PATH, 1);
    loop(t, core, NODAL_NODE, n_out);
    add(t, core, NODAL_TERM, (uint64_t)n_out * (terms(p) - 1));
    if (p == 0) { /* the term loop is skipped, by a taken branch */
        sub(t, core, NODAL_P0_SKIP, n_out);
        tf_insn_taken(t, n_out);
    } else {
        tf_insn_falls_through(t, n_out);
    }
}

/* Ranks whose rows run in assembly: TFIT_MODAL_ASM_MAX_RANK of
 * target/src/tfit_internal.h. */
#define MODAL_ASM_MAX_RANK 8u

/* The rows of a modal model of rank r <= 8 in assembly
 * (tfit_modal_armv7em.c): the dispatch, the rank's function (its path loads
 * the r amplitudes with one VLDM) and its loop over the output points. */
static void modal_rows_asm(tf_insn_mix *t, tf_core core, uint32_t r, uint32_t n_out)
{
    add(t, core, MR_DISPATCH, 1);
    add(t, core, MR_PATH, 1);
    t->n[TF_INSN_FWORDS] += r;
    loop(t, core, (block_id)(MR_POINT_1 + (r - 1)), n_out);
}

void tf_insn_modal_rows_asm(tf_insn_mix *t, tf_core core, uint32_t r, uint32_t n_out)
{
    modal_rows_asm(t, core, r, n_out);
}

/* The basis, the r amplitudes (loops 1, 2), then the rows in assembly
 * (r <= 8) or in C (loops 3, 4: r > 8, so the mode loop always runs). */
void tf_insn_modal(tf_insn_mix *t, tf_core core, uint32_t p, uint32_t r, uint32_t n_out)
{
    tf_insn_basis(t, core, p);
    add(t, core, r <= MODAL_ASM_MAX_RANK ? MODAL_PATH : MODAL_PATH_C, 1);
    loop(t, core, MODAL_AMP, r);
    add(t, core, MODAL_AMP_TERM, (uint64_t)r * (terms(p) - 1));
    if (p == 0) { /* skipped by a taken branch */
        sub(t, core, MODAL_AMP_P0_SKIP, r);
        tf_insn_taken(t, r);
    } else {
        tf_insn_falls_through(t, r);
    }
    if (r <= MODAL_ASM_MAX_RANK) {
        modal_rows_asm(t, core, r, n_out);
        return;
    }
    loop(t, core, MODAL_NODE, n_out);
    add(t, core, MODAL_MODE, (uint64_t)n_out * (r - 1));
    tf_insn_falls_through(t, n_out);
}
