/*
 * zhou2017.c — see zhou2017.h; the family's registry entry at the end.
 */
#include "fitting/families/zhou2017.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/basis.h"
#include "fitting/cv_folds.h"
#include "fitting/families/common.h"
#include "fitting/families/family.h"

#define BETA_MAX 4 /* k searched in 0..4: the seed needed 1 */

/* Normalised in-plane coordinates of the output points: [-1, 1]. */
static void plane_coordinates(const tf_fitdata *d, double *xy)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (uint32_t j = 0; j < d->n_out; ++j) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = fmin(lo[k], d->rest[j][k]);
            hi[k] = fmax(hi[k], d->rest[j][k]);
        }
    }
    for (uint32_t j = 0; j < d->n_out; ++j) {
        for (int k = 0; k < 2; ++k) {
            double half = 0.5 * (hi[k] - lo[k]);
            double v = half > 0 ? (d->rest[j][k] - 0.5 * (hi[k] + lo[k])) / half : 0.0;
            /* the float the model will store, so the fit sees the same point */
            xy[2 * j + (uint32_t)k] = (double)(float)fmax(-1.0, fmin(1.0, v));
        }
    }
}

int tf_zhou_applicable(tf_ctx *ctx, const tf_fitdata *d)
{
    double zlo, zhi;
    if (!tf_fitdata_flat(d, &zlo, &zhi)) {
        return tf_fail(
            ctx,
            "family zhou2017 needs the output points on one plane z = const ([Zhou2017] §3.2 "
            "fits surfaces in x and y only); these span z = %g .. %g mm",
            zlo, zhi);
    }
    if (d->centre[0] != 0 || d->centre[1] != 0 || d->centre[2] != 0) {
        return tf_fail(
            ctx,
            "family zhou2017 needs a force envelope centred at zero (its contact law is a "
            "polynomial of each force component alone); the centre is (%g, %g, %g) N",
            d->centre[0], d->centre[1], d->centre[2]);
    }
    return 0;
}

/* Stage 1 on cases idx: d_a = r(g_a), returns the coefficients in r[]. */
static int contact_law(tf_ctx *ctx, const tf_fitdata *d, int a, const size_t *idx, size_t m,
                       uint32_t lambda, double *r)
{
    double *design = malloc(m * (lambda + 1) * sizeof *design), *y = malloc(m * sizeof *y);
    int rc = -1;
    if (design && y) {
        for (size_t i = 0; i < m; ++i) {
            size_t n = tf_family_case(idx, i);
            double pw[TFIT_MAX_DEGREE + 1];
            tf_chebyshev(lambda, d->force[n][a] / d->radius, pw);
            for (uint32_t k = 0; k <= lambda; ++k) {
                design[i + k * m] = pw[k];
            }
            y[i] = d->contact[n][a];
        }
        rc = tf_family_lsq(ctx, design, m, lambda + 1, y, 1, r);
    }
    free(design);
    free(y);
    return rc;
}

/* The separable surface basis [1, X..X^A, Y..Y^B] at points pts[0..np). */
static double *surface_design(const double *xy, const size_t *pts, size_t np, uint32_t A,
                              uint32_t B)
{
    size_t cols = A + B + 1;
    double *s = malloc(np * cols * sizeof *s);
    for (size_t q = 0; s && q < np; ++q) {
        const double *p = xy + 2 * tf_family_case(pts, q);
        double px[TFIT_ZHOU_MAX_ORDER + 1], py[TFIT_ZHOU_MAX_ORDER + 1];
        tf_chebyshev(A, p[0], px);
        tf_chebyshev(B, p[1], py);
        for (uint32_t k = 0; k <= A; ++k) {
            s[q + k * np] = px[k];
        }
        for (uint32_t k = 1; k <= B; ++k) {
            s[q + (A + k) * np] = py[k];
        }
    }
    return s;
}

