/*
 * context.h — what a run of the tool carries down through the layers instead
 * of global variables: where messages go and how many of them, how many
 * threads the parallel loops use, and the message of the last failure.
 *
 * One context per run (cli/main.c makes it; a test makes its own), used by
 * one thread at a time, like CHOLMOD's cholmod_common.  A function that takes
 * a context reports a failure by returning non-zero with the message in
 * ctx->err (tf_fail); a leaf function without a context keeps the
 * (char *err, size_t errlen) pair.
 */
#ifndef TF_CONTEXT_H
#define TF_CONTEXT_H

#include <stddef.h>

/* Severity of a message; a context shows those at or below its level. */
typedef enum tf_log_level {
    TF_LOG_ERROR = 0, /* always shown */
    TF_LOG_WARN = 1,  /* shown unless quiet beyond errors */
    TF_LOG_INFO = 2,  /* progress; `tissuefit -q` drops it */
} tf_log_level;

/* Receives every message that passes the level, without a trailing newline. */
typedef void (*tf_log_sink)(void *user, tf_log_level level, const char *msg);

#define TF_CTX_ERR_MAX 1024

typedef struct tf_ctx {
    tf_log_level level;  /* most verbose level shown */
    tf_log_sink sink;    /* NULL: standard error with the tool's prefixes */
    void *sink_user;
    int threads;         /* OpenMP threads of parallel loops; 0: OpenMP's default */
    char err[TF_CTX_ERR_MAX]; /* message of the last failure ("" before any) */
} tf_ctx;

/* Progress shown, errors to standard error, OpenMP's thread count. */
void tf_ctx_init(tf_ctx *ctx);

/* The thread count parallel loops use: ctx->threads, or OpenMP's default. */
int tf_ctx_threads(const tf_ctx *ctx);

/* Writes the message into ctx->err and returns -1 (for `return tf_fail(...)`). */
int tf_fail(tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_CONTEXT_H */
