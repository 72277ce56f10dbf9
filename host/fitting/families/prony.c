/*
 * prony.c — the prony family (docs/header-format.md §5.6, docs/fitting.md
 * §7): the relaxed static map (a nodal or modal model fitted to the static
 * cases, which a time-dependent solver gives fully relaxed) at the force
 * filtered by K exponential terms, fitted to the cases' force histories by
 * the stateful families' loop (stateful_family.h) with this filter fit:
 * the terms' time constants and weights (fitting/prony_terms.h), time
 * constants from the tick to the histories' length.
 *
 *   orders {p, r, K, tick_ns}: the static map's degree (and rank, 0 for
 *   nodal), the terms, the histories' tick.
 *
 * Applies when the cases carry histories (a time-dependent solver, or the
 * synthetic linear creep of histories.h).  K = 0 ..
 * TF_PRONY_SEARCH_TERMS are searched.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "fitting/families/stateful_family.h"
#include "fitting/histories.h"
#include "fitting/prony_terms.h"
#include "model/forms/prony.h"

/* Time constants a tick resolves and float32 updates accurately: from the
 * tick up to the histories' length (longer ones the data cannot tell
 * apart from a static offset); beyond TF_PRONY_MAX_TAU_TICKS ticks the
 * model is refused (tf_prony_tick_allows). */
static void tau_range(const tf_histories *h, double *lo, double *hi)
{
    *lo = h->tick;
    *hi = fmax(2 * h->tick, (double)h->train.n_ticks * h->tick);
}

int tf_prony_tick_allows(tf_ctx *ctx, const tf_prony_terms *t, const tf_histories *h)
{
    for (int k = 0; k < t->n; ++k) {
        if (t->tau[k] > TF_PRONY_MAX_TAU_TICKS * h->tick) {
            return tf_fail(
                ctx,
                "prony: the creep time constant %.4g s is %.3g ticks of %u ns: beyond %.0e "
                "ticks the float32 update loses more than 0.1 %% of the peak over 10^6 "
                "ticks (docs/fitting.md §7); fit with a tick of at least %.3g us",
                t->tau[k], t->tau[k] / h->tick, h->tick_ns, TF_PRONY_MAX_TAU_TICKS,
                1e6 * t->tau[k] / TF_PRONY_MAX_TAU_TICKS);
        }
    }
    return 0;
}

/* ---- the filter fit -------------------------------------------------------- */

/* Three starts for a model, one for each of cross-validation's folds. */
static int fit_terms(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h, const size_t *idx,
                     size_t n, int k, int cv, void *terms)
{
    double lo, hi;
    tau_range(h, &lo, &hi);
    return cv ? tf_prony_fit_terms_from(ctx, d, idx, n, k, lo, hi, 1, terms)
              : tf_prony_fit_terms(ctx, d, idx, n, k, lo, hi, terms);
}

static double rms(const tf_prony_data *d, const size_t *idx, size_t n, const void *terms)
{
    return tf_prony_terms_rms(d, idx, n, terms);
}

/* The prony model of static map s and terms t at the histories' tick: s's
 * input map and tables after the terms' pairs (model/forms/prony.h); a term
 * too slow for the tick is refused. */
static tf_model *assemble(tf_ctx *ctx, const tf_model *s, const void *terms, const tf_histories *h)
{
    const tf_prony_terms *t = terms;
    if (tf_prony_tick_allows(ctx, t, h) != 0) {
        return NULL;
    }
    tf_model *m = tf_stateful_new(ctx, TFIT_FAMILY_PRONY, "prony", s, (uint32_t)t->n, h->tick_ns);
    for (int k = 0; m != NULL && k < t->n; ++k) {
        tf_prony_set_term(m, (uint32_t)k, t->tau[k], t->w[k]);
    }
    return m;
}

static const tf_filter_fit prony_fit = {
    .name = "prony",
    .terms = "terms",
    .id = TFIT_FAMILY_PRONY,
    .search = TF_PRONY_SEARCH_TERMS,
    .size = sizeof(tf_prony_terms),
    .fit = fit_terms,
    .rms = rms,
    .assemble = assemble,
};

int tf_prony_select_terms(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h,
                          const tf_fit_plan *plan, double *cv, int *best, tf_prony_terms *terms)
{
    return tf_stateful_select_terms(ctx, &prony_fit, d, h, plan, cv, best, terms);
}

/* ---- the family ----------------------------------------------------------- */

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    return tf_stateful_fit(ctx, &prony_fit, c, idx, m, orders);
}

static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    return tf_stateful_select(ctx, &prony_fit, c, plan, r);
}

static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    return tf_stateful_candidates(ctx, &prony_fit, c, plan, take, arg);
}

static int applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    (void)plan;
    if (c->hist == NULL) {
        return tf_fail(ctx, "the problem does not creep: its solver is not time-dependent, so "
                            "there are no force histories to fit time constants to");
    }
    return 0;
}

double tf_prony_q31_heldout(const tf_model *m, const tf_cases *c)
{
    if (c->hist == NULL) {
        return NAN;
    }
    const tf_history_set *set = &c->hist->heldout;
    tf_ctx scratch; /* no Q31 form gives NAN: its message is not wanted */
    tf_ctx_init(&scratch);
    tf_q31 *q = m->family == TFIT_FAMILY_PRONY ? tf_q31_quantise(&scratch, m) : NULL;
    const size_t rows = 3 * (size_t)m->n_out;
    int32_t *out = malloc(rows * sizeof *out);
    double e_max = NAN;
    for (size_t h = 0; q != NULL && out != NULL && h < set->n; ++h) {
        int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
        tf_q31_ref_prony_reset(q, state);
        e_max = h == 0 ? 0 : e_max;
        for (size_t n = 0; n < set->n_ticks; ++n) {
            const double *f = tf_history_force(set, h, n), *u = tf_history_u(set, h, n);
            const int32_t in[3] = {tf_q31_from_value((double)(float)f[0], q->in_exp),
                                   tf_q31_from_value((double)(float)f[1], q->in_exp),
                                   tf_q31_from_value((double)(float)f[2], q->in_exp)};
            tf_q31_ref_prony_step(q, state, in, out);
            for (size_t o = 0; o < rows; ++o) {
                e_max = fmax(e_max, fabs(tf_q31_to_value(out[o], q->out_exp) - u[o]));
            }
        }
    }
    free(out);
    tf_q31_free(q);
    return e_max;
}

const tf_family tf_family_prony = {
    .id = TFIT_FAMILY_PRONY,
    .name = "prony",
    .kind = TF_FAMILY_FORWARD,
    .applicable = applicable,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = tf_stateful_orders_text,
    .q31 = tf_q31_quantise, /* nodal static maps (q31-format.md §8) */
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
    .heldout = tf_stateful_heldout,
};
