/*
 * atomic_file.c — temporary file + rename (see atomic_file.h).
 */
#include "base/atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/interrupts.h"

/* The directory part of path ("." when there is none). */
static void dir_of(const char *path, char *dir, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL) {
        snprintf(dir, n, ".");
    } else if (slash == path) {
        snprintf(dir, n, "/");
    } else {
        snprintf(dir, n, "%.*s", (int)(slash - path), path);
    }
}

int tf_afile_target(tf_ctx *ctx, const char *path, char *dst, size_t dstlen)
{
    struct stat st;
    size_t len = strlen(path);
    if (len == 0 || path[len - 1] == '/') {
        return tf_fail(ctx, "'%s' is not a file name", path);
    }
    if (snprintf(dst, dstlen, "%s", path) >= (int)dstlen) {
        return tf_fail(ctx, "%s: path too long", path);
    }
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        char *real = realpath(path, NULL); /* written through, as cp does */
        if (real == NULL) {
            return tf_fail(ctx, "%s: a symbolic link to nothing (%s): not writing through it", path,
                           strerror(errno));
        }
        int fits = snprintf(dst, dstlen, "%s", real) < (int)dstlen;
        free(real);
        if (!fits) {
            return tf_fail(ctx, "%s: path too long", path);
        }
    }
    if (stat(dst, &st) == 0 && !S_ISREG(st.st_mode)) {
        return tf_fail(ctx, "%s: exists and is not a regular file (%s): not replacing it", path,
                       S_ISDIR(st.st_mode) ? "a directory" : "a device, FIFO or socket");
    }
    char dir[sizeof ((tf_afile *)0)->dst];
    dir_of(dst, dir, sizeof dir);
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        return tf_fail(ctx, "%s: no directory %s", path, dir);
    }
    if (access(dir, W_OK | X_OK) != 0) {
        return tf_fail(ctx, "%s: cannot write in %s: %s", path, dir, strerror(errno));
    }
    return 0;
}

int tf_afile_check(tf_ctx *ctx, const char *path)
{
    char dst[sizeof ((tf_afile *)0)->dst];
    return tf_afile_target(ctx, path, dst, sizeof dst);
}

/* SIGINT, SIGTERM and SIGHUP: held back while a temporary exists. */
static void interrupts(sigset_t *set)
{
    sigemptyset(set);
    sigaddset(set, SIGINT);
    sigaddset(set, SIGTERM);
    sigaddset(set, SIGHUP);
}

static void hold_interrupts(tf_ctx *ctx, tf_afile *a)
{
    sigset_t hold;
    interrupts(&hold);
    pthread_sigmask(SIG_BLOCK, &hold, &a->before);
    a->guard = ctx->interrupts;
    if (a->guard != NULL) {
        tf_interrupts_hold(a->guard);
    }
}

/* Releases the interrupts that were not held before any of files[0..n)
 * was opened (a pending one is delivered now, its temporaries gone). */
static void release_interrupts(tf_afile *const *files, size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        if (files[k]->guard != NULL) {
            tf_interrupts_release(files[k]->guard);
        }
    }
    sigset_t hold, release;
    interrupts(&hold);
    sigemptyset(&release);
    const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t k = 0; k < n; ++k) {
        for (int i = 0; i < 3; ++i) {
            if (!sigismember(&files[k]->before, sigs[i])) {
                sigaddset(&release, sigs[i]);
            }
        }
    }
    pthread_sigmask(SIG_UNBLOCK, &release, NULL);
}

int tf_afile_open(tf_ctx *ctx, tf_afile *a, const char *path)
{
    a->fp = NULL;
    a->tmp[0] = '\0';
    if (tf_afile_target(ctx, path, a->dst, sizeof a->dst) != 0) {
        return -1;
    }
    if (snprintf(a->tmp, sizeof a->tmp, "%s.tmp.XXXXXX", a->dst) >= (int)sizeof a->tmp) {
        return tf_fail(ctx, "%s: path too long", path);
    }
    hold_interrupts(ctx, a);
    tf_afile *self[1] = {a};
    int fd = mkstemp(a->tmp);
    if (fd < 0) {
        tf_fail(ctx, "%s: cannot create a temporary file: %s", path, strerror(errno));
        a->tmp[0] = '\0';
        release_interrupts(self, 1);
        return -1;
    }
    /* mkstemp creates 0600; give the result the mode a plain fopen would. */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || (a->fp = fdopen(fd, "w")) == NULL) {
        tf_fail(ctx, "%s: %s", a->tmp, strerror(errno));
        close(fd);
        unlink(a->tmp);
        a->tmp[0] = '\0';
        release_interrupts(self, 1);
        return -1;
    }
    return 0;
}

/* Writes out, syncs and closes the temporary; errno-style code or 0. */
static int settle(tf_afile *a)
{
    int failed = ferror(a->fp) || fflush(a->fp) != 0 || fsync(fileno(a->fp)) != 0;
    int saved = failed ? (errno ? errno : EIO) : 0;
    if (fclose(a->fp) != 0 && !failed) {
        saved = errno ? errno : EIO;
    }
    a->fp = NULL;
    return saved;
}

static void sync_dir(const char *dst)
{
    char dir[sizeof ((tf_afile *)0)->dst];
    dir_of(dst, dir, sizeof dir);
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        fsync(fd); /* best effort: the renames are durable once this returns */
        close(fd);
    }
}

/* Renames every temporary in order (interrupts are held back since the
 * files were opened).  errno-style code or 0; *bad is the file that
 * failed. */
static int rename_all(tf_afile *const *files, size_t n, size_t *bad)
{
    int code = 0;
    for (size_t k = 0; k < n; ++k) {
        if (rename(files[k]->tmp, files[k]->dst) != 0) {
            code = errno;
            *bad = k;
            break;
        }
        files[k]->tmp[0] = '\0'; /* renamed: nothing left to remove */
    }
    for (size_t k = 0; k < n && code == 0; ++k) {
        sync_dir(files[k]->dst);
    }
    return code;
}

int tf_afile_commit_all(tf_ctx *ctx, tf_afile *const *files, size_t n)
{
    int code = 0;
    size_t bad = 0;
    for (size_t k = 0; k < n; ++k) {
        int c = settle(files[k]);
        if (c != 0 && code == 0) {
            code = c;
            bad = k;
        }
    }
    if (code == 0) {
        code = rename_all(files, n, &bad);
    }
    if (code != 0) {
        tf_fail(ctx, "%s: write failed: %s", files[bad]->dst, strerror(code));
        for (size_t k = 0; k < n; ++k) {
            if (files[k]->tmp[0] != '\0') {
                unlink(files[k]->tmp);
                files[k]->tmp[0] = '\0';
            }
        }
    }
    release_interrupts(files, n);
    return code != 0 ? -1 : 0;
}

int tf_afile_commit(tf_ctx *ctx, tf_afile *a)
{
    tf_afile *one[1] = {a};
    return tf_afile_commit_all(ctx, one, 1);
}

void tf_afile_abort(tf_afile *a)
{
    if (a->fp != NULL) {
        fclose(a->fp);
        a->fp = NULL;
    }
    if (a->tmp[0] != '\0') {
        unlink(a->tmp);
        a->tmp[0] = '\0';
        tf_afile *self[1] = {a};
        release_interrupts(self, 1);
    }
}
