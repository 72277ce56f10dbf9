/*
 * input_file.h — the files the tool reads: a scene, a load-history table, a
 * surface mesh.  Only a regular file of bounded size is read: a FIFO would
 * block the reader (it is opened here without waiting for a writer, then
 * refused), a device such as /dev/zero would be read until memory runs
 * out, and a file of a million triangles would keep a mesher busy for
 * minutes.  `what` names the file in messages ("scene", "load-history
 * table", "surface mesh").
 */
#ifndef TF_INPUT_FILE_H
#define TF_INPUT_FILE_H

#include <stddef.h>

#include "base/context.h"

/* 0 when path is a regular file of at most max_bytes bytes (a file handed
 * to a library by its name); else -1 with "PATH: ..." in ctx. */
int tf_input_file_check(tf_ctx *ctx, const char *path, const char *what, size_t max_bytes);

/* The bytes of such a file, NUL-terminated (*len bytes before the NUL;
 * the caller frees them), or NULL with "PATH: ..." in ctx. */
char *tf_input_file_read(tf_ctx *ctx, const char *path, const char *what, size_t max_bytes,
                         size_t *len);

#endif /* TF_INPUT_FILE_H */
