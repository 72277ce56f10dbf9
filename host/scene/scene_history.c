/*
 * scene_history.c — the `history:` section: a load history's checks and its
 * table of forces read from a CSV file (scene_history.h).
 */
#include "scene/scene_history.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/input_file.h"

/* Which fields a segment kind takes: to, time, amplitude, period. */
static const unsigned char takes[5][4] = {
    [TF_SEG_STEP] = {1, 0, 0, 0},     [TF_SEG_RELEASE] = {0, 0, 0, 0},
    [TF_SEG_RAMP] = {1, 1, 0, 0},     [TF_SEG_HOLD] = {0, 1, 0, 0},
    [TF_SEG_SINUSOID] = {0, 1, 1, 1},
};

static int segment(const sd_segment *d, size_t k, tf_segment *g, sd_issue *is)
{
    static const char *names[4] = {"to", "time", "amplitude", "period"};
    static const char *kinds[5] = {"step", "release", "ramp", "hold", "sinusoid"};
    const double *v[4] = {d->to, d->time, d->amplitude, d->period};
    char path[96];
    g->kind = (tf_segment_kind)d->kind;
    for (int f = 0; f < 4; ++f) {
        snprintf(path, sizeof path, "history.segments.%zu.%s", k, names[f]);
        if (takes[g->kind][f] && v[f] == NULL) {
            return sd_fail(is, path, "a %s segment needs %s", kinds[g->kind], names[f]);
        }
        if (!takes[g->kind][f] && v[f] != NULL) {
            return sd_fail(is, path, "a %s segment takes no %s", kinds[g->kind], names[f]);
        }
        if (v[f] != NULL && !isfinite(*v[f])) {
            return sd_fail(is, path, "must be a finite number");
        }
        if (v[f] != NULL && f > 0 && !(*v[f] > 0)) {
            return sd_fail(is, path, "must be positive (s)");
        }
    }
    g->to = d->to ? *d->to : 0;
    g->time = d->time ? *d->time : 0;
    g->amplitude = d->amplitude ? *d->amplitude : 0;
    g->period = d->period ? *d->period : 1;
    return 0;
}

/* The table file's path: relative to the scene file's folder. */
static void table_path(const char *source, const char *file, char *out, size_t len)
{
    const char *slash = strrchr(source, '/');
    if (file[0] == '/' || slash == NULL) {
        snprintf(out, len, "%s", file);
    } else {
        snprintf(out, len, "%.*s/%s", (int)(slash - source), source, file);
    }
}

/* The largest table force taken, N: beyond it a value is a unit or typing
 * error (tissue envelopes are a few newtons), and differences of forces
 * near the double range overflow when the table is interpolated. */
#define TABLE_FORCE_MAX 1e6
#define TABLE_MAX_BYTES ((size_t)64 << 20)

/* Whether a row's first cell begins with a number (after blanks and a
 * quote): such a row is data, never a header. */
static int starts_numeric(const char *line)
{
    line += strspn(line, " \t\"'");
    char *end;
    (void)strtod(line, &end);
    return end != line;
}

/* One data row "t, fx, fy, fz" into r (first: the table's first line,
 * which would have been its header); -1 with the message in is. */
static int table_row(const char *path, int lineno, int first, const char *line,
                     const tf_history *h, double r[4], sd_issue *is)
{
    char tail;
    if (sscanf(line, "%lf , %lf , %lf , %lf %c", &r[0], &r[1], &r[2], &r[3], &tail) != 4) {
        return sd_fail(is, "history.table",
                       "%s:%d: expected four numbers t,fx,fy,fz (s, N)%s", path, lineno,
                       first ? " (a header row's first cell is not a number)" : "");
    }
    if (!isfinite(r[0]) || r[0] < 0 || (h->n_rows > 0 && !(r[0] > h->table[4 * (h->n_rows - 1)]))) {
        return sd_fail(is, "history.table", "%s:%d: times must be finite, >= 0 and increasing",
                       path, lineno);
    }
    for (int a = 1; a < 4; ++a) {
        if (!(fabs(r[a]) <= TABLE_FORCE_MAX)) {
            return sd_fail(is, "history.table",
                           "%s:%d: force %g N: forces must be finite and at most %g N in size",
                           path, lineno, r[a], TABLE_FORCE_MAX);
        }
    }
    return 0;
}

