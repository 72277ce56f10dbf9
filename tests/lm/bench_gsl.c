/*
 * bench_gsl.c — `make bench-lm`: the 54 NIST StRD runs with tissuefit's
 * Levenberg–Marquardt (lm.c through fit.c) and with GSL's
 * gsl_multifit_nlinear (trust region, Levenberg–Marquardt steps, Moré
 * scaling, QR: its defaults), side by side: correct digits (the smaller of
 * the parameters' minimum LRE and the RSS LRE) and evaluations per run, then
 * the median time of the whole suite for each and their ratio, and the
 * median over the runs of the per-run time ratio (the suite's total is
 * dominated by the few runs that take thousands of evaluations).
 *
 * Both get the same model functions and analytic Jacobians
 * (host/numerics/nist_models.c), the same starting points and the same BLAS
 * (OpenBLAS serves GSL's CBLAS calls).  GSL runs with the tolerances of its
 * manual's example (xtol = gtol = 1e-8, ftol = 0) and with tight ones
 * (xtol = gtol = ftol = 1e-15, like ours); the side-by-side columns use the
 * tight set.  GSL is used only here: `make` and `make check` never need it.
 *
 *   bench_gsl [REPEATS]     (run from the repository root)
 */
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_time.h"
#include "numerics/nist_fit.h"

#define DIR "../shared/reference/nist-strd"
#define MAX_RUNS 64

typedef struct problem {
    tf_nist d;
    const tf_nist_model *model;
    double *y; /* the response as fitted (log y for Nelson) */
} problem;

typedef struct outcome {
    double digits; /* min over parameter LREs and the RSS LRE */
    size_t fevals, jevals;
} outcome;

/* ------------------------------------------------------------------------ */
/* GSL side. */

static int gsl_f(const gsl_vector *b, void *ctx, gsl_vector *f)
{
    const problem *p = ctx;
    for (size_t i = 0; i < p->d.n_obs; ++i) {
        double v = p->model->f(b->data, p->d.x + i * p->d.n_x, NULL) - p->y[i];
        gsl_vector_set(f, i, v);
    }
    return GSL_SUCCESS;
}

static int gsl_df(const gsl_vector *b, void *ctx, gsl_matrix *jac)
{
    const problem *p = ctx;
    double g[TF_NIST_MAX_PAR];
    for (size_t i = 0; i < p->d.n_obs; ++i) {
        p->model->f(b->data, p->d.x + i * p->d.n_x, g);
        for (size_t j = 0; j < p->d.n_par; ++j) {
            gsl_matrix_set(jac, i, j, g[j]);
        }
    }
    return GSL_SUCCESS;
}

static double digits(const problem *p, const double *b, double rss)
{
    double m = tf_lre(rss, p->d.certified_rss);
    if (m < 6 && fabs(rss - p->d.certified_rss) <= tf_nist_rss_resolution(&p->d, p->model)) {
        m = TF_LRE_CAP; /* RSS at the rounding floor (Lanczos1): judge the parameters */
    }
    for (size_t j = 0; j < p->d.n_par; ++j) {
        m = fmin(m, tf_lre(b[j], p->d.certified[j]));
    }
    return m;
}

static outcome run_gsl(problem *p, int start, double xtol, double gtol, double ftol)
{
    const size_t n = p->d.n_par, m = p->d.n_obs;
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_workspace *w =
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, m, n);
    gsl_multifit_nlinear_fdf fdf = {gsl_f, gsl_df, NULL, m, n, p, 0, 0, 0};
    gsl_vector_const_view x0 = gsl_vector_const_view_array(p->d.start[start - 1], n);
    gsl_multifit_nlinear_init(&x0.vector, &fdf, w);
    int info;
    gsl_multifit_nlinear_driver(10000, xtol, gtol, ftol, NULL, NULL, &info, w);
    const gsl_vector *x = gsl_multifit_nlinear_position(w);
    const gsl_vector *f = gsl_multifit_nlinear_residual(w);
    double rss;
    gsl_blas_ddot(f, f, &rss);
    outcome o = {digits(p, x->data, rss), fdf.nevalf, fdf.nevaldf};
    gsl_multifit_nlinear_free(w);
    return o;
}

/* ------------------------------------------------------------------------ */
/* tissuefit side. */

static outcome run_ours(const problem *p, int start)
{
    tf_lsfit_options o;
    tf_nist_options(&o, p->d.n_par);
    tf_nist_score s;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_nist_fit(&ctx, &p->d, p->model, start, &o, 0, &s) != 0) {
        fprintf(stderr, "bench_gsl: %s\n", ctx.err);
        exit(1);
    }
    outcome r = {digits(p, s.estimate, s.rss), s.evals, s.jac_evals};
    if (!tf_stop_converged(s.stop)) {
        r.digits = 0;
    }
    return r;
}

/* ------------------------------------------------------------------------ */

/* Median over repeats of the seconds one run takes with each solver, and
 * the ratio ours / GSL. */
static double run_ratio(problem *p, int start, int repeats)
{
    double a[1000], g[1000];
    for (int r = 0; r < repeats; ++r) {
        double t0 = bench_now();
        run_ours(p, start);
        double t1 = bench_now();
        run_gsl(p, start, 1e-15, 1e-15, 1e-15);
        a[r] = t1 - t0;
        g[r] = bench_now() - t1;
    }
    return bench_median(a, repeats) / bench_median(g, repeats);
}

