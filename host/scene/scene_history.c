/*
 * scene_history.c — the `history:` section: a load history's checks and its
 * table of forces read from a CSV file (scene_history.h).
 */
#include "scene/scene_history.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


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

/* Rows "t, fx, fy, fz" (a first line that is not four numbers is a
 * header; blank lines and # comments are skipped). */
static int read_table(const char *path, tf_history *h, sd_issue *is)
{
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        return sd_fail(is, "history.table", "cannot read %s: %s", path, strerror(errno));
    }
    char line[512];
    size_t cap = 0;
    int rc = 0, lineno = 0;
    while (rc == 0 && fgets(line, sizeof line, fp) != NULL) {
        lineno++;
        double r[4];
        char tail;
        if (line[0] == '#' || strspn(line, " \t\r\n") == strlen(line)) {
            continue;
        }
        int got = sscanf(line, "%lf , %lf , %lf , %lf %c", &r[0], &r[1], &r[2], &r[3], &tail);
        if (got != 4) {
            if (lineno == 1 && h->n_rows == 0) {
                continue; /* header */
            }
            rc = sd_fail(is, "history.table", "%s:%d: expected four numbers t,fx,fy,fz (s, N)",
                      path, lineno);
            break;
        }
        if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(r[2]) || !isfinite(r[3]) ||
            r[0] < 0 || (h->n_rows > 0 && !(r[0] > h->table[4 * (h->n_rows - 1)]))) {
            rc = sd_fail(is, "history.table",
                      "%s:%d: times must be finite, >= 0 and increasing, forces finite", path,
                      lineno);
            break;
        }
        if (h->n_rows == cap) {
            cap = 2 * cap + 64;
            double *t = realloc(h->table, 4 * cap * sizeof *t);
            if (t == NULL) {
                rc = sd_fail(is, "history.table", "out of memory");
                break;
            }
            h->table = t;
        }
        memcpy(h->table + 4 * h->n_rows++, r, sizeof r);
    }
    fclose(fp);
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
