/*
 * region_surface.c — the surface for the current contact of a region
 * (docs/header-format.md §5.11): the proxy site (a region law's state) and
 * the contact force (N) -> the outputs' displacements (mm), through r
 * modes shared by every site.  Its target evaluator is tfit_region_surface
 * (target/src/tfit_region_surface.c; the self-test in
 * tfit_region_check.c).  dims = {nx, ny, r, p, has_site_modes, near}.
 *
 * The layout, checks and golden design are model/region_model.c's, the
 * reference evaluation model/region_ref.c's.  Golden vector v (and
 * self-test input k) is evaluated at the proxy state of
 * tf_region_ref_golden_state(v): grid fractions from the cut form's
 * progress table, in contact; the far inputs of the self-test go through
 * the force map (coef + 20), not through the chart at coef[0..12).
 */
#include "model/forms/form.h"

#include <string.h>

#include "base/context.h"
#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/ref_eval.h"
#include "model/region_layout.h"
#include "model/region_model.h"
#include "model/region_ref.h"

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    return tf_region_surface_ncoef(n_out, dims);
}

static int bounds(tf_ctx *ctx, const tf_model *m)
{
    return tf_region_surface_validate(ctx, m) != 0; /* 1 with the message in ctx */
}

/* ---- cost (§6) ---- */
/* One call of tfit_region_surface: its path (the arguments, the force map,
 * the proxy's site, the monomials, tfit_region_rows; one for ranks 1-8,
 * whose rows are the modal family's assembly, one for the rows in C),
 * the powers' loop when p >= 2, then per mode the paths of
 * tfit_region_blend and tfit_region_dot, and the loops.  The paths are the
 * QEMU traces of check-qemu-region less the loops (objdump), the same for
 * every traced surface of each kind. */
enum {
    PATH_ASM,   /* p = 1, r <= 8 */
    PATH_C,     /* p = 1, r > 8 */
    POWERS,     /* p >= 2: the powers' loop entered (and its skip falls through) */
    MODE,       /* per mode: the calls of tfit_region_blend and _dot outside their loops */
    MONO_POWER, /* tfit_region_monomials loop 1: one power n = 2 .. p of the three */
    MONO_TERM,  /* loop 2: one monomial */
    BLEND_Q,    /* tfit_region_blend loop 1: one blended quantity (16 terms) */
    DOT_TERM,   /* tfit_region_dot loop 1: one term after the first */
    AMP_MODE,   /* tfit_region_amplitudes loop 1: one mode's two calls */
    ROWS_POINT, /* tfit_region_rows loop 1 (r > 8): one output point */
    ROWS_MODE,  /* loop 2: one mode of its three rows */
    NEAR_PATH,  /* near > 0: the call of tfit_region_near outside its loops */
    NEAR_ROW,   /* tfit_region_near loop 1: one row l of control points */
    NEAR_POINT, /* loop 2: one control point (its weight, its entries' start) */
    NEAR_ENTRY, /* loop 3: one entry {j, D} (the window's mask, the output's address) */
    NEAR_COMP,  /* loop 4: one component i of the entry's term */
    N_BLOCKS
};
static const tf_block blocks[N_BLOCKS] = {
    [PATH_ASM] = {"tfit_region_surface", 0, 0,
                  {"alu=217 mul=8 mla=4 load=28 store=11 ldm=6 ldm_pc=5 stm=8 words=90 fload=22 "
                   "fstore=24 fldm=1 fstm=1 fwords=4 fadd=30 fmul=65 fother=24 fmov=32 branch=19 "
                   "nbranch=6",
                   "alu=217 mul=8 mla=4 load=26 store=13 ldm=7 ldm_pc=5 stm=7 words=96 fload=22 "
                   "fstore=24 fldm=1 fstm=1 fwords=4 fadd=30 fmul=65 fother=24 fmov=32 branch=19 "
                   "nbranch=6"}},
    [PATH_C] = {"tfit_region_surface", 0, 0,
                {"alu=230 mul=8 mla=4 load=28 store=12 ldm=5 ldm_pc=6 stm=7 words=88 fload=22 "
                 "fstore=24 fldm=1 fstm=1 fwords=4 fadd=30 fmul=65 fother=24 fmov=32 branch=17 "
                 "nbranch=8",
                 "alu=230 mul=8 mla=4 load=26 store=12 ldm=6 ldm_pc=6 stm=7 words=96 fload=22 "
                 "fstore=24 fldm=1 fstm=1 fwords=4 fadd=30 fmul=65 fother=24 fmov=32 branch=17 "
                 "nbranch=8"}},
    [POWERS] = {"tfit_region_monomials", 0, 0, TF_SAME("alu=3 fother=3")},
    [MODE] = {"tfit_region_amplitudes", 0, 0,
              {"alu=15 mul=1 mla=1 load=3 ldm_pc=1 stm=1 words=16 fload=10 fldm=1 fstm=1 "
               "fwords=12 fmul=1 branch=1 nbranch=2",
               "alu=15 mul=1 mla=1 load=3 ldm_pc=1 stm=1 words=16 fload=10 fldm=1 fstm=1 "
               "fwords=8 fmul=1 branch=1 nbranch=2"}},
    [MONO_POWER] = {"tfit_region_monomials", 1, 1,
                    TF_SAME("alu=1 fstore=2 fstm=1 fwords=1 fmul=3 branch=1")},
    [MONO_TERM] = {"tfit_region_monomials", 2, 1,
                   {"alu=7 load=3 fload=3 fstm=1 fwords=1 fmul=2 branch=1",
                    "alu=6 load=3 fload=3 fstm=1 fwords=1 fmul=2 branch=1"}},
    [BLEND_Q] = {"tfit_region_blend", 1, 1,
                 TF_SAME("alu=12 fload=11 fldm=5 fstm=1 fwords=6 fadd=15 fmul=20 branch=1")},
    [DOT_TERM] = {"tfit_region_dot", 1, 1, TF_SAME("alu=1 fldm=2 fwords=2 fadd=1 fmul=1 branch=1")},
    [AMP_MODE] = {"tfit_region_amplitudes", 1, 1, TF_SAME("alu=9 load=2 store=2 fmov=1 branch=3")},
    [ROWS_POINT] = {"tfit_region_rows", 1, 1,
                    TF_SAME("alu=13 load=1 store=3 fload=4 fmul=3 fmov=3 branch=1")},
    [ROWS_MODE] = {"tfit_region_rows", 2, 2,
                   TF_SAME("alu=1 fldm=4 fwords=4 fadd=3 fmul=3 branch=1")},
    [NEAR_PATH] = {"tfit_region_near", 0, 0,
                  {"alu=32 mul=7 mla=1 load=11 store=8 ldm=3 ldm_pc=1 stm=2 words=26 branch=1 "
                   "nbranch=1",
                   "alu=30 mul=7 mla=1 load=11 store=8 ldm=3 ldm_pc=1 stm=2 words=26 branch=1 "
                   "nbranch=1"}},
    [NEAR_ROW] = {"tfit_region_near", 1, 1, TF_SAME("alu=7 load=6 store=1 branch=1")},
    [NEAR_POINT] = {"tfit_region_near", 2, 2,
                    TF_SAME("alu=7 load=2 store=1 ldm=1 stm=1 words=4 fload=1 fldm=1 fwords=1 "
                            "fmul=1 branch=2")},
    [NEAR_ENTRY] = {"tfit_region_near", 3, 3,
                    TF_SAME("alu=12 load=1 fload=1 fother=1 fmov=1 branch=1")},
    [NEAR_COMP] = {"tfit_region_near", 4, 4,
                   TF_SAME("alu=6 load=1 store=1 fload=7 fadd=3 fmul=4 fmov=3 branch=1")},
};

