/*
 * contact.c — the contact form (docs/header-format.md §5.2): the haptic
 * impedance, contact displacement -> contact force, the nodal layout with
 * one output point.  Its target evaluator is tfit_contact_force
 * (target/src/tfit_eval.c, with tfit_nodal.c's rows; p = 1 in the assembly
 * of tfit_degree1_armv7em.c).  dims = {p}.
 */
#include "model/forms/form.h"

#include "cost/evaluator.h"
#include "model/golden.h"
#include "model/model.h"
#include "model/q31.h"

/* The nodal form's layout, bounds, evaluation and operations. */
extern const tf_form tf_form_nodal;

static uint64_t coefs(const tf_form *f, uint32_t n_out, const uint32_t *dims)
{
    (void)f;
    return n_out == 1 ? tf_form_nodal.coefs(&tf_form_nodal, n_out, dims) : 0;
}

static int bounds(tf_ctx *ctx, const tf_model *m)
{
    return tf_form_nodal.bounds(ctx, m);
}

static void ref_map(tf_arith *c, const tf_model *m, const float g[3], float *out)
{
    tf_form_nodal.ref_map(c, m, g, out);
}

static void ops(const tf_model *m, tf_opcount *out)
{
    tf_form_nodal.ops(m, out);
}

enum { ENTRY_CONTACT, D1_ENTRY_CONTACT, D1_ONE, N_BLOCKS };
static const tf_block blocks[N_BLOCKS] = {
    /* tfit_contact_force, p != 1: argument and family checks, tail call */
    [ENTRY_CONTACT] = {"tfit_contact_force", 0, 0,
                       TF_SAME("alu=5 load=2 ldm=2 stm=1 words=6 branch=1 nbranch=6")},
    /* tfit_contact_force, p = 1: the same */
    [D1_ENTRY_CONTACT] = {"tfit_contact_force", 0, 0,
                          TF_SAME("alu=5 load=2 ldm=2 stm=1 words=6 branch=2 nbranch=5")},
    /* tfit_degree1_one_asm(): the whole p = 1 evaluation (objdump counts one
     * more alu: the nop before its literal pool) */
    [D1_ONE] = {"tfit_degree1_one_asm", 0, 0,
                TF_SAME("alu=52 load=2 ldm=1 ldm_pc=1 stm=1 words=11 fldm=2 fstm=1 fwords=27 "
                        "fadd=23 fmul=42 fother=3 fmov=11")},
};

static void insn_mix(const tf_model *m, tf_core core, tf_insn_mix *mix)
{
    if (m->dims[0] == 1) {
        tf_insn_add(mix, &blocks[D1_ENTRY_CONTACT], core, 1);
        tf_insn_add(mix, &blocks[D1_ONE], core, 1);
        return;
    }
    tf_insn_input(mix, core);
    tf_insn_add(mix, &blocks[ENTRY_CONTACT], core, 1);
    tf_insn_evaluate_nodal(mix, core);
    tf_insn_nodal(mix, core, m->dims[0], m->n_out);
}

static void emit_tables(FILE *f, const tf_model *m, const char *site)
{
    (void)site;
    tf_form_write_rows(f, m, m->coef + TFIT_INPUT_MAP_FLOATS, tf_terms(m->dims[0]), "node",
                       " force");
}

const tf_form tf_form_contact = {
    .id = TFIT_FAMILY_CONTACT,
    .name = "contact",
    .n_dims = TFIT_CONTACT_DIMS,
    .coefs = coefs,
    .bounds = bounds,
    .ref_map = ref_map,
    TF_FORM_EACH_INPUT,
    .ops = ops,
    .insn_mix = insn_mix,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .input = "contact displacement [mm]",
    .emit_tables = emit_tables,
    .emit_banner = NULL,
    .emit_macros = NULL,
    .q31 = &tf_q31_rows,
    .filter = NULL,
};
