/*
 * main.c — the `tissuefit` entry point: global options, the run's context
 * (base/context.h) and dispatch to the command table (cli.h).
 */
#include <stdio.h>
#include <string.h>

#include "base/blas_pin.h"
#include "cli/cli.h"
#include "base/log.h"
#include "tfit.h"

static const tf_command *const commands[] = {
    &tf_cmd_fit,
    &tf_cmd_replay,
    &tf_cmd_sweep,
    &tf_cmd_demo_model,
    &tf_cmd_lm_strd,
    &tf_cmd_solve,
    &tf_cmd_verify,
};
#define N_COMMANDS (sizeof commands / sizeof commands[0])

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
    return tf_finish_stdout(&run, dispatch(&run, argc, argv));
}
