/*
 * region.c — the contact law over a region (docs/header-format.md §5.10):
 * tool-tip position (mm) -> contact force (N), with a caller-owned proxy
 * state (TFIT_REGION_STATE_WORDS floats).  Its target evaluator is
 * tfit_region_force (target/src/tfit_region.c, the splines in
 * tfit_region_spline.c, the self-test in tfit_region_check.c).  dims =
 * {nx, ny, P}; n_out = 1.
 *
 * The layout, checks and golden design are model/region_model.c's, the
 * reference tick model/region_ref.c's (written from header-format.md).
 * The golden vectors are one tick sequence from the reset state, as
 * tfit_golden_run() runs them; so is the self-test (§8), whose far inputs
 * are ticks at check input 1 offset by the far sequence times 2^-100.
 */
#include "model/forms/form.h"

#include <string.h>

#include "base/context.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/region_layout.h"
#include "model/region_model.h"
#include "model/region_ref.h"

_Static_assert(TFIT_REGION_STATE_WORDS <= TFIT_RESONANT_MAX_STATE,
               "the golden run's and the self-test's state hold a region law's");

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    return tf_region_law_ncoef(n_out, dims);
}

static int bounds(tf_ctx *ctx, const tf_model *m)
{
    return tf_region_law_validate(ctx, m) != 0; /* 1 with the message in ctx */
}

/* ---- cost (§6) ---- */
/* One tick of tfit_region_force executes the same instructions whatever
 * the tip, the state and the grid (check-insncount-region; the grid's size
 * changes only which control points are read): one path per degree P, as
 * the QEMU traces of check-qemu-region executed it (tests/region: a tick
 * of a P = 2, 3 and 4 law), the calls it makes included. */
enum { TICK_P2, TICK_P3, TICK_P4, N_BLOCKS };
static const tf_block blocks[N_BLOCKS] = {
    [TICK_P2] = {"tfit_region_force", 0, 0,
                 {"alu=828 mul=5 mla=7 load=150 store=98 ldm=6 ldm_pc=12 stm=18 words=185 "
                  "fload=362 fstore=90 fldm=128 fstm=52 fwords=244 fadd=536 fmul=853 fother=99 "
                  "fmov=111 branch=81 nbranch=23",
                  "alu=828 mul=5 mla=7 load=168 store=102 ldm=6 ldm_pc=12 stm=21 words=193 "
                  "fload=361 fstore=89 fldm=128 fstm=52 fwords=236 fadd=536 fmul=853 fother=100 "
                  "fmov=111 branch=81 nbranch=23"}},
    [TICK_P3] = {"tfit_region_force", 0, 0,
                 {"alu=2053 mul=13 mla=11 load=392 store=154 ldm=8 ldm_pc=14 stm=22 words=213 "
                  "fload=794 fstore=126 fldm=624 fstm=264 fwords=952 fadd=1130 fmul=1897 "
                  "fother=115 fmov=115 branch=329 nbranch=57",
                  "alu=2051 mul=13 mla=11 load=418 store=166 ldm=8 ldm_pc=14 stm=25 words=221 "
                  "fload=793 fstore=125 fldm=624 fstm=264 fwords=944 fadd=1130 fmul=1897 "
                  "fother=116 fmov=115 branch=329 nbranch=57"}},
    [TICK_P4] = {"tfit_region_force", 0, 0,
                 {"alu=3246 mul=13 mla=11 load=632 store=199 ldm=8 ldm_pc=14 stm=22 words=213 "
                  "fload=1353 fstore=138 fldm=1181 fstm=480 fwords=1725 fadd=2030 fmul=3325 "
                  "fother=117 fmov=117 branch=605 nbranch=57",
                  "alu=3244 mul=13 mla=11 load=673 store=226 ldm=8 ldm_pc=14 stm=25 words=221 "
                  "fload=1352 fstore=137 fldm=1181 fstm=480 fwords=1717 fadd=2030 fmul=3325 "
                  "fother=118 fmov=117 branch=605 nbranch=57"}},
};

