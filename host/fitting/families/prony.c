/*
 * prony.c — the prony family (docs/header-format.md §5.6, docs/fitting.md
 * §7): the relaxed static map (a nodal or modal model fitted to the static
 * cases, which a time-dependent solver gives fully relaxed) at the force
 * filtered by K exponential terms, fitted to the cases' force histories.
 *
 *   orders {p, r, K, tick_ns}: the static map's degree (and rank, 0 for
 *   nodal), the terms, the histories' tick.
 *
 * Applies when the cases carry histories (a time-dependent solver, or the
 * synthetic linear creep of histories.h).  The order search: p by the
 * nodal family's cross-validation on the static cases; K = 0 ..
 * TF_PRONY_SEARCH_TERMS by cross-validation over the training histories
 * (folds of whole histories, the RMS of the static map's input h), the
 * cheapest within 2 % of the best.  Held-out errors are those of the
 * float32 model stepped through the held-out histories (tf_stateful_step)
 * against the truth, relative to the largest displacement there.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/families/common.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "fitting/histories.h"
#include "fitting/prony_terms.h"
#include "model/basis.h"
#include "model/forms/prony.h"
#include "model/forms/stateful.h"

extern const tf_family tf_family_prony;

/* ---- the static map's input h from the truth ----------------------------- */

/* The static map of s at h in double (its float coefficients): nodal rows or
 * modal modes times amplitudes. */
static void static_map(const tf_model *s, const double h[3], double *phi, double *amp, double *u)
{
    const uint32_t p = s->dims[0], t = tf_terms(p), rows = 3 * s->n_out;
    const float *c = s->coef + TFIT_INPUT_MAP_FLOATS;
    tf_basis(p, h, phi);
    const uint32_t r = s->family == TFIT_FAMILY_MODAL ? s->dims[1] : 0;
    for (uint32_t k = 0; k < r; ++k) {
        amp[k] = 0;
        for (uint32_t j = 0; j < t; ++j) {
            amp[k] += (double)c[k * t + j] * phi[j];
        }
    }
    for (uint32_t o = 0; o < rows; ++o) {
        double v = 0;
        if (r == 0) {
            for (uint32_t j = 0; j < t; ++j) {
                v += (double)c[o * t + j] * phi[j];
            }
        } else {
            for (uint32_t k = 0; k < r; ++k) {
                v += (double)c[r * t + o * r + k] * amp[k];
            }
        }
        u[o] = v;
    }
}

/* h minimising |S(h) - u| by Gauss-Newton from h (central differences in
 * h; the 3 x 3 normal equations by Cramer's rule). */
static void solve_h(const tf_model *s, const double *u, double h[3], double *work)
{
    const uint32_t rows = 3 * s->n_out;
    double *phi = work, *amp = phi + TF_FAMILY_MAX_TERMS, *f0 = amp + TFIT_MAX_RANK;
    double *jac = f0 + rows, *fp = jac + 3 * (size_t)rows;
    for (int it = 0; it < 8; ++it) {
        static_map(s, h, phi, amp, f0);
        for (int c = 0; c < 3; ++c) {
            double hp[3] = {h[0], h[1], h[2]}, hm[3] = {h[0], h[1], h[2]};
            hp[c] += 1e-6;
            hm[c] -= 1e-6;
            static_map(s, hp, phi, amp, fp);
            static_map(s, hm, phi, amp, jac + (size_t)c * rows);
            for (uint32_t o = 0; o < rows; ++o) {
                jac[(size_t)c * rows + o] = (fp[o] - jac[(size_t)c * rows + o]) / 2e-6;
            }
        }
        double a[3][3] = {{0}}, b[3] = {0};
        for (int i = 0; i < 3; ++i) {
            for (uint32_t o = 0; o < rows; ++o) {
                b[i] += jac[(size_t)i * rows + o] * (u[o] - f0[o]);
                for (int j = 0; j < 3; ++j) {
                    a[i][j] += jac[(size_t)i * rows + o] * jac[(size_t)j * rows + o];
                }
            }
        }
        const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        if (!(fabs(det) > 0)) {
            return;
        }
        double step = 0;
        for (int c = 0; c < 3; ++c) { /* Cramer: column c replaced by b */
            double m[3][3];
            memcpy(m, a, sizeof m);
            for (int i = 0; i < 3; ++i) {
                m[i][c] = b[i];
            }
            const double dc = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) / det;
            h[c] += dc;
            step = fmax(step, fabs(dc));
        }
        if (step < 1e-13) {
            return;
        }
    }
}

