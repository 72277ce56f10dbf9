/*
 * modal.c — the modal form (target/src/tfit_modal.c, the rows of
 * tfit_modal_armv7em.c; docs/header-format.md §5.3): r modes times
 * polynomial amplitudes.  dims = {p, r}; coef = input map | A[r][T(p)]
 * (the amplitudes' rows) | U[3 n_out][r] (the modes at each output
 * component).
 */
#include "model/forms/form.h"

#include <math.h>

#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/ref_arith.h"

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    if (dims[0] > TFIT_MAX_DEGREE || dims[1] == 0 || dims[1] > TFIT_MAX_RANK) {
        return 0;
    }
    return TFIT_INPUT_MAP_FLOATS + (uint64_t)dims[1] * tf_terms(dims[0]) + 3ull * n_out * dims[1];
}

/* Each amplitude on the unit ball, then each output as the modes weighted
 * by those bounds. */
static int bounds(tf_ctx *ctx, const tf_model *m)
{
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    const uint32_t t = tf_terms(m->dims[0]), r = m->dims[1];
    double amax[TFIT_MAX_RANK];
    for (uint32_t k = 0; k < r; ++k) {
        amax[k] = tf_form_abs_poly(c + k * t, t - 1, 1.0);
        if (tf_form_bound_fail(ctx, amax[k], "mode amplitude", m, k)) {
            return 1;
        }
    }
    const float *u = c + r * t;
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        double b = 0;
        for (uint32_t k = 0; k < r; ++k) {
            b += fabs((double)u[o * r + k]) * amax[k];
        }
        if (tf_form_bound_fail(ctx, b, "output", m, o)) {
            return 1;
        }
    }
    return 0;
}

/* The amplitudes as rows at the basis, then each output
 * ((u_0 a_0) + u_1 a_1) + ... */
static void ref_map(tf_arith *c, const tf_model *m, const float g[3], float *out)
{
    const uint32_t t = tf_terms(m->dims[0]), r = m->dims[1];
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *modes = amp + (size_t)r * t;
    float phi[TF_REF_TERMS_MAX], a[TFIT_MAX_RANK];
    tf_ref_basis(c, m->dims[0], g, phi);
    tf_ref_rows(c, amp, r, t, phi, a);
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        const float *u = modes + (size_t)o * r;
        float acc = tf_ref_mul(c, u[0], a[0]);
        for (uint32_t k = 1; k < r; ++k) {
            acc = tf_ref_add(c, acc, tf_ref_mul(c, u[k], a[k]));
        }
        out[o] = acc;
    }
}

static void ops(const tf_model *m, tf_opcount *ops)
{
    const uint64_t t = tf_terms(m->dims[0]), r = m->dims[1], rows = 3ull * m->n_out;
    tf_form_input_ops(ops);
    tf_form_basis_ops(m->dims[0], ops);
    ops->mul += r * (t - 1) + rows * r;
    ops->add += r * (t - 1) + rows * (r - 1);
}

enum { EVAL_MODAL, N_BLOCKS };
static const tf_block blocks[N_BLOCKS] = {
    /* evaluate(): the projection's call, the family switch, the status */
    [EVAL_MODAL] = {"evaluate", 0, 0,
                    TF_SAME("alu=17 load=4 ldm_pc=1 stm=1 words=10 branch=4")},
};

static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    tf_insn_input(mix, core);
    tf_insn_displacements(mix, core, m->dims[0]);
    tf_insn_add(mix, &blocks[EVAL_MODAL], core, 1);
    tf_insn_modal(mix, core, m->dims[0], m->dims[1], m->n_out);
}

static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    static const char comp[] = "xyz";
    char note[128];
    const uint32_t t = tf_terms(m->dims[0]), r = m->dims[1];
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < r; ++k, c += t) {
        snprintf(note, sizeof note, "amplitude of mode %u", k);
        tf_form_write_floats(f, c, t, note);
    }
    for (uint32_t o = 0; o < 3 * m->n_out; ++o, c += r) {
        snprintf(note, sizeof note, "modes at %s %u %c", site, m->node_ids[o / 3], comp[o % 3]);
        tf_form_write_floats(f, c, r, note);
    }
}

const tf_form tf_form_modal = {
    .id = TFIT_FAMILY_MODAL,
    .name = "modal",
    .n_dims = TFIT_MODAL_DIMS,
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
