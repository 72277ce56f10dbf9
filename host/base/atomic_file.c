/*
 * atomic_file.c — temporary file + rename (see atomic_file.h).
 */
#include "base/atomic_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int tf_afile_open(tf_afile *a, const char *path, char *err, size_t errlen)
{
    a->fp = NULL;
    if (snprintf(a->dst, sizeof a->dst, "%s", path) >= (int)sizeof a->dst ||
        snprintf(a->tmp, sizeof a->tmp, "%s.tmp.XXXXXX", path) >= (int)sizeof a->tmp) {
        snprintf(err, errlen, "%s: path too long", path);
        return -1;
    }
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create a temporary file: %s", path, strerror(errno));
        return -1;
    }
    /* mkstemp creates 0600; give the result the mode a plain fopen would. */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) {
        snprintf(err, errlen, "%s: %s", a->tmp, strerror(errno));
        close(fd);
        unlink(a->tmp);
        return -1;
    }
    a->fp = fdopen(fd, "w");
    if (a->fp == NULL) {
        snprintf(err, errlen, "%s: %s", a->tmp, strerror(errno));
        close(fd);
        unlink(a->tmp);
        return -1;
    }
    return 0;
}

int tf_afile_commit(tf_afile *a, char *err, size_t errlen)
{
    int failed = ferror(a->fp) || fflush(a->fp) != 0 || fsync(fileno(a->fp)) != 0;
    int saved = errno;
    if (fclose(a->fp) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    a->fp = NULL;
    if (!failed && rename(a->tmp, a->dst) != 0) {
        failed = 1;
        saved = errno;
    }
    if (failed) {
        snprintf(err, errlen, "%s: write failed: %s", a->dst, strerror(saved));
        unlink(a->tmp);
        return -1;
    }
    return 0;
}

void tf_afile_abort(tf_afile *a)
{
    if (a->fp != NULL) {
        fclose(a->fp);
        a->fp = NULL;
    }
    unlink(a->tmp);
}
