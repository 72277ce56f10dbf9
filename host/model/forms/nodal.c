/*
 * nodal.c — the nodal form (target/src/tfit_nodal.c; docs/header-format.md
 * §5.2): each output component a polynomial of total degree p in the
 * projected force.  dims = {p}; coef = input map | C[3 n_out][T(p)].  The
 * degree-1 models (p = 1, every linear-elastic one) run the assembly of
 * tfit_degree1_armv7em.c on Cortex-M4F/M7, without evaluate()'s dispatch.
 */
#include "model/forms/form.h"

#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/q31.h"
#include "model/ref_arith.h"

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    if (dims[0] > TFIT_MAX_DEGREE) {
        return 0;
    }
    return TFIT_INPUT_MAP_FLOATS + 3ull * n_out * tf_terms(dims[0]);
}

static int bounds(tf_ctx *ctx, const tf_model *m)
{
    return tf_form_rows_bounds(ctx, m, m->coef + TFIT_INPUT_MAP_FLOATS, 3ull * m->n_out,
                               tf_terms(m->dims[0]));
}

/* §5.1, §5.2: the basis, then every row summed left to right. */
static void ref_map(tf_arith *c, const tf_model *m, const float g[3], float *out)
{
    float phi[TF_REF_TERMS_MAX];
    tf_ref_basis(c, m->dims[0], g, phi);
    tf_ref_rows(c, m->coef + TFIT_INPUT_MAP_FLOATS, 3 * m->n_out, tf_terms(m->dims[0]), phi, out);
}

static void ops(const tf_model *m, tf_opcount *ops)
{
    const uint64_t rows = 3ull * m->n_out, t = tf_terms(m->dims[0]);
    tf_form_input_ops(ops);
    tf_form_basis_ops(m->dims[0], ops);
    ops->mul += rows * (t - 1);
    ops->add += rows * (t - 1);
}

enum { D1_ENTRY_FORWARD, N_BLOCKS };
static const tf_block blocks[N_BLOCKS] = {
    /* tfit_displacements, nodal p = 1: checks, tail call */
    [D1_ENTRY_FORWARD] = {"tfit_displacements", 0, 0,
                          TF_SAME("alu=8 load=2 ldm=2 stm=1 words=8 branch=1 nbranch=6")},
};

/* p = 1: tfit_displacements' fast path to the degree-1 assembly; else
 * evaluate() and tfit_eval_nodal. */
static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    if (m->dims[0] == 1) {
        tf_insn_add(mix, &blocks[D1_ENTRY_FORWARD], core, 1);
        tf_insn_degree1(mix, core, m->n_out);
        return;
    }
    tf_insn_input(mix, core);
    tf_insn_displacements(mix, core, m->dims[0]);
    tf_insn_evaluate_nodal(mix, core);
    tf_insn_nodal(mix, core, m->dims[0], m->n_out);
}

static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    tf_form_write_rows(f, m, m->coef + TFIT_INPUT_MAP_FLOATS, tf_terms(m->dims[0]), site, "");
}

const tf_form tf_form_nodal = {
    .id = TFIT_FAMILY_NODAL,
    .name = "nodal",
    .n_dims = TFIT_NODAL_DIMS,
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
    .q31 = &tf_q31_rows,
    .filter = NULL,
};
