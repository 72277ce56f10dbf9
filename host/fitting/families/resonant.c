/*
 * resonant.c — the resonant family (docs/header-format.md §5.8,
 * docs/fitting.md §8): the static map (a nodal or modal model fitted to the
 * static cases, which a time-dependent solver gives at equilibrium) at the
 * force carried through K damped second-order modes (inertia), fitted to
 * the cases' force histories by the stateful families' loop
 * (stateful_family.h) with this filter fit: the modes' frequencies,
 * damping ratios and weights (fitting/resonant_modes.h) within the bounds
 * the tick allows.
 *
 *   orders {p, r, K, tick_ns}: the static map's degree (and rank, 0 for
 *   nodal), the modes, the histories' tick.
 *
 * Applies when the cases carry histories and the plan asks for it
 * (fit.family: resonant): the pipeline then designs dynamic histories
 * (strikes, press-release, ramps, smooth random forces; histories.h).
 * K = 0 .. TF_RESONANT_SEARCH_MODES are searched.
 */
#include <math.h>
#include <stdio.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "fitting/families/resonant_family.h"
#include "fitting/families/stateful_family.h"
#include "fitting/histories.h"
#include "fitting/resonant_modes.h"
#include "model/forms/resonant.h"
#include "model/oscillator.h"

extern const tf_family tf_family_resonant;

/* The lowest omega whose mode the float recursion carries at zeta_lo
 * (tf_resonant_params_check; the margin grows with omega T and zeta, so
 * every mode of the box above it passes), by bisection in log omega. */
static double lowest_carried(double tick, double zeta_lo, double omega_hi)
{
    tf_ctx scratch; /* a test, not a failure: the message is not wanted */
    tf_ctx_init(&scratch);
    double lo = 1e-6 * omega_hi, hi = omega_hi;
    for (int it = 0; it < 60; ++it) {
        const double mid = sqrt(lo * hi);
        if (tf_resonant_params_check(&scratch, mid, zeta_lo, tick) == 0) {
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

tf_model *tf_resonant_assemble(tf_ctx *ctx, const tf_model *s, const tf_resonant_modes *t,
                               uint32_t tick_ns)
{
    for (int k = 0; k < t->n; ++k) {
        if (tf_resonant_params_check(ctx, t->omega[k], t->zeta[k], 1e-9 * tick_ns) != 0) {
            return NULL;
        }
    }
    tf_model *m =
        tf_stateful_new(ctx, TFIT_FAMILY_RESONANT, "resonant", s, (uint32_t)t->n, tick_ns);
    for (int k = 0; m != NULL && k < t->n; ++k) {
        tf_resonant_set_mode(m, (uint32_t)k, t->omega[k], t->zeta[k], t->w[k]);
    }
    return m;
}

/* ---- the filter fit -------------------------------------------------------- */

/* TF_RESONANT_STARTS frequencies for each new mode of a model,
 * TF_RESONANT_CV_STARTS in cross-validation's folds. */
static int fit_modes(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h, const size_t *idx,
                     size_t n, int k, int cv, void *modes)
{
    tf_resonant_bounds b;
    tf_resonant_bounds_for(h, &b);
    return cv ? tf_resonant_fit_modes_from(ctx, d, idx, n, k, &b, TF_RESONANT_CV_STARTS, modes)
              : tf_resonant_fit_modes(ctx, d, idx, n, k, &b, modes);
}

static double rms(const tf_prony_data *d, const size_t *idx, size_t n, const void *modes)
{
    return tf_resonant_modes_rms(d, idx, n, modes);
}

static tf_model *assemble(tf_ctx *ctx, const tf_model *s, const void *modes, const tf_histories *h)
{
    return tf_resonant_assemble(ctx, s, modes, h->tick_ns);
}

static const tf_filter_fit resonant_fit = {
    .name = "resonant",
    .terms = "modes",
    .id = TFIT_FAMILY_RESONANT,
    .search = TF_RESONANT_SEARCH_MODES,
    .size = sizeof(tf_resonant_modes),
    .fit = fit_modes,
    .rms = rms,
    .assemble = assemble,
};

int tf_resonant_select_modes(tf_ctx *ctx, const tf_prony_data *d, const tf_histories *h,
                             const tf_fit_plan *plan, double *cv, int *best,
                             tf_resonant_modes *modes)
{
    return tf_stateful_select_terms(ctx, &resonant_fit, d, h, plan, cv, best, modes);
}

/* ---- the family ----------------------------------------------------------- */

static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    return tf_stateful_fit(ctx, &resonant_fit, c, idx, m, orders);
}

static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    return tf_stateful_select(ctx, &resonant_fit, c, plan, r);
}

static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    return tf_stateful_candidates(ctx, &resonant_fit, c, plan, take, arg);
}

static int applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    if (c->hist == NULL) {
        return tf_fail(ctx, "the problem has no inertia to fit: its solver is not "
                            "time-dependent, so there are no force histories");
    }
    if (plan->family != &tf_family_resonant) {
        return tf_fail(ctx, "fitted only when asked for (fit.family: resonant), which "
                            "designs dynamic histories (strikes) for it");
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