/* Ranks whose rows run in the modal assembly (TFIT_MODAL_ASM_MAX_RANK). */
#define ROWS_ASM_MAX_RANK 8u

/* The near field: its call, then 4 rows x 4 control points x near entries
 * x 3 components; each control point's skip of an empty entry loop falls
 * through. */
static void near_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    const uint32_t near = m->dims[5];
    if (near == 0) {
        return;
    }
    tf_insn_add(mix, &blocks[NEAR_PATH], core, 1);
    tf_insn_loop(mix, &blocks[NEAR_ROW], core, 4);
    for (uint32_t c = 0; c < 4; ++c) {
        tf_insn_loop(mix, &blocks[NEAR_POINT], core, 4);
    }
    tf_insn_falls_through(mix, 16);
    for (uint32_t c = 0; c < 16; ++c) {
        tf_insn_loop(mix, &blocks[NEAR_ENTRY], core, near);
    }
    for (uint32_t e = 0; e < 16 * near; ++e) {
        tf_insn_loop(mix, &blocks[NEAR_COMP], core, 3);
    }
}

static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    const uint32_t r = m->dims[2], p = m->dims[3], n_out = m->n_out;
    const uint32_t n_t = tf_region_surface_terms(p);
    tf_insn_add(mix, &blocks[r <= ROWS_ASM_MAX_RANK ? PATH_ASM : PATH_C], core, 1);
    if (p >= 2) {
        tf_insn_add(mix, &blocks[POWERS], core, 1);
        tf_insn_falls_through(mix, 1);
    }
    tf_insn_loop(mix, &blocks[MONO_POWER], core, p - 1);
    tf_insn_loop(mix, &blocks[MONO_TERM], core, n_t);
    tf_insn_add(mix, &blocks[MODE], core, r);
    for (uint32_t k = 0; k < r; ++k) {
        tf_insn_loop(mix, &blocks[BLEND_Q], core, n_t);
        tf_insn_loop(mix, &blocks[DOT_TERM], core, n_t - 1);
    }
    tf_insn_loop(mix, &blocks[AMP_MODE], core, r);
    if (r <= ROWS_ASM_MAX_RANK) {
        tf_insn_modal_rows_asm(mix, core, r, n_out);
    } else {
        tf_insn_loop(mix, &blocks[ROWS_POINT], core, n_out);
        for (uint32_t j = 0; j < n_out; ++j) {
            tf_insn_loop(mix, &blocks[ROWS_MODE], core, r - 1);
        }
    }
    near_mix(m, core, mix);
}