/* Stage 2: p (rows x m, column per case) of component c over points pts. */
static int surfaces(tf_ctx *ctx, const tf_fitdata *d, int c, const size_t *cases, size_t m,
                    const double *xy, const size_t *pts, size_t np, uint32_t A, uint32_t B,
                    double *p)
{
    double *s = surface_design(xy, pts, np, A, B);
    double *y = malloc(np * m * sizeof *y);
    int rc = -1;
    if (s && y) {
        for (size_t i = 0; i < m; ++i) {
            const double *u = d->u + 3 * (size_t)d->n_out * tf_family_case(cases, i);
            for (size_t q = 0; q < np; ++q) {
                y[q + i * np] = u[3 * tf_family_case(pts, q) + (size_t)c];
            }
        }
        rc = tf_family_lsq(ctx, s, np, A + B + 1, y, m, p);
    }
    free(s);
    free(y);
    return rc;
}

/* Stage 3: beta (k+1 x rows) from p (rows x m) against t (m). */
static int beta_fit(tf_ctx *ctx, const double *t, size_t m, const double *p, uint32_t rows,
                    uint32_t k, double *beta)
{
    double *design = malloc(m * (k + 1) * sizeof *design), *y = malloc(m * rows * sizeof *y);
    int rc = -1;
    if (design && y) {
        for (size_t i = 0; i < m; ++i) {
            double pw[BETA_MAX + 1];
            tf_chebyshev(k, t[i], pw);
            for (uint32_t j = 0; j <= k; ++j) {
                design[i + j * m] = pw[j];
            }
            for (uint32_t r = 0; r < rows; ++r) {
                y[i + r * m] = p[r + i * rows];
            }
        }
        rc = tf_family_lsq(ctx, design, m, k + 1, y, rows, beta);
    }
    free(design);
    free(y);
    return rc;
}

/* s_a = 1 / sum_k |r_k| of the stored (float) contact law of axis a at
 * order lambda, shrunk by 2^-16 and rounded towards zero.  |T_k(g)| <= 1 for
 * |g| <= 1 (every input after the projection, header-format.md §4), so
 * |d_a| <= sum |r_k| and t_a = d_a s_a lies in [-1, 1], where the Chebyshev
 * series in t are bounded by their coefficient sums; the margin covers the
 * rounding of Clenshaw's recurrence (a few n^2 ulps of sum |r_k|, 2^-17.6
 * relative for n = 8).  A maximum over the training cases (API version 2)
 * would not do: the fitted law extrapolates past the largest training
 * displacement wherever the cases do not reach |g_a| = 1. */
float tf_zhou_scale(const float *r, uint32_t lambda)
{
    double sum = 0;
    for (uint32_t k = 0; k <= lambda; ++k) {
        sum += fabs((double)r[k]);
    }
    double want = sum > 0 ? (1 - 0x1p-16) / sum : 1.0;
    if (want > FLT_MAX) { /* a law of subnormal size: any smaller scale is safe */
        want = FLT_MAX;
    }
    float s = (float)want;
    if ((double)s > want) {
        s = nextafterf(s, 0.0f);
    }
    return s;
}

static int contact_scale(tf_ctx *ctx, const tf_fitdata *d, int a, uint32_t lambda, double *scale)
{
    double r[TFIT_MAX_DEGREE + 1];
    if (contact_law(ctx, d, a, NULL, d->n_cases, lambda, r) != 0) {
        return -1;
    }
    float rf[TFIT_MAX_DEGREE + 1];
    for (uint32_t k = 0; k <= lambda; ++k) {
        rf[k] = (float)r[k]; /* as stored in the model */
    }
    *scale = (double)tf_zhou_scale(rf, lambda);
    return 0;
}

static int fill_pair(tf_ctx *ctx, const tf_fitdata *d, int a, int c, const tf_zhou_orders *o,
                     const double *xy, float *out)
{
    const int pair = 3 * a + c;
    const uint32_t A = o->a[pair], B = o->b[pair], k = o->k[pair], rows = A + B + 1;
    const size_t m = d->n_cases;
    double *p = malloc(rows * m * sizeof *p), *t = malloc(m * sizeof *t);
    double *beta = malloc((k + 1) * rows * sizeof *beta);
    double scale = 1;
    int rc = -1;
    if (p && t && beta) {
        rc = contact_scale(ctx, d, a, o->lambda[a], &scale);
    }
    if (rc == 0) {
        rc = surfaces(ctx, d, c, NULL, m, xy, NULL, d->n_out, A, B, p);
    }
    if (rc == 0) {
        for (size_t i = 0; i < m; ++i) {
            t[i] = d->contact[i][a] * scale;
        }
        rc = beta_fit(ctx, t, m, p, rows, k, beta);
    }
    if (rc == 0) {
        for (uint32_t r = 0; r < rows; ++r) {
            for (uint32_t j = 0; j <= k; ++j) {
                out[r * (k + 1) + j] = (float)beta[j + r * (k + 1)];
            }
        }
    }
    free(p);
    free(t);
    free(beta);
    return rc;
}

