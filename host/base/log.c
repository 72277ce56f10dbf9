/*
 * log.c — stderr messages (see log.h).
 */
#include "base/log.h"

#include <stdarg.h>
#include <stdio.h>

int tf_quiet = 0;

void tf_info(const char *fmt, ...)
{
    if (tf_quiet) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void tf_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("tissuefit: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}
