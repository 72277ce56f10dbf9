/*
 * geom_msg.c — error and note texts of the geometry layer (geom_msg.h).
 */
#include "geometry/geom_msg.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int tf_geom_fail(tf_geom_msg *m, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->error, sizeof m->error, fmt, ap);
    va_end(ap);
    return code;
}

void tf_geom_note(tf_geom_msg *m, const char *fmt, ...)
{
    size_t used = strlen(m->notes);
    if (used + 2 >= sizeof m->notes) {
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m->notes + used, sizeof m->notes - used - 1, fmt, ap);
    va_end(ap);
    used = strlen(m->notes);
    m->notes[used] = '\n';
    m->notes[used + 1] = '\0';
}
