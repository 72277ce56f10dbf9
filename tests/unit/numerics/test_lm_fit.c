/*
 * test_lm_fit.c — the fitting interface (fit.h): linear models by pivoted
 * QR with many data columns, weights, covariance against closed forms, rank
 * deficiency (linear and nonlinear) with a covariance that means something,
 * and bad input.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "assert_close.h"
#include "numerics/lsfit.h"

#define M 21

/* Design with columns t^0 .. t^(n-1) (or a chosen set), t in [-1, 1]. */
typedef struct poly {
    double t[M];
    int dup;           /* duplicate column 1 as 2 * column 1 (rank deficient) */
    double col_scale;  /* multiplies column 1 (units) */
    int poison;        /* put a NaN in the matrix */
} poly;

static void poly_init(poly *p)
{
    memset(p, 0, sizeof *p);
    for (int i = 0; i < M; ++i) {
        p->t[i] = -1 + 2.0 * i / (M - 1);
    }
    p->col_scale = 1;
}

static int poly_design(void *ctx, size_t m, size_t n, double *a, size_t lda)
{
    const poly *p = ctx;
    for (size_t i = 0; i < m; ++i) {
        double v = 1;
        for (size_t j = 0; j < n; ++j, v *= p->t[i]) {
            a[i + j * lda] = v;
        }
        a[i + lda] *= p->col_scale;
        if (p->dup) {
            a[i + 2 * lda] = 2 * a[i + lda];
        }
    }
    if (p->poison) {
        a[3] = NAN;
    }
    return 0;
}

static double noise(int i, int k)
{
    return 1e-3 * (((i * 37 + k * 11) % 13) - 6);
}

static int fit_linear(tf_ctx *ctx, poly *p, size_t n, size_t k, const double *y, const double *w,
                      tf_lsfit_result *r)
{
    tf_lsfit_model model = {.n_par = n, .design = poly_design, .ctx = p};
    tf_lsfit_data data = {M, k, y, M, w};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, n);
    return tf_lsfit(ctx, &model, &data, &o, r);
}

static void many_columns_in_one_factorisation(void **state)
{
    (void)state;
    enum { N = 4, K = 6 };
    poly p;
    poly_init(&p);
    double coef[N * K], y[M * K];
    for (int k = 0; k < K; ++k) {
        for (int j = 0; j < N; ++j) {
            coef[j + k * N] = (j + 1) * (k - 2.5);
        }
        for (int i = 0; i < M; ++i) {
            double v = 0, tp = 1;
            for (int j = 0; j < N; ++j, tp *= p.t[i]) {
                v += coef[j + k * N] * tp;
            }
            y[i + k * M] = v;
        }
    }
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(fit_linear(&ctx, &p, N, K, y, NULL, &r), 0);
    assert_int_equal(r.stop, TF_STOP_DIRECT);
    assert_int_equal(r.rank, N);
    for (int k = 0; k < K; ++k) {
        for (int j = 0; j < N; ++j) {
            assert_close(r.par[j + k * N], coef[j + k * N], 1e-12);
        }
        assert_true(r.rss[k] < 1e-24);
        /* Each column alone gives the same answer. */
        tf_lsfit_result one;
        assert_int_equal(fit_linear(&ctx, &p, N, 1, y + k * M, NULL, &one), 0);
        for (int j = 0; j < N; ++j) {
            assert_close(one.par[j], r.par[j + k * N], 1e-13);
        }
        tf_lsfit_result_free(&one);
    }
    tf_lsfit_result_free(&r);
}

/* Straight line: the textbook covariance, var(slope) = s^2 / Sxx and
 * var(intercept) = s^2 (1/n + mean^2 / Sxx). */