/* g of force f as the device projects it (inside the ball: W (f - x0)). */
static void project(const tf_model *s, const double f[3], double g[3])
{
    tf_family_normalise(s, f, g);
    const double n = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    for (int c = 0; n > 1 && c < 3; ++c) {
        g[c] /= n;
    }
}

void tf_prony_data_free(tf_prony_data *d)
{
    free((void *)d->g);
    free((void *)d->target);
    d->g = d->target = NULL;
}

int tf_prony_data_build(const tf_model *s, const tf_history_set *set, double tick,
                        tf_prony_data *d, char *err, size_t errlen)
{
    const size_t ticks = set->n * set->n_ticks, rows = 3 * (size_t)s->n_out;
    double *g = malloc(3 * ticks * sizeof *g), *h = malloc(3 * ticks * sizeof *h);
    double *work = malloc((TF_FAMILY_MAX_TERMS + TFIT_MAX_RANK + 5 * rows) * sizeof *work);
    if (g == NULL || h == NULL || work == NULL) {
        free(g);
        free(h);
        free(work);
        snprintf(err, errlen, "prony: out of memory for %zu ticks", ticks);
        return -1;
    }
    *d = (tf_prony_data){.n_hist = set->n, .n_ticks = set->n_ticks, .g = g, .target = h,
                         .tick = tick};
    const double zero[3] = {0, 0, 0};
    project(s, zero, d->g_rest);
    for (size_t hi = 0; hi < set->n; ++hi) {
        double cur[3];
        memcpy(cur, d->g_rest, sizeof cur);
        for (size_t n = 0; n < set->n_ticks; ++n) {
            const size_t at = 3 * (hi * set->n_ticks + n);
            project(s, tf_history_force(set, hi, n), g + at);
            solve_h(s, tf_history_u(set, hi, n), cur, work); /* from the last tick's h */
            memcpy(h + at, cur, sizeof cur);
        }
    }
    free(work);
    return 0;
}

/* ---- models ------------------------------------------------------------- */

static const tf_family *static_family(uint32_t r)
{
    return tf_family_find(r == 0 ? "nodal" : "modal");
}

/* The prony model of static map s and terms t at tick_ns: s's input map and
 * tables after the terms' pairs (prony.h). */
static tf_model *assemble(const tf_model *s, const tf_prony_terms *t, uint32_t tick_ns, char *err,
                          size_t errlen)
{
    const uint32_t dims[TFIT_PRONY_DIMS] = {s->dims[0],
                                            s->family == TFIT_FAMILY_MODAL ? s->dims[1] : 0,
                                            (uint32_t)t->n, tick_ns};
    tf_model *m = tf_model_new("prony", TFIT_FAMILY_PRONY, s->n_out, dims, TFIT_PRONY_DIMS, err,
                               errlen);
    if (m == NULL) {
        return NULL;
    }
    memcpy(m->coef, s->coef, TFIT_INPUT_MAP_FLOATS * sizeof *m->coef);
    memcpy(m->coef + TFIT_INPUT_MAP_FLOATS + 2 * t->n, s->coef + TFIT_INPUT_MAP_FLOATS,
           (s->n_coef - TFIT_INPUT_MAP_FLOATS) * sizeof *m->coef);
    memcpy(m->node_ids, s->node_ids, s->n_out * sizeof *m->node_ids);
    m->envelope_radius = s->envelope_radius;
    for (int k = 0; k < t->n; ++k) {
        tf_prony_set_term(m, (uint32_t)k, t->tau[k], t->w[k]);
    }
    return m;
}

/* Time constants a tick resolves and float32 updates accurately: from the
 * tick up to the histories' length (longer ones the data cannot tell
 * apart from a static offset); beyond TF_PRONY_MAX_TAU_TICKS ticks the
 * model is refused below. */
