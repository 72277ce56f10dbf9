/*
 * scene_issue.c — recording a scene issue (scene_issue.h).
 */
#include "scene/scene_issue.h"

#include <stdarg.h>
#include <stdio.h>

int sd_fail(sd_issue *is, const char *path, const char *fmt, ...)
{
    va_list ap;
    snprintf(is->path, sizeof is->path, "%s", path);
    va_start(ap, fmt);
    vsnprintf(is->msg, sizeof is->msg, fmt, ap);
    va_end(ap);
    return -1;
}