static int append_row(tf_history *h, size_t *cap, const double r[4], sd_issue *is)
{
    if (h->n_rows == *cap) {
        *cap = 2 * *cap + 64;
        double *t = realloc(h->table, 4 * *cap * sizeof *t);
        if (t == NULL) {
            return sd_fail(is, "history.table", "out of memory");
        }
        h->table = t;
    }
    memcpy(h->table + 4 * h->n_rows++, r, 4 * sizeof *r);
    return 0;
}

/* Rows "t, fx, fy, fz" of a text file (base/input_file.h: a regular file
 * of at most TABLE_MAX_BYTES).  A UTF-8 byte-order mark is skipped; blank
 * lines and # comments are skipped; the first other line is a header when
 * its first cell is not a number (a malformed first data row is an error,
 * never dropped as a header). */
static int read_table(const char *path, tf_history *h, sd_issue *is)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    size_t len;
    char *text = tf_input_file_read(&ctx, path, "load-history table", TABLE_MAX_BYTES, &len);
    if (text == NULL) {
        return sd_fail(is, "history.table", "%s", ctx.err);
    }
    if (strlen(text) != len) {
        free(text);
        return sd_fail(is, "history.table", "%s: holds a NUL byte: not a text table", path);
    }
    char *line = strncmp(text, "\xEF\xBB\xBF", 3) == 0 ? text + 3 : text;
    size_t cap = 0;
    int rc = 0, lineno = 0, seen = 0;
    while (rc == 0 && line != NULL && *line != '\0') {
        char *next = strchr(line, '\n');
        if (next != NULL) {
            *next++ = '\0';
        }
        lineno++;
        double r[4];
        if (line[0] == '#' || strspn(line, " \t\r") == strlen(line)) {
            line = next;
            continue;
        }
        if (!seen++ && !starts_numeric(line)) {
            line = next;
            continue; /* header */
        }
        rc = table_row(path, lineno, seen == 1, line, h, r, is);
        rc = rc == 0 ? append_row(h, &cap, r, is) : rc;
        line = next;
    }
    free(text);
    if (rc == 0 && h->n_rows == 0) {
        rc = sd_fail(is, "history.table", "%s holds no row of t,fx,fy,fz", path);
    }
    return rc;
}

int sd_history_build(const sd_history *d, tf_problem *p, sd_issue *is)
{
    tf_history *h = &p->history;
    memset(h, 0, sizeof *h);
    h->contact = -1;
    if (d == NULL) {
        return 0;
    }
    h->present = 1;
    h->dt = d->dt;
    h->duration = d->duration;
    if (!(isfinite(h->dt) && h->dt > 0)) {
        return sd_fail(is, "history.dt", "the time step must be a positive number of seconds");
    }
    if (!(isfinite(h->duration) && h->duration > 0)) {
        return sd_fail(is, "history.duration", "must be a positive number of seconds");
    }
    if (h->duration / h->dt > 1e6) {
        return sd_fail(is, "history.dt", "%.0f steps: more than a million", h->duration / h->dt);
    }
    if ((d->segments != NULL) == (d->table != NULL)) {
        return sd_fail(is, "history", "give exactly one of segments or table");
    }
    if (d->contact) {
        h->contact = tf_problem_contact(p, d->contact);
        if (h->contact < 0) {
            return sd_fail(is, "history.contact", "names no contact site of the scene");
        }
    } else {
        h->contact = p->n_contacts > 0 ? 0 : -1;
    }
    if (d->force) {
        if (d->table) {
            return sd_fail(is, "history.force", "a table gives the force itself: no force here");
        }
        if (h->contact < 0) {
            return sd_fail(is, "history.force", "the scene has no contact site to apply it at");
        }
        for (int a = 0; a < 3; ++a) {
            h->force[a] = d->force[a];
            if (!isfinite(h->force[a])) {
                return sd_fail(is, "history.force", "must be finite (N)");
            }
        }
    }
    if (d->table) {
        char path[4096 + 512];
        if (h->contact < 0) {
            return sd_fail(is, "history.table", "the scene has no contact site for the table's force");
        }
        table_path(p->source, d->table, path, sizeof path);
        return read_table(path, h, is);
    }
    h->seg = calloc(d->segments_count, sizeof *h->seg);
    if (h->seg == NULL) {
        return sd_fail(is, "history.segments", "out of memory");
    }
    h->n_seg = d->segments_count;
    for (size_t k = 0; k < h->n_seg; ++k) {
        if (segment(&d->segments[k], k, &h->seg[k], is) != 0) {
            return -1;
        }
    }
    return 0;
}
