/*
 * zhou2017.c — the zhou2017 form (target/src/tfit_zhou2017.c;
 * docs/header-format.md §5.4): seed 000's structure, a per-axis contact
 * law (eqs 40-42) and the coefficients of separable x/y surface
 * polynomials as polynomials of the contact displacement (eqs 44-46), all
 * Chebyshev series.  dims = {lambda[3], then (A, B, k) for 9 (axis,
 * component) pairs}; coef = input map | per axis its contact law
 * (lambda + 1) and scale | per pair its surface beta[A + B + 1][k + 1] |
 * the normalised node coordinates X, Y of every output.
 */
#include "model/forms/form.h"

#include <math.h>

#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/ref_arith.h"

/* Rows of pair `pair`'s surface: A + B + 1. */
static uint32_t surface_rows(const uint32_t *dims, int pair)
{
    return dims[3 + 3 * pair] + dims[4 + 3 * pair] + 1;
}

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    uint64_t n = TFIT_INPUT_MAP_FLOATS;
    for (int a = 0; a < 3; ++a) {
        if (dims[a] > TFIT_MAX_DEGREE) {
            return 0;
        }
        n += dims[a] + 2;
    }
    for (int pair = 0; pair < 9; ++pair) {
        const uint32_t *o = dims + 3 + 3 * pair;
        if (o[0] > TFIT_ZHOU_MAX_ORDER || o[1] > TFIT_ZHOU_MAX_ORDER || o[2] > TFIT_MAX_DEGREE) {
            return 0;
        }
        n += (uint64_t)surface_rows(dims, pair) * (o[2] + 1);
    }
    return n + 2ull * n_out;
}

/* The contact laws and their scales on the unit ball; the surfaces as
 * Chebyshev series in |t| <= tau, where |T_k|, |U_k| <= (2 tau)^k
 * (header-format.md §8); the node coordinates in [-1, 1]. */
static int bounds(tf_ctx *ctx, const tf_model *m)
{
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    double tau[3], comp[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a) {
        double d = tf_form_abs_poly(c, m->dims[a], 1.0);
        c += m->dims[a] + 1;
        double t = d * fabs((double)*c++);
        if (tf_form_bound_fail(ctx, d, "contact displacement of axis", m, (uint32_t)a) ||
            tf_form_bound_fail(ctx, t, "normalised contact displacement of axis", m, (uint32_t)a)) {
            return 1;
        }
        tau[a] = 2 * (t > 1 ? t : 1);
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t rows = surface_rows(m->dims, pair), k = m->dims[5 + 3 * pair];
        for (uint32_t i = 0; i < rows; ++i, c += k + 1) {
            comp[pair % 3] += tf_form_abs_poly(c, k, tau[pair / 3]);
        }
    }
    for (uint32_t j = 0; j < 2 * m->n_out; ++j) {
        if (!(fabs((double)c[j]) <= 1.0)) {
            tf_fail(ctx, "model '%s': normalised node coordinate %u is %g, outside [-1, 1]",
                    m->name, j, (double)c[j]);
            return 1;
        }
    }
    for (uint32_t k = 0; k < 3; ++k) {
        if (tf_form_bound_fail(ctx, comp[k], "displacement component", m, k)) {
            return 1;
        }
    }
    return 0;
}

/* The surface coefficients of every (axis, component) pair first, then the
 * nodes; the per-output sum order is S_x, + S_y, + S_z (§5.4). */
static void ref_map(tf_arith *c, const tf_model *m, const float g[3], float *out)
{
    const uint32_t *dm = m->dims;
    const float *q = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *xy = m->coef + m->n_coef - 2 * m->n_out;
    float t[3];
    float p[9][2 * TFIT_ZHOU_MAX_ORDER + 1];

    for (int a = 0; a < 3; ++a) {
        float d = tf_ref_clenshaw(c, q, dm[a], g[a]);
        q += dm[a] + 1;
        t[a] = tf_ref_mul(c, d, *q++);
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = dm[3 + 3 * pair], by = dm[4 + 3 * pair], k = dm[5 + 3 * pair];
        for (uint32_t i = 0; i <= ax + by; ++i, q += k + 1) {
            p[pair][i] = tf_ref_clenshaw(c, q, k, t[pair / 3]);
        }
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = dm[3 + 3 * pair], by = dm[4 + 3 * pair];
        int comp = pair % 3;
        for (uint32_t j = 0; j < m->n_out; ++j) {
            float s = tf_ref_clenshaw(c, p[pair], ax, xy[2 * j]);
            if (by > 0) {
                s = tf_ref_add(c, s, tf_ref_clenshaw_tail(c, p[pair] + ax, by, xy[2 * j + 1]));
            }
            float *dst = &out[3 * j + comp];
            *dst = pair < 3 ? s : tf_ref_add(c, *dst, s);
        }
    }
}