tf_model *tf_zhou_fit(tf_ctx *ctx, const tf_fitdata *const axis[3], const tf_zhou_orders *o,
                      const char *name)
{
    const tf_fitdata *d0 = axis[0];
    uint32_t dims[TFIT_ZHOU2017_DIMS];
    for (int a = 0; a < 3; ++a) {
        dims[a] = o->lambda[a];
    }
    for (int pair = 0; pair < 9; ++pair) {
        dims[3 + 3 * pair] = o->a[pair];
        dims[4 + 3 * pair] = o->b[pair];
        dims[5 + 3 * pair] = o->k[pair];
    }
    tf_model *model =
        tf_model_new(ctx, name, TFIT_FAMILY_ZHOU2017, d0->n_out, dims, TFIT_ZHOU2017_DIMS);
    double *xy = malloc(2 * d0->n_out * sizeof *xy);
    if (model == NULL || xy == NULL) {
        tf_model_free(model);
        free(xy);
        return NULL;
    }
    tf_family_forward_setup(model, d0);
    plane_coordinates(d0, xy);
    float *c = tf_model_tables(model);
    int rc = 0;
    for (int a = 0; rc == 0 && a < 3; ++a) {
        double r[TFIT_MAX_DEGREE + 1];
        rc = contact_law(ctx, axis[a], a, NULL, axis[a]->n_cases, o->lambda[a], r);
        for (uint32_t k = 0; rc == 0 && k <= o->lambda[a]; ++k) {
            *c++ = (float)r[k];
        }
        double scale = 1;
        if (rc == 0) {
            rc = contact_scale(ctx, axis[a], a, o->lambda[a], &scale);
        }
        *c++ = (float)scale;
    }
    for (int pair = 0; rc == 0 && pair < 9; ++pair) {
        rc = fill_pair(ctx, axis[pair / 3], pair / 3, pair % 3, o, xy, c);
        c += (o->a[pair] + o->b[pair] + 1) * (o->k[pair] + 1);
    }
    for (uint32_t j = 0; rc == 0 && j < 2 * d0->n_out; ++j) {
        c[j] = (float)xy[j];
    }
    free(xy);
    if (rc != 0) {
        tf_model_free(model);
        return NULL;
    }
    return model;
}

/* Smallest order whose CV error is within 2 % (plus 1 nm) of the best:
 * higher orders must earn their cost. */
static uint32_t pick(const double *cv, uint32_t n)
{
    double best = INFINITY;
    for (uint32_t i = 0; i < n; ++i) {
        best = fmin(best, cv[i]);
    }
    for (uint32_t i = 0; i < n; ++i) {
        if (cv[i] <= 1.02 * best + 1e-6) {
            return i;
        }
    }
    return 0;
}

static double rms_of(double sum2, size_t count)
{
    return count > 0 ? sqrt(sum2 / (double)count) : INFINITY;
}

/* A fold whose cases cannot determine the orders makes the orders'
 * CV error infinite (common.h); anything else is a failure. */
static int undetermined(int rc, const char *err, double *out)
{
    if (rc != 0 && strncmp(err, TF_FAMILY_UNDETERMINED, strlen(TF_FAMILY_UNDETERMINED)) == 0) {
        *out = INFINITY;
        return 1;
    }
    return 0;
}