static void tau_range(const tf_histories *h, double *lo, double *hi)
{
    *lo = h->tick;
    *hi = fmax(2 * h->tick, (double)h->train.n_ticks * h->tick);
}

int tf_prony_tick_allows(const tf_prony_terms *t, const tf_histories *h, char *err,
                         size_t errlen)
{
    for (int k = 0; k < t->n; ++k) {
        if (t->tau[k] > TF_PRONY_MAX_TAU_TICKS * h->tick) {
            snprintf(err, errlen,
                     "prony: the creep time constant %.4g s is %.3g ticks of %u ns: beyond %.0e "
                     "ticks the float32 update loses more than 0.1 %% of the peak over 10^6 "
                     "ticks (docs/fitting.md §7); fit with a tick of at least %.3g us",
                     t->tau[k], t->tau[k] / h->tick, h->tick_ns, TF_PRONY_MAX_TAU_TICKS,
                     1e6 * t->tau[k] / TF_PRONY_MAX_TAU_TICKS);
            return -1;
        }
    }
    return 0;
}

/* The static map of orders {p, r} on static cases idx, the terms of K on
 * every training history, the model. */
static tf_model *fit(const tf_cases *c, const size_t *idx, size_t m, const uint32_t *orders,
                     char *err, size_t errlen)
{
    const tf_histories *h = c->hist;
    if (h == NULL) {
        snprintf(err, errlen, "prony: no force histories (the solver is not time-dependent)");
        return NULL;
    }
    const uint32_t static_orders[2] = {orders[0], orders[1]};
    const tf_family *sf = static_family(orders[1]);
    tf_model *s = sf->fit(c, idx, m, static_orders, err, errlen);
    if (s == NULL) {
        return NULL;
    }
    tf_prony_data d;
    tf_prony_terms t;
    double lo, hi;
    tau_range(h, &lo, &hi);
    tf_model *model = NULL;
    if (tf_prony_data_build(s, &h->train, h->tick, &d, err, errlen) == 0) {
        if (tf_prony_fit_terms(&d, NULL, 0, (int)orders[2], lo, hi, &t, err, errlen) == 0 &&
            tf_prony_tick_allows(&t, h, err, errlen) == 0) {
            model = assemble(s, &t, h->tick_ns, err, errlen);
        }
        tf_prony_data_free(&d);
    }
    tf_model_free(s);
    return model;
}

/* One fold of the term search (tf_family_history_cv). */
typedef struct {
    const tf_prony_data *d;
    double lo, hi;
    char *err;
    size_t errlen;
} prony_fold_ctx;

static int prony_fold(void *ctx, int k, const size_t *train, size_t nt, const size_t *valid,
                      size_t nv, double *rms)
{
    const prony_fold_ctx *x = ctx;
    tf_prony_terms t;
    if (tf_prony_fit_terms_from(x->d, train, nt, k, x->lo, x->hi, 1, &t, x->err, x->errlen) != 0) {
        return -1;
    }
    *rms = tf_prony_terms_rms(x->d, valid, nv, &t);
    return 0;
}

int tf_prony_select_terms(const tf_prony_data *d, const tf_histories *h, const tf_fit_plan *plan,
                          double *cv, int *best, tf_prony_terms *terms, char *err, size_t errlen)
{
    double lo, hi;
    tau_range(h, &lo, &hi);
    const size_t n = d->n_hist, folds = plan->folds < n ? plan->folds : n;
    prony_fold_ctx x = {d, lo, hi, err, errlen};
    if (tf_family_history_cv(n, folds, TF_PRONY_SEARCH_TERMS, prony_fold, &x, cv) != 0) {
        snprintf(err, errlen, "prony: out of memory");
        return -1;
    }
    *best = (int)tf_family_cheapest_within(cv, 0, TF_PRONY_SEARCH_TERMS);
    if (!isfinite(cv[*best])) {
        snprintf(err, errlen, "%s: prony: no number of terms is determined by %zu histories",
                 TF_FAMILY_UNDETERMINED, n);
        return -1;
    }
    return tf_prony_fit_terms(d, NULL, 0, *best, lo, hi, terms, err, errlen);
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
    tf_prony_terms t;
    double cv[TF_PRONY_SEARCH_TERMS + 1];
    int k, rc = tf_prony_data_build(s, &c->hist->train, c->hist->tick, &d, err, errlen);
    if (rc == 0) {
        rc = tf_prony_select_terms(&d, c->hist, plan, cv, &k, &t, err, errlen);
        tf_prony_data_free(&d);
    }
    if (rc == 0 && tf_prony_tick_allows(&t, c->hist, err, errlen) == 0) {
        r->model = assemble(s, &t, c->hist->tick_ns, err, errlen);
    }
    tf_model_free(s);
    return r->model != NULL ? 0 : -1;
}

