/*
 * strd_table.c — the NIST StRD table of docs/lm.md: every problem from both
 * starting points, with the stop reason, iterations, evaluations and the
 * correct digits (LRE) of the parameters, the RSS and the standard errors,
 * as Markdown on stdout.
 *
 *   strd_table [--factor F] [--finite-diff | --central-diff] [--summary]
 *
 * --factor changes the initial trust region (the study in docs/lm.md),
 * --finite-diff uses forward differences instead of the analytic Jacobian,
 * --central-diff central ones,
 * --summary prints only the closing lines.  Run from the repository root
 * (the data are read from ../shared/reference/nist-strd).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/nist_fit.h"

#define DIR "../shared/reference/nist-strd"

typedef struct totals {
    int runs, below6;
    size_t n_lre, evals, jac_evals, iterations;
    double sum_lre, sum_min, min_lre, min_se;
} totals;

static double min_of(const double *v, size_t n)
{
    double m = TF_LRE_CAP;
    for (size_t j = 0; j < n; ++j) {
        m = fmin(m, v[j]);
    }
    return m;
}

static void one_run(const tf_nist *d, const tf_nist_model *model, int start,
                    const tf_lsfit_options *o, int fd, int rows, totals *t)
{
    tf_nist_score s;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_nist_fit(&ctx, d, model, start, o, fd, &s) != 0) {
        fprintf(stderr, "strd_table: %s\n", ctx.err);
        exit(1);
    }
    double par = min_of(s.lre, d->n_par), se = min_of(s.se_lre, d->n_par);
    int rss_ok = s.rss_lre >= 6 || fabs(s.rss - d->certified_rss) <=
                                       tf_nist_rss_resolution(d, model);
    int ok = par >= 6 && rss_ok && tf_stop_converged(s.stop);
    if (rows) {
        printf("| %s | %d | %s | %zu | %zu | %zu | %.2f | %.2f%s | %.2f |%s\n", d->name, start,
               tf_stop_name(s.stop), s.iterations, s.evals, s.jac_evals, par, s.rss_lre,
               s.rss_lre < 6 && rss_ok ? " (a)" : "", se, ok ? "" : " **below 6** |");
    }
    t->runs++;
    t->below6 += !ok;
    for (size_t j = 0; j < d->n_par; ++j) {
        t->sum_lre += s.lre[j];
    }
    t->n_lre += d->n_par;
    t->sum_min += par;
    t->min_lre = fmin(t->min_lre, par);
    t->min_se = fmin(t->min_se, se);
    t->evals += s.evals;
    t->jac_evals += s.jac_evals;
    t->iterations += s.iterations;
}

int main(int argc, char **argv)
{
    double factor = 0;
    int fd = 0, central = 0, rows = 1;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--factor") == 0 && i + 1 < argc) {
            factor = atof(argv[++i]);
        } else if (strcmp(argv[i], "--finite-diff") == 0) {
            fd = 1;
        } else if (strcmp(argv[i], "--central-diff") == 0) {
            fd = central = 1;
        } else if (strcmp(argv[i], "--summary") == 0) {
            rows = 0;
        } else {
            fprintf(stderr, "usage: strd_table [--factor F] [--finite-diff | --central-diff] "
                            "[--summary]\n");
            return 2;
        }
    }
    if (factor <= 0) {
        tf_lm_options dflt;
        tf_lm_default_options(&dflt, 1);
        factor = dflt.factor;
    }
    size_t n;
    const char *const *names = tf_nist_suite(&n);
    totals t = {.min_lre = TF_LRE_CAP, .min_se = TF_LRE_CAP};
    if (rows) {
        printf("| problem | start | stop | iterations | f evals | J evals | min LRE b | "
               "LRE RSS | min LRE se |\n|---|---|---|---|---|---|---|---|---|\n");
    }
    for (size_t k = 0; k < n; ++k) {
        tf_nist d;
        const tf_nist_model *model;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        if (tf_nist_load(&ctx, DIR, names[k], &d, &model) != 0) {
            fprintf(stderr, "strd_table: %s\n", ctx.err);
            return 1;
        }
        tf_lsfit_options o;
        tf_nist_options(&o, d.n_par);
        o.lm.factor = factor;
        o.lm.central_diff = central;
        for (int start = 1; start <= 2; ++start) {
            one_run(&d, model, start, &o, fd, rows, &t);
        }
        tf_nist_free(&d);
    }
    printf("\n%d runs (%s Jacobian, factor %g): %d below 6 digits.  Parameter LRE: mean %.2f "
           "over all %zu parameters, mean of the per-run minimum %.2f, minimum %.2f.  Standard "
           "errors: minimum LRE %.2f.  Totals: %zu iterations, %zu f evaluations, %zu J "
           "evaluations.\n",
           t.runs, central ? "central-difference" : fd ? "forward-difference" : "analytic", factor,
           t.below6,
           t.sum_lre / (double)t.n_lre, t.n_lre, t.sum_min / t.runs, t.min_lre, t.min_se,
           t.iterations, t.evals, t.jac_evals);
    return 0;
}
