/*
 * resonant.c — the resonant family (docs/header-format.md §5.8,
 * docs/fitting.md §8): the static map (a nodal or modal model fitted to the
 * static cases, which a time-dependent solver gives at equilibrium) at the
 * force carried through K damped second-order modes (inertia), fitted to
 * the cases' force histories.
 *
 *   orders {p, r, K, tick_ns}: the static map's degree (and rank, 0 for
 *   nodal), the modes, the histories' tick.
 *
 * Applies when the cases carry histories and the plan asks for it
 * (fit.family: resonant): the pipeline then designs dynamic histories
 * (strikes, press-release, ramps, smooth random forces; histories.h).  The
 * order search: p by the nodal family's cross-validation on the static
 * cases; K = 0 .. TF_RESONANT_SEARCH_MODES by cross-validation over the
 * training histories (folds of whole histories, the RMS of the static
 * map's input h), the cheapest within 2 % of the best.  Held-out errors
 * are those of the float32 model stepped through the held-out histories
 * against the truth (shared with prony: tf_prony_history_errors).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "fitting/families/resonant_family.h"
#include "fitting/histories.h"
#include "fitting/resonant_modes.h"
#include "model/basis.h"
#include "model/forms/resonant.h"
#include "model/oscillator.h"

extern const tf_family tf_family_resonant;

static const tf_family *static_family(uint32_t r)
{
    return tf_family_find(r == 0 ? "nodal" : "modal");
}

/* The lowest omega whose mode the float recursion carries at zeta_lo
 * (tf_resonant_params_check; the margin grows with omega T and zeta, so
 * every mode of the box above it passes), by bisection in log omega. */
