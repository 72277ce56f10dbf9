/*
 * api_fit.c — `tissuefit fit` through the API (api.h): the command itself,
 * given the words of its command line, so that a header written from
 * Python is the tool's, byte for byte.
 */
#include <stdlib.h>

#include "api/api_internal.h"
#include "cli/cli.h"

int tf_api_fit(tf_ctx *ctx, const char *const *args, size_t n_args, int *status)
{
    /* argv as main() hands it on: the command's name first, NULL last;
     * getopt may reorder the pointers, never the strings */
    char **argv = malloc((n_args + 2) * sizeof *argv);
    if (argv == NULL) {
        if (status != NULL) {
            *status = TF_EXIT_FAIL;
        }
        return tf_fail(ctx, "fit: out of memory");
    }
    argv[0] = (char *)"fit";
    for (size_t i = 0; i < n_args; ++i) {
        argv[i + 1] = (char *)args[i];
    }
    argv[n_args + 1] = NULL;
    ctx->err[0] = '\0';
    int rc = tf_cmd_fit.run(ctx, (int)n_args + 1, argv);
    free(argv);
    if (status != NULL) {
        *status = rc;
    }
    if (rc != TF_EXIT_OK && ctx->err[0] == '\0') {
        tf_fail(ctx, "fit: failed with exit status %d", rc);
    }
    return rc == TF_EXIT_OK ? 0 : -1;
}
