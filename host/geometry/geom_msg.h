/*
 * geom_msg.h — what the geometry layer tells its caller: one error (the
 * caller prefixes file:line:field) and the repairs it made (notes), plus
 * the status codes, which are the tool's exit statuses.
 */
#ifndef TF_GEOM_MSG_H
#define TF_GEOM_MSG_H

#include <stddef.h>

enum {
    TF_GEOM_OK = 0,
    TF_GEOM_FAILED = 1,    /* failure while running (out of memory, mesher error) */
    TF_GEOM_BAD_INPUT = 2, /* the mesh file or a parameter is unusable */
};

typedef struct tf_geom_msg {
    char error[512];  /* set when a call returns non-zero */
    char notes[1024]; /* repairs made, one per line, "" when none */
} tf_geom_msg;

/* Sets the error text; returns code, so that `return tf_geom_fail(m, 2, ...)`. */
int tf_geom_fail(tf_geom_msg *m, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Appends one line to the notes (truncated when full). */
void tf_geom_note(tf_geom_msg *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif /* TF_GEOM_MSG_H */
