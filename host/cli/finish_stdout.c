/*
 * finish_stdout.c — tf_finish_stdout (cli.h), shared by tissuefit and
 * tissuefit-mpi.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "base/log.h"
#include "cli/cli.h"

/* Standard output written in full, or a failure: a command whose table went
 * to a full disk (>/dev/full) must not exit 0.  Every command's output
 * passes here, so none can forget the final flush and close. */
int tf_finish_stdout(tf_ctx *ctx, int rc)
{
    int bad = fflush(stdout) != 0 || ferror(stdout);
    int saved = errno;
    if (fclose(stdout) != 0 && !bad) {
        bad = 1;
        saved = errno;
    }
    if (bad) {
        tf_error(ctx, "cannot write standard output: %s", strerror(saved));
        return rc == TF_EXIT_OK ? TF_EXIT_FAIL : rc;
    }
    return rc;
}