static void line_covariance_is_the_textbook_one(void **state)
{
    (void)state;
    poly p;
    poly_init(&p);
    for (int i = 0; i < M; ++i) {
        p.t[i] = 3 + 0.5 * i;
    }
    double y[M], mean = 0, sxx = 0;
    for (int i = 0; i < M; ++i) {
        y[i] = 1.5 - 0.25 * p.t[i] + noise(i, 0);
        mean += p.t[i] / M;
    }
    for (int i = 0; i < M; ++i) {
        sxx += (p.t[i] - mean) * (p.t[i] - mean);
    }
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, NULL, &r), 0);
    double s2 = r.rss[0] / (M - 2);
    assert_close(r.sigma2[0], s2, 1e-18);
    assert_close(r.se[1], sqrt(s2 / sxx), 1e-12);
    assert_close(r.se[0], sqrt(s2 * (1.0 / M + mean * mean / sxx)), 1e-12);
    assert_close(tf_lsfit_cov(&r, 0, 0, 1), -s2 * mean / sxx, 1e-12);
    assert_close(r.par[1], -0.25, 1e-3);
    tf_lsfit_result_free(&r);
}

/* Weight 2 on a row is the same fit as that row given twice: fit A
 * weights row 5 by 2 and row 20 by 0; fit B replaces row 20 by a copy of
 * row 5, unweighted. */
static void weights_act_as_repeated_rows(void **state)
{
    (void)state;
    poly p, q;
    poly_init(&p);
    q = p;
    q.t[20] = p.t[5];
    double y[M], y2[M], w[M];
    for (int i = 0; i < M; ++i) {
        y[i] = cos(p.t[i]) + noise(i, 1);
        w[i] = i == 5 ? 2 : i == 20 ? 0 : 1;
    }
    memcpy(y2, y, sizeof y);
    y2[20] = y[5];
    tf_lsfit_result a, b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(fit_linear(&ctx, &p, 3, 1, y, w, &a), 0);
    assert_int_equal(fit_linear(&ctx, &q, 3, 1, y2, NULL, &b), 0);
    for (int j = 0; j < 3; ++j) {
        assert_close(a.par[j], b.par[j], 1e-13);
    }
    assert_close(a.rss[0], b.rss[0], 1e-15);
    assert_true(a.rss[0] > 1e-6); /* the data are not on the model */
    tf_lsfit_result_free(&a);
    tf_lsfit_result_free(&b);
}

/* Columns 1, t, 2t: the third is the second twice over.  The fit is the fit
 * of 1, t alone, the dependent parameter is flagged and held at 0, and the
 * covariance of the others is that of the reduced model. */
static void rank_deficient_linear_fit(void **state)
{
    (void)state;
    poly p;
    poly_init(&p);
    double y[M];
    for (int i = 0; i < M; ++i) {
        y[i] = 0.5 + 3 * p.t[i] + noise(i, 2);
    }
    tf_lsfit_result full, reduced;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, NULL, &reduced), 0);
    p.dup = 1;
    assert_int_equal(fit_linear(&ctx, &p, 3, 1, y, NULL, &full), 0);
    assert_int_equal(full.rank, 2);
    assert_int_equal(full.state[0], TF_PAR_FREE);
    int dep = full.state[1] == TF_PAR_DEPENDENT ? 1 : 2, kept = 3 - dep;
    assert_int_equal(full.state[dep], TF_PAR_DEPENDENT);
    assert_int_equal(full.state[kept], TF_PAR_FREE);
    assert_true(full.par[dep] == 0 && isnan(full.se[dep]));
    double slope = full.par[kept] * (kept == 2 ? 2 : 1);
    double slope_se = full.se[kept] * (kept == 2 ? 2 : 1);
    assert_close(full.par[0], reduced.par[0], 1e-12);
    assert_close(slope, reduced.par[1], 1e-12);
    assert_close(full.se[0], reduced.se[0], 1e-12);
    assert_close(slope_se, reduced.se[1], 1e-12);
    assert_close(full.rss[0], reduced.rss[0], 1e-14);
    assert_close(full.sigma2[0], reduced.sigma2[0], 1e-15); /* n - rank, not n - 3 */
    for (int j = 0; j < 3; ++j) {
        assert_true(full.cov[dep + j * 3] == 0 && full.cov[j + dep * 3] == 0);
    }
    tf_lsfit_result_free(&full);
    tf_lsfit_result_free(&reduced);
}

