/*
 * cmd_lm_strd.c — `tissuefit lm-strd FILE.dat --start 1|2`: fit one NIST
 * StRD nonlinear problem with the Levenberg–Marquardt core and print, as
 * CSV, each estimate against its certified value in correct digits (LRE).
 */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "base/log.h"
#include "numerics/nist_fit.h"

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit lm-strd FILE.dat --start 1|2 [--finite-diff | --central-diff]\n\n"
            "Fits a NIST StRD nonlinear least-squares problem (the .dat files of\n"
            "../shared/reference/nist-strd) from its first or second starting point\n"
            "and prints CSV on stdout:\n\n"
            "  name,estimate,certified,lre\n"
            "  b1,...            one row per parameter\n"
            "  rss,...           the residual sum of squares\n\n"
            "lre = -log10(|estimate - certified| / |certified|), capped at %.0f: the\n"
            "number of correct significant digits.  The model is recognised from the\n"
            "formula in the file.  Tolerances: ftol = xtol = 1e-15 (docs/lm.md).\n\n"
            "Options:\n"
            "  --start N       starting point 1 or 2 (required)\n"
            "  --finite-diff   forward-difference Jacobian instead of the analytic one\n"
            "  --central-diff  central-difference Jacobian instead of the analytic one\n\n"
            "Exit status: 0 converged, 1 the solver did not converge (the CSV is still\n"
            "printed), 2 bad usage or a file that cannot be read (message with file:line).\n",
            TF_LRE_CAP);
}

static void print_csv(const tf_nist *d, const tf_nist_score *s)
{
    printf("name,estimate,certified,lre\n");
    for (size_t j = 0; j < d->n_par; ++j) {
        printf("b%zu,%.17g,%.11g,%.2f\n", j + 1, s->estimate[j], d->certified[j], s->lre[j]);
    }
    printf("rss,%.17g,%.11g,%.2f\n", s->rss, d->certified_rss, s->rss_lre);
}

/* --start N: 1 or 2, else 0. */
static int parse_start(const char *arg)
{
    return strcmp(arg, "1") == 0 ? 1 : strcmp(arg, "2") == 0 ? 2 : 0;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    static const struct option opts[] = {{"start", required_argument, NULL, 's'},
                                         {"finite-diff", no_argument, NULL, 'f'},
                                         {"central-diff", no_argument, NULL, 'c'},
                                         {0}};
    int start = 0, finite_diff = 0, central = 0, c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (c == 's' && (start = parse_start(optarg)) == 0) {
            tf_error(ctx, "lm-strd: --start '%s' must be 1 or 2", optarg);
            return TF_EXIT_USAGE;
        } else if (c == 'f' || c == 'c') {
            finite_diff = 1;
            central |= c == 'c';
        } else if (c != 's') {
            tf_error(ctx, "lm-strd: bad option '%s' (see tissuefit lm-strd --help)",
                     argv[optind - 1]);
            return TF_EXIT_USAGE;
        }
    }
    if (optind != argc - 1 || start == 0) {
        tf_error(ctx, "lm-strd: expected one FILE.dat and --start 1|2");
        return TF_EXIT_USAGE;
    }
    const char *path = argv[optind];
    tf_nist d;
    if (tf_nist_read(ctx, path, &d) != 0) {
        tf_error(ctx, "lm-strd: %s", ctx->err);
        return TF_EXIT_USAGE;
    }
    const tf_nist_model *model = tf_nist_match(ctx, &d, path);
    if (model == NULL) {
        tf_error(ctx, "lm-strd: %s", ctx->err);
        tf_nist_free(&d);
        return TF_EXIT_USAGE;
    }
    tf_lsfit_options o;
    tf_nist_options(&o, d.n_par);
    o.lm.central_diff = central;
    tf_nist_score s;
    if (tf_nist_fit(ctx, &d, model, start, &o, finite_diff, &s) != 0) {
        tf_error(ctx, "lm-strd: %s: %s", path, ctx->err);
        tf_nist_free(&d);
        return TF_EXIT_FAIL;
    }
    print_csv(&d, &s);
    tf_info(ctx, "lm-strd: %s start %d: stop %s after %zu iterations, %zu evaluations, %zu "
            "Jacobians; min LRE %.2f",
            d.name, start, tf_stop_name(s.stop), s.iterations, s.evals, s.jac_evals, s.min_lre);
    int ok = tf_stop_converged(s.stop);
    if (!ok) {
        tf_error(ctx, "lm-strd: %s start %d did not converge (%s)", d.name, start,
                 tf_stop_name(s.stop));
    }
    tf_nist_free(&d);
    return ok ? TF_EXIT_OK : TF_EXIT_FAIL;
}

const tf_command tf_cmd_lm_strd = {
    .name = "lm-strd",
    .summary = "fit a NIST StRD nonlinear problem and print correct digits (CSV)",
    .run = run,
    .help = help,
};
