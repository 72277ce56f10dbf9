/*
 * modal.c — the modal family: the first r POD modes of the training
 * displacements (pod.h), and each mode's amplitude a polynomial of total
 * degree p in the normalised force.  Amplitudes of the training cases are
 * their projections on the (orthonormal) modes.  The degree by
 * cross-validation at the largest rank searched, then the rank by
 * cross-validation at that degree.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "numerics/pod.h"

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    const tf_fitdata *d = &c->train;
    const uint32_t p = orders[0], r = orders[1];
    if (idx == NULL) {
        m = d->n_cases;
    }
    const size_t rows = 3 * (size_t)d->n_out;
    if (r > m || r > rows) {
        tf_fail(ctx, "modal r=%u: more modes than the %zu cases or %zu outputs", r, m, rows);
        return NULL;
    }
    tf_model *model =
        tf_family_forward_model(ctx, "modal", TFIT_FAMILY_MODAL, orders, 2, p, d, idx, m);
    if (model == NULL) {
        return NULL;
    }
    const uint32_t t = tf_terms(p);
    double *y = tf_family_gather_u(d, idx, m); /* m x rows: row = case */
    double *data = malloc(rows * m * sizeof *data);
    double *amp = malloc(m * r * sizeof *amp);
    double *a = tf_family_design(model, d->force, idx, m, p);
    double *x = malloc(t * r * sizeof *x);
    tf_pod pod = {0};
    int rc = -1;
    if (y && data && amp && a && x) {
        for (size_t i = 0; i < m; ++i) {
            for (size_t o = 0; o < rows; ++o) {
                data[o + i * rows] = y[i + o * m];
            }
        }
        rc = tf_pod_compute(ctx, data, (int)rows, (int)m, &pod);
    } else {
        tf_fail(ctx, "modal p=%u r=%u: out of memory", p, r);
    }
    if (rc == 0) {
        for (size_t i = 0; i < m; ++i) { /* amplitudes: U_r^T u_i */
            for (uint32_t k = 0; k < r; ++k) {
                double s = 0;
                for (size_t o = 0; o < rows; ++o) {
                    s += pod.modes[o + k * rows] * data[o + i * rows];
                }
                amp[i + k * m] = s;
            }
        }
        rc = tf_family_lsq(ctx, a, m, t, amp, r, x);
    }
    if (rc == 0) {
        float *coef = tf_model_tables(model);
        for (uint32_t k = 0; k < r; ++k) {
            for (uint32_t j = 0; j < t; ++j) {
                coef[k * t + j] = (float)x[j + k * t];
            }
        }
        float *u = coef + (size_t)r * t;
        for (size_t o = 0; o < rows; ++o) {
            for (uint32_t k = 0; k < r; ++k) {
                u[o * r + k] = (float)pod.modes[o + k * rows];
            }
        }
    }
    tf_pod_free(&pod);
    free(y);
    free(data);
    free(amp);
    free(a);
    free(x);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}

/* The largest rank the plan and the cases allow. */
static uint32_t top_rank(const tf_cases *c, const tf_fit_plan *plan)
{
    const size_t fold_cases = tf_family_fold_cases(c, plan);
    uint32_t rmax = plan->max_rank;
    if (rmax > TF_FAMILY_MAX_RANK) {
        rmax = TF_FAMILY_MAX_RANK;
    }
    if (rmax > fold_cases) {
        rmax = (uint32_t)fold_cases;
    }
    if (rmax > 3 * c->train.n_out) { /* no more modes than output components (3 outputs: 9) */
        rmax = 3 * c->train.n_out;
    }
    return rmax;
}

/* The degree at the top rank, then the rank at that degree; the held-out
 * error of every rank for the report. */
static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *res)
{
    const uint32_t rmax = top_rank(c, plan);
    uint32_t p;
    if (tf_family_select_degree(ctx, res->family, c, plan, 0, rmax, res->cv, &p) != 0) {
        return -1;
    }
    res->cv_rank[0] = res->heldout_rank[0] = INFINITY;
    for (uint32_t r = 1; r <= TF_FAMILY_MAX_RANK; ++r) {
        const uint32_t orders[2] = {p, r};
        res->cv_rank[r] = res->heldout_rank[r] = INFINITY;
        if (r > rmax) {
            continue;
        }
        if (tf_family_cv_error(ctx, res->family, c, orders, plan->folds, plan->seed,
                               &res->cv_rank[r], NULL) != 0) {
            return -1;
        }
        tf_model *m = fit(ctx, c, NULL, 0, orders);
        if (m == NULL) {
            return -1;
        }
        tf_family_errors(m, &c->heldout, NULL, c->heldout.n_cases, &res->heldout_rank[r], NULL,
                         NULL);
        tf_model_free(m);
    }
    const uint32_t orders[2] = {p, tf_family_cheapest_within(res->cv_rank, 1, rmax)};
    res->model = fit(ctx, c, NULL, 0, orders);
    return res->model ? 0 : -1;
}

/* p = 1 .. max_degree and r = 1 .. max_rank, while the cases and outputs
 * allow: a nonlinear scene's amplitudes pay for degrees above 2 (block48_nh,
 * docs/tradeoff.md). */
static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    const tf_fitdata *d = &c->train;
    for (uint32_t p = 1; p <= plan->max_degree && tf_terms(p) <= d->n_cases; ++p) {
        for (uint32_t r = 1; r <= plan->max_rank && r <= 3 * d->n_out && r <= d->n_cases; ++r) {
            const uint32_t orders[2] = {p, r};
            tf_model *m = fit(ctx, c, NULL, 0, orders);
            if (m == NULL || take(arg, m) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

const tf_family tf_family_modal = {
    .id = TFIT_FAMILY_MODAL,
    .name = "modal",
    .kind = TF_FAMILY_FORWARD,
    .applicable = tf_family_always,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_family_rank_text,
    .q31 = NULL, /* no Q31 form (docs/q31-format.md §1) */
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
};
