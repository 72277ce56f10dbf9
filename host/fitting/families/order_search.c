/*
 * order_search.c — choosing a family's degree by k-fold cross-validation,
 * and the order search and sweep candidates of the families searched by
 * degree alone (common.h).
 */
#include <math.h>
#include <stdio.h>

#include "fitting/families/common.h"

/* Below this CV error a higher order buys nothing the float32 target can
 * show (mm or N). */
#define CV_FLOOR 1e-6

uint32_t tf_family_cheapest_within(const double *v, uint32_t lo, uint32_t hi)
{
    double best = INFINITY;
    for (uint32_t i = lo; i <= hi; ++i) {
        best = fmin(best, v[i]);
    }
    for (uint32_t i = lo; i <= hi; ++i) {
        if (v[i] <= 1.02 * best + CV_FLOOR) {
            return i;
        }
    }
    return lo;
}

size_t tf_family_fold_cases(const tf_cases *c, const tf_fit_plan *plan)
{
    const size_t n = c->train.n_cases;
    return n - (n + plan->folds - 1) / plan->folds;
}

int tf_family_select_degree(tf_ctx *ctx, const tf_family *f, const tf_cases *c,
                            const tf_fit_plan *plan, uint32_t lo, uint32_t extra, double *cv,
                            uint32_t *best)
{
    const size_t fold_cases = tf_family_fold_cases(c, plan);
    uint32_t hi = lo;
    for (uint32_t p = 0; p <= TFIT_MAX_DEGREE; ++p) {
        cv[p] = INFINITY;
        if (p < lo || p > plan->max_degree || tf_terms(p) > fold_cases) {
            continue;
        }
        const uint32_t orders[2] = {p, extra};
        if (tf_family_cv_error(ctx, f, c, orders, plan->folds, plan->seed, &cv[p], NULL) != 0) {
            return -1;
        }
        hi = p;
    }
    *best = tf_family_cheapest_within(cv, lo, hi);
    if (!isfinite(cv[*best])) {
        return tf_fail(
            ctx,
            "%s: no degree is determined by the %zu training cases (repeated or collinear "
            "load cases?)",
            TF_FAMILY_UNDETERMINED, c->train.n_cases);
    }
    return 0;
}

int tf_family_select_by_degree(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, uint32_t lo,
                               tf_family_result *r)
{
    uint32_t p;
    if (tf_family_select_degree(ctx, r->family, c, plan, lo, 0, r->cv, &p) != 0) {
        return -1;
    }
    r->model = r->family->fit(ctx, c, NULL, 0, &p);
    return r->model ? 0 : -1;
}

int tf_family_degree_candidates(tf_ctx *ctx, const tf_family *f, const tf_cases *c,
                                const tf_fit_plan *plan, uint32_t lo, tf_family_take take,
                                void *arg)
{
    for (uint32_t p = lo; p <= plan->max_degree; ++p) {
        if (tf_terms(p) > c->train.n_cases) {
            continue;
        }
        tf_model *m = f->fit(ctx, c, NULL, 0, &p);
        if (m == NULL || take(arg, m) != 0) {
            return -1;
        }
    }
    return 0;
}
