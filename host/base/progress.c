/*
 * progress.c — throttled progress lines (progress.h).
 */
#include "base/progress.h"

#include <stdarg.h>
#include <stdio.h>

#include "base/clock.h"
#include "base/log.h"

void tf_progress_start(tf_progress *p, const tf_ctx *ctx, double every)
{
    p->ctx = ctx;
    p->t0 = p->shown = tf_seconds();
    p->every = every;
}

void tf_progress_line(tf_progress *p, const char *fmt, ...)
{
    double now = tf_seconds();
    if (!(now - p->shown >= p->every) || p->ctx->level < TF_LOG_INFO) {
        return;
    }
    char line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    tf_info(p->ctx, "%s (%.0f s)", line, now - p->t0);
    p->shown = now;
}
