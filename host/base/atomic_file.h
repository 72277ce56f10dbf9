/*
 * atomic_file.h — write a file so that it is either complete or absent:
 * data goes to a temporary file beside the destination, which is renamed
 * over it only after every write, flush and fsync succeeded.
 *
 * Destinations are what cp and compilers write: a path that does not exist
 * yet, a regular file, or a symbolic link to a regular file, written
 * through (the link stays, the file it names is replaced).  A directory, a
 * device, a FIFO or a dangling link is refused: renaming a temporary over
 * /dev/full would turn the device into a file.
 *
 * Files that belong together (a header and its golden vectors) are written
 * to temporaries that are all synced before the first rename
 * (tf_afile_commit_all), so a full disk or a failed write changes none of
 * them.  An interrupt (SIGINT, SIGTERM, SIGHUP) is held back from the
 * moment a temporary exists until it is renamed or removed, so no exit
 * path leaves a temporary behind and no interrupt falls between two
 * renames.  Only SIGKILL or a crash can (header-format.md §1).  The tool
 * has threads (OpenMP's workers), and a signal sent to the process may go
 * to any of them: it holds interrupts back through the run's watcher
 * (ctx->interrupts, base/interrupts.h); without one (a library user), in
 * the writing thread only.
 */
#ifndef TF_ATOMIC_FILE_H
#define TF_ATOMIC_FILE_H

#include <signal.h>
#include <stddef.h>
#include <stdio.h>

#include "base/context.h"

struct tf_interrupts;

typedef struct tf_afile {
    FILE *fp;
    sigset_t before; /* the thread's signal mask before open held interrupts back */
    struct tf_interrupts *guard; /* the run's watcher (ctx->interrupts), or NULL */
    char tmp[4096];
    char dst[4096]; /* the file replaced: the path, or the file its link names */
} tf_afile;

/* The file that writing path replaces: path itself, or the regular file its
 * symbolic link names.  Checks that it is absent or a regular file and that
 * its directory exists and is writable.  Commands call this on every output
 * before they start work, so a bad path is reported before the solve.
 * Returns 0, or -1 with a message naming path. */
int tf_afile_check(tf_ctx *ctx, const char *path);

/* The same, writing the file replaced to dst. */
int tf_afile_target(tf_ctx *ctx, const char *path, char *dst, size_t dstlen);

/* Opens a temporary file next to the destination.  Returns 0, or -1 with a
 * message (nothing is left behind). */
int tf_afile_open(tf_ctx *ctx, tf_afile *a, const char *path);

/* Flushes, syncs and renames over the destination.  On failure the
 * temporary file is removed and the destination left untouched. */
int tf_afile_commit(tf_ctx *ctx, tf_afile *a);

/* Commits n files together: every one is written out and synced before the
 * first rename, then they are renamed in order and their directories
 * synced.  When a write fails, every temporary is removed and no
 * destination changes.  A crash between two renames can still leave the
 * first file new and the next one old: files that must match say so in
 * their content (header-format.md §1). */
int tf_afile_commit_all(tf_ctx *ctx, tf_afile *const *files, size_t n);

/* Discards the temporary file.  Abort files in the reverse order of their
 * opening: interrupts held back since the first one are released with it. */
void tf_afile_abort(tf_afile *a);

#endif /* TF_ATOMIC_FILE_H */