static double lowest_carried(double tick, double zeta_lo, double omega_hi)
{
    char err[512];
    double lo = 1e-6 * omega_hi, hi = omega_hi;
    for (int it = 0; it < 60; ++it) {
        const double mid = sqrt(lo * hi);
        if (tf_resonant_params_check(mid, zeta_lo, tick, err, sizeof err) == 0) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return 1.05 * hi; /* clear of the rounding's few per cent */
}

void tf_resonant_bounds_for(const tf_histories *h, tf_resonant_bounds *b)
{
    const double length = (double)h->train.n_ticks * h->tick;
    b->zeta_lo = TF_RESONANT_ZETA_LO;
    b->zeta_hi = 1.0;
    b->omega_hi = TF_RESONANT_MAX_WT / h->tick;
    b->omega_lo = fmin(0.5 * b->omega_hi,
                       fmax(2 * 6.28318530717958647692 / length,
                            lowest_carried(h->tick, b->zeta_lo, b->omega_hi)));
}

tf_model *tf_resonant_assemble(const tf_model *s, const tf_resonant_modes *t, uint32_t tick_ns,
                               char *err, size_t errlen)
{
    const uint32_t dims[TFIT_RESONANT_DIMS] = {s->dims[0],
                                               s->family == TFIT_FAMILY_MODAL ? s->dims[1] : 0,
                                               (uint32_t)t->n, tick_ns};
    tf_model *m = tf_model_new("resonant", TFIT_FAMILY_RESONANT, s->n_out, dims,
                               TFIT_RESONANT_DIMS, err, errlen);
    if (m == NULL) {
        return NULL;
    }
    memcpy(m->coef, s->coef, TFIT_INPUT_MAP_FLOATS * sizeof *m->coef);
    memcpy(m->coef + TFIT_INPUT_MAP_FLOATS + 7 * t->n, s->coef + TFIT_INPUT_MAP_FLOATS,
           (s->n_coef - TFIT_INPUT_MAP_FLOATS) * sizeof *m->coef);
    memcpy(m->node_ids, s->node_ids, s->n_out * sizeof *m->node_ids);
    m->envelope_radius = s->envelope_radius;
    for (int k = 0; k < t->n; ++k) {
        if (tf_resonant_params_check(t->omega[k], t->zeta[k], 1e-9 * tick_ns, err, errlen) != 0) {
            tf_model_free(m);
            return NULL;
        }
        tf_resonant_set_mode(m, (uint32_t)k, t->omega[k], t->zeta[k], t->w[k]);
    }
    return m;
}

/* The static map of orders {p, r} on static cases idx, the modes of K on
 * every training history, the model. */
static tf_model *fit(const tf_cases *c, const size_t *idx, size_t m, const uint32_t *orders,
                     char *err, size_t errlen)
{
    const tf_histories *h = c->hist;
    if (h == NULL) {
        snprintf(err, errlen, "resonant: no force histories (the solver is not time-dependent)");
        return NULL;
    }
    const uint32_t static_orders[2] = {orders[0], orders[1]};
    tf_model *s = static_family(orders[1])->fit(c, idx, m, static_orders, err, errlen);
    if (s == NULL) {
        return NULL;
    }
    tf_prony_data d;
    tf_resonant_modes t;
    tf_resonant_bounds b;
    tf_resonant_bounds_for(h, &b);
    tf_model *model = NULL;
    if (tf_prony_data_build(s, &h->train, h->tick, &d, err, errlen) == 0) {
        if (tf_resonant_fit_modes(&d, NULL, 0, (int)orders[2], &b, &t, err, errlen) == 0) {
            model = tf_resonant_assemble(s, &t, h->tick_ns, err, errlen);
        }
        tf_prony_data_free(&d);
    }
    tf_model_free(s);
    return model;
}

/* One fold of the mode search (tf_family_history_cv). */
typedef struct {
    const tf_prony_data *d;
    const tf_resonant_bounds *b;
    char *err;
    size_t errlen;
} resonant_fold_ctx;

static int resonant_fold(void *ctx, int k, const size_t *train, size_t nt, const size_t *valid,
                         size_t nv, double *rms)
{
    const resonant_fold_ctx *x = ctx;
    tf_resonant_modes t;
    if (tf_resonant_fit_modes_from(x->d, train, nt, k, x->b, TF_RESONANT_CV_STARTS, &t, x->err,
                                   x->errlen) != 0) {
        return -1;
    }
    *rms = tf_resonant_modes_rms(x->d, valid, nv, &t);
    return 0;
}

int tf_resonant_select_modes(const tf_prony_data *d, const tf_histories *h,
                             const tf_fit_plan *plan, double *cv, int *best,
                             tf_resonant_modes *modes, char *err, size_t errlen)
{
    tf_resonant_bounds b;
    tf_resonant_bounds_for(h, &b);
    const size_t n = d->n_hist, folds = plan->folds < n ? plan->folds : n;
    resonant_fold_ctx x = {d, &b, err, errlen};
    if (tf_family_history_cv(n, folds, TF_RESONANT_SEARCH_MODES, resonant_fold, &x, cv) != 0) {
        snprintf(err, errlen, "resonant: out of memory");
        return -1;
    }
    *best = (int)tf_family_cheapest_within(cv, 0, TF_RESONANT_SEARCH_MODES);
    if (!isfinite(cv[*best])) {
        snprintf(err, errlen, "%s: resonant: no number of modes is determined by %zu histories",
                 TF_FAMILY_UNDETERMINED, n);
        return -1;
    }
    return tf_resonant_fit_modes(d, NULL, 0, *best, &b, modes, err, errlen);
}

static int select_orders(const tf_cases *c, const tf_fit_plan *plan, tf_family_result *r,
                         char *err, size_t errlen)
{
    uint32_t p;
    const tf_family *nodal = static_family(0);
    if (tf_family_select_degree(nodal, c, plan, 0, 0, r->cv, &p, err, errlen) != 0) {
        return -1;
    }
    tf_model *s = nodal->fit(c, NULL, 0, &p, err, errlen);
    if (s == NULL) {
        return -1;
    }
    tf_prony_data d;
    tf_resonant_modes t;
    double cv[TF_RESONANT_SEARCH_MODES + 1];
    int k, rc = tf_prony_data_build(s, &c->hist->train, c->hist->tick, &d, err, errlen);
    if (rc == 0) {
        rc = tf_resonant_select_modes(&d, c->hist, plan, cv, &k, &t, err, errlen);
        tf_prony_data_free(&d);
    }
    if (rc == 0) {
        r->model = tf_resonant_assemble(s, &t, c->hist->tick_ns, err, errlen);
    }
    tf_model_free(s);
    return r->model != NULL ? 0 : -1;
}

static int candidates(const tf_cases *c, const tf_fit_plan *plan, tf_family_take take, void *arg,
                      char *err, size_t errlen)
{
    for (uint32_t p = 0; p <= plan->max_degree; ++p) {
        for (uint32_t k = 0; k <= TF_RESONANT_SEARCH_MODES; ++k) {
            if (tf_terms(p) > c->train.n_cases) {
                return 0;
            }
            const uint32_t orders[TFIT_RESONANT_DIMS] = {p, 0, k, c->hist->tick_ns};
            tf_model *m = fit(c, NULL, 0, orders, err, errlen);
            if (m == NULL || take(arg, m) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

static int applicable(const tf_cases *c, const tf_fit_plan *plan, char *why, size_t whylen)
{
    if (c->hist == NULL) {
        snprintf(why, whylen, "the problem has no inertia to fit: its solver is not "
                              "time-dependent, so there are no force histories");
        return -1;
    }
    if (plan->family != &tf_family_resonant) {
        snprintf(why, whylen, "fitted only when asked for (fit.family: resonant), which "
                              "designs dynamic histories (strikes) for it");
        return -1;
    }
    return 0;
}

const tf_family tf_family_resonant = {
    .id = TFIT_FAMILY_RESONANT,
    .name = "resonant",
    .kind = TF_FAMILY_FORWARD,
    .applicable = applicable,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_stateful_orders_text,
    .q31 = NULL,
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
    .heldout = tf_stateful_heldout,
};
