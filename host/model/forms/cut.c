/*
 * cut.c — the cut form (target/src/tfit_cut.c; docs/header-format.md §5.7,
 * docs/cutting.md): displacements as a function of the force and the cut
 * progress s.  dims = {p, K}; coef = input map | K + 1 nodal tables, knot
 * k at s_k = k / K, linear in s between knots.
 */
#include "model/forms/cut.h"

#include <math.h>

#include "cost/evaluator.h"
#include "model/forms/form.h"
#include "model/golden.h"
#include "model/ref_arith.h"

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    if (dims[0] > TFIT_MAX_DEGREE || dims[1] == 0 || dims[1] > TFIT_CUT_MAX_INTERVALS) {
        return 0;
    }
    return TFIT_INPUT_MAP_FLOATS + (dims[1] + 1ull) * 3ull * n_out * tf_terms(dims[0]);
}

/* Every knot's rows: a + w (b - a), w in [0, 1], stays within twice the
 * larger. */
static int bounds(tf_ctx *ctx, const tf_model *m)
{
    return tf_form_rows_bounds(ctx, m, m->coef + TFIT_INPUT_MAP_FLOATS,
                               3ull * m->n_out * (m->dims[1] + 1), tf_terms(m->dims[0]));
}

/* s clamped onto [0, 1] (NaN/Inf: bad, taken as 0), t = s K,
 * j = min(trunc t, K - 1), w = t - j; per output a + w (b - a) with a, b
 * the rows of knots j and j + 1. */
tfit_status tf_cut_ref_eval(const tf_model *m, const float in[3], float s, float *out,
                            tf_opcount *ops)
{
    tf_arith c = {{0, 0, 0}};
    float g[3], phi[TF_REF_TERMS_MAX];
    int clamped, bad;
    tf_ref_project(&c, m, in, g, &clamped, &bad);
    const int s_bad = !isfinite(s);
    float sc = s_bad ? 0.0f : s;
    if (sc < 0.0f || sc > 1.0f) {
        clamped = 1;
        sc = sc < 0.0f ? 0.0f : 1.0f;
    }
    bad = bad || s_bad;
    const uint32_t k = m->dims[1], p = m->dims[0], terms = tf_terms(p);
    const float t = tf_ref_mul(&c, sc, (float)k);
    uint32_t j = (uint32_t)floor((double)t);
    j = j > k - 1 ? k - 1 : j;
    const float w = tf_ref_sub(&c, t, (float)j);
    tf_ref_basis(&c, p, g, phi);
    const size_t rows = 3 * (size_t)m->n_out;
    const float *a = m->coef + TFIT_INPUT_MAP_FLOATS + (size_t)j * rows * terms;
    float xa, xb;
    for (size_t o = 0; o < rows; ++o) {
        tf_ref_rows(&c, a + o * terms, 1, terms, phi, &xa);
        tf_ref_rows(&c, a + (rows + o) * terms, 1, terms, phi, &xb);
        const float v = tf_ref_add(&c, xa, tf_ref_mul(&c, w, tf_ref_sub(&c, xb, xa)));
        out[o] = bad ? 0.0f : v;
    }
    tf_ref_count(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

/* The scene's cuts in full, as its other cases. */
static tfit_status ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    return tf_cut_ref_eval(m, in, 1.0f, out, ops);
}

/* Golden vector v at the cut progress TFIT_CUT_GOLDEN_S_BITS[v mod 16] (tfit.h). */
static void golden_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                       float *out)
{
    static const uint32_t s_bits[16] = TFIT_CUT_GOLDEN_S_BITS;
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_cut_ref_eval(m, in[v], tf_ref_float(s_bits[v & 15]),
                                             out + v * 3 * (size_t)m->n_out, NULL);
    }
}

/* Self-test input k at s_k = k/4 - 1/4 (tfit_check.c). */
static tfit_status check_step(const tf_model *m, float *state, int k, const float in[3],
                              float *out)
{
    (void)state;
    return tf_cut_ref_eval(m, in, (float)k * 0.25f - 0.25f, out, NULL);
}

/* §5.7: t = s K, w = t - j; two rows per output, then a + w (b - a). */
static void ops(const tf_model *m, tf_opcount *ops)
{
    const uint64_t rows = 3ull * m->n_out, t = tf_terms(m->dims[0]);
    tf_form_input_ops(ops);
    tf_form_basis_ops(m->dims[0], ops);
    ops->mul += 1 + rows * (2 * (t - 1) + 1);
    ops->add += 1 + rows * (2 * (t - 1) + 2);
}

typedef enum block_id {
    CUT_ENTRY,      /* tfit_displacements_cut: checks, the calls, the status */
    CUT_PROGRESS,   /* tfit_cut_progress(): straight-line code */
    CUT_ROWS_D1,    /* tfit_cut_rows() outside its loops, p = 1 */
    CUT_D1_POINT,   /* loop 3: one output point at p = 1, both knots */
    CUT_ROWS_PATH,  /* tfit_cut_rows() outside its loops, p != 1 */
    CUT_POINT,      /* loop 1: one output point, any p */
    CUT_P0_SKIP,    /* ... minus the inner-loop set-up that p = 0 skips */
    CUT_TERM,       /* loop 2: one basis term of the six rows */
    N_BLOCKS
} block_id;

