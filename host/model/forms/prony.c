/*
 * prony.c — see prony.h: the prony form's filter over the stateful layer
 * (stateful.c).  A term is {a_k, D_k} (2 table floats), its state z_k[3];
 * one tick, per term k and axis i:
 *     z_ki <- (a_k z_ki) + (D_k d_i),   h_i <- h_i - z_ki
 * (docs/header-format.md §5.6, target/src/tfit_prony.c).
 */
#include "model/forms/prony.h"

#include <math.h>

#include "model/golden.h"
#include "model/q31.h"

float tf_prony_decay(double tick, double tau)
{
    return (float)exp(-tick / tau);
}

/* -ln(a) for a float a in (0, 1): 1 - a is exact in double (a has 24
 * bits), and log1p keeps its relative accuracy when it is small. */
static double realised_rate(float decay)
{
    return -log1p(-(1.0 - (double)decay));
}

double tf_prony_realised_tau(double tick, float decay)
{
    return tick / realised_rate(decay);
}

double tf_prony_hold_gain(float decay)
{
    const double one_minus_a = 1.0 - (double)decay; /* exact */
    if (decay <= 0.0f) {
        return 0.0; /* r = inf: the term settles within the tick */
    }
    return one_minus_a / realised_rate(decay);
}

double tf_prony_set_term(tf_model *m, uint32_t k, double tau, double weight)
{
    const double tick = tf_stateful_tick(m);
    float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    pt[0] = tf_prony_decay(tick, tau);
    pt[1] = (float)(weight * tf_prony_hold_gain(pt[0]));
    return tf_prony_realised_tau(tick, pt[0]);
}

void tf_prony_get_term(const tf_model *m, uint32_t k, double *tau, double *weight)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    const double gain = tf_prony_hold_gain(pt[0]);
    *tau = tf_prony_realised_tau(tf_stateful_tick(m), pt[0]);
    *weight = gain > 0 ? (double)pt[1] / gain : 0.0;
}

/* ---- the filter ---------------------------------------------------------- */

static void ref_terms(tf_arith *c, const tf_model *m, const float d[3], const float *z, float *zn,
                      float h[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        for (int i = 0; i < 3; ++i) {
            const float zk = tf_ref_add(c, tf_ref_mul(c, pt[2 * k], z[3 * k + (uint32_t)i]),
                                        tf_ref_mul(c, pt[2 * k + 1], d[i]));
            zn[3 * k + (uint32_t)i] = zk;
            h[i] = tf_ref_sub(c, h[i], zk);
        }
    }
}

/* header-format.md §8: 0 <= a_k <= 1 - 2^-19 (the target's limit is
 * 1 - 2^-20: a bit of margin) and |D_k| <= 2^63. */
static int term_check(tf_ctx *ctx, const tf_model *m, uint32_t k)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    const double a = pt[0], d = fabs((double)pt[1]);
    if (!(a >= 0 && a <= 1 - 0x1p-19) || !(d <= 0x1p63)) {
        tf_fail(ctx,
                "model '%s': prony term %u has decay %g and gain %g (decay in [0, 1 - 2^-19] "
                "and |gain| <= 2^63 keep the state finite)",
                m->name, k, a, (double)pt[1]);
        return 1;
    }
    return 0;
}

typedef enum block_id {
    PRONY_DISPATCH, /* tfit_stateful_step's call of the prony filter */
    PRONY_FILTER,   /* tfit_prony_filter() outside its loop, K >= 1 */
    PRONY_FILTER_SETUP, /* ... the loop's set-up and exit load, which K = 0 skips */
    PRONY_FILTER_STUB,  /* ... the out-of-line code K = 0 runs instead */
    PRONY_TERM,     /* loop 1: one term, three axes */
    N_BLOCKS
} block_id;

static const tf_block blocks[N_BLOCKS] = {
    /* the family test falls through to the prony filter's call, and
     * branches to the resonant one's and back */
    [PRONY_DISPATCH] = {"tfit_stateful_step", 0, 0, TF_SAME("branch=1 nbranch=1")},
    [PRONY_FILTER] = {"tfit_prony_filter", 0, 0,
                      TF_SAME("alu=52 load=4 store=5 ldm=1 ldm_pc=1 stm=1 words=10 fload=7 fstore=1 "
                           "fadd=3 fmov=3 nbranch=1")},
    [PRONY_FILTER_SETUP] = {"tfit_prony_filter", 0, 0, TF_SAME("alu=6 fload=1")},
    [PRONY_FILTER_STUB] = {"tfit_prony_filter", 0, 0, TF_SAME("fother=1 branch=1")},
    [PRONY_TERM] = {"tfit_prony_filter", 1, 1,
                    TF_SAME("alu=5 fload=5 fstore=3 fadd=6 fmul=6 branch=1")},
};

/* tfit_stateful_step's call, then tfit_prony_filter: its loop over K
 * terms; K = 0 jumps past it. */
static void insn_mix(tf_insn_mix *t, tf_core core, uint32_t terms)
{
    tf_insn_add(t, &blocks[PRONY_DISPATCH], core, 1);
    tf_insn_add(t, &blocks[PRONY_FILTER], core, 1);
    tf_insn_loop(t, &blocks[PRONY_TERM], core, terms);
    if (terms == 0) {
        tf_insn_sub(t, &blocks[PRONY_FILTER_SETUP], core, 1);
        tf_insn_add(t, &blocks[PRONY_FILTER_STUB], core, 1);
        tf_insn_taken(t, 1);
    }
}

/* The creep function the terms realise. */
static void emit_terms(FILE *f, const tf_model *m)
{
    fprintf(f, " creep J(t)/J(inf) = 1");
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double tau, w;
        tf_prony_get_term(m, k, &tau, &w);
        fprintf(f, " - %.4g exp(-t/%.4g s)", w, tau);
    }
}

static void emit_term(FILE *f, const tf_model *m, uint32_t k)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    double tau, w;
    tf_prony_get_term(m, k, &tau, &w);
    fprintf(f, "    /* prony term %u: decay a, gain D (tau %.6g s, weight %.6g) */\n    %af, %af,\n",
            k, tau, w, (double)pt[0], (double)pt[1]);
}

static const tf_filter filter = {
    .floats = 2,
    .words = 3,
    .max_terms = TFIT_PRONY_MAX_TERMS,
    .term_add = 6, /* per term, three axes: 6 mul and 3 add for z, 3 sub for h */
    .term_mul = 6,
    .reset = "tfit_prony_reset",
    .step = "tfit_prony_step",
    .count = "TERMS",
    .ref_terms = ref_terms,
    .term_check = term_check,
    .insn_mix = insn_mix,
    .emit_terms = emit_terms,
    .emit_term = emit_term,
};

const tf_form tf_form_prony = {
    .id = TFIT_FAMILY_PRONY,
    .name = "prony",
    .n_dims = TFIT_PRONY_DIMS,
    TF_STATEFUL_FORM,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .q31 = &tf_q31_prony,
    .filter = &filter,
};