/* Seconds for all 54 runs with one solver (gsl != 0: GSL, tight set). */
static double suite_time(problem *pr, size_t np, int gsl)
{
    double t0 = bench_now();
    for (size_t k = 0; k < np; ++k) {
        for (int start = 1; start <= 2; ++start) {
            if (gsl) {
                run_gsl(&pr[k], start, 1e-15, 1e-15, 1e-15);
            } else {
                run_ours(&pr[k], start);
            }
        }
    }
    return bench_now() - t0;
}

static void load_all(problem *pr, size_t *np)
{
    const char *const *names = tf_nist_suite(np);
    for (size_t k = 0; k < *np; ++k) {
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        if (tf_nist_load(&ctx, DIR, names[k], &pr[k].d, &pr[k].model) != 0) {
            fprintf(stderr, "bench_gsl: %s\n", ctx.err);
            exit(1);
        }
        pr[k].y = malloc(pr[k].d.n_obs * sizeof *pr[k].y);
        for (size_t i = 0; i < pr[k].d.n_obs; ++i) {
            pr[k].y[i] = pr[k].model->log_response ? log(pr[k].d.y[i]) : pr[k].d.y[i];
        }
    }
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 11;
    if (repeats < 1 || repeats > 1000) {
        fprintf(stderr, "usage: bench_gsl [REPEATS 1..1000]\n");
        return 2;
    }
    gsl_set_error_handler_off();
    static problem pr[MAX_RUNS];
    size_t np;
    load_all(pr, &np);

    printf("NIST StRD, 54 runs: correct digits (min LRE of parameters and RSS; 0 = did not "
           "converge) and evaluations f+J\n");
    printf("%-9s %-5s | %-6s %-10s | %-6s %-10s | %-6s\n", "problem", "start", "ours", "f+J",
           "GSL", "f+J", "GSL@1e-8");
    int ours_ok = 0, gsl_ok = 0, gsl_loose_ok = 0;
    double ours_sum = 0, gsl_sum = 0;
    size_t ours_ev = 0, gsl_ev = 0;
    for (size_t k = 0; k < np; ++k) {
        for (int start = 1; start <= 2; ++start) {
            outcome a = run_ours(&pr[k], start);
            outcome g = run_gsl(&pr[k], start, 1e-15, 1e-15, 1e-15);
            outcome l = run_gsl(&pr[k], start, 1e-8, 1e-8, 0);
            char fa[32], fg[32];
            snprintf(fa, sizeof fa, "%zu+%zu", a.fevals, a.jevals);
            snprintf(fg, sizeof fg, "%zu+%zu", g.fevals, g.jevals);
            printf("%-9s %-5d | %6.2f %-10s | %6.2f %-10s | %6.2f%s\n", pr[k].d.name, start,
                   a.digits, fa, g.digits, fg, l.digits,
                   a.digits < 6 || g.digits < 6 ? "   <- below 6" : "");
            ours_ok += a.digits >= 6;
            gsl_ok += g.digits >= 6;
            gsl_loose_ok += l.digits >= 6;
            ours_sum += a.digits;
            gsl_sum += g.digits;
            ours_ev += a.fevals + a.jevals;
            gsl_ev += g.fevals + g.jevals;
        }
    }
    printf("runs with >= 6 digits: ours %d/54, GSL %d/54 (GSL with xtol = gtol = 1e-8: %d/54)\n",
           ours_ok, gsl_ok, gsl_loose_ok);
    printf("mean digits: ours %.2f, GSL %.2f; evaluations f+J in total: ours %zu, GSL %zu\n",
           ours_sum / 54, gsl_sum / 54, ours_ev, gsl_ev);

    double t_ours[1000], t_gsl[1000];
    for (int r = 0; r < repeats; ++r) { /* interleaved, so drift hits both */
        t_ours[r] = suite_time(pr, np, 0);
        t_gsl[r] = suite_time(pr, np, 1);
    }
    double mo = bench_median(t_ours, repeats), mg = bench_median(t_gsl, repeats);
    printf("time for the 54 runs, median of %d: ours %.2f ms, GSL %.2f ms; ratio ours/GSL "
           "%.2f\n",
           repeats, 1e3 * mo, 1e3 * mg, mo / mg);
    double ratios[MAX_RUNS * 2];
    int nr = 0;
    for (size_t k = 0; k < np; ++k) {
        for (int start = 1; start <= 2; ++start) {
            ratios[nr++] = run_ratio(&pr[k], start, repeats);
        }
    }
    double lo = ratios[0], hi = ratios[0];
    for (int i = 1; i < nr; ++i) {
        lo = fmin(lo, ratios[i]);
        hi = fmax(hi, ratios[i]);
    }
    printf("time per run, ours/GSL (medians of %d): median over the 54 runs %.2f, range %.2f "
           "to %.2f\n",
           repeats, bench_median(ratios, nr), lo, hi);
    for (size_t k = 0; k < np; ++k) {
        free(pr[k].y);
        tf_nist_free(&pr[k].d);
    }
    return 0;
}
