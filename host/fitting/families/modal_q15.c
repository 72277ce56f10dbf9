/*
 * modal_q15.c — the modal_q15 family (docs/header-format.md §5.9): the modal
 * family's fit at rank 8 (modal.c: POD modes, polynomial amplitudes),
 * stored for the integer reconstruction: each mode scaled to +-16255 and
 * rounded (u_k = max_o |U[o][k]| / 16255), the amplitudes converted per
 * call to integers in [-8192, 8191] with v_k = u_k / S, where S makes the
 * largest rigorous amplitude bound B_k = sum_t |A[k][t]| (|phi_t| <= 1 on
 * the unit ball) land on 8191, so no amplitude in the envelope saturates.
 * The errors the pipeline and the sweep measure are the reference
 * evaluator's on this layout, so the quantisation is part of them.
 * Applicable only when the scene asks for it (fit.family: modal_q15).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"

extern const tf_family tf_family_modal;
extern const tf_family tf_family_modal_q15;

#define Q_MAX 16255.0 /* |q| of a mode coefficient (the word layout keeps NaN bits out) */
#define C_MAX 8191.0  /* |c_k| the scale S aims the largest amplitude bound at */

/* The Q15 layout of a float modal model of rank 8. */
static tf_model *quantise(tf_ctx *ctx, const tf_model *f)
{
    const uint32_t p = f->dims[0], r = TFIT_MODAL_Q15_RANK, t = tf_terms(p);
    const uint32_t dims[2] = {p, r};
    tf_model *m = tf_model_new(ctx, "modal_q15", TFIT_FAMILY_MODAL_Q15, f->n_out, dims, 2);
    if (m == NULL) {
        return NULL;
    }
    memcpy(m->coef, f->coef, TFIT_INPUT_MAP_FLOATS * sizeof *m->coef);
    memcpy(m->node_ids, f->node_ids, f->n_out * sizeof *m->node_ids);
    m->envelope_radius = f->envelope_radius;
    const float *amp = f->coef + TFIT_INPUT_MAP_FLOATS, *modes = amp + (size_t)r * t;
    float *at = tf_model_tables(m), *v = at + (size_t)r * t, *rows = v + r + 1;
    double u[TFIT_MODAL_Q15_RANK], s = 0;
    for (uint32_t k = 0; k < r; ++k) {
        double umax = 0, b = 0;
        for (uint32_t o = 0; o < 3 * f->n_out; ++o) {
            umax = fmax(umax, fabs((double)modes[(size_t)o * r + k]));
        }
        for (uint32_t j = 0; j < t; ++j) {
            at[(size_t)j * r + k] = amp[(size_t)k * t + j];
            b += fabs((double)amp[(size_t)k * t + j]);
        }
        u[k] = umax > 0 ? umax / Q_MAX : 1.0;
        s = fmax(s, b * u[k] / C_MAX);
    }
    const float scale = s > 0 ? (float)s : 1.0f;
    for (uint32_t k = 0; k < r; ++k) {
        v[k] = (float)(u[k] / (double)scale);
    }
    v[r] = scale;
    for (uint32_t o = 0; o < 3 * f->n_out; ++o) {
        for (uint32_t j = 0; j < TFIT_MODAL_Q15_WORDS; ++j) {
            const float *uo = modes + (size_t)o * r + 2 * j;
            const long lo = lround((double)uo[0] / u[2 * j]);
            const long hi = lround((double)uo[1] / u[2 * j + 1]);
            const uint32_t w = ((uint32_t)lo & 0xffffu) | ((uint32_t)(hi + 16384) << 16);
            memcpy(&rows[(size_t)o * TFIT_MODAL_Q15_WORDS + j], &w, sizeof w);
        }
    }
    return m;
}

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    const uint32_t o[2] = {orders[0], TFIT_MODAL_Q15_RANK};
    tf_model *f = tf_family_modal.fit(ctx, c, idx, m, o);
    if (f == NULL) {
        return NULL;
    }
    tf_model *q = quantise(ctx, f);
    tf_model_free(f);
    return q;
}

static int applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    if (plan->family != &tf_family_modal_q15) {
        return tf_fail(ctx, "fitted when the scene asks for it (fit.family: modal_q15)");
    }
    if (3 * c->train.n_out < TFIT_MODAL_Q15_RANK || c->train.n_cases < TFIT_MODAL_Q15_RANK) {
        return tf_fail(ctx, "rank 8 needs at least 8 output components and 8 training cases");
    }
    return 0;
}

/* The degree by cross-validation at rank 8 (p >= 1: the amplitude loop
 * runs at least once); the held-out error at rank 8 for the report. */
static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *res)
{
    uint32_t p;
    if (tf_family_select_degree(ctx, res->family, c, plan, 1, TFIT_MODAL_Q15_RANK, res->cv, &p) !=
        0) {
        return -1;
    }
    for (uint32_t r = 0; r <= TF_FAMILY_MAX_RANK; ++r) {
        res->cv_rank[r] = res->heldout_rank[r] = INFINITY;
    }
    const uint32_t orders[2] = {p, TFIT_MODAL_Q15_RANK};
    res->model = fit(ctx, c, NULL, 0, orders);
    return res->model ? 0 : -1;
}

/* p = 1 .. max_degree at rank 8, while the cases determine the terms. */
static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    const tf_fitdata *d = &c->train;
    if (3 * d->n_out < TFIT_MODAL_Q15_RANK || d->n_cases < TFIT_MODAL_Q15_RANK) {
        return 0;
    }
    for (uint32_t p = 1; p <= plan->max_degree && tf_terms(p) <= d->n_cases; ++p) {
        const uint32_t orders[2] = {p, TFIT_MODAL_Q15_RANK};
        tf_model *m = fit(ctx, c, NULL, 0, orders);
        if (m == NULL || take(arg, m) != 0) {
            return -1;
        }
    }
    return 0;
}

const tf_family tf_family_modal_q15 = {
    .id = TFIT_FAMILY_MODAL_Q15,
    .name = "modal_q15",
    .kind = TF_FAMILY_FORWARD,
    .applicable = applicable,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_family_rank_text,
    .q31 = NULL,
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
};