/* CV over load cases of the contact law of axis a at order lambda. */
static int cv_lambda(tf_ctx *ctx, const tf_fitdata *d, int a, uint32_t lambda, const unsigned *fold,
                     unsigned folds, size_t *tr, size_t *te, double *out)
{
    double sum2 = 0;
    size_t count = 0;
    for (unsigned f = 0; f < folds; ++f) {
        size_t nt = tf_cv_select(fold, d->n_cases, f, 0, tr);
        size_t nv = tf_cv_select(fold, d->n_cases, f, 1, te);
        double r[TFIT_MAX_DEGREE + 1], pw[TFIT_MAX_DEGREE + 1];
        int rc = contact_law(ctx, d, a, tr, nt, lambda, r);
        if (undetermined(rc, ctx->err, out)) {
            return 0;
        }
        if (rc != 0) {
            return -1;
        }
        for (size_t i = 0; i < nv; ++i) {
            tf_chebyshev(lambda, d->force[te[i]][a] / d->radius, pw);
            double v = 0;
            for (uint32_t k = 0; k <= lambda; ++k) {
                v += r[k] * pw[k];
            }
            double e = v - d->contact[te[i]][a];
            sum2 += e * e;
            count++;
        }
    }
    *out = rms_of(sum2, count);
    return 0;
}

/* CV over output points of the surfaces of component c at orders (A, B). */
static int cv_surface(tf_ctx *ctx, const tf_fitdata *d, int c, const double *xy, uint32_t A,
                      uint32_t B, const unsigned *fold, unsigned folds, size_t *tr, size_t *te,
                      double *out)
{
    const size_t m = d->n_cases, rows = A + B + 1;
    double *p = malloc(rows * m * sizeof *p);
    double sum2 = 0;
    size_t count = 0;
    int rc = p ? 0 : -1;
    for (unsigned f = 0; rc == 0 && f < folds; ++f) {
        size_t nt = tf_cv_select(fold, d->n_out, f, 0, tr);
        size_t nv = tf_cv_select(fold, d->n_out, f, 1, te);
        if (nt < rows) {
            sum2 = INFINITY;
            break;
        }
        rc = surfaces(ctx, d, c, NULL, m, xy, tr, nt, A, B, p);
        if (undetermined(rc, ctx->err, out)) {
            free(p);
            return 0;
        }
        double *s = rc == 0 ? surface_design(xy, te, nv, A, B) : NULL;
        for (size_t i = 0; s && i < m; ++i) {
            const double *u = d->u + 3 * (size_t)d->n_out * i;
            for (size_t q = 0; q < nv; ++q) {
                double v = 0;
                for (size_t k = 0; k < rows; ++k) {
                    v += s[q + k * nv] * p[k + i * rows];
                }
                double e = v - u[3 * te[q] + (size_t)c];
                sum2 += e * e;
                count++;
            }
        }
        free(s);
    }
    free(p);
    *out = rms_of(sum2, count);
    return rc;
}

/* CV over load cases of the beta polynomials of order k for one pair. */
static int cv_beta(tf_ctx *ctx, const tf_fitdata *d, int a, int c, const double *xy,
                   uint32_t lambda, uint32_t A, uint32_t B, uint32_t k, const unsigned *fold,
                   unsigned folds, size_t *tr, size_t *te, double *out)
{
    const size_t m = d->n_cases, rows = A + B + 1;
    double *p = malloc(rows * m * sizeof *p), *ptr = malloc(rows * m * sizeof *ptr);
    double *t = malloc(m * sizeof *t), *beta = malloc((k + 1) * rows * sizeof *beta);
    double *s = surface_design(xy, NULL, d->n_out, A, B);
    double scale = 1;
    double sum2 = 0;
    size_t count = 0;
    int rc = (p && ptr && t && beta && s) ? contact_scale(ctx, d, a, lambda, &scale) : -1;
    if (rc == 0) {
        rc = surfaces(ctx, d, c, NULL, m, xy, NULL, d->n_out, A, B, p);
    }
    for (unsigned f = 0; rc == 0 && f < folds; ++f) {
        size_t nt = tf_cv_select(fold, m, f, 0, tr);
        size_t nv = tf_cv_select(fold, m, f, 1, te);
        for (size_t i = 0; i < nt; ++i) {
            t[i] = d->contact[tr[i]][a] * scale;
            memcpy(ptr + i * rows, p + tr[i] * rows, rows * sizeof *p);
        }
        rc = beta_fit(ctx, t, nt, ptr, (uint32_t)rows, k, beta);
        if (undetermined(rc, ctx->err, &sum2)) {
            rc = 0;
            count = 1;
            break;
        }
        for (size_t i = 0; rc == 0 && i < nv; ++i) {
            double pw[BETA_MAX + 1], coef[2 * TFIT_ZHOU_MAX_ORDER + 1];
            tf_chebyshev(k, d->contact[te[i]][a] * scale, pw);
            for (size_t r = 0; r < rows; ++r) {
                coef[r] = 0;
                for (uint32_t j = 0; j <= k; ++j) {
                    coef[r] += beta[j + r * (k + 1)] * pw[j];
                }
            }
            const double *u = d->u + 3 * (size_t)d->n_out * te[i];
            for (uint32_t q = 0; q < d->n_out; ++q) {
                double v = 0;
                for (size_t r = 0; r < rows; ++r) {
                    v += s[q + r * d->n_out] * coef[r];
                }
                double e = v - u[3 * q + (uint32_t)c];
                sum2 += e * e;
                count++;
            }
        }
    }
    free(p);
    free(ptr);
    free(t);
    free(beta);
    free(s);
    *out = rms_of(sum2, count);
    return rc;
}

