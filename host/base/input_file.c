/*
 * input_file.c — regular files of bounded size, checked and read
 * (input_file.h).
 */
#include "base/input_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* path opened without blocking and checked; returns the descriptor with
 * its size in *size, or -1 with a message. */
static int open_checked(tf_ctx *ctx, const char *path, const char *what, size_t max_bytes,
                        size_t *size)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0) {
        tf_fail(ctx, "%s: cannot open: %s", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
        }
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        tf_fail(ctx, "%s: not a regular file (a %s is read from a file, not a %s)", path, what,
                S_ISDIR(st.st_mode) ? "directory" : "device, FIFO or socket");
        close(fd);
        return -1;
    }
    if ((unsigned long long)st.st_size > max_bytes) {
        tf_fail(ctx, "%s: %lld bytes, more than the %zu MiB a %s file may hold", path,
                (long long)st.st_size, max_bytes >> 20, what);
        close(fd);
        return -1;
    }
    *size = (size_t)st.st_size;
    return fd;
}

int tf_input_file_check(tf_ctx *ctx, const char *path, const char *what, size_t max_bytes)
{
    size_t size;
    int fd = open_checked(ctx, path, what, max_bytes, &size);
    if (fd < 0) {
        return -1;
    }
    close(fd);
    return 0;
}

char *tf_input_file_read(tf_ctx *ctx, const char *path, const char *what, size_t max_bytes,
                         size_t *len)
{
    size_t size;
    int fd = open_checked(ctx, path, what, max_bytes, &size);
    if (fd < 0) {
        return NULL;
    }
    size_t cap = size + 1, used = 0; /* one more: a file that grew is seen */
    char *text = malloc(cap + 1);
    ssize_t n = 1;
    while (text != NULL && used < cap && n > 0) {
        n = read(fd, text + used, cap - used);
        if (n < 0 && errno == EINTR) {
            n = 1;
        } else if (n > 0) {
            used += (size_t)n;
        }
    }
    int saved = errno;
    close(fd);
    if (text == NULL || n < 0 || used == cap) {
        tf_fail(ctx, "%s: cannot read: %s", path,
                text == NULL ? "out of memory"
                : n < 0      ? strerror(saved)
                             : "it changed while read");
        free(text);
        return NULL;
    }
    text[used] = '\0';
    *len = used;
    return text;
}