/* A column in tiny units is not mistaken for a dependent one. */
static void rank_decision_ignores_units(void **state)
{
    (void)state;
    poly p;
    poly_init(&p);
    p.col_scale = 1e-12;
    double y[M];
    for (int i = 0; i < M; ++i) {
        y[i] = 1 + 2 * p.t[i];
    }
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, NULL, &r), 0);
    assert_int_equal(r.rank, 2);
    assert_close(r.par[1], 2e12, 1e-1);
    tf_lsfit_result_free(&r);
}

static void bad_linear_input_is_refused(void **state)
{
    (void)state;
    poly p;
    poly_init(&p);
    double y[M] = {0}, w[M];
    for (int i = 0; i < M; ++i) {
        w[i] = 1;
    }
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    p.poison = 1;
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, NULL, &r), -1);
    assert_non_null(strstr(ctx.err, "design matrix entry (3, 0)"));
    p.poison = 0;
    w[4] = -1;
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, w, &r), -1);
    assert_non_null(strstr(ctx.err, "weight 4"));
    w[4] = 1;
    y[7] = INFINITY;
    assert_int_equal(fit_linear(&ctx, &p, 2, 1, y, w, &r), -1);
    assert_non_null(strstr(ctx.err, "data value (7"));
    tf_lsfit_model both = {.n_par = 2, .design = poly_design, .value = NULL, .ctx = &p};
    tf_lsfit_data data = {M, 1, y, 0, NULL};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, 2);
    both.n_par = 0;
    assert_int_equal(tf_lsfit(&ctx, &both, &data, &o, &r), -1);
}

/* More parameters than observations: the rank is at most the number of
 * observations and the data are still matched exactly. */
static void underdetermined_fit(void **state)
{
    (void)state;
    poly p;
    poly_init(&p);
    double y[M];
    for (int i = 0; i < M; ++i) {
        y[i] = sin(3 * p.t[i]);
    }
    tf_lsfit_model model = {.n_par = 5, .design = poly_design, .ctx = &p};
    tf_lsfit_data data = {3, 1, y, M, NULL};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, 5);
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &r), 0);
    assert_int_equal(r.rank, 3);
    assert_true(r.rss[0] < 1e-28);
    assert_true(isnan(r.sigma2[0]));
    tf_lsfit_result_free(&r);
}

/* ------------------------------------------------------------------------ */
/* Nonlinear, rank deficient: f = exp(a + b) x + c.  Only a + b is
 * determined; the Jacobian columns of a and b are identical everywhere. */

typedef struct expo {
    double x[M], y[M];
    int joint; /* 1: parameters (a, b, c); 0: the reduced model (s, c) */
} expo;

static int expo_value(void *ctx, const double *p, double *f)
{
    const expo *e = ctx;
    double s = e->joint ? p[0] + p[1] : p[0], c = e->joint ? p[2] : p[1];
    for (int i = 0; i < M; ++i) {
        f[i] = exp(s) * e->x[i] + c;
    }
    return 0;
}

static int expo_jacobian(void *ctx, const double *p, double *j)
{
    const expo *e = ctx;
    double s = e->joint ? p[0] + p[1] : p[0];
    for (int i = 0; i < M; ++i) {
        double d = exp(s) * e->x[i];
        j[i] = d;
        j[i + M] = e->joint ? d : 1;
        if (e->joint) {
            j[i + 2 * M] = 1;
        }
    }
    return 0;
}

static void fit_expo(expo *e, int joint, int analytic, tf_lsfit_result *r)
{
    e->joint = joint;
    const double start3[3] = {0.1, 0.2, 0}, start2[2] = {0.3, 0};
    tf_lsfit_model model = {joint ? 3 : 2, NULL, expo_value, analytic ? expo_jacobian : NULL, e};
    tf_lsfit_data data = {M, 1, e->y, 0, NULL};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, model.n_par);
    o.start = joint ? start3 : start2;
    o.lm.ftol = o.lm.xtol = 1e-14;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, r), 0);
    assert_true(tf_stop_converged(r->stop));
}

