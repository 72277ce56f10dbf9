/*
 * cli.h — the tissuefit command table.  Each command lives in its own
 * cmd_*.c file, prints its own --help, and returns the process exit status:
 * 0 success, 1 failure while running, 2 bad usage or bad input (nothing is
 * written in that case).
 */
#ifndef TF_CLI_H
#define TF_CLI_H

#include <stdio.h>

#include "base/context.h"

#define TF_EXIT_OK 0
#define TF_EXIT_FAIL 1
#define TF_EXIT_USAGE 2

typedef struct tf_command {
    const char *name;
    const char *summary;               /* one line for `tissuefit --help` */
    int (*run)(tf_ctx *ctx, int argc, char **argv); /* argv[0] is the command name */
    void (*help)(FILE *out);           /* `tissuefit NAME --help` */
} tf_command;

/* Defined in the cmd_*.c files. */
extern const tf_command tf_cmd_demo_model;
extern const tf_command tf_cmd_eval;
extern const tf_command tf_cmd_fit;
extern const tf_command tf_cmd_replay;
extern const tf_command tf_cmd_sweep;
extern const tf_command tf_cmd_lm_strd;
extern const tf_command tf_cmd_solve;
extern const tf_command tf_cmd_verify;

/* True when argv holds --help or -h (checked before any other parsing). */
int tf_wants_help(int argc, char **argv);

/* Flushes and closes standard output; rc, or TF_EXIT_FAIL (with a message)
 * when rc was 0 and the output could not be written in full. */
int tf_finish_stdout(tf_ctx *ctx, int rc);

#endif /* TF_CLI_H */
