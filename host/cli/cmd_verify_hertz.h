/*
 * cmd_verify_hertz.h — `tissuefit verify hertz` (cmd_verify_hertz.c), the
 * part of `tissuefit verify` that runs the collocation solver's Hertz test.
 */
#ifndef TF_CMD_VERIFY_HERTZ_H
#define TF_CMD_VERIFY_HERTZ_H

#include <stdio.h>

#include "base/context.h"

/* Runs `verify ... hertz ...` (argv as for the verify command); returns the
 * exit status. */
int tf_verify_hertz(tf_ctx *ctx, int argc, char **argv);

/* Its part of `tissuefit verify --help`. */
void tf_verify_hertz_help(FILE *out);

#endif /* TF_CMD_VERIFY_HERTZ_H */
