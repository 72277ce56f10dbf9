/*
 * cmd_sweep.c — `tissuefit sweep`: every candidate model of a scene, its
 * cost and its held-out error, the Pareto front marked (sweep.h,
 * docs/tradeoff.md).
 */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "base/log.h"
#include "base/plot.h"
#include "base/atomic_file.h"
#include "report/sweep_report.h"
#include "tradeoff/region_sweep.h"
#include "tradeoff/sweep.h"

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit sweep SCENE [--csv FILE] [--md FILE] [--png FILE]\n"
            "                       [--outputs scene|all] [--set KEY=VALUE]...\n\n"
            "Fits every candidate model of the scene to the same load cases (the fit:\n"
            "section) and measures each the same way: coefficients, table bytes, float\n"
            "operations, estimated microseconds on a 168 MHz Cortex-M4F and a 480 MHz\n"
            "Cortex-M7, native nanoseconds per call of the real evaluator (median), and\n"
            "the held-out error against true solves.  Candidates: nodal p = 0..max and\n"
            "modal p = 1..max with r = 1..max_rank (float32; nodal also Q31 and float64),\n"
            "zhou2017 at its cross-validated orders, the contact inverse p = 1..max.\n"
            "--outputs all (default) repeats the forward candidates for the contact\n"
            "site alone and for every node, to show what each output costs.\n"
            "A scene whose contact is a region gets the region's trade instead: the\n"
            "site spacings tissuefit fit's density rule fits and, at each, the surface\n"
            "at ranks 1, 2, 4 .. 48 with its near field: the law's and the surface's\n"
            "held-out errors at the cell centres, table bytes and Cortex-M4F cycles\n"
            "(--png: the surface error against the table's bytes).\n\n"
            "Options:\n"
            "  --csv FILE    the table as CSV (default: standard output)\n"
            "  --md FILE     the table as Markdown\n"
            "  --png FILE    log-log plot of error against time, with the seed's point\n"
            "  --outputs S   scene: the scene's outputs only; all: also contact-only and\n"
            "                every node (default)\n"
            "  --set K=V     override a scene value (repeatable)\n");
}

static int write_region(tf_ctx *ctx, const tf_region_sweep *sw, const char *path, int md)
{
    tf_afile f;
    if (tf_afile_open(ctx, &f, path) != 0) {
        return -1;
    }
    if ((md ? tf_region_sweep_markdown(sw, f.fp) : tf_region_sweep_csv(sw, f.fp)) != 0) {
        tf_afile_abort(&f);
        return tf_fail(ctx, "%s: %s", path, strerror(errno));
    }
    return tf_afile_commit(ctx, &f);
}

