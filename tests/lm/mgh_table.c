/*
 * mgh_table.c — the Moré–Garbow–Hillstrom table of docs/lm.md: the 53 runs
 * of MINPACK's lmder driver with tissuefit's LM, each with its stop reason,
 * evaluations, final norm ||f|| and the known minimum it reached, as
 * Markdown on stdout.
 *
 *   mgh_table [--scale up|down|alternate] [--tol T] [--summary]
 *
 * --scale runs every problem with its parameters rescaled (the solver sees
 * q = x / s): up s_j = 1e10, down s_j = 1e-10, alternate s_j = 1e10 for
 * even j and 1e-10 for odd j.  --tol sets ftol = xtol (default 1e-15).
 * --summary prints only the closing line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/mgh_fit.h"

static void scales(const char *how, size_t n, double *s)
{
    for (size_t j = 0; j < n; ++j) {
        if (strcmp(how, "up") == 0) {
            s[j] = 1e10;
        } else if (strcmp(how, "down") == 0) {
            s[j] = 1e-10;
        } else if (strcmp(how, "alternate") == 0) {
            s[j] = j % 2 == 0 ? 1e10 : 1e-10;
        } else {
            fprintf(stderr, "mgh_table: --scale up, down or alternate, not '%s'\n", how);
            exit(2);
        }
    }
}

int main(int argc, char **argv)
{
    const char *scale = NULL;
    double tol = 1e-15;
    int rows = 1;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--scale") == 0 && i + 1 < argc) {
            scale = argv[++i];
        } else if (strcmp(argv[i], "--tol") == 0 && i + 1 < argc) {
            tol = atof(argv[++i]);
        } else if (strcmp(argv[i], "--summary") == 0) {
            rows = 0;
        } else {
            fprintf(stderr, "usage: mgh_table [--scale up|down|alternate] [--tol T] [--summary]\n");
            return 2;
        }
    }
    size_t nr;
    const tf_mgh_run *runs = tf_mgh_runs(&nr);
    if (rows) {
        printf("| # | problem | n | m | start | stop | f evals | J evals | ||f|| | minimum |\n");
        printf("|---|---|---|---|---|---|---|---|---|---|\n");
    }
    size_t fe = 0, je = 0, global = 0, local = 0, elsewhere = 0, failed = 0;
    for (size_t k = 0; k < nr; ++k) {
        const tf_mgh_run *r = &runs[k];
        tf_lm_options o;
        tf_mgh_options(&o, r->n);
        o.ftol = o.xtol = tol;
        double s[TF_MGH_MAX_N];
        if (scale != NULL) {
            scales(scale, r->n, s);
        }
        tf_mgh_score sc;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        if (tf_mgh_fit(&ctx, r, &o, scale != NULL ? s : NULL, &sc) != 0) {
            fprintf(stderr, "mgh_table: %s\n", ctx.err);
            return 1;
        }
        int ok = tf_stop_converged(sc.stop);
        if (rows) {
            char at[64];
            tf_mgh_describe(r, sc.minimum, at, sizeof at);
            printf("| %d | %s | %zu | %zu | %gx0 | %s | %zu | %zu | %.7e | %s |\n", r->problem,
                   tf_mgh_name(r->problem), r->n, r->m, r->factor, tf_stop_name(sc.stop),
                   sc.evals, sc.jac_evals, sqrt(sc.rss), at);
        }
        fe += sc.evals;
        je += sc.jac_evals;
        global += ok && sc.minimum == 0;
        local += ok && sc.minimum > 0;
        elsewhere += ok && sc.minimum < 0;
        failed += !ok;
    }
    printf("%s%s, tol %g: %zu runs converged at the global minimum, %zu at another known "
           "minimum, %zu at none (claimed convergence), %zu did not converge; evaluations %zu f "
           "+ %zu J\n",
           scale != NULL ? "scale " : "unscaled", scale != NULL ? scale : "", tol, global, local,
           elsewhere, failed, fe, je);
    return 0;
}