/* Clenshaw (§5.4): the tail sum_{k=1..n} c_k T_k takes n + 1 mul and
 * 2n + 2 add (h, n steps of a product, a difference and a sum, then
 * (x b_1) - b_2), n = 0 included; the full series one add more (+ c_0). */
static uint64_t tail_add(uint32_t n)
{
    return 2 * (uint64_t)n + 2;
}

static uint64_t series_add(uint32_t n)
{
    return tail_add(n) + 1;
}

static void ops(const tf_model *m, tf_opcount *ops)
{
    tf_form_input_ops(ops);
    for (int a = 0; a < 3; ++a) {
        ops->mul += m->dims[a] + 2; /* the series, then t_a = d_a s_a */
        ops->add += series_add(m->dims[a]);
    }
    for (int pair = 0; pair < 9; ++pair) {
        const uint32_t *o = m->dims + 3 + 3 * pair;
        const uint64_t rows_p = surface_rows(m->dims, pair);
        ops->mul += rows_p * (o[2] + 1ull) +
                    m->n_out * ((o[0] + 1ull) + (o[1] > 0 ? o[1] + 1ull : 0));
        ops->add += rows_p * series_add(o[2]) +
                    m->n_out * (series_add(o[0]) + (o[1] > 0 ? tail_add(o[1]) + 1 : 0) +
                                (pair >= 3 ? 1 : 0));
    }
}

typedef enum block_id {
    EVAL_ZHOU,
    MASK_WORD,      /* evaluate() loop 1: the output mask after zhou2017 */
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
    N_BLOCKS
} block_id;

static const tf_block blocks[N_BLOCKS] = {
    [EVAL_ZHOU] = {"evaluate", 0, 0, TF_SAME("alu=21 load=5 ldm_pc=1 stm=1 words=10 branch=4 nbranch=2")},
    [MASK_WORD] = {"evaluate", 1, 1, TF_SAME("alu=3 load=1 store=1 branch=1")},
    [ZHOU_PATH] = {"tfit_eval_zhou2017", 0, 0,
                   {"alu=16 load=3 store=5 ldm=1 ldm_pc=1 stm=1 words=20 fload=2",
                    "alu=17 load=3 store=5 ldm=1 ldm_pc=1 stm=1 words=20 fload=2"}},
    [ZHOU_AXIS] = {"tfit_eval_zhou2017", 1, 1,
                   TF_SAME("alu=6 load=1 fload=1 fldm=2 fstm=1 fwords=3 fadd=3 fmul=2 fother=2 "
                        "branch=2 nbranch=1")},
    [ZHOU_AXIS_STEP] = {"tfit_eval_zhou2017", 2, 2,
                        TF_SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_AXIS_SETUP] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("alu=3 fother=2 branch=1")},
    [ZHOU_AXIS_STUB] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("alu=1 fload=1 fother=1 branch=1")},
    [ZHOU_SURF_AXIS] = {"tfit_eval_zhou2017", 3, 1, TF_SAME("alu=8 load=2 store=2 branch=1")},
    [ZHOU_PAIR] = {"tfit_eval_zhou2017", 4, 2,
                   TF_SAME("alu=25 mla=1 load=9 store=3 ldm=1 words=2 fload=2 fadd=1 branch=1 "
                        "nbranch=2")},
    [ZHOU_ROW] = {"tfit_eval_zhou2017", 5, 3,
                  TF_SAME("alu=4 fload=1 fstm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=2 "
                       "nbranch=1")},
    [ZHOU_ROW_STEP] = {"tfit_eval_zhou2017", 6, 4,
                       TF_SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_ROW_SETUP] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("alu=1 fother=2 branch=1")},
    [ZHOU_ROW_STUB] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("fother=2 branch=1")},
    [ZHOU_NODE] = {"tfit_eval_zhou2017", 7, 3,
                   TF_SAME("alu=7 fload=3 fstore=1 fadd=7 fmul=2 fother=4 branch=3 nbranch=3")},
    [ZHOU_X_STEP] = {"tfit_eval_zhou2017", 8, 4,
                     TF_SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_X_SETUP] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("alu=1 fother=2 branch=1")},
    [ZHOU_X_STUB] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("fother=2 branch=1")},
    [ZHOU_Y_STEP] = {"tfit_eval_zhou2017", 9, 4,
                     TF_SAME("alu=1 fldm=1 fwords=1 fadd=2 fmul=1 fother=2 branch=1")},
    [ZHOU_Y_PART] = {"tfit_eval_zhou2017", 0, 0,
                     TF_SAME("alu=1 fload=1 fadd=3 fmul=1 fother=2 branch=1")},
    [ZHOU_SUM] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("fload=1 fadd=1")},
    [STEP_ENTRY] = {"tfit_eval_zhou2017", 0, 0, TF_SAME("fother=1")},
};

