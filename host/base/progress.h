/*
 * progress.h — progress lines for long loops: at most one every few
 * seconds, through the context's log at the info level (so `tissuefit -q`
 * drops them), each ending with the seconds since the loop began.
 */
#ifndef TF_PROGRESS_H
#define TF_PROGRESS_H

#include "base/context.h"

typedef struct tf_progress {
    const tf_ctx *ctx;
    double t0, shown; /* tf_seconds() at the start and at the last line */
    double every;     /* seconds between lines */
} tf_progress;

/* Starts the clock; lines come at most every `every` seconds. */
void tf_progress_start(tf_progress *p, const tf_ctx *ctx, double every);

/* Prints the line (a printf format) with " (N s)" appended when `every`
 * seconds have passed since the last one (or the start); otherwise
 * nothing. */
void tf_progress_line(tf_progress *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_PROGRESS_H */
