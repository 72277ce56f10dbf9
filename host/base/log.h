/*
 * log.h — messages through a run's context (context.h): progress for long
 * runs (dropped by `tissuefit -q`), warnings and errors, each handed to the
 * context's sink when its level shows it.  The default sink
 * writes them to standard error, errors prefixed "tissuefit: error: " and
 * warnings "tissuefit: warning: ".
 */
#ifndef TF_LOG_H
#define TF_LOG_H

#include "base/context.h"

/* Progress or information. */
void tf_info(const tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Something the user should change; shown under -q. */
void tf_warn(const tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* An error; always shown. */
void tf_error(const tf_ctx *ctx, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_LOG_H */
