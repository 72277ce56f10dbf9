/*
 * resonant.c — see resonant.h: the resonant form's filter over the
 * stateful layer (stateful.c).  A mode is {f11, f12, f21, f22, w0, w1, w2}
 * (7 table floats), its state s[3], v[3]; one tick, per mode k and axis i:
 *     e1 = s_i - d_i,  s_i <- (f11 e1) + (f12 v_i),  v_i <- (f21 e1) + (f22 v_i),
 *     h_i <- h_i + w_ki s_i
 * (docs/header-format.md §5.8, target/src/tfit_resonant.c).
 */
#include "model/forms/resonant.h"

#include <math.h>

#include "model/golden.h"

#define MODE_FLOATS 7
#define TWO_PI 6.28318530717958647692

void tf_resonant_set_mode(tf_model *m, uint32_t k, double omega, double zeta,
                          const double w[3])
{
    double f[4];
    float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k;
    tf_resonant_transition(omega * tf_stateful_tick(m), zeta, f);
    for (int i = 0; i < 4; ++i) {
        pt[i] = (float)f[i];
    }
    for (int i = 0; i < 3; ++i) {
        pt[4 + i] = (float)w[i];
    }
}

/* The eigenvalues of F are exp(T (-zeta w +- i w sqrt(1 - zeta^2))): det F
 * gives zeta w, the trace the damped frequency (or, overdamped, the two
 * real rates, whose product is w^2 and sum 2 zeta w). */
void tf_resonant_get_mode(const tf_model *m, uint32_t k, double *omega, double *zeta,
                          double w[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k;
    const double t = tf_stateful_tick(m), tr = (double)pt[0] + (double)pt[3];
    const double det = (double)pt[0] * pt[3] - (double)pt[1] * pt[2];
    const double disc = 0.25 * tr * tr - det;
    if (!(det > 0)) {
        *omega = *zeta = NAN;
    } else if (disc < 0) {
        const double sigma = -0.5 * log(det) / t, wd = acos(0.5 * tr / sqrt(det)) / t;
        *omega = sqrt(sigma * sigma + wd * wd);
        *zeta = sigma / *omega;
    } else {
        const double r1 = -log(0.5 * tr + sqrt(disc)) / t, r2 = -log(0.5 * tr - sqrt(disc)) / t;
        *omega = sqrt(r1 * r2);
        *zeta = 0.5 * (r1 + r2) / *omega;
    }
    for (int i = 0; i < 3; ++i) {
        w[i] = pt[4 + i];
    }
}

int tf_resonant_mode_check(tf_ctx *ctx, const tf_model *m, uint32_t k)
{
    return tf_resonant_floats_check(ctx, m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k, m->name,
                                    k);
}

/* ---- the filter ---------------------------------------------------------- */

static void ref_terms(tf_arith *c, const tf_model *m, const float d[3], const float *z, float *zn,
                      float h[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k, pt += MODE_FLOATS) {
        const float *q = z + 6 * k;
        float *qn = zn + 6 * k;
        for (int i = 0; i < 3; ++i) {
            const float e1 = tf_ref_sub(c, q[i], d[i]);
            qn[i] = tf_ref_add(c, tf_ref_mul(c, pt[0], e1), tf_ref_mul(c, pt[1], q[3 + i]));
            qn[3 + i] = tf_ref_add(c, tf_ref_mul(c, pt[2], e1), tf_ref_mul(c, pt[3], q[3 + i]));
            h[i] = tf_ref_add(c, h[i], tf_ref_mul(c, pt[4 + i], qn[i]));
        }
    }
}

/* The device's magnitude limits (tfit_check.c), and the contraction of the
 * rounded transition matrix that keeps the state finite (oscillator.h). */
static int term_check(tf_ctx *ctx, const tf_model *m, uint32_t k)
{
    return tf_resonant_mode_check(ctx, m, k);
}

typedef enum block_id {
    RESONANT_DISPATCH, /* tfit_stateful_step's call of the resonant filter */
    RESONANT_FILTER, /* tfit_resonant_filter() outside its loop, K >= 1 (K = 0, no test
                      * model, would skip the loop's set-up: not modelled) */
    RESONANT_MODE,  /* tfit_resonant_filter loop 1: one mode, three axes */
    N_BLOCKS
} block_id;

static const tf_block blocks[N_BLOCKS] = {
    [RESONANT_DISPATCH] = {"tfit_stateful_step", 0, 0, TF_SAME("branch=3")},
    [RESONANT_FILTER] = {"tfit_resonant_filter", 0, 0,
                         TF_SAME("alu=52 load=4 store=5 ldm=1 ldm_pc=1 stm=1 words=10 fload=7 "
                              "fstore=1 fldm=1 fstm=1 fwords=8 fadd=3 fmov=3 nbranch=1")},
    [RESONANT_MODE] = {"tfit_resonant_filter", 1, 1,
                       TF_SAME("alu=5 fload=13 fstore=6 fadd=12 fmul=15 branch=1")},
};

/* tfit_stateful_step's call, then tfit_resonant_filter: its loop over K
 * modes. */
static void insn_mix(tf_insn_mix *t, tf_core core, uint32_t modes)
{
    tf_insn_add(t, &blocks[RESONANT_DISPATCH], core, 1);
    tf_insn_add(t, &blocks[RESONANT_FILTER], core, 1);
    tf_insn_loop(t, &blocks[RESONANT_MODE], core, modes);
}

/* The modes as the rounded F realises them. */
static void emit_terms(FILE *f, const tf_model *m)
{
    fprintf(f, " %u damped mode%s:", m->dims[2], m->dims[2] == 1 ? "" : "s");
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        double omega, zeta, w[3];
        tf_resonant_get_mode(m, k, &omega, &zeta, w);
        fprintf(f, " %.4g Hz zeta %.3g w (%.3g %.3g %.3g)%s", omega / TWO_PI, zeta, w[0], w[1],
                w[2], k + 1 < m->dims[2] ? ";" : "");
    }
}

static void emit_term(FILE *f, const tf_model *m, uint32_t k)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k;
    double omega, zeta, w[3];
    tf_resonant_get_mode(m, k, &omega, &zeta, w);
    fprintf(f,
            "    /* resonant mode %u: F (2 x 2, row-major), weights x y z (%.6g Hz, zeta "
            "%.6g) */\n",
            k, omega / TWO_PI, zeta);
    fprintf(f, "    %af, %af, %af, %af, %af, %af, %af,\n", (double)pt[0], (double)pt[1],
            (double)pt[2], (double)pt[3], (double)pt[4], (double)pt[5], (double)pt[6]);
}

static const tf_filter filter = {
    .floats = MODE_FLOATS,
    .words = 6,
    .max_terms = TFIT_RESONANT_MAX_MODES,
    .term_add = 12, /* per mode, three axes: 15 mul and 12 add or sub */
    .term_mul = 15,
    .reset = "tfit_resonant_reset",
    .step = "tfit_resonant_step",
    .count = "MODES",
    .ref_terms = ref_terms,
    .term_check = term_check,
    .insn_mix = insn_mix,
    .emit_terms = emit_terms,
    .emit_term = emit_term,
};

const tf_form tf_form_resonant = {
    .id = TFIT_FAMILY_RESONANT,
    .name = "resonant",
    .n_dims = TFIT_RESONANT_DIMS,
    TF_STATEFUL_FORM,
    .blocks = blocks,
    .n_blocks = N_BLOCKS,
    .q31 = NULL,
    .filter = &filter,
};
