/*
 * cmd_verify.c — `tissuefit verify`: convergence table of the cantilever or
 * the patch test against their analytic solutions; `verify hertz` is the
 * collocation solver's Hertz test (cmd_verify_hertz.c).
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/atomic_file.h"
#include "cli/cli.h"
#include "cli/cmd_args.h"
#include "cli/cmd_verify_hertz.h"
#include "base/log.h"
#include "scene/scene_levels.h"
#include "verify/verify.h"

#define MAX_LEVELS 12

static void help(FILE *out)
{
    fprintf(out,
            "usage: tissuefit verify cantilever|patch [--scene FILE] [--levels N]\n"
            "                        [--vary grid|gauss] [--set KEY=VALUE]... [--csv FILE]\n\n"
            "Solves a scene with an analytic reference at successive levels and prints\n"
            "level,nodes,dofs,error_l2,error_energy,rate (relative errors, rate of the L2\n"
            "error against the nodal spacing).\n\n"
            "  cantilever  coeffs/cantilever.yaml: Timoshenko beam, plane strain;\n"
            "              default --vary grid, 4 levels\n"
            "  patch       tests/solver/patch.yaml: linear field on a jittered cloud;\n"
            "              default --vary gauss, 6 levels\n\n"
            "--vary grid:  level k halves the spacing k times (cells and an absolute d_c\n"
            "              with it; a relative d_c follows by itself; an\n"
            "              axis of two nodes keeps them and shrinks instead)\n"
            "--vary gauss: level column = Gauss points per axis, 1 .. N\n\n"
            "Options:\n"
            "  --scene FILE      the scene (default above, relative to the repository)\n"
            "  --levels N        number of levels (1 to %d)\n"
            "  --set KEY=VALUE   override a scene value for every level (repeatable)\n"
            "  --csv FILE        also write the table to FILE\n"
            "Errors are integrated with %d^3 Gauss points per background cell.\n",
            MAX_LEVELS, TF_VERIFY_ERROR_ORDER);
    fputc('\n', out);
    tf_verify_hertz_help(out);
}

typedef struct verify_args {
    const char *scene, *csv;
    unsigned levels;
    tf_vary vary;
    tf_sets sets;
} verify_args;

static int parse(tf_ctx *ctx, int argc, char **argv, verify_args *a)
{
    static const struct option opts[] = {{"scene", required_argument, NULL, 'S'},
                                         {"levels", required_argument, NULL, 'l'},
                                         {"vary", required_argument, NULL, 'v'},
                                         {"set", required_argument, NULL, 's'},
                                         {"csv", required_argument, NULL, 'c'},
                                         {0}};
    int c, vary = -1;
    char *end;
    optind = 1;
    opterr = 0;
    while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
        switch (c) {
        case 'S':
            a->scene = optarg;
            break;
        case 'l':
            a->levels = (unsigned)strtoul(optarg, &end, 10);
            if (*end != '\0' || a->levels < 1 || a->levels > MAX_LEVELS) {
                tf_error(ctx, "verify: --levels '%s' is not 1 to %d", optarg, MAX_LEVELS);
                return -1;
            }
            break;
        case 'v':
            vary = strcmp(optarg, "grid") == 0 ? TF_VARY_GRID
                   : strcmp(optarg, "gauss") == 0 ? TF_VARY_GAUSS
                                                  : -2;
            if (vary == -2) {
                tf_error(ctx, "verify: --vary '%s' is not grid or gauss", optarg);
                return -1;
            }
            break;
        case 's':
            if (tf_sets_add(&a->sets, optarg) != 0) {
                return -1;
            }
            break;
        case 'c':
            a->csv = optarg;
            break;
        default:
            tf_error(ctx, "verify: bad option '%s' (see tissuefit verify --help)",
                     argv[optind - 1]);
            return -1;
        }
    }
    if (optind + 1 != argc) {
        tf_error(ctx, "verify: expected cantilever or patch (see tissuefit verify --help)");
        return -1;
    }
    int cantilever = strcmp(argv[optind], "cantilever") == 0;
    if (!cantilever && strcmp(argv[optind], "patch") != 0) {
        tf_error(ctx, "verify: '%s' is not cantilever or patch", argv[optind]);
        return -1;
    }
    if (a->scene == NULL) {
        a->scene = cantilever ? "coeffs/cantilever.yaml" : "tests/solver/patch.yaml";
    }
    a->vary = vary >= 0 ? (tf_vary)vary : cantilever ? TF_VARY_GRID : TF_VARY_GAUSS;
    if (a->levels == 0) {
        a->levels = cantilever ? 4 : 6;
    }
    return 0;
}

static void print_table(FILE *fp, const tf_verify_row *rows, size_t n)
{
    fprintf(fp, "level,nodes,dofs,error_l2,error_energy,rate\n");
    for (size_t k = 0; k < n; ++k) {
        fprintf(fp, "%u,%zu,%zu,%.6e,%.6e,", rows[k].level, rows[k].nodes, rows[k].dofs,
                rows[k].error_l2, rows[k].error_energy);
        if (isfinite(rows[k].rate)) {
            fprintf(fp, "%.3f", rows[k].rate);
        }
        fputc('\n', fp);
    }
}

static int run(tf_ctx *ctx, int argc, char **argv)
{
    for (int k = 1; k < argc; ++k) {
        if (strcmp(argv[k], "hertz") == 0) {
            return tf_verify_hertz(ctx, argc, argv);
        }
    }
    verify_args a = {0};
    tf_verify_row rows[MAX_LEVELS];
    if (parse(ctx, argc, argv, &a) != 0 || tf_cmd_outputs(ctx, "verify", &a.csv, 1) != 0) {
        tf_sets_free(&a.sets);
        return TF_EXIT_USAGE;
    }
    int rc = TF_EXIT_OK;
    for (unsigned k = 0; k < a.levels && rc == TF_EXIT_OK; ++k) {
        unsigned label;
        tf_scene *s = tf_scene_level(ctx, a.scene, a.sets.item, a.sets.n, a.vary, k, &label);
        if (s == NULL) {
            tf_error(ctx, "verify: %s", ctx->err);
            rc = TF_EXIT_USAGE;
            break;
        }
        int verified = tf_verify_problem(&s->problem, label, ctx, &rows[k]);
        tf_scene_free(s);
        if (verified != 0) {
            tf_error(ctx, "verify: %s", ctx->err);
            rc = verified == -2 ? TF_EXIT_USAGE : TF_EXIT_FAIL;
            break;
        }
        tf_info(ctx, "verify: level %u: %zu nodes, L2 error %.3e, energy error %.3e (%.2f s)",
                rows[k].level, rows[k].nodes, rows[k].error_l2, rows[k].error_energy,
                rows[k].seconds);
    }
    tf_sets_free(&a.sets);
    if (rc != TF_EXIT_OK) {
        return rc;
    }
    if (a.vary == TF_VARY_GRID) {
        tf_verify_rates(rows, a.levels);
    }
    if (a.csv) {
        tf_afile f;
        if (tf_afile_open(ctx, &f, a.csv) != 0) {
            tf_error(ctx, "verify: %s", ctx->err);
            return TF_EXIT_FAIL;
        }
        print_table(f.fp, rows, a.levels);
        if (tf_afile_commit(ctx, &f) != 0) {
            tf_error(ctx, "verify: %s", ctx->err);
            return TF_EXIT_FAIL;
        }
    }
    print_table(stdout, rows, a.levels);
    return TF_EXIT_OK;
}

const tf_command tf_cmd_verify = {
    .name = "verify",
    .summary = "convergence table of the cantilever or the patch test; the Hertz test",
    .run = run,
    .help = help,
};
