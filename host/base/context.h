/*
 * context.h — what a run of the tool carries down through the layers instead
 * of global variables: where messages go and how many of them, how many
 * threads the parallel loops use, and the message of the last failure.
 *
 * One context per run (cli/main.c makes it; a test makes its own), like
 * CHOLMOD's cholmod_common.  Every fallible host function takes it first
 * (tf_ctx *ctx) and reports a failure by returning -1 (or NULL) with the
 * message in ctx->err: `return tf_fail(ctx, ...)`.  A caller that puts its
 * own words around a callee's message passes ctx->err back in
 * (tf_fail(ctx, "%s: %s", where, ctx->err)), which tf_fail allows.  A
 * solver reports in the context it was created with (solver->ctx).
 *
 * A context is written by one thread at a time.  Where the threads of a
 * parallel region call fallible functions (verify/error_norm.c: the error
 * integral's cells), each thread has a context of its own, and after the
 * region the message of the lowest failing item is copied into the caller's.
 * The assembly and gradient loops of solvers/ keep such a message per thread
 * in their shape work buffers (meshfree/shape.h).  An answer that is not a
 * failure (a Q31 form a family does not have, a bound being searched for)
 * may use a scratch context whose message is dropped.
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

struct tf_interrupts;

typedef struct tf_ctx {
    tf_log_level level;  /* most verbose level shown */
    tf_log_sink sink;    /* NULL: standard error with the tool's prefixes */
    void *sink_user;
    int threads;         /* OpenMP threads of parallel loops; 0: OpenMP's default */
    /* The run's signal watcher (base/interrupts.h), which holds interrupts
     * back while outputs are written; NULL: the writing thread's mask only. */
    struct tf_interrupts *interrupts;
    char err[TF_CTX_ERR_MAX]; /* message of the last failure ("" before any) */
} tf_ctx;

/* Progress shown, errors to standard error, OpenMP's thread count. */
void tf_ctx_init(tf_ctx *ctx);

/* The thread count parallel loops use: ctx->threads, or OpenMP's default. */
int tf_ctx_threads(const tf_ctx *ctx);

/* Writes the message into ctx->err and returns -1 (for `return tf_fail(...)`). */
int tf_fail(tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_CONTEXT_H */
