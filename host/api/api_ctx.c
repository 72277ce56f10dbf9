/*
 * api_ctx.c — the API's context (api.h): the tool's messages on standard
 * error, the last error kept for the caller, and the OpenBLAS pin.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_internal.h"
#include "base/blas_pin.h"

/* OpenBLAS's own interface (its cblas.h), declared here rather than
 * included: the header's path depends on the Debian variant installed. */
char *openblas_get_corename(void);
void openblas_set_num_threads(int n);

/* Errors are kept for tf_api_ctx_error (the caller raises them); warnings
 * and progress go to standard error with the tool's prefixes. */
static void keep_errors(void *user, tf_log_level level, const char *msg)
{
    tf_ctx *ctx = user;
    if (level == TF_LOG_ERROR) {
        snprintf(ctx->err, sizeof ctx->err, "%s", msg);
    } else {
        fprintf(stderr, "%s%s\n", level == TF_LOG_WARN ? "tissuefit: warning: " : "", msg);
    }
}

tf_ctx *tf_api_ctx_new(int level)
{
    tf_ctx *ctx = malloc(sizeof *ctx);
    if (ctx == NULL) {
        return NULL;
    }
    tf_ctx_init(ctx);
    ctx->level = level <= 0 ? TF_LOG_ERROR : level == 1 ? TF_LOG_WARN : TF_LOG_INFO;
    ctx->sink = keep_errors;
    ctx->sink_user = ctx;
    return ctx;
}

void tf_api_ctx_free(tf_ctx *ctx)
{
    free(ctx);
}

const char *tf_api_ctx_error(const tf_ctx *ctx)
{
    return ctx->err;
}

int tf_api_blas_check(tf_ctx *ctx)
{
    openblas_set_num_threads(1);
    const char *want = tf_blas_wanted_coretype(), *have = openblas_get_corename();
    if (want != NULL && (have == NULL || strcmp(want, have) != 0)) {
        return tf_fail(ctx,
                       "OpenBLAS runs its %s kernels, not the %s kernels tissuefit pins: solves "
                       "may differ from the tool's in the last bits (set OPENBLAS_CORETYPE=%s "
                       "before the process loads OpenBLAS, e.g. import tissuefit before numpy)",
                       have ? have : "unknown", want, want);
    }
    return 0;
}

int tf_api_fail_on(tf_ctx *ctx, const char *fmt, ...)
{
    char before[TF_CTX_ERR_MAX], prefix[TF_CTX_ERR_MAX];
    snprintf(before, sizeof before, "%s", ctx->err);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, ap);
    va_end(ap);
    return tf_fail(ctx, "%s: %s", prefix, before);
}