/* One inlined Clenshaw series of order n (tfit_cheb): the enclosing loop
 * body holds the set-up of its step loop; n >= 1 runs n steps, entering the
 * loop past its first instruction (a register move); n = 0 branches past
 * the set-up and the loop to an out-of-line stub and back (the test that
 * falls through for n >= 1 is then taken). */
static void clenshaw_mix(tf_insn_mix *t, tf_core core, uint32_t n, uint64_t times, block_id step,
                         block_id setup, block_id stub)
{
    if (n == 0) {
        tf_insn_sub(t, &blocks[setup], core, times);
        tf_insn_add(t, &blocks[stub], core, times);
        tf_insn_taken(t, times);
        return;
    }
    tf_insn_add(t, &blocks[step], core, times * n);
    tf_insn_sub(t, &blocks[STEP_ENTRY], core, times);
    tf_insn_falls_through(t, times);
}

/* tfit_displacements, evaluate() with its output mask, tfit_eval_zhou2017. */
static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *t)
{
    const uint32_t *d = m->dims;
    const uint64_t n = m->n_out;
    tf_insn_input(t, core);
    tf_insn_displacements(t, core, d[0]);
    tf_insn_add(t, &blocks[EVAL_ZHOU], core, 1);
    tf_insn_loop(t, &blocks[MASK_WORD], core, 3 * n);
    tf_insn_add(t, &blocks[ZHOU_PATH], core, 1);
    tf_insn_loop(t, &blocks[ZHOU_AXIS], core, 3);
    tf_insn_loop(t, &blocks[ZHOU_SURF_AXIS], core, 3);
    for (int a = 0; a < 3; ++a) {
        clenshaw_mix(t, core, d[a], 1, ZHOU_AXIS_STEP, ZHOU_AXIS_SETUP, ZHOU_AXIS_STUB);
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = d[3 + 3 * pair], by = d[4 + 3 * pair], k = d[5 + 3 * pair];
        uint64_t rows = (uint64_t)ax + by + 1;
        tf_insn_add(t, &blocks[ZHOU_PAIR], core, 1);
        if (pair % 3 == 2) { /* the pair loop's back edge, once per force axis */
            tf_insn_falls_through(t, 1);
        }
        tf_insn_loop(t, &blocks[ZHOU_ROW], core, rows);
        clenshaw_mix(t, core, k, rows, ZHOU_ROW_STEP, ZHOU_ROW_SETUP, ZHOU_ROW_STUB);
        tf_insn_loop(t, &blocks[ZHOU_NODE], core, n);
        clenshaw_mix(t, core, ax, n, ZHOU_X_STEP, ZHOU_X_SETUP, ZHOU_X_STUB);
        if (by == 0) { /* the Y part skipped by a taken branch */
            tf_insn_sub(t, &blocks[ZHOU_Y_PART], core, n);
            tf_insn_taken(t, n);
        } else {
            tf_insn_add(t, &blocks[ZHOU_Y_STEP], core, n * by);
            tf_insn_sub(t, &blocks[STEP_ENTRY], core, n);
            tf_insn_falls_through(t, n);
        }
        if (pair < 3) { /* force axis x stores instead of adding: a taken branch */
            tf_insn_sub(t, &blocks[ZHOU_SUM], core, n);
            tf_insn_taken(t, n);
        }
    }
}

static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    static const char comp[] = "xyz";
    char note[128];
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    (void)site;
    for (int a = 0; a < 3; ++a) {
        snprintf(note, sizeof note, "contact displacement %c(g%c), then its scale", comp[a],
                 comp[a]);
        tf_form_write_floats(f, c, m->dims[a] + 2, note);
        c += m->dims[a] + 2;
    }
    for (int pair = 0; pair < 9; ++pair) {
        const uint32_t *o = m->dims + 3 + 3 * pair;
        uint32_t n = (o[0] + o[1] + 1) * (o[2] + 1);
        snprintf(note, sizeof note, "surface u%c under force %c: beta[%u][%u]", comp[pair % 3],
                 comp[pair / 3], o[0] + o[1] + 1, o[2] + 1);
        tf_form_write_floats(f, c, n, note);
        c += n;
    }
    tf_form_write_floats(f, c, 2 * m->n_out, "normalised node coordinates X, Y");
}

const tf_form tf_form_zhou2017 = {
    .id = TFIT_FAMILY_ZHOU2017,
    .name = "zhou2017",
    .n_dims = TFIT_ZHOU2017_DIMS,
    .coefs = coefs,
    .bounds = bounds,
    .ref_map = ref_map,
    TF_FORM_EACH_INPUT,
    .ops = ops,
    .insn_mix = insn_mix,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .input = "force [N]",
    .emit_tables = emit_tables,
    .emit_banner = NULL,
    .emit_macros = NULL,
    .q31 = NULL,
    .filter = NULL,
};
