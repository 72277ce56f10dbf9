/*
 * main.c — the `tissuefit` entry point: global options, the run's context
 * (base/context.h) and dispatch to the command table (cli.h).
 */
#include <stdio.h>
#include <string.h>

#include "base/blas_pin.h"
#include "base/interrupts.h"
#include "cli/cli.h"
#include "base/log.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "solvers/solver.h"
#include "tfit.h"

static const tf_command *const commands[] = {
    &tf_cmd_fit,
    &tf_cmd_replay,
    &tf_cmd_sweep,
    &tf_cmd_eval,
    &tf_cmd_demo_model,
    &tf_cmd_lm_strd,
    &tf_cmd_solve,
    &tf_cmd_verify,
};
#define N_COMMANDS (sizeof commands / sizeof commands[0])

/* "  name" and text from column 22, in lines of at most 79 characters. */
static void entry(FILE *out, const char *name, const char *text)
{
    int col = fprintf(out, "  %s", name);
    if (col > 21) {
        fputc('\n', out);
        col = 0;
    }
    for (const char *p = text + strspn(text, " "); *p != '\0'; p += strspn(p, " ")) {
        int w = (int)strcspn(p, " ");
        if (col > 22 && col + 1 + w > 79) {
            fputc('\n', out);
            col = 0;
        }
        col += fprintf(out, "%*s%.*s", col < 22 ? 22 - col : 1, "", w, p);
        p += w;
    }
    fputc('\n', out);
}

/* Every registered solver and material law, and the Newton tangents, from
 * their registries (the scene schema for the tangents). */
static void registries(FILE *out)
{
    char text[512];
    fprintf(out, "\nSolvers (scene key solver.method):\n");
    for (size_t i = 0; i < tf_solver_type_count(); ++i) {
        const tf_solver_ops *t = tf_solver_type_at(i);
        entry(out, t->name, t->summary);
    }
    fprintf(out, "\nMaterial laws (scene key material.law; its parameters are keys of material):\n");
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        char params[128];
        tf_law_param_list(l, 0, params, sizeof params);
        snprintf(text, sizeof text, "%s. Parameters: %s.", l->summary, params);
        entry(out, l->name, text);
    }
    tf_scene_key_values("solver.newton.tangent", text, sizeof text);
    fprintf(out, "\nNewton tangents (scene key solver.newton.tangent, the Newton solvers):\n  %s\n",
            text);
}

static void usage(FILE *out)
{
    fprintf(out,
            "usage: tissuefit [-q] COMMAND [OPTIONS]\n"
            "       tissuefit COMMAND --help\n"
            "       tissuefit --version\n\n"
            "tissuefit turns a soft-tissue scene into a generated C header that firmware\n"
            "evaluates in a fixed number of operations (see README.md).\n\n"
            "Commands:\n");
    for (size_t i = 0; i < N_COMMANDS; ++i) {
        fprintf(out, "  %-12s %s\n", commands[i]->name, commands[i]->summary);
    }
    registries(out);
    fprintf(out,
            "\nGlobal options:\n"
            "  -q, --quiet   no progress messages on stderr (errors are still shown)\n"
            "  -h, --help    this text\n"
            "  --version     tool and target API version\n\n"
            "Exit status: 0 success, 1 failure while running, 2 bad usage or input.\n");
}

static int dispatch(tf_ctx *ctx, int argc, char **argv)
{
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; ++i) {
        if (strcmp(argv[i], "-q") == 0 || strcmp(argv[i], "--quiet") == 0) {
            ctx->level = TF_LOG_WARN;
        } else if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            return TF_EXIT_OK;
        } else if (strcmp(argv[i], "--version") == 0) {
            printf("tissuefit %s (tfit API %d, OpenBLAS kernels %s)\n", TFIT_TOOL_VERSION,
                   TFIT_API_VERSION, tf_blas_coretype());
            return TF_EXIT_OK;
        } else {
            tf_error(ctx, "unknown option '%s' (try 'tissuefit --help')", argv[i]);
            return TF_EXIT_USAGE;
        }
    }
    if (i == argc) {
        usage(stderr);
        return TF_EXIT_USAGE;
    }
    const char *name = argv[i];
    if (strcmp(name, "help") == 0) {
        if (i + 1 == argc) {
            usage(stdout);
            return TF_EXIT_OK;
        }
        name = argv[i + 1];
        for (size_t k = 0; k < N_COMMANDS; ++k) {
            if (strcmp(commands[k]->name, name) == 0) {
                commands[k]->help(stdout);
                return TF_EXIT_OK;
            }
        }
        tf_error(ctx, "no command '%s' (try 'tissuefit --help')", name);
        return TF_EXIT_USAGE;
    }
    for (size_t k = 0; k < N_COMMANDS; ++k) {
        if (strcmp(commands[k]->name, name) == 0) {
            if (tf_wants_help(argc - i, argv + i)) {
                commands[k]->help(stdout);
                return TF_EXIT_OK;
            }
            return commands[k]->run(ctx, argc - i, argv + i);
        }
    }
    tf_error(ctx, "no command '%s' (try 'tissuefit --help')", name);
    return TF_EXIT_USAGE;
}

int main(int argc, char **argv)
{
    tf_blas_pin(argv);
    tf_ctx run;
    tf_ctx_init(&run);
    /* before any thread: interrupts wait while outputs are written, whichever
     * thread the kernel would hand them to (base/interrupts.h) */
    tf_interrupts watch;
    run.interrupts = tf_interrupts_start(&watch) == 0 ? &watch : NULL;
    return tf_finish_stdout(&run, dispatch(&run, argc, argv));
}
