/*
 * modal_q15.c — the modal_q15 form (target/src/tfit_modal_q15.c, the
 * assembly of tfit_modal_q15_armv7em.c; docs/header-format.md §5.9): modal
 * at rank 8 with the modes in Q15 and the products summed in integers (the
 * M4's dual 16-bit MACs).  dims = {p >= 1, 8}; coef = input map |
 * At[T(p)][8] (the amplitudes' rows, transposed) | v[8] (the amplitudes'
 * Q15 scales) | S (the output scale) | 3 n_out rows of 4 words, two Q15
 * modes a word (bits q[2j] | (q[2j+1] + 16384) << 16).
 */
#include "model/forms/form.h"

#include <math.h>
#include <string.h>

#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/ref_arith.h"

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    if (dims[0] == 0 || dims[0] > TFIT_MAX_DEGREE || dims[1] != TFIT_MODAL_Q15_RANK) {
        return 0;
    }
    return TFIT_INPUT_MAP_FLOATS + (uint64_t)TFIT_MODAL_Q15_RANK * (tf_terms(dims[0]) + 1) + 1 +
           3ull * n_out * TFIT_MODAL_Q15_WORDS;
}

/* The amplitudes bounded as modal's, the scales finite (a_k v_k may
 * overflow to +-Inf: it saturates), S in [0, 2^64], every row word's
 * halves within [-16255, 16255] (so that the sums cannot overflow and no
 * word is a NaN or Inf pattern). */
static int bounds(tf_ctx *ctx, const tf_model *m)
{
    const uint32_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + (size_t)r * t;
    for (uint32_t k = 0; k < r; ++k) {
        double b = 0;
        for (uint32_t j = 0; j < t; ++j) {
            b += fabs((double)at[(size_t)j * r + k]);
        }
        if (tf_form_bound_fail(ctx, b, "mode amplitude", m, k)) {
            return 1;
        }
        if (!(fabs((double)v[k]) <= TF_FORM_BOUND_LIMIT)) {
            tf_fail(ctx, "model '%s': Q15 scale of mode %u is %g (not finite)", m->name, k,
                    (double)v[k]);
            return 1;
        }
    }
    if (!(v[r] >= 0.0f && v[r] <= 0x1p64f)) {
        tf_fail(ctx, "model '%s': Q15 output scale %g outside [0, 2^64]", m->name, (double)v[r]);
        return 1;
    }
    const float *rows = v + r + 1;
    for (uint32_t i = 0; i < 3 * m->n_out * TFIT_MODAL_Q15_WORDS; ++i) {
        uint32_t w;
        memcpy(&w, &rows[i], sizeof w);
        const int32_t lo = (int32_t)(int16_t)(uint16_t)(w & 0xffffu);
        const int32_t hi = (int32_t)(w >> 16) - 16384;
        if (lo < -16255 || lo > 16255 || hi < -16255 || hi > 16255) {
            tf_fail(ctx, "model '%s': Q15 row word %u holds %d, %d beyond +-16255", m->name, i, lo,
                    hi);
            return 1;
        }
    }
    return 0;
}

/* The amplitudes term by term (each mode's operations in tfit_row's
 * order), c_k = trunc(a_k v_k) saturated to [-8192, 8191], the integer sums
 * exactly (|sum| < 2^31 by the layout), one conversion and one product by
 * S per output.  The bias and the +16384 of the high halves cancel, so the
 * sum is taken directly over the decoded q. */
static void ref_map(tf_arith *c, const tf_model *m, const float g[3], float *out)
{
    const uint32_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + (size_t)r * t;
    const float *rows = m->coef + m->n_coef - 3 * (size_t)m->n_out * TFIT_MODAL_Q15_WORDS;
    float phi[TF_REF_TERMS_MAX];
    int32_t q[TFIT_MODAL_Q15_RANK];
    tf_ref_basis(c, m->dims[0], g, phi);
    for (uint32_t k = 0; k < r; ++k) {
        float a = at[k];
        for (uint32_t j = 1; j < t; ++j) {
            a = tf_ref_add(c, a, tf_ref_mul(c, at[(size_t)j * r + k], phi[j]));
        }
        const float x = tf_ref_mul(c, a, v[k]);
        q[k] = x >= 8191.0f ? 8191 : x <= -8192.0f ? -8192 : (int32_t)x;
    }
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        int64_t s = 0;
        for (uint32_t j = 0; j < TFIT_MODAL_Q15_WORDS; ++j) {
            const uint32_t w = tf_ref_bits(rows[(size_t)o * TFIT_MODAL_Q15_WORDS + j]);
            const int32_t lo = (int32_t)(int16_t)(uint16_t)(w & 0xffffu);
            const int32_t hi = (int32_t)(w >> 16) - 16384;
            s += (int64_t)lo * q[2 * j] + (int64_t)hi * q[2 * j + 1];
        }
        out[o] = tf_ref_mul(c, (float)(int32_t)s, v[r]);
    }
}

/* Float operations only: the amplitudes, a_k v_k, and S per output (the
 * mode sums are integer). */
