/*
 * cmd_verify_hertz.c — `tissuefit verify hertz`: the Hertz test of the MLS
 * collocation solver (verify/hertz.h) at several particle counts, the
 * force-indentation pairs against Hertz's theory and their L2 errors
 * (seed 004 Figs 3-5).
 */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "base/log.h"
#include "cli/cmd_verify_hertz.h"
#include "materials/material.h"
#include "verify/hertz.h"

#define MAX_COUNTS 8

/* "linear, svk, ...": the registered laws with parameters E and nu. */
static void elastic_laws(char *out, size_t len)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t i = 0; i < tf_law_count() && used < len; ++i) {
        const tf_law_ops *l = tf_law_at(i);
        if (tf_law_param_index(l, "E") >= 0 && tf_law_param_index(l, "nu") >= 0) {
            int w = snprintf(out + used, len - used, "%s%s", used ? ", " : "", l->name);
            used += w > 0 ? (size_t)w : 0;
        }
    }
}

void tf_verify_hertz_help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit verify hertz [--cells C1,C2,..] [--law NAME]\n"
            "                              [--csv FILE]\n\n"
            "Presses a rigid sphere (R = 100 mm) into a block of E = 1 MPa, nu = 0.3 with\n"
            "the MLS collocation solver (docs/collocation.md) at d/R = 1e-4, 2.5e-4, 4e-4,\n"
            "6.25e-4 (contact radius 1 to 2.5 mm) and compares the force with Hertz's\n"
            "F = 4/3 E* sqrt(R) d^(3/2).  The block is a quarter with mirror planes, its\n"
            "particles on 7 nested grids (half-width 320 mm); --cells sets the cells\n"
            "across each grid, one run per value (default 4,6,8: 713, 2017, 4353\n"
            "particles).  Prints particles,h0,d,a,F,F_theory,d_theory,d_error for every\n"
            "indentation and the L2 errors of each run.\n\n"
            "  --cells LIST  cells per nested grid, 2 to 32 each, up to %d values\n"
            "  --law NAME    a material law with parameters E and nu (default linear;\n"
            "                svk is [Aras-MLS]'s): ",
            MAX_COUNTS);
    char names[256];
    elastic_laws(names, sizeof names);
    fprintf(out, "%s\n  --csv FILE    also write the rows to FILE\n", names);
}

typedef struct hertz_args {
    int cells[MAX_COUNTS];
    size_t n;
    const tf_law_ops *law;
    const char *csv;
} hertz_args;

static int parse_cells(tf_ctx *ctx, const char *s, hertz_args *a)
{
    char buf[128], *save = NULL, *end;
    snprintf(buf, sizeof buf, "%s", s);
    a->n = 0;
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        long c = strtol(t, &end, 10);
        if (*end != '\0' || c < 2 || c > 32 || a->n == MAX_COUNTS) {
            tf_error(ctx, "verify hertz: --cells '%s': up to %d whole numbers 2 to 32", s,
                     MAX_COUNTS);
            return -1;
        }
        a->cells[a->n++] = (int)c;
    }
    return a->n ? 0 : -1;
}

static int parse(tf_ctx *ctx, int argc, char **argv, hertz_args *a)
{
    static const struct option opts[] = {{"cells", required_argument, NULL, 'c'},
                                         {"law", required_argument, NULL, 'l'},
                                         {"csv", required_argument, NULL, 'o'},
                                         {0}};
    *a = (hertz_args){.cells = {4, 6, 8}, .n = 3, .law = tf_law_find("linear")};
    int c;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        if (c == 'c') {
            if (parse_cells(ctx, optarg, a) != 0) {
                return -1;
            }
        } else if (c == 'l') {
            const tf_law_ops *law = tf_law_find(optarg);
            if (law == NULL || tf_law_param_index(law, "E") < 0 ||
                tf_law_param_index(law, "nu") < 0) {
                char names[256];
                elastic_laws(names, sizeof names);
                tf_error(ctx, "verify hertz: --law '%s' is not one of %s", optarg, names);
                return -1;
            }
            a->law = law;
        } else if (c == 'o') {
            a->csv = optarg;
        } else {
            tf_error(ctx, "verify hertz: bad option '%s' (see tissuefit verify --help)",
                     argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc || strcmp(argv[optind], "hertz") != 0) {
        tf_error(ctx, "verify hertz: expected only options and 'hertz'");
        return -1;
    }
    return 0;
}

static void print_rows(FILE *fp, const tf_hertz_row *r, size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        fprintf(fp, "%zu,%.6g,%.6g,%.6g,%.9g,%.9g,%.9g,%+.5f\n", r[k].particles, r[k].h0, r[k].d,
                r[k].a, r[k].F, r[k].F_theory, r[k].d_theory, r[k].d / r[k].d_theory - 1);
    }
}

static const char header[] = "particles,h0_mm,d_mm,a_mm,F_N,F_theory_N,d_theory_mm,d_error\n";

int tf_verify_hertz(tf_ctx *ctx, int argc, char **argv)
{
    hertz_args a;
    if (parse(ctx, argc, argv, &a) != 0) {
        return 2;
    }
    tf_hertz_row rows[MAX_COUNTS][TF_HERTZ_MAX_INDENT];
    tf_hertz_opts o;
    tf_hertz_defaults(&o);
    o.law = a.law;
    o.colloc.threads = tf_ctx_threads(ctx);
    for (size_t k = 0; k < a.n; ++k) {
        o.cells = a.cells[k];
        if (tf_hertz_run(&o, rows[k], ctx) != 0) {
            tf_error(ctx, "verify %s", ctx->err);
            return 1;
        }
        double l2F, l2d, worst;
        tf_hertz_errors(rows[k], o.n_indent, &l2F, &l2d, &worst);
        tf_info(ctx, "verify hertz: %zu particles: L2 error of the force %.4f, of the "
                     "indentation %.4f, largest indentation error %.4f",
                rows[k][0].particles, l2F, l2d, worst);
    }
    if (a.csv) {
        tf_afile f;
        if (tf_afile_open(ctx, &f, a.csv) != 0) {
            tf_error(ctx, "verify hertz: %s", ctx->err);
            return 1;
        }
        fputs(header, f.fp);
        for (size_t k = 0; k < a.n; ++k) {
            print_rows(f.fp, rows[k], o.n_indent);
        }
        if (tf_afile_commit(ctx, &f) != 0) {
            tf_error(ctx, "verify hertz: %s", ctx->err);
            return 1;
        }
    }
    fputs(header, stdout);
    for (size_t k = 0; k < a.n; ++k) {
        print_rows(stdout, rows[k], o.n_indent);
    }
    printf("particles,l2_force,l2_indentation,largest_indentation_error\n");
    for (size_t k = 0; k < a.n; ++k) {
        double l2F, l2d, worst;
        tf_hertz_errors(rows[k], o.n_indent, &l2F, &l2d, &worst);
        printf("%zu,%.5f,%.5f,%.5f\n", rows[k][0].particles, l2F, l2d, worst);
    }
    return 0;
}