static const tf_block blocks[N_BLOCKS] = {
    [CUT_ENTRY] = {"tfit_displacements_cut", 0, 0,
                   {"alu=33 load=9 store=4 ldm=1 ldm_pc=1 stm=1 words=16 fload=1 fldm=1 fstm=1 "
                    "fwords=4 fother=2 branch=4 nbranch=5",
                    "alu=33 load=9 store=4 ldm=1 ldm_pc=1 stm=1 words=16 fload=1 fldm=1 fstm=1 "
                    "fwords=4 fother=2 branch=4 nbranch=5"}},
    [CUT_PROGRESS] = {"tfit_cut_progress", 0, 0,
                      TF_SAME("alu=31 load=1 store=2 ldm_pc=1 stm=1 words=8 fstore=2 fadd=1 fmul=1 "
                           "fother=6 fmov=8")},
    [CUT_ROWS_D1] = {"tfit_cut_rows", 0, 0,
                     {"alu=15 mul=4 mla=2 load=10 store=2 ldm_pc=1 stm=1 words=18 fload=3 fldm=1 "
                      "fstm=1 fwords=16 branch=1 nbranch=1",
                      "alu=15 mul=4 mla=2 load=10 store=2 ldm_pc=1 stm=1 words=18 fload=3 fldm=1 "
                      "fstm=1 fwords=12 branch=1 nbranch=1"}},
    [CUT_D1_POINT] = {"tfit_cut_rows", 3, 1,
                      TF_SAME("alu=8 store=3 fload=24 fadd=24 fmul=21 fmov=3 branch=1")},
    [CUT_ROWS_PATH] = {"tfit_cut_rows", 0, 0,
                       {"alu=28 mul=4 mla=2 load=8 store=10 ldm_pc=1 stm=1 words=18 fldm=1 fstm=1 "
                        "fwords=16 nbranch=2",
                        "alu=28 mul=4 mla=2 load=8 store=10 ldm_pc=1 stm=1 words=18 fldm=1 fstm=1 "
                        "fwords=12 nbranch=2"}},
    [CUT_POINT] = {"tfit_cut_rows", 1, 1,
                   TF_SAME("alu=22 load=11 store=4 fload=6 fadd=6 fmul=3 fmov=3 branch=1 nbranch=1")},
    [CUT_P0_SKIP] = {"tfit_cut_rows", 0, 0, TF_SAME("alu=8 load=5")},
    [CUT_TERM] = {"tfit_cut_rows", 2, 2, TF_SAME("alu=2 fldm=7 fwords=7 fadd=6 fmul=6 branch=1")},
};

/* The entry, the projection, the progress, the basis, then the rows of
 * both knots per output point: at p = 1 loop 3, else loop 1 with its term
 * loop (which p = 0 skips by a taken branch). */
static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *t)
{
    const uint32_t p = m->dims[0], terms = tf_terms(p);
    tf_insn_add(t, &blocks[CUT_ENTRY], core, 1);
    tf_insn_input(t, core);
    tf_insn_add(t, &blocks[CUT_PROGRESS], core, 1);
    tf_insn_basis(t, core, p);
    if (p == 1) {
        tf_insn_add(t, &blocks[CUT_ROWS_D1], core, 1);
        tf_insn_loop(t, &blocks[CUT_D1_POINT], core, m->n_out);
        return;
    }
    tf_insn_add(t, &blocks[CUT_ROWS_PATH], core, 1);
    tf_insn_loop(t, &blocks[CUT_POINT], core, m->n_out);
    if (p == 0) {
        tf_insn_sub(t, &blocks[CUT_P0_SKIP], core, m->n_out);
        tf_insn_taken(t, m->n_out);
    } else {
        tf_insn_add(t, &blocks[CUT_TERM], core, (uint64_t)m->n_out * (terms - 1));
        tf_insn_falls_through(t, m->n_out);
    }
}

/* A nodal table per knot s = k / K. */
static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    static const char comp[] = "xyz";
    char note[128];
    const uint32_t t = tf_terms(m->dims[0]);
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t o = 0; o < 3 * m->n_out * (m->dims[1] + 1); ++o, c += t) {
        uint32_t knot = o / (3 * m->n_out), r = o % (3 * m->n_out);
        snprintf(note, sizeof note, "s = %u/%u: %s %u %c", knot, m->dims[1], site,
                 m->node_ids[r / 3], comp[r % 3]);
        tf_form_write_floats(f, c, t, note);
    }
}

const tf_form tf_form_cut = {
    .id = TFIT_FAMILY_CUT,
    .name = "cut",
    .n_dims = TFIT_CUT_DIMS,
    .coefs = coefs,
    .bounds = bounds,
    .ref_map = NULL,
    .ref_eval = ref_eval,
    .golden_inputs = tf_golden_inputs,
    .check_pick = tf_golden_pick_points,
    .golden_run = golden_run,
    .check_step = check_step,
    .ops = ops,
    .insn_mix = insn_mix,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .input = "force [N] and cut progress s in [0, 1] (tfit_displacements_cut)",
    .emit_tables = emit_tables,
    .emit_banner = NULL,
    .emit_macros = NULL,
    .q31 = NULL,
    .filter = NULL,
};
