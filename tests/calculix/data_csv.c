/*
 * data_csv.c — reading the committed CalculiX reference data (data_csv.h).
 */
#include "data_csv.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

const char *data_dir;
int failures;

void fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL: ");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    ++failures;
}

FILE *open_data(const char *name)
{
    char path[2 * PATH_LEN];
    snprintf(path, sizeof path, "%s/%s", data_dir, name);
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        fail("%s: missing", path);
    }
    return fp;
}

int parse_num(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v);
}

int split(char *line, char **fields, int max)
{
    line[strcspn(line, "\r\n")] = '\0';
    char *p = line;
    for (int n = 0; n < max; ++n) {
        fields[n] = p;
        p = strchr(p, ',');
        if (p == NULL) {
            return n + 1;
        }
        *p++ = '\0';
    }
    return max + 1;
}

FILE *open_table(const char *name, const char *want)
{
    FILE *fp = open_data(name);
    char line[1024];
    if (fp != NULL && (fgets(line, sizeof line, fp) == NULL || strcspn(line, "\r\n") != strlen(want) ||
                       strncmp(line, want, strlen(want)) != 0)) {
        fail("%s line 1: header is not %s", name, want);
        fclose(fp);
        fp = NULL;
    }
    return fp;
}

static int on_clamped_edge(const grid_spec *g, int i, int j)
{
    return ((g->clamp & CLAMP_X0) && i == 0) || ((g->clamp & CLAMP_X1) && i == g->nx - 1) ||
           ((g->clamp & CLAMP_Y0) && j == 0) || ((g->clamp & CLAMP_Y1) && j == g->ny - 1);
}

static int check_row(const char *name, const grid_spec *g, int row, char **f, field *out)
{
    double v[7];
    for (int k = 0; k < 7; ++k) {
        if (!parse_num(f[k], &v[k])) {
            fail("%s line %d: field %d (%s) is not a finite number", name, row + 2, k + 1, f[k]);
            return -1;
        }
    }
    int i = row % g->nx, j = row / g->nx;
    if (v[0] != row + 1 || fabs(v[1] - g->spacing * i) > 1e-9 ||
        fabs(v[2] - g->spacing * j) > 1e-9 || fabs(v[3] - g->top) > 1e-9) {
        fail("%s line %d: expected point %d at (%g, %g, %g)", name, row + 2, row + 1,
             g->spacing * i, g->spacing * j, g->top);
        return -1;
    }
    for (int k = 0; k < 3; ++k) {
        out->u[row][k] = v[4 + k];
        out->max_abs = fmax(out->max_abs, fabs(v[4 + k]));
        if (on_clamped_edge(g, i, j) && v[4 + k] != 0) {
            fail("%s line %d: clamped edge point %d moves", name, row + 2, row + 1);
            return -1;
        }
    }
    return 0;
}

int read_field(const char *name, const grid_spec *g, field *out)
{
    memset(out, 0, sizeof *out);
    out->n = g->nx * g->ny;
    FILE *fp = open_table(name, "node,x,y,z,ux,uy,uz");
    if (fp == NULL) {
        return -1;
    }
    char line[1024];
    int rows = 0, bad = 0;
    while (!bad && fgets(line, sizeof line, fp) != NULL) {
        char *f[8];
        if (rows == out->n || split(line, f, 7) != 7) {
            fail("%s line %d: a row too many, or not 7 fields", name, rows + 2);
            bad = 1;
        } else {
            bad = check_row(name, g, rows++, f, out) != 0;
        }
    }
    fclose(fp);
    if (!bad && rows != out->n) {
        fail("%s: %d rows, expected %d", name, rows, out->n);
        bad = 1;
    }
    return bad ? -1 : 0;
}

static double norm3(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

double field_change(const field *coarse, const field *fine, int point)
{
    double num = 0, den = 0;
    for (int n = 0; n < fine->n; ++n) {
        if (point >= 0 && n != point) {
            continue;
        }
        double d[3] = {fine->u[n][0] - coarse->u[n][0], fine->u[n][1] - coarse->u[n][1],
                       fine->u[n][2] - coarse->u[n][2]};
        num += norm3(d) * norm3(d);
        den += norm3(fine->u[n]) * norm3(fine->u[n]);
    }
    return sqrt(num / den);
}
