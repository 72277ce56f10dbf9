/*
 * nodal.c — the nodal family: each output component a polynomial of
 * total degree p in the normalised force; one QR factorisation of the
 * design matrix serves all 3 n_out columns.  Degree by cross-validation.
 */
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"

extern const tf_family tf_family_nodal;

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    const tf_fitdata *d = &c->train;
    const uint32_t p = orders[0];
    if (idx == NULL) {
        m = d->n_cases;
    }
    tf_model *model = tf_family_forward_model(ctx, "nodal", TFIT_FAMILY_NODAL, &p, 1, p, d, idx, m);
    if (model == NULL) {
        return NULL;
    }
    const uint32_t t = tf_terms(p);
    const size_t rows = 3 * (size_t)d->n_out;
    double *a = tf_family_design(model, d->force, idx, m, p);
    double *y = tf_family_gather_u(d, idx, m);
    double *x = malloc(t * rows * sizeof *x);
    int rc = (a && y && x) ? tf_family_lsq(ctx, a, m, t, y, rows, x) : -1;
    if (rc == 0) {
        float *coef = tf_model_tables(model);
        for (size_t o = 0; o < rows; ++o) {
            for (uint32_t k = 0; k < t; ++k) {
                coef[o * t + k] = (float)x[k + o * t];
            }
        }
    } else if (!(a && y && x)) {
        tf_fail(ctx, "nodal p=%u: out of memory", p);
    }
    free(a);
    free(y);
    free(x);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}

/* The degree by cross-validation, p >= 0. */
static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    return tf_family_select_by_degree(ctx, c, plan, 0, r);
}

static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    return tf_family_degree_candidates(ctx, &tf_family_nodal, c, plan, 0, take, arg);
}

const tf_family tf_family_nodal = {
    .id = TFIT_FAMILY_NODAL,
    .name = "nodal",
    .kind = TF_FAMILY_FORWARD,
    .applicable = tf_family_always,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_family_degree_text,
    .q31 = tf_q31_quantise,
    .f64_errors = tf_family_poly_f64_errors,
    .cost = tf_family_layout_cost,
};
