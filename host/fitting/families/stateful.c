/*
 * stateful.c — the stateful families' one fit loop (stateful_family.h):
 * the filter's data from the histories, the order search, the model, the
 * candidates, the held-out errors.  A family brings its tf_filter_fit
 * (prony.c, resonant.c).
 */
#include "fitting/families/stateful_family.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fitting/families/common.h"
#include "model/basis.h"
#include "model/forms/stateful.h"

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

int tf_prony_data_build(tf_ctx *ctx, const tf_model *s, const tf_history_set *set, double tick,
                        tf_prony_data *d)
{
    const size_t ticks = set->n * set->n_ticks, rows = 3 * (size_t)s->n_out;
    double *g = malloc(3 * ticks * sizeof *g), *h = malloc(3 * ticks * sizeof *h);
    double *work = malloc((TF_FAMILY_MAX_TERMS + TFIT_MAX_RANK + 5 * rows) * sizeof *work);
    if (g == NULL || h == NULL || work == NULL) {
        free(g);
        free(h);
        free(work);
        return tf_fail(ctx, "prony: out of memory for %zu ticks", ticks);
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

/* ---- the fit loop -------------------------------------------------------- */

/* The family that fits the static map of rank r (0: nodal). */
static const tf_family *static_family(uint32_t r)
{
    return tf_family_find(r == 0 ? "nodal" : "modal");
}

/* The terms of the model (the caller's buffer of ff->size bytes), freed
 * by the caller. */
static void *terms_buffer(tf_ctx *ctx, const tf_filter_fit *ff)
{
    void *t = malloc(ff->size);
    if (t == NULL) {
        tf_fail(ctx, "%s: out of memory", ff->name);
    }
    return t;
}

tf_model *tf_stateful_fit(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                          const size_t *idx, size_t m, const uint32_t *orders)
{
    const tf_histories *h = c->hist;
    if (h == NULL) {
        tf_fail(ctx, "%s: no force histories (the solver is not time-dependent)", ff->name);
        return NULL;
    }
    const uint32_t static_orders[2] = {orders[0], orders[1]};
    tf_model *s = static_family(orders[1])->fit(ctx, c, idx, m, static_orders);
    void *t = s != NULL ? terms_buffer(ctx, ff) : NULL;
    tf_model *model = NULL;
    tf_prony_data d;
    if (t != NULL && tf_prony_data_build(ctx, s, &h->train, h->tick, &d) == 0) {
        if (ff->fit(ctx, &d, h, NULL, 0, (int)orders[2], 0, t) == 0) {
            model = ff->assemble(ctx, s, t, h);
        }
        tf_prony_data_free(&d);
    }
    free(t);
    tf_model_free(s);
    return model;
}

/* One fold of the search (tf_family_history_cv): the terms fitted into
 * the caller's buffer (the final fit overwrites them). */
typedef struct {
    const tf_filter_fit *ff;
    const tf_prony_data *d;
    const tf_histories *h;
    void *terms;
    tf_ctx *ctx;
} fold_ctx;

static int fold(void *ctx, int k, const size_t *train, size_t nt, const size_t *valid, size_t nv,
                double *rms)
{
    const fold_ctx *x = ctx;
    if (x->ff->fit(x->ctx, x->d, x->h, train, nt, k, 1, x->terms) != 0) {
        return -1;
    }
    *rms = x->ff->rms(x->d, valid, nv, x->terms);
    return 0;
}

int tf_stateful_select_terms(tf_ctx *ctx, const tf_filter_fit *ff, const tf_prony_data *d,
                             const tf_histories *h, const tf_fit_plan *plan, double *cv, int *best,
                             void *terms)
{
    const size_t n = d->n_hist, folds = plan->folds < n ? plan->folds : n;
    fold_ctx x = {ff, d, h, terms, ctx};
    if (tf_family_history_cv(n, folds, ff->search, fold, &x, cv) != 0) {
        return tf_fail(ctx, "%s: out of memory", ff->name);
    }
    *best = (int)tf_family_cheapest_within(cv, 0, (uint32_t)ff->search);
    if (!isfinite(cv[*best])) {
        return tf_fail(ctx, "%s: %s: no number of %s is determined by %zu histories",
                       TF_FAMILY_UNDETERMINED, ff->name, ff->terms, n);
    }
    return ff->fit(ctx, d, h, NULL, 0, *best, 0, terms);
}

int tf_stateful_select(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                       const tf_fit_plan *plan, tf_family_result *r)
{
    uint32_t p;
    const tf_family *nodal = static_family(0);
    if (tf_family_select_degree(ctx, nodal, c, plan, 0, 0, r->cv, &p) != 0) {
        return -1;
    }
    tf_model *s = nodal->fit(ctx, c, NULL, 0, &p);
    void *t = s != NULL ? terms_buffer(ctx, ff) : NULL;
    if (t != NULL) {
        tf_prony_data d;
        double cv[TF_STATEFUL_MAX_SEARCH + 1];
        int k, rc = tf_prony_data_build(ctx, s, &c->hist->train, c->hist->tick, &d);
        if (rc == 0) {
            rc = tf_stateful_select_terms(ctx, ff, &d, c->hist, plan, cv, &k, t);
            tf_prony_data_free(&d);
        }
        if (rc == 0) {
            r->model = ff->assemble(ctx, s, t, c->hist);
        }
    }
    free(t);
    tf_model_free(s);
    return r->model != NULL ? 0 : -1;
}

int tf_stateful_candidates(tf_ctx *ctx, const tf_filter_fit *ff, const tf_cases *c,
                           const tf_fit_plan *plan, tf_family_take take, void *arg)
{
    for (uint32_t p = 0; p <= plan->max_degree; ++p) {
        for (uint32_t k = 0; k <= (uint32_t)ff->search; ++k) {
            if (tf_terms(p) > c->train.n_cases) {
                return 0;
            }
            const uint32_t orders[TFIT_PRONY_DIMS] = {p, 0, k, c->hist->tick_ns};
            tf_model *m = tf_stateful_fit(ctx, ff, c, NULL, 0, orders);
            if (m == NULL || take(arg, m) != 0) {
                return -1;
            }
        }
    }
    return 0;
}

/* ---- held-out errors and orders ------------------------------------------ */

int tf_stateful_history_errors(const tf_model *m, const tf_history_set *set, double *max,
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

int tf_stateful_heldout(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max,
                        double *rms, double *rel_max, uint32_t *n)
{
    double peak;
    if (c->hist == NULL || tf_stateful_history_errors(m, &c->hist->heldout, max, rms, &peak) != 0) {
        return tf_fail(ctx, "%s: out of memory for its held-out errors",
                       tf_family_of(m->family)->name);
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