static int candidates(const tf_cases *c, const tf_fit_plan *plan, tf_family_take take, void *arg,
                      char *err, size_t errlen)
{
    for (uint32_t p = 0; p <= plan->max_degree; ++p) {
        for (uint32_t k = 0; k <= TF_PRONY_SEARCH_TERMS; ++k) {
            if (tf_terms(p) > c->train.n_cases) {
                return 0;
            }
            const uint32_t orders[TFIT_PRONY_DIMS] = {p, 0, k, c->hist->tick_ns};
            tf_model *m = fit(c, NULL, 0, orders, err, errlen);
            if (m == NULL) {
                return -1;
            }
            if (take(arg, m) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

static int applicable(const tf_cases *c, const tf_fit_plan *plan, char *why, size_t whylen)
{
    (void)plan;
    if (c->hist == NULL) {
        snprintf(why, whylen, "the problem does not creep: its solver is not time-dependent, so "
                              "there are no force histories to fit time constants to");
        return -1;
    }
    return 0;
}

int tf_prony_history_errors(const tf_model *m, const tf_history_set *set, double *max,
                            double *rms, double *peak)
{
    const size_t rows = 3 * (size_t)m->n_out;
    float *out = malloc(rows * sizeof *out);
    if (out == NULL) {
        return -1;
    }
    double e_max = 0, e2 = 0, big = 0;
    for (size_t h = 0; h < set->n; ++h) {
        float state[TF_STATEFUL_MAX_STATE];
        tf_stateful_reset(m, state);
        for (size_t n = 0; n < set->n_ticks; ++n) {
            const double *f = tf_history_force(set, h, n), *u = tf_history_u(set, h, n);
            const float in[3] = {(float)f[0], (float)f[1], (float)f[2]};
            tf_stateful_step(m, state, in, out, NULL);
            for (size_t o = 0; o < rows; ++o) {
                const double e = (double)out[o] - u[o];
                e_max = fmax(e_max, fabs(e));
                e2 += e * e;
                big = fmax(big, fabs(u[o]));
            }
        }
    }
    free(out);
    *max = e_max;
    *rms = sqrt(e2 / (double)(set->n * set->n_ticks * rows));
    *peak = big;
    return 0;
}

double tf_prony_q31_heldout(const tf_model *m, const tf_cases *c)
{
    if (c->hist == NULL) {
        return NAN;
    }
    const tf_history_set *set = &c->hist->heldout;
    char err[256];
    tf_q31 *q = m->family == TFIT_FAMILY_PRONY ? tf_q31_quantise(m, err, sizeof err) : NULL;
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

int tf_stateful_heldout(const tf_model *m, const tf_cases *c, double *max, double *rms,
                        double *rel_max, uint32_t *n)
{
    double peak;
    if (c->hist == NULL || tf_prony_history_errors(m, &c->hist->heldout, max, rms, &peak) != 0) {
        return -1;
    }
    *rel_max = *max / peak;
    *n = (uint32_t)c->hist->heldout.n;
    return 0;
}

void tf_stateful_orders_text(const tf_model *m, int style, char *buf, size_t n)
{
    char rank[24] = "";
    if (m->dims[1] > 0) {
        snprintf(rank, sizeof rank, " r=%u", m->dims[1]);
    }
    if (style == TF_ORDERS_FULL) {
        snprintf(buf, n, "p=%u%s K=%u tick=%uns", m->dims[0], rank, m->dims[2], m->dims[3]);
    } else {
        snprintf(buf, n, "p=%u%s K=%u", m->dims[0], rank, m->dims[2]);
    }
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
