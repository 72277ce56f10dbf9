/*
 * obj_digits.c — an OBJ file's own vertex coordinates (obj_digits.h).
 *
 * assimp keeps no map from its vertices back to the file's `v` records
 * (faces are triangulated and identical positions joined), so each vertex
 * is matched by value: the record whose coordinates lie within a few
 * float32 units in the last place of assimp's.  Equality to (float)strtod
 * cannot be required, because assimp's own number parser is not correctly
 * rounded.
 */
#include "geometry/obj_digits.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* How many float32 units in the last place assimp's value may be from the
 * record's; its parser errs by one or two. */
#define MATCH_ULPS 8.0

typedef struct record {
    double x[3];
    size_t line;
} record;

typedef struct records {
    record *r;
    size_t n, cap;
} records;

static int push(records *rs, const double x[3], size_t line)
{
    if (rs->n == rs->cap) {
        size_t cap = rs->cap ? 2 * rs->cap : 1024;
        record *r = realloc(rs->r, cap * sizeof *r);
        if (r == NULL) {
            return -1;
        }
        rs->r = r;
        rs->cap = cap;
    }
    memcpy(rs->r[rs->n].x, x, sizeof rs->r[rs->n].x);
    rs->r[rs->n++].line = line;
    return 0;
}

/* One line: a `v` record with three numbers adds a record (a fourth
 * number, the weight, or vertex colours after it are ignored, as assimp
 * ignores them); anything else is left to assimp. */
static int scan_line(const char *p, size_t line, records *rs)
{
    while (*p == ' ' || *p == '\t') {
        ++p;
    }
    if (p[0] != 'v' || (p[1] != ' ' && p[1] != '\t')) {
        return 0;
    }
    double x[3];
    p += 2;
    for (int a = 0; a < 3; ++a) {
        char *end;
        x[a] = strtod(p, &end);
        if (end == p) {
            return 0;
        }
        p = end;
    }
    if (!(isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]))) {
        return 0; /* assimp's value stays, and is reported as not finite */
    }
    return push(rs, x, line);
}

static int scan(char *text, records *rs)
{
    size_t line = 1;
    for (char *p = text; *p != '\0'; ++line) {
        char *nl = strchr(p, '\n');
        if (nl != NULL) {
            *nl = '\0';
        }
        if (scan_line(p, line, rs) != 0) {
            return -1;
        }
        if (nl == NULL) {
            break;
        }
        p = nl + 1;
    }
    return 0;
}

static int by_x(const void *a, const void *b)
{
    double u = ((const record *)a)->x[0], v = ((const record *)b)->x[0];
    return (u > v) - (u < v);
}

/* The distance within which assimp's float32 value f may lie from the
 * record's value. */
static double tolerance(double f)
{
    int e;
    frexp(f, &e);
    return f != 0 ? ldexp(MATCH_ULPS, e - 24) : ldexp(MATCH_ULPS, -149);
}

/* The first record with x >= lo (records sorted by x). */
static size_t lower_bound(const records *rs, double lo)
{
    size_t a = 0, b = rs->n;
    while (a < b) {
        size_t c = a + (b - a) / 2;
        if (rs->r[c].x[0] < lo) {
            a = c + 1;
        } else {
            b = c;
        }
    }
    return a;
}

/* How far record r lies from f, in units of tol (<= 1: within reach). */
static double reach(const double f[3], const record *r, const double tol[3])
{
    double d = 0;
    for (int a = 0; a < 3; ++a) {
        d = fmax(d, fabs(f[a] - r->x[a]) / tol[a]);
    }
    return d;
}

/* Two different records that float32 rounds to the same point: assimp has
 * read them as one vertex. */
static int same_float(const record *a, const record *b)
{
    return memcmp(a->x, b->x, sizeof a->x) != 0 && (float)a->x[0] == (float)b->x[0] &&
           (float)a->x[1] == (float)b->x[1] && (float)a->x[2] == (float)b->x[2];
}

/* Vertex v's record: the nearest within reach. */
static int match(const char *path, const records *rs, tf_surface *s, size_t v, tf_geom_msg *m)
{
    double *f = s->xyz + 3 * v, tol[3];
    for (int a = 0; a < 3; ++a) {
        tol[a] = tolerance(f[a]);
    }
    size_t k0 = lower_bound(rs, f[0] - tol[0]), k1 = k0;
    const record *best = NULL;
    for (; k1 < rs->n && rs->r[k1].x[0] <= f[0] + tol[0]; ++k1) {
        const record *r = rs->r + k1;
        if (reach(f, r, tol) <= 1 && (best == NULL || reach(f, r, tol) < reach(f, best, tol))) {
            best = r;
        }
    }
    if (best == NULL) {
        return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                            "'%s': vertex (%.9g, %.9g, %.9g) as the mesh reader read it matches "
                            "no 'v' line of three numbers", path,
                            f[0], f[1], f[2]);
    }
    for (size_t k = k0; k < k1; ++k) {
        if (same_float(best, rs->r + k)) {
            size_t l1 = best->line < rs->r[k].line ? best->line : rs->r[k].line;
            size_t l2 = best->line < rs->r[k].line ? rs->r[k].line : best->line;
            return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                "'%s': the vertices of lines %zu and %zu are closer than the "
                                "mesh reader's float32 tells apart, so it joins them (the "
                                "coordinates lie far from the origin for their spacing: move "
                                "the file's origin into the organ)",
                                path, l1, l2);
        }
    }
    memcpy(f, best->x, sizeof best->x);
    return TF_GEOM_OK;
}

static int restore(const char *path, const records *rs, tf_surface *s, tf_geom_msg *m)
{
    for (size_t v = 0; v < s->nv; ++v) {
        const double *f = s->xyz + 3 * v;
        if (!(isfinite(f[0]) && isfinite(f[1]) && isfinite(f[2]))) {
            continue;
        }
        int rc = match(path, rs, s, v, m);
        if (rc != TF_GEOM_OK) {
            return rc;
        }
    }
    return TF_GEOM_OK;
}

/* A NUL byte would end the text for the scan but not for assimp, which
 * would then read vertices the scan never saw. */
static int nul_byte(const char *path, const char *text, size_t len, tf_geom_msg *m)
{
    size_t at = strlen(text), line = 1;
    if (at == len) {
        return TF_GEOM_OK;
    }
    for (size_t k = 0; k < at; ++k) {
        line += text[k] == '\n';
    }
    return tf_geom_fail(m, TF_GEOM_BAD_INPUT, "'%s': line %zu holds a NUL byte (an OBJ file is text)",
                        path, line);
}

int tf_obj_digits_restore(const char *path, char *text, size_t len, tf_surface *s,
                          tf_geom_msg *m)
{
    records rs = {0};
    int rc = nul_byte(path, text, len, m);
    if (rc == TF_GEOM_OK && scan(text, &rs) != 0) {
        rc = tf_geom_fail(m, TF_GEOM_FAILED, "'%s': out of memory", path);
    }
    if (rc == TF_GEOM_OK && rs.n > 1) {
        qsort(rs.r, rs.n, sizeof *rs.r, by_x);
    }
    if (rc == TF_GEOM_OK) {
        rc = restore(path, &rs, s, m);
    }
    free(rs.r);
    return rc;
}