/* A contact region: its spacings and ranks (region_sweep.h). */
static int region_sweep(tf_ctx *ctx, const tf_problem *p, int contact, const char *csv,
                        const char *md, const char *png)
{
    if (png != NULL && !tf_plot_available()) {
        tf_error(ctx,
                 "sweep: --png needs gnuplot with the pngcairo terminal (Debian: gnuplot-nox)");
        return TF_EXIT_USAGE;
    }
    tf_region_sweep sw = {0};
    tf_solver *solver = tf_solver_create(p, NULL, ctx);
    int rc = TF_EXIT_FAIL;
    if (solver == NULL || tf_region_sweep_run(ctx, p, solver, contact, &sw) != 0) {
        tf_error(ctx, "sweep: %s", ctx->err);
    } else if (!csv && tf_region_sweep_csv(&sw, stdout) != 0) {
        tf_error(ctx, "sweep: cannot write the table to standard output: %s", strerror(errno));
    } else if ((csv && write_region(ctx, &sw, csv, 0) != 0) ||
               (md && write_region(ctx, &sw, md, 1) != 0) ||
               (png && tf_region_sweep_plot(ctx, &sw, png) != 0)) {
        tf_error(ctx, "sweep: %s", ctx->err);
    } else {
        tf_info(ctx, "sweep: contact region '%s': %zu spacings x ranks measured",
                p->contacts[contact].name, sw.n);
        rc = TF_EXIT_OK;
    }
    tf_region_sweep_free(&sw);
    tf_solver_destroy(solver);
    return rc;
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    static const struct option opts[] = {{"csv", required_argument, NULL, 'c'},
                                         {"md", required_argument, NULL, 'm'},
                                         {"png", required_argument, NULL, 'p'},
                                         {"outputs", required_argument, NULL, 'o'},
                                         {"set", required_argument, NULL, 's'},
                                         {0}};
    const char *csv = NULL, *md = NULL, *png = NULL;
    unsigned sets = TF_SWEEP_ALL_SETS;
    tf_sets overrides = {0};
    int c, rc = TF_EXIT_USAGE;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (c == 'c') {
            csv = optarg;
        } else if (c == 'm') {
            md = optarg;
        } else if (c == 'p') {
            png = optarg;
        } else if (c == 'o' && (strcmp(optarg, "scene") == 0 || strcmp(optarg, "all") == 0)) {
            sets = strcmp(optarg, "scene") == 0 ? 1u << TF_SET_SCENE : TF_SWEEP_ALL_SETS;
        } else if (c == 's' && tf_sets_add(&overrides, optarg) == 0) {
            continue;
        } else {
            tf_error(ctx, "sweep: bad option '%s' (see tissuefit sweep --help)", argv[optind - 1]);
            tf_sets_free(&overrides);
            return TF_EXIT_USAGE;
        }
    }
    if (optind + 1 != argc) {
        tf_error(ctx, "sweep: expected one scene file (see tissuefit sweep --help)");
        tf_sets_free(&overrides);
        return TF_EXIT_USAGE;
    }
    if (tf_cmd_outputs(ctx, "sweep", (const char *[]){csv, md, png}, 3) != 0) {
        tf_sets_free(&overrides);
        return TF_EXIT_USAGE;
    }
    tf_scene *s = tf_cmd_scene(ctx, argv[optind], &overrides);
    const tf_problem *p = s ? &s->problem : NULL;
    tf_solver *solver = NULL;
    tf_sweep sw = {0};
    if (s == NULL) {
        /* reported */
    } else if (p->n_contacts == 0) {
        tf_error(ctx, "sweep: %s has no contact site to apply forces at", argv[optind]);
    } else if (s->fit.contact >= 0 &&
               p->contacts[s->fit.contact].region.kind != TF_CONTACT_REGION_NONE) {
        rc = region_sweep(ctx, p, s->fit.contact, csv, md, png);
    } else if (png != NULL && !tf_plot_available()) {
        tf_error(ctx,
                 "sweep: --png needs gnuplot with the pngcairo terminal (Debian: gnuplot-nox)");
    } else {
        rc = TF_EXIT_FAIL;
        solver = tf_solver_create(p, NULL, ctx);
        if (solver == NULL || tf_sweep_run(ctx, p, solver, &s->fit, sets, &sw) != 0) {
            tf_error(ctx, "sweep: %s", ctx->err);
        } else if (!csv && tf_report_sweep_csv_write(&sw, stdout) != 0) {
            tf_error(ctx, "sweep: cannot write the table to standard output: %s",
                     strerror(errno));
        } else if ((csv && tf_report_sweep_csv(ctx, &sw, csv) != 0) ||
                   (md && tf_report_sweep_markdown(ctx, &sw, p, md) != 0) ||
                   (png && tf_report_sweep_plot(ctx, &sw, png) != 0)) {
            tf_error(ctx, "sweep: %s", ctx->err);
        } else {
            tf_info(ctx, "sweep: %zu candidates measured", sw.n);
            rc = TF_EXIT_OK;
        }
    }
    tf_sweep_free(&sw);
    tf_solver_destroy(solver);
    tf_scene_free(s);
    tf_sets_free(&overrides);
    return rc;
}

const tf_command tf_cmd_sweep = {
    .name = "sweep",
    .summary = "every candidate model's cost and held-out error, Pareto front marked",
    .run = run,
    .help = help,
};
