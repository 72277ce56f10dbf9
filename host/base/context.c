/*
 * context.c — a run's context (context.h).
 */
#include "base/context.h"

#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void tf_ctx_init(tf_ctx *ctx)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->level = TF_LOG_INFO;
}

int tf_ctx_threads(const tf_ctx *ctx)
{
    return ctx->threads > 0 ? ctx->threads : omp_get_max_threads();
}

/* Formats into a copy first, so that a caller may wrap the message a callee
 * left: tf_fail(ctx, "%s: %s", where, ctx->err). */
int tf_fail(tf_ctx *ctx, const char *fmt, ...)
{
    char msg[sizeof ctx->err];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    memcpy(ctx->err, msg, sizeof msg);
    return -1;
}