int tf_zhou_select(tf_ctx *ctx, const tf_fitdata *const axis[3], unsigned folds, uint64_t seed,
                   tf_zhou_orders *o, tf_zhou_cv *cv)
{
    const uint32_t n_out = axis[0]->n_out;
    size_t most = n_out;
    for (int a = 0; a < 3; ++a) {
        most = axis[a]->n_cases > most ? axis[a]->n_cases : most;
    }
    double *xy = malloc(2 * n_out * sizeof *xy);
    size_t *tr = malloc(most * sizeof *tr), *te = malloc(most * sizeof *te);
    unsigned *cfold = malloc(most * sizeof *cfold), *pfold = malloc(n_out * sizeof *pfold);
    tf_zhou_cv *own = cv ? NULL : malloc(sizeof *own);
    tf_zhou_cv *c = cv ? cv : own;
    int rc = (xy && tr && te && cfold && pfold && c) ? 0 : -1;
    if (rc != 0) {
        tf_fail(ctx, "zhou2017: out of memory");
    } else {
        plane_coordinates(axis[0], xy);
        tf_cv_folds(n_out, folds, seed ^ 0x5bd1e995u, pfold);
    }
    for (int a = 0; rc == 0 && a < 3; ++a) {
        const tf_fitdata *d = axis[a];
        tf_cv_folds(d->n_cases, folds, seed + (uint64_t)a, cfold);
        uint32_t top = d->n_cases > 2 ? (uint32_t)fmin(TFIT_MAX_DEGREE, d->n_cases - 2) : 0;
        for (uint32_t l = 0; rc == 0 && l <= TFIT_MAX_DEGREE; ++l) {
            c->lambda_rms[a][l] = INFINITY;
            if (l <= top) {
                rc = cv_lambda(ctx, d, a, l, cfold, folds, tr, te, &c->lambda_rms[a][l]);
            }
        }
        o->lambda[a] = pick(c->lambda_rms[a], top + 1);
        for (int comp = 0; rc == 0 && comp < 3; ++comp) {
            const int pair = 3 * a + comp;
            double best = INFINITY;
            for (uint32_t A = 0; rc == 0 && A <= TFIT_ZHOU_MAX_ORDER; ++A) {
                for (uint32_t B = 0; rc == 0 && B <= TFIT_ZHOU_MAX_ORDER; ++B) {
                    rc = cv_surface(ctx, d, comp, xy, A, B, pfold, folds, tr, te,
                                    &c->surface_rms[pair][A][B]);
                    best = fmin(best, c->surface_rms[pair][A][B]);
                }
            }
            /* the cheapest (A + B, then A) within 2 % of the best */
            uint32_t ba = 0, bb = 0, cost = UINT32_MAX;
            for (uint32_t A = 0; A <= TFIT_ZHOU_MAX_ORDER; ++A) {
                for (uint32_t B = 0; B <= TFIT_ZHOU_MAX_ORDER; ++B) {
                    if (c->surface_rms[pair][A][B] <= 1.02 * best + 1e-6 && A + B < cost) {
                        cost = A + B;
                        ba = A;
                        bb = B;
                    }
                }
            }
            o->a[pair] = ba;
            o->b[pair] = bb;
            uint32_t ktop = d->n_cases > 2 ? (uint32_t)fmin(BETA_MAX, d->n_cases - 2) : 0;
            for (uint32_t k = 0; rc == 0 && k <= BETA_MAX; ++k) {
                c->beta_rms[pair][k] = INFINITY;
                if (k <= ktop) {
                    rc = cv_beta(ctx, d, a, comp, xy, o->lambda[a], ba, bb, k, cfold, folds, tr, te,
                                 &c->beta_rms[pair][k]);
                }
            }
            o->k[pair] = pick(c->beta_rms[pair], ktop + 1);
        }
    }
    free(xy);
    free(tr);
    free(te);
    free(cfold);
    free(pfold);
    free(own);
    return rc;
}

