/*
 * data_csv.h — reading the committed CalculiX reference data
 * (tests/calculix/data) for the data checkers (check_data.c, check_nlgeom.c,
 * check_beam.c): failure reporting, CSV splitting, and the output-point
 * displacement files node,x,y,z,ux,uy,uz of a box scene's output grid.
 */
#ifndef DATA_CSV_H
#define DATA_CSV_H

#include <stdio.h>

#define MAX_POINTS 121
#define PATH_LEN 512

/* The output grid of a scene: nx x ny points spacing mm apart on the top
 * face z = top, point N = i + nx j + 1 at (spacing i, spacing j, top); the
 * points on the clamped edges (CLAMP_* bits) must not move. */
enum { CLAMP_X0 = 1, CLAMP_X1 = 2, CLAMP_Y0 = 4, CLAMP_Y1 = 8 };
typedef struct {
    int nx, ny;
    double spacing, top;
    int clamp;
} grid_spec;

typedef struct {
    double u[MAX_POINTS][3]; /* ux, uy, uz of point N at u[N - 1] */
    double max_abs;
    int n;
} field;

extern const char *data_dir;
extern int failures;

/* Prints "FAIL: ..." and counts the failure. */
void fail(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Opens DATA_DIR/name; a missing file is a failure (returns NULL). */
FILE *open_data(const char *name);
/* Parses a whole field as a finite double. */
int parse_num(const char *s, double *v);
/* Splits a CSV line in place; returns the number of fields (max + 1 when
 * there are more than max). */
int split(char *line, char **fields, int max);
/* Reads one output-point file; returns 0 when its format is right. */
int read_field(const char *name, const grid_spec *g, field *out);
/* Reads a CSV file's header (which must be want) and returns the open file
 * positioned at the first row, or NULL (a failure). */
FILE *open_table(const char *name, const char *want);
/* Relative change |fine - coarse| / |fine| over all points (point < 0,
 * RMS of the vector norms) or at one point (index). */
double field_change(const field *coarse, const field *fine, int point);

#endif
