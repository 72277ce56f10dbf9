/*
 * cut.c — the cut family (docs/cutting.md, "Cut progress"): the
 * displacements as a function of (force, s), s the progress of the scene's
 * cuts along their paths.  At each knot s_k = k / K a nodal table of degree
 * p in the force, fitted by least squares to the training forces'
 * responses at that s (p = 1 is exact per s for linear elasticity); linear
 * in s between knots (tfit_cut.c).  K by validation on the s values
 * between the finest knots, which no fit sees; the error the header states
 * is at held-out s values and held-out forces (cut_progress.h).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/cut_progress.h"
#include "fitting/families/common.h"
#include "fitting/families/family.h"

extern const tf_family tf_family_cut;

#define CUT_DEGREE 1 /* exact per s for linear elasticity (the affine solvers it needs) */

static int applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    (void)plan;
    if (c->cut == NULL) {
        return tf_fail(ctx, "cut: needs a scene with cuts and fit.cut_intervals (the cut "
                            "progress values to solve)");
    }
    return 0;
}

/* Knot k of a K-interval model: sample k K_max / K of the cut cases. */
static int fit_knot(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m, tf_model *model,
                    uint32_t k)
{
    const tf_cut_cases *cc = c->cut;
    const tf_fitdata *d = &c->train;
    const uint32_t p = model->dims[0], t = tf_terms(p);
    const size_t rows = cc->rows, sample = (size_t)k * (cc->knots / model->dims[1]);
    double *a = tf_family_design(model, d->force, idx, m, p);
    double *y = malloc(m * rows * sizeof *y), *u = malloc(rows * sizeof *u);
    double *x = malloc(t * rows * sizeof *x);
    int rc = (a && y && u && x) ? 0 : -1;
    for (size_t i = 0; rc == 0 && i < m; ++i) {
        tf_cut_cases_response(cc, sample, d->force[tf_family_case(idx, i)], u);
        for (size_t o = 0; o < rows; ++o) {
            y[i + o * m] = u[o];
        }
    }
    if (rc != 0) {
        tf_fail(ctx, "cut: out of memory");
    } else {
        rc = tf_family_lsq(ctx, a, m, t, y, rows, x);
    }
    float *coef = tf_model_tables(model) + (size_t)k * rows * t;
    for (size_t o = 0; rc == 0 && o < rows; ++o) {
        for (uint32_t j = 0; j < t; ++j) {
            coef[o * t + j] = (float)x[j + o * t];
        }
    }
    free(a);
    free(y);
    free(u);
    free(x);
    return rc;
}

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    const uint32_t p = orders[0], k = orders[1];
    if (c->cut == NULL || k == 0 || c->cut->knots % k != 0) {
        tf_fail(ctx, "cut: %u intervals are not a divisor of the %u solved", k,
                c->cut ? c->cut->knots : 0);
        return NULL;
    }
    if (idx == NULL) {
        m = c->train.n_cases;
    }
    tf_model *model = tf_family_forward_model(ctx, "cut", TFIT_FAMILY_CUT, orders, TFIT_CUT_DIMS, p,
                                              &c->train, idx, m);
    for (uint32_t j = 0; model != NULL && j <= k; ++j) {
        if (fit_knot(ctx, c, idx, m, model, j) != 0) {
            tf_model_free(model);
            model = NULL;
        }
    }
    return model;
}

/* Errors of a cut model at the cut samples of one role and the forces
 * of d (cut_progress.h).  Returns 0, or -1 when out of memory. */
static int role_errors(const tf_model *m, const tf_cut_cases *cc, int role,
                       const tf_fitdata *d, double *max, double *rms, uint32_t *n)
{
    double emax = 0, sum2 = 0;
    size_t count = 0;
    for (size_t i = 0; i < cc->n; ++i) {
        double imax, isum2;
        if (cc->role[i] != role) {
            continue;
        }
        if (tf_cut_cases_errors(m, cc, i, d, &imax, &isum2) != 0) {
            return -1;
        }
        emax = fmax(emax, imax);
        sum2 += isum2;
        count += d->n_cases;
    }
    *max = emax;
    *rms = count > 0 ? sqrt(sum2 / ((double)count * cc->rows)) : 0;
    if (n != NULL) {
        *n = (uint32_t)count;
    }
    return 0;
}

/* K = K_max, K_max / 2, ..., 1 by the RMS error at the validation s values
 * (cv_rank[K]); the cheapest within 2 % of the best (common.h). */
static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    (void)plan;
    double v[TFIT_CUT_MAX_INTERVALS + 1];
    for (uint32_t k = 0; k <= TFIT_CUT_MAX_INTERVALS; ++k) {
        v[k] = INFINITY;
    }
    for (uint32_t k = 1; k <= c->cut->knots; k *= 2) {
        const uint32_t orders[2] = {CUT_DEGREE, k};
        tf_model *m = fit(ctx, c, NULL, 0, orders);
        double max, rms;
        if (m == NULL) {
            return -1;
        }
        int rc = role_errors(m, c->cut, TF_CUT_VALIDATE, &c->train, &max, &rms, NULL);
        tf_model_free(m);
        if (rc != 0) {
            return tf_fail(ctx, "cut: out of memory");
        }
        v[k] = rms;
        if (k <= TF_FAMILY_MAX_RANK) {
            r->cv_rank[k] = rms;
            r->heldout_rank[k] = max;
        }
    }
    const uint32_t orders[2] = {CUT_DEGREE, tf_family_cheapest_within(v, 1, c->cut->knots)};
    r->cv[CUT_DEGREE] = v[orders[1]];
    r->model = fit(ctx, c, NULL, 0, orders);
    return r->model ? 0 : -1;
}

static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    (void)plan;
    for (uint32_t k = 1; k <= c->cut->knots; k *= 2) {
        const uint32_t orders[2] = {CUT_DEGREE, k};
        tf_model *m = fit(ctx, c, NULL, 0, orders);
        if (m == NULL) {
            return -1;
        }
        if (take(arg, m) != 0) {
            return -1;
        }
    }
    return 0;
}

static void orders_text(const tf_model *m, int style, char *buf, size_t n)
{
    (void)style;
    snprintf(buf, n, "p=%u K=%u", m->dims[0], m->dims[1]);
}

/* Held-out: every held-out s value at every held-out force. */
static int heldout(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max, double *rms,
                   double *rel_max, uint32_t *n)
{
    *rel_max = NAN;
    if (role_errors(m, c->cut, TF_CUT_HELDOUT, &c->heldout, max, rms, n) != 0) {
        return tf_fail(ctx, "cut: out of memory for its held-out errors");
    }
    return 0;
}

const tf_family tf_family_cut = {
    .id = TFIT_FAMILY_CUT,
    .name = "cut",
    .kind = TF_FAMILY_FORWARD,
    .applicable = applicable,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = orders_text,
    .q31 = NULL,
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
    .heldout = heldout,
};