static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    tf_insn_add(mix, &blocks[TICK_P2 + (m->dims[2] - 2)], core, 1);
}

/* The law's static response: one tick from the reset state (no contact
 * before it), i.e. the force of a fresh press at the tip. */
static tfit_status ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    float state[TFIT_REGION_STATE_WORDS];
    tf_region_ref_reset(state);
    if (ops != NULL) {
        tf_form_mix_ops(m, ops);
    }
    return tf_region_ref_force(m, state, in, out);
}

static void golden_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status,
                       float *out)
{
    float state[TFIT_REGION_STATE_WORDS];
    tf_region_ref_reset(state);
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)tf_region_ref_force(m, state, in[v], out + 3 * v);
    }
}

static tfit_status check_step(const tf_model *m, float *state, int k, const float in[3],
                              float *out)
{
    (void)k;
    return tf_region_ref_force(m, state, in, out);
}

/* The self-test's inputs in the tick design (region_model.c): a press, a
 * slide, a NaN tick, beyond the envelope, off the edge, far, a press
 * elsewhere.  Check input 1 is pressed in: the far ticks slide about it. */
static const size_t check_pick[TFIT_CHECK_INPUTS] = {2, 5, 10, 19, 24, 29, 37, 45};

/* A far tick: check input 1 plus x 2^-100 (offsets of at most 1 mm in
 * steps of 2^-23 mm; the float sum rounded once, as the target's); its
 * status, new state and force. */
static uint32_t check_far(const tf_model *m, float *state, const uint32_t *check,
                          const float x[3], uint32_t crc)
{
    float tip[3], f[3];
    for (int i = 0; i < 3; ++i) {
        float base;
        memcpy(&base, &check[3 + i], sizeof base);
        tip[i] = (float)((double)base + (double)(x[i] * 0x1p-100f));
    }
    const tfit_status s = tf_region_ref_force(m, state, tip, f);
    crc = tf_crc32_u32(crc, (uint32_t)(int32_t)s);
    crc = tf_form_crc_floats(crc, state, TFIT_REGION_STATE_WORDS);
    return tf_form_crc_floats(crc, f, 3);
}

/* The control points' blocks {h, e_1 .. e_T}, after the chart's scalars. */
static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    (void)site;
    const float *sc = m->coef + TF_REGION_CHART;
    tf_form_write_floats(f, sc, TF_REGION_LAW_SCALARS,
                         "region scalars: 1/ha, 1/hb, ha, hb (mm), s_u (1/mm), 1/s_u (mm), mu");
    const uint32_t stride = tf_region_law_stride(m->dims), nx = m->dims[0], ny = m->dims[1];
    const float *ctrl = m->coef + TF_REGION_LAW_CTRL;
    char note[96];
    for (uint32_t j = 0; j < ny + 2; ++j) {
        for (uint32_t i = 0; i < nx + 2; ++i, ctrl += stride) {
            snprintf(note, sizeof note, "control point (%d, %d): h (mm), e_1 .. e_%u (N mm)",
                     (int)i - 1, (int)j - 1, stride - 1);
            tf_form_write_floats(f, ctrl, stride, note);
        }
    }
}

const tf_form tf_form_region = {
    .id = TFIT_FAMILY_REGION,
    .name = "region",
    .n_dims = TFIT_REGION_DIMS,
    .coefs = coefs,
    .bounds = bounds,
    .ref_map = NULL,
    .ref_eval = ref_eval,
    .golden_inputs = tf_region_law_golden_design,
    .check_pick = check_pick,
    .golden_run = golden_run,
    .check_step = check_step,
    .state_words = TFIT_REGION_STATE_WORDS,
    .check_far = check_far,
    .ops = tf_form_mix_ops,
    .insn_mix = insn_mix,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .input = "tool-tip position [mm]",
    .emit_tables = emit_tables,
    .emit_banner = NULL,
    .emit_macros = NULL,
    .q31 = NULL,
    .filter = NULL,
};