/* The surface's static response: the contact at the grid's centre site. */
static tfit_status ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    const float state[3] = {(float)(m->dims[0] - 1) * 0.5f, (float)(m->dims[1] - 1) * 0.5f, 1.0f};
    if (ops != NULL) {
        tf_form_mix_ops(m, ops);
    }
    return tf_region_ref_surface(m, state, in, out);
}

static void golden_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                       float *out)
{
    const size_t n_out = 3 * (size_t)m->n_out;
    for (size_t v = 0; v < n; ++v) {
        float state[3];
        tf_region_ref_golden_state(m, (uint32_t)v, state);
        status[v] = (int32_t)tf_region_ref_surface(m, state, in[v], out + v * n_out);
    }
}

static tfit_status check_step(const tf_model *m, float *state, int k, const float in[3],
                              float *out)
{
    (void)state;
    float at[3];
    tf_region_ref_golden_state(m, (uint32_t)k, at);
    return tf_region_ref_surface(m, at, in, out);
}

/* The far forces through the force map: the projected force's words. */
static uint32_t check_far(const tf_model *m, float *state, const uint32_t *check,
                          const float x[3], uint32_t crc)
{
    (void)state;
    (void)check;
    tf_model map = *m;
    float f[3];
    int clamped, bad;
    map.coef = m->coef + TF_REGION_FORCE_MAP;
    tf_ref_input(&map, x, f, &clamped, &bad, NULL);
    return tf_form_crc_floats(crc, f, 3);
}

/* The scalars, the force map, the control points' blocks {A[r][T(p) - 1],
 * Phi_site[3][r]}, their near fields, then the modes' rows. */
static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    tf_form_write_floats(f, m->coef + TF_REGION_CHART, TF_REGION_SURFACE_SCALARS,
                         "region scalars: 1/ha, 1/hb, ha, hb (mm), s_u (1/mm), 1/s_u (mm), mu, "
                         "1/R_F (1/N)");
    tf_form_write_floats(f, m->coef + TF_REGION_FORCE_MAP, TFIT_INPUT_MAP_FLOATS,
                         "force map: x0 (N), W (1/N)");
    const uint32_t stride = tf_region_surface_stride(m->dims), nx = m->dims[0], ny = m->dims[1];
    const uint32_t r = m->dims[2];
    const float *c = m->coef + TF_REGION_SURFACE_CTRL;
    char note[128];
    for (uint32_t j = 0; j < ny + 2; ++j) {
        for (uint32_t i = 0; i < nx + 2; ++i, c += stride) {
            snprintf(note, sizeof note, "control point (%d, %d): amplitudes A[%u][%u]%s",
                     (int)i - 1, (int)j - 1, r, tf_region_surface_terms(m->dims[3]),
                     m->dims[4] ? ", site modes Phi_site[3][r]" : "");
            tf_form_write_floats(f, c, stride, note);
        }
    }
    const uint32_t near = m->dims[5];
    for (uint32_t j = 0; near != 0 && j < ny + 2; ++j) {
        for (uint32_t i = 0; i < nx + 2; ++i, c += near * TF_REGION_NEAR_FLOATS) {
            snprintf(note, sizeof note,
                     "control point (%d, %d): near field, %u entries {output point, D[3][3]}",
                     (int)i - 1, (int)j - 1, near);
            tf_form_write_floats(f, c, near * TF_REGION_NEAR_FLOATS, note);
        }
    }
    static const char comp[] = "xyz";
    for (uint32_t o = 0; o < 3 * m->n_out; ++o, c += r) {
        snprintf(note, sizeof note, "%s %u %c modes", site, m->node_ids[o / 3], comp[o % 3]);
        tf_form_write_floats(f, c, r, note);
    }
}

const tf_form tf_form_region_surface = {
    .id = TFIT_FAMILY_REGION_SURFACE,
    .name = "region_surface",
    .n_dims = TFIT_REGION_SURFACE_DIMS,
    .coefs = coefs,
    .bounds = bounds,
    .ref_map = NULL,
    .ref_eval = ref_eval,
    .golden_inputs = tf_region_surface_golden_design,
    .check_pick = tf_golden_pick_points,
    .golden_run = golden_run,
    .check_step = check_step,
    .state_words = 0,
    .check_far = check_far,
    .ops = tf_form_mix_ops,
    .insn_mix = insn_mix,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .input = "contact force [N] at the proxy site",
    .emit_tables = emit_tables,
    .emit_banner = NULL,
    .emit_macros = NULL,
    .q31 = NULL,
    .filter = NULL,
};