/* ---- the registry's operations (family.h) -------------------------------- */

static void orders_of(const uint32_t *dims, tf_zhou_orders *o)
{
    for (int a = 0; a < 3; ++a) {
        o->lambda[a] = dims[a];
    }
    for (int pair = 0; pair < 9; ++pair) {
        o->a[pair] = dims[3 + 3 * pair];
        o->b[pair] = dims[4 + 3 * pair];
        o->k[pair] = dims[5 + 3 * pair];
    }
}

/* The fit uses the single-axis cases, all of them: no selection. */
static tf_model *fit(tf_ctx *ctx, const tf_cases *c, const size_t *idx, size_t m,
                     const uint32_t *orders)
{
    (void)m;
    if (idx != NULL) {
        tf_fail(ctx, "zhou2017 fits every single-axis case: no selection of cases");
        return NULL;
    }
    const tf_fitdata *axis[3] = {&c->axis[0], &c->axis[1], &c->axis[2]};
    tf_zhou_orders o;
    orders_of(orders, &o);
    return tf_zhou_fit(ctx, axis, &o, "zhou2017");
}

/* The seed's model needs the outputs on one plane and a centred envelope,
 * and its surface orders are cross-validated over the output points: at
 * least one per fold. */
static int applicable(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    if (c->train.n_out < plan->folds) {
        return tf_fail(
            ctx,
            "family zhou2017 cross-validates its surfaces over the output points: it needs "
            "at least %u (the folds), not %u",
            plan->folds, c->train.n_out);
    }
    return tf_zhou_applicable(ctx, &c->train);
}

/* Orders by cross-validation (tf_zhou_select), then the model. */
static tf_model *cross_validated(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan)
{
    const tf_fitdata *axis[3] = {&c->axis[0], &c->axis[1], &c->axis[2]};
    tf_zhou_orders o;
    if (tf_zhou_select(ctx, axis, plan->folds, plan->seed, &o, NULL) != 0) {
        return NULL;
    }
    return tf_zhou_fit(ctx, axis, &o, "zhou2017");
}

static int select_orders(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan,
                         tf_family_result *r)
{
    r->model = cross_validated(ctx, c, plan);
    return r->model ? 0 : -1;
}

/* One candidate: the cross-validated orders. */
static int candidates(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, tf_family_take take,
                      void *arg)
{
    tf_model *m = cross_validated(ctx, c, plan);
    return (m == NULL || take(arg, m) != 0) ? -1 : 0;
}

/* Full: "lambda=1,1,1 xx:A/B/k ..." per (force axis, component); short:
 * the contact-law orders. */
static void orders_text(const tf_model *m, int style, char *buf, size_t n)
{
    const uint32_t *d = m->dims;
    int k = snprintf(buf, n, "lambda=%u,%u,%u", d[0], d[1], d[2]);
    for (int pair = 0; style == TF_ORDERS_FULL && pair < 9 && k > 0 && (size_t)k < n; ++pair) {
        k += snprintf(buf + k, n - (size_t)k, " %c%c:%u/%u/%u", "xyz"[pair / 3], "xyz"[pair % 3],
                      d[3 + 3 * pair], d[4 + 3 * pair], d[5 + 3 * pair]);
    }
}

const tf_family tf_family_zhou2017 = {
    .id = TFIT_FAMILY_ZHOU2017,
    .name = "zhou2017",
    .kind = TF_FAMILY_FORWARD,
    .applicable = applicable,
    .select = select_orders,
    .fit = fit,
    .candidates = candidates,
    .orders_text = orders_text,
    .q31 = NULL, /* no Q31 form (docs/q31-format.md §1) */
    .f64_errors = NULL,
    .cost = tf_family_layout_cost,
};
