/*
 * log.h — messages on stderr: progress for long runs (silenced by -q) and
 * errors (always shown).
 */
#ifndef TF_LOG_H
#define TF_LOG_H

/* Set by the command line: 1 when -q was given. */
extern int tf_quiet;

/* Progress or information, unless quiet. */
void tf_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* An error message prefixed with "tissuefit: error: ". */
void tf_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

#endif /* TF_LOG_H */
