/*
 * log.c — messages through the context's sink (log.h).
 */
#include "base/log.h"

#include <stdarg.h>
#include <stdio.h>

static void stderr_sink(tf_log_level level, const char *msg)
{
    static const char *const prefix[] = {"tissuefit: error: ", "tissuefit: warning: ", ""};
    fprintf(stderr, "%s%s\n", prefix[level], msg);
}

static void vlog(const tf_ctx *ctx, tf_log_level level, const char *fmt, va_list ap)
{
    if (level > ctx->level) {
        return;
    }
    char msg[4096];
    vsnprintf(msg, sizeof msg, fmt, ap);
    if (ctx->sink != NULL) {
        ctx->sink(ctx->sink_user, level, msg);
    } else {
        stderr_sink(level, msg);
    }
}

void tf_info(const tf_ctx *ctx, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(ctx, TF_LOG_INFO, fmt, ap);
    va_end(ap);
}

void tf_warn(const tf_ctx *ctx, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(ctx, TF_LOG_WARN, fmt, ap);
    va_end(ap);
}

void tf_error(const tf_ctx *ctx, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(ctx, TF_LOG_ERROR, fmt, ap);
    va_end(ap);
}