static void rank_deficient_jacobian_has_meaningful_covariance(void **state)
{
    (void)state;
    expo e;
    for (int i = 0; i < M; ++i) {
        e.x[i] = 0.1 * i;
        e.y[i] = 2 * e.x[i] + 1 + noise(i, 3);
    }
    for (int analytic = 0; analytic < 2; ++analytic) {
        tf_lsfit_result joint, reduced;
        fit_expo(&e, 0, analytic, &reduced);
        fit_expo(&e, 1, analytic, &joint);
        assert_int_equal(joint.rank, 2);
        assert_int_equal(reduced.rank, 2);
        int dep = joint.state[0] == TF_PAR_DEPENDENT ? 0 : 1, kept = 1 - dep;
        assert_int_equal(joint.state[dep], TF_PAR_DEPENDENT);
        assert_int_equal(joint.state[kept], TF_PAR_FREE);
        assert_int_equal(joint.state[2], TF_PAR_FREE);
        assert_true(isnan(joint.se[dep]));
        /* The determined combination and its uncertainty: those of the
         * reduced model. */
        assert_close(joint.par[0] + joint.par[1], reduced.par[0], 1e-8);
        assert_close(joint.par[2], reduced.par[1], 1e-8);
        assert_close(joint.rss[0], reduced.rss[0], 1e-14);
        assert_close(joint.se[kept], reduced.se[0], 1e-6 * reduced.se[0]);
        assert_close(joint.se[2], reduced.se[1], 1e-6 * reduced.se[1]);
        assert_close(tf_lsfit_cov(&joint, 0, kept, 2), tf_lsfit_cov(&reduced, 0, 0, 1),
                     1e-6 * fabs(tf_lsfit_cov(&reduced, 0, 0, 1)));
        assert_close(exp(reduced.par[0]), 2, 0.01);
        tf_lsfit_result_free(&joint);
        tf_lsfit_result_free(&reduced);
    }
}

static int failing_value(void *ctx, const double *p, double *f)
{
    (void)ctx;
    (void)p;
    (void)f;
    return 1;
}

static void nonlinear_misuse_is_refused(void **state)
{
    (void)state;
    expo e = {0};
    double start[2] = {0, 0}, w[M];
    for (int i = 0; i < M; ++i) {
        w[i] = 1;
    }
    tf_lsfit_model model = {2, NULL, failing_value, NULL, &e};
    tf_lsfit_data data = {M, 1, e.y, 0, w};
    tf_lsfit_options o;
    tf_lsfit_default_options(&o, 2);
    tf_lsfit_result r;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &r), -1); /* no start */
    o.start = start;
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &r), -1);
    assert_non_null(strstr(ctx.err, "callback failed"));
    model.value = expo_value;
    w[2] = NAN;
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &r), -1);
    assert_non_null(strstr(ctx.err, "observation 2"));
    w[2] = 1;
    data.n_rhs = 2;
    assert_int_equal(tf_lsfit(&ctx, &model, &data, &o, &r), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(many_columns_in_one_factorisation),
        cmocka_unit_test(line_covariance_is_the_textbook_one),
        cmocka_unit_test(weights_act_as_repeated_rows),
        cmocka_unit_test(rank_deficient_linear_fit),
        cmocka_unit_test(rank_decision_ignores_units),
        cmocka_unit_test(bad_linear_input_is_refused),
        cmocka_unit_test(underdetermined_fit),
        cmocka_unit_test(rank_deficient_jacobian_has_meaningful_covariance),
        cmocka_unit_test(nonlinear_misuse_is_refused),
    };
    return cmocka_run_group_tests_name("lm_fit", tests, NULL, NULL);
}