static void ops(const tf_model *m, tf_opcount *ops)
{
    const uint64_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK, rows = 3ull * m->n_out;
    tf_form_input_ops(ops);
    tf_form_basis_ops(m->dims[0], ops);
    ops->mul += r * (t - 1) + r + rows;
    ops->add += r * (t - 1);
}

typedef enum block_id {
    EVAL_MODAL_Q15, /* evaluate(): the modal_q15 case */
    MQ_PATH,        /* tfit_eval_modal_q15(): the basis, the two assembly calls */
    MQA_PATH,       /* tfit_q15_amp_asm() outside its loop: set-up, conversion, packing */
    MQA_TERM,       /* loop 1: one basis term of the eight amplitudes */
    MQR_PATH,       /* tfit_q15_rows_asm() outside its loop, without the odd point */
    MQR_POINT,      /* the odd output point */
    MQR_PAIR,       /* loop 1: two output points */
    N_BLOCKS
} block_id;

static const tf_block blocks[N_BLOCKS] = {
    /* modal_q15 (tfit_modal_q15.c, tfit_modal_q15_armv7em.c); objdump
     * counts one more alu in each path: the nop after the return */
    /* forward_other() instead of evaluate(), reached by the branch of
     * tfit_displacements' family test that families 1-3 fall through */
    [EVAL_MODAL_Q15] = {"forward_other", 0, 0, TF_SAME("alu=16 load=4 ldm_pc=1 stm=1 words=8 branch=3")},
    [MQ_PATH] = {"tfit_eval_modal_q15", 0, 0,
                 {"alu=22 mul=2 mla=1 load=7 store=2 ldm_pc=1 stm=1 words=16 fload=1 branch=3",
                  "alu=22 mul=2 mla=1 load=7 store=2 ldm_pc=1 stm=1 words=18 fload=1 branch=3"}},
    [MQA_PATH] = {"tfit_q15_amp_asm", 0, 0,
                  TF_SAME("alu=24 ldm=2 stm=2 words=21 fldm=3 fstm=1 fwords=32 fmul=8 fother=9 "
                       "fmov=7 branch=1")},
    [MQA_TERM] = {"tfit_q15_amp_asm", 1, 1, TF_SAME("alu=1 fldm=2 fwords=9 fadd=8 fmul=8 branch=1")},
    /* both skips (no odd point, no pair) counted as falling through */
    [MQR_PATH] = {"tfit_q15_rows_asm", 0, 0,
                  TF_SAME("alu=4 load=1 ldm=2 ldm_pc=1 stm=1 words=22 nbranch=2")},
    [MQR_POINT] = {"tfit_q15_rows_asm", 0, 0,
                   TF_SAME("alu=12 ldm=3 words=12 fstm=1 fwords=3 fmul=3 fother=3 fmov=3")},
    [MQR_PAIR] = {"tfit_q15_rows_asm", 1, 1,
                  TF_SAME("alu=25 ldm=6 words=24 fstm=2 fwords=6 fmul=6 fother=6 fmov=6 branch=1")},
};

/* tfit_displacements' other families' path, then tfit_eval_modal_q15: the
 * basis (p >= 1), the amplitudes term by term (T - 1 iterations), then the
 * rows: the odd point, then n_out / 2 pairs, each part skipped by a taken
 * branch when empty. */
static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    const uint32_t p = m->dims[0], pairs = m->n_out >> 1;
    tf_insn_input(mix, core);
    tf_insn_displacements(mix, core, p);
    tf_insn_add(mix, &blocks[EVAL_MODAL_Q15], core, 1);
    tf_insn_basis(mix, core, p);
    tf_insn_add(mix, &blocks[MQ_PATH], core, 1);
    tf_insn_add(mix, &blocks[MQA_PATH], core, 1);
    tf_insn_loop(mix, &blocks[MQA_TERM], core, tf_terms(p) - 1);
    tf_insn_add(mix, &blocks[MQR_PATH], core, 1);
    if (m->n_out & 1u) {
        tf_insn_add(mix, &blocks[MQR_POINT], core, 1);
    }
    tf_insn_loop(mix, &blocks[MQR_PAIR], core, pairs);
    tf_insn_taken(mix, !(m->n_out & 1u) + (pairs == 0));
}

static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    static const char comp[] = "xyz";
    char note[128];
    const uint32_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t j = 0; j < t; ++j, c += r) {
        snprintf(note, sizeof note, "term %u of the 8 mode amplitudes", j);
        tf_form_write_floats(f, c, r, note);
    }
    tf_form_write_floats(f, c, r, "Q15 amplitude scales v_k");
    tf_form_write_floats(f, c + r, 1, "output scale S (mm)");
    c += r + 1;
    for (uint32_t o = 0; o < 3 * m->n_out; ++o, c += TFIT_MODAL_Q15_WORDS) {
        snprintf(note, sizeof note, "Q15 modes at %s %u %c (word bits: q[2j] | q[2j+1] + 16384)",
                 site, m->node_ids[o / 3], comp[o % 3]);
        tf_form_write_floats(f, c, TFIT_MODAL_Q15_WORDS, note);
    }
}

const tf_form tf_form_modal_q15 = {
    .id = TFIT_FAMILY_MODAL_Q15,
    .name = "modal_q15",
    .n_dims = TFIT_MODAL_Q15_DIMS,
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
