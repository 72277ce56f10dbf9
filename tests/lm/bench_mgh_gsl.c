/*
 * bench_mgh_gsl.c — `make bench-lm`, second part: the 53 Moré–Garbow–
 * Hillstrom runs (MINPACK's lmder driver set, host/numerics/mgh_problems.c)
 * with tissuefit's LM and with GSL's gsl_multifit_nlinear (its defaults:
 * trust region, Levenberg–Marquardt steps, Moré scaling, QR), side by
 * side: the known minimum each reached, and its evaluations f + J.  Then
 * the median time of the whole set for each and their ratio.
 *
 * Both get the same residuals, analytic Jacobians and starts.  GSL runs
 * with tight tolerances (xtol = gtol = ftol = 1e-15, like ours) and with
 * its manual's example ones (xtol = gtol = 1e-8, ftol = 0), 10000
 * iterations.  A run succeeds when the solver reports convergence
 * (tf_stop_converged, GSL_SUCCESS) at one of the problem's known minima
 * (tf_mgh_which_minimum: the global one or another the paper lists).
 *
 *   bench_mgh_gsl [REPEATS]
 */
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_time.h"
#include "numerics/mgh_fit.h"

typedef struct outcome {
    int ok;      /* converged */
    int minimum; /* tf_mgh_which_minimum, -1 for none */
    size_t fevals, jevals;
} outcome;

static int gsl_f(const gsl_vector *x, void *ctx, gsl_vector *f)
{
    tf_mgh_residual(ctx, x->data, f->data);
    return GSL_SUCCESS;
}

/* GSL's matrices are row-major: fill ours, then transpose. */
static int gsl_df(const gsl_vector *x, void *ctx, gsl_matrix *jac)
{
    const tf_mgh_run *r = ctx;
    double buf[TF_MGH_MAX_M * TF_MGH_MAX_N];
    tf_mgh_jacobian(r, x->data, buf);
    for (size_t i = 0; i < r->m; ++i) {
        for (size_t j = 0; j < r->n; ++j) {
            gsl_matrix_set(jac, i, j, buf[i + j * r->m]);
        }
    }
    return GSL_SUCCESS;
}

static outcome run_gsl(const tf_mgh_run *r, double xtol, double gtol, double ftol)
{
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_workspace *w =
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, r->m, r->n);
    gsl_multifit_nlinear_fdf fdf = {gsl_f, gsl_df, NULL, r->m, r->n, (void *)r, 0, 0, 0};
    double x0[TF_MGH_MAX_N];
    tf_mgh_start(r, x0);
    gsl_vector_view x0v = gsl_vector_view_array(x0, r->n);
    gsl_multifit_nlinear_init(&x0v.vector, &fdf, w);
    int info;
    int status = gsl_multifit_nlinear_driver(10000, xtol, gtol, ftol, NULL, NULL, &info, w);
    const gsl_vector *f = gsl_multifit_nlinear_residual(w);
    double rss;
    gsl_blas_ddot(f, f, &rss);
    outcome o = {status == GSL_SUCCESS, tf_mgh_which_minimum(r, rss), fdf.nevalf, fdf.nevaldf};
    gsl_multifit_nlinear_free(w);
    return o;
}

static outcome run_ours(const tf_mgh_run *r)
{
    tf_lm_options o;
    tf_mgh_options(&o, r->n);
    tf_mgh_score s;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_mgh_fit(&ctx, r, &o, NULL, &s) != 0) {
        fprintf(stderr, "bench_mgh_gsl: %s\n", ctx.err);
        exit(1);
    }
    outcome a = {tf_stop_converged(s.stop), s.minimum, s.evals, s.jac_evals};
    return a;
}

static int success(outcome o)
{
    return o.ok && o.minimum >= 0;
}

/* "global", "local F", "none", or "failed" (no convergence). */
static void verdict(const tf_mgh_run *r, outcome o, char *buf, size_t len)
{
    if (!o.ok) {
        snprintf(buf, len, "failed");
    } else {
        tf_mgh_describe(r, o.minimum, buf, len);
    }
}

/* Seconds for all runs with one solver (gsl != 0: GSL, tight set). */
static double set_time(const tf_mgh_run *runs, size_t nr, int gsl)
{
    double t0 = bench_now();
    for (size_t k = 0; k < nr; ++k) {
        if (gsl) {
            run_gsl(&runs[k], 1e-15, 1e-15, 1e-15);
        } else {
            run_ours(&runs[k]);
        }
    }
    return bench_now() - t0;
}

int main(int argc, char **argv)
{
    int repeats = argc > 1 ? atoi(argv[1]) : 11;
    if (repeats < 1 || repeats > 1000) {
        fprintf(stderr, "usage: bench_mgh_gsl [REPEATS 1..1000]\n");
        return 2;
    }
    gsl_set_error_handler_off();
    size_t nr;
    const tf_mgh_run *runs = tf_mgh_runs(&nr);
    printf("Moré-Garbow-Hillstrom, %zu runs: minimum reached (global; local F = another "
           "known minimum, sum f^2 = F; none; failed = no convergence) and evaluations f+J\n",
           nr);
    printf("%-2s %-20s %3s %3s %5s | %-17s %-9s | %-17s %-11s | %-17s %-9s\n", "#", "problem",
           "n", "m", "start", "ours", "f+J", "GSL", "f+J", "GSL@1e-8", "f+J");
    int ok[3] = {0}, global[3] = {0};
    size_t ev[3] = {0};
    for (size_t k = 0; k < nr; ++k) {
        const tf_mgh_run *r = &runs[k];
        outcome o[3] = {run_ours(r), run_gsl(r, 1e-15, 1e-15, 1e-15), run_gsl(r, 1e-8, 1e-8, 0)};
        char fj[3][32], at[3][32];
        for (int s = 0; s < 3; ++s) {
            snprintf(fj[s], sizeof fj[s], "%zu+%zu", o[s].fevals, o[s].jevals);
            verdict(r, o[s], at[s], sizeof at[s]);
            ok[s] += success(o[s]);
            global[s] += success(o[s]) && o[s].minimum == 0;
            ev[s] += o[s].fevals + o[s].jevals;
        }
        printf("%-2d %-20.20s %3zu %3zu %4gx | %-17s %-9s | %-17s %-11s | %-17s %-9s\n",
               r->problem, tf_mgh_name(r->problem), r->n, r->m, r->factor, at[0], fj[0], at[1],
               fj[1], at[2], fj[2]);
    }
    printf("runs at a known minimum: ours %d/%zu (%d global), GSL %d/%zu (%d global), GSL with "
           "xtol = gtol = 1e-8 %d/%zu (%d global)\n",
           ok[0], nr, global[0], ok[1], nr, global[1], ok[2], nr, global[2]);
    printf("evaluations f+J in total: ours %zu, GSL %zu, GSL with 1e-8 %zu\n", ev[0], ev[1],
           ev[2]);
    double t_ours[1000], t_gsl[1000];
    for (int k = 0; k < repeats; ++k) { /* interleaved, so drift hits both */
        t_ours[k] = set_time(runs, nr, 0);
        t_gsl[k] = set_time(runs, nr, 1);
    }
    double mo = bench_median(t_ours, repeats), mg = bench_median(t_gsl, repeats);
    printf("time for the %zu runs, median of %d: ours %.2f ms, GSL %.2f ms; ratio ours/GSL %.2f\n",
           nr, repeats, 1e3 * mo, 1e3 * mg, mo / mg);
    return 0;
}
