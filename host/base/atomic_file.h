/*
 * atomic_file.h — write a file so that it is either complete or absent:
 * data goes to a temporary file beside the destination, which is renamed
 * over it only after every write, flush and fsync succeeded.
 */
#ifndef TF_ATOMIC_FILE_H
#define TF_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

typedef struct tf_afile {
    FILE *fp;
    char tmp[4096];
    char dst[4096];
} tf_afile;

/* Opens a temporary file next to path.  Returns 0, or -1 with a message. */
int tf_afile_open(tf_afile *a, const char *path, char *err, size_t errlen);

/* Flushes, syncs and renames over the destination.  On failure the
 * temporary file is removed and the destination left untouched. */
int tf_afile_commit(tf_afile *a, char *err, size_t errlen);

/* Discards the temporary file. */
void tf_afile_abort(tf_afile *a);

#endif /* TF_ATOMIC_FILE_H */
