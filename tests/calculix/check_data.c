/*
 * check_data.c — validates the committed CalculiX reference data for
 * block48 (tests/calculix/data) without running CalculiX:
 *
 *   - every displacement file is present, has the header
 *     node,x,y,z,ux,uy,uz and 121 rows of finite numbers, node N = i + 11 j + 1
 *     at (4.8 i, 4.8 j, 6), and zero displacement on the clamped edges;
 *   - symmetries the mesh and the loads have exactly: fy is fx mirrored
 *     about the diagonal x = y; fx is even/odd about the centre lines; fz is
 *     symmetric about both centre lines and the diagonal;
 *   - mesh convergence: between the two finest levels, the RMS change over
 *     the 121 nodes and the change at node 61 are below the given bounds;
 *   - the reference list names the finest level's files;
 *   - the nu sweep at nu = 0.49 is the same data as its level's files;
 *   - every run's reaction total balances the applied 1 N force.
 *
 * usage: check_data DIR LEVELS NUS SWEEP_LEVEL RMS_BOUND NODE61_BOUND
 *   LEVELS   comma list, coarse to fine (e.g. h2.4,h1.2,h0.6)
 *   NUS      comma list of the sweep's Poisson ratios (0,0.3,0.45,0.49,0.499)
 *   bounds   relative, e.g. 0.01 for 1 %
 * Prints one line per failed check; exits 1 if any failed, 2 on bad usage.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GRID 11
#define NODES (GRID * GRID)
#define SPACING 4.8
#define TOP 6.0
#define PATH_LEN 512
#define LIST_MAX 8
/* CalculiX prints 7 significant digits: exact symmetries hold to that,
 * relative to the largest displacement of the field. */
#define SYM_TOL 1e-5
#define REACTION_TOL 1e-6

typedef struct {
    double u[NODES][3]; /* ux, uy, uz of block48 node N at u[N - 1] */
    double max_abs;
} field;

static const char *const cases[3] = {"fx", "fy", "fz"};
static const char *data_dir;
static int failures;

static void fail(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL: ");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    ++failures;
}

static FILE *open_data(const char *name)
{
    char path[2 * PATH_LEN];
    snprintf(path, sizeof path, "%s/%s", data_dir, name);
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        fail("%s: missing", path);
    }
    return fp;
}

/* Parses a whole field as a finite double. */
static int parse_num(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0' && isfinite(*v);
}

/* Splits a CSV line in place; returns the number of fields (max + 1 when
 * there are more than max). */
static int split(char *line, char **fields, int max)
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

static int check_row(const char *name, int row, char **f, field *out)
{
    double v[7];
    for (int k = 0; k < 7; ++k) {
        if (!parse_num(f[k], &v[k])) {
            fail("%s line %d: field %d (%s) is not a finite number", name, row + 2, k + 1, f[k]);
            return -1;
        }
    }
    int i = row % GRID, j = row / GRID;
    if (v[0] != row + 1 || fabs(v[1] - SPACING * i) > 1e-9 || fabs(v[2] - SPACING * j) > 1e-9 ||
        fabs(v[3] - TOP) > 1e-9) {
        fail("%s line %d: expected node %d at (%g, %g, %g)", name, row + 2, row + 1, SPACING * i,
             SPACING * j, TOP);
        return -1;
    }
    int edge = i == 0 || j == 0 || i == GRID - 1 || j == GRID - 1;
    for (int k = 0; k < 3; ++k) {
        out->u[row][k] = v[4 + k];
        out->max_abs = fmax(out->max_abs, fabs(v[4 + k]));
        if (edge && v[4 + k] != 0) {
            fail("%s line %d: clamped edge node %d moves", name, row + 2, row + 1);
            return -1;
        }
    }
    return 0;
}

/* Reads one displacement file; returns 0 when its format is right. */
static int read_field(const char *name, field *out)
{
    FILE *fp = open_data(name);
    if (fp == NULL) {
        return -1;
    }
    memset(out, 0, sizeof *out);
    char line[1024];
    int rows = 0, bad = 0;
    if (fgets(line, sizeof line, fp) == NULL || strcmp(line, "node,x,y,z,ux,uy,uz\n") != 0) {
        fail("%s line 1: header is not node,x,y,z,ux,uy,uz", name);
        bad = 1;
    }
    while (!bad && fgets(line, sizeof line, fp) != NULL) {
        char *f[8];
        if (rows == NODES || split(line, f, 7) != 7) {
            fail("%s line %d: a 122nd row, or not 7 fields", name, rows + 2);
            bad = 1;
        } else {
            bad = check_row(name, rows++, f, out) != 0;
        }
    }
    fclose(fp);
    if (!bad && rows != NODES) {
        fail("%s: %d rows, expected 121", name, rows);
        bad = 1;
    }
    return bad ? -1 : 0;
}

/* Reads the three cases of the files named PREFIX CASE SUFFIX. */
static int read_cases(const char *prefix, const char *suffix, field c[3])
{
    int bad = 0;
    for (int k = 0; k < 3; ++k) {
        char name[PATH_LEN];
        snprintf(name, sizeof name, "%s%s%s", prefix, cases[k], suffix);
        bad |= read_field(name, &c[k]) != 0;
    }
    return bad ? -1 : 0;
}

static int node_at(int i, int j) { return i + GRID * j; }

static void expect_equal(const char *set, const char *what, double a, double b, double scale)
{
    if (fabs(a - b) > SYM_TOL * scale) {
        fail("%s: %s broken by %.3g mm", set, what, fabs(a - b));
    }
}

/* g(i, j) is f(j, i) with ux and uy exchanged. */
static void check_diagonal(const char *set, const char *what, const field *f, const field *g)
{
    double s = fmax(f->max_abs, g->max_abs);
    for (int j = 0; j < GRID; ++j) {
        for (int i = 0; i < GRID; ++i) {
            const double *a = g->u[node_at(i, j)], *b = f->u[node_at(j, i)];
            expect_equal(set, what, a[0], b[1], s);
            expect_equal(set, what, a[1], b[0], s);
            expect_equal(set, what, a[2], b[2], s);
        }
    }
}

/* Reflection about x = 24 (axis 0) or y = 24 (axis 1): component k at the
 * mirror node is sign[k] times component k here. */
static void check_reflection(const char *set, const char *what, const field *f, int axis,
                             const double sign[3])
{
    for (int j = 0; j < GRID; ++j) {
        for (int i = 0; i < GRID; ++i) {
            int m = axis == 0 ? node_at(GRID - 1 - i, j) : node_at(i, GRID - 1 - j);
            for (int k = 0; k < 3; ++k) {
                expect_equal(set, what, f->u[m][k], sign[k] * f->u[node_at(i, j)][k], f->max_abs);
            }
        }
    }
}

static void check_symmetry(const char *set, const field c[3])
{
    /* A force along +x is reversed by the mirror x -> 48 - x, kept by
     * y -> 48 - y; a force along -z is kept by both. */
    static const double fx_x[3] = {1, -1, -1}, fx_y[3] = {1, -1, 1};
    static const double fz_x[3] = {-1, 1, 1}, fz_y[3] = {1, -1, 1};
    check_diagonal(set, "fy = fx mirrored about x = y", &c[0], &c[1]);
    check_diagonal(set, "fz symmetric about x = y", &c[2], &c[2]);
    check_reflection(set, "fx symmetry about x = 24", &c[0], 0, fx_x);
    check_reflection(set, "fx symmetry about y = 24", &c[0], 1, fx_y);
    check_reflection(set, "fz symmetry about x = 24", &c[2], 0, fz_x);
    check_reflection(set, "fz symmetry about y = 24", &c[2], 1, fz_y);
}

static double norm3(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* Relative RMS over the nodes (node < 0) or at one node of |fine - coarse|. */
static double change(const field *coarse, const field *fine, int node)
{
    double num = 0, den = 0;
    for (int n = 0; n < NODES; ++n) {
        if (node >= 0 && n != node) {
            continue;
        }
        double d[3] = {fine->u[n][0] - coarse->u[n][0], fine->u[n][1] - coarse->u[n][1],
                       fine->u[n][2] - coarse->u[n][2]};
        num += norm3(d) * norm3(d);
        den += norm3(fine->u[n]) * norm3(fine->u[n]);
    }
    return sqrt(num / den);
}

static void check_convergence(const char *coarse, const char *fine, const field fc[3],
                              const field ff[3], double rms_bound, double n61_bound)
{
    for (int k = 0; k < 3; ++k) {
        double rms = change(&fc[k], &ff[k], -1), n61 = change(&fc[k], &ff[k], 60);
        printf("  %s %s -> %s: RMS change %.3f %% (bound %.3g %%), node 61 %.3f %% (bound %.3g %%)\n",
               cases[k], coarse, fine, 100 * rms, 100 * rms_bound, 100 * n61, 100 * n61_bound);
        if (!(rms < rms_bound) || !(n61 < n61_bound)) {
            fail("%s %s -> %s: mesh-convergence change above its bound", cases[k], coarse, fine);
        }
    }
}

/* block48_reference.csv names, for each case, the finest level's file. */
static void check_reference(const char *finest)
{
    FILE *fp = open_data("block48_reference.csv");
    if (fp == NULL) {
        return;
    }
    char line[1024], want[PATH_LEN];
    int seen[3] = {0, 0, 0}, row = 1;
    if (fgets(line, sizeof line, fp) == NULL || strcmp(line, "case,level,file\n") != 0) {
        fail("block48_reference.csv line 1: header is not case,level,file");
    }
    while (fgets(line, sizeof line, fp) != NULL) {
        char *f[4];
        ++row;
        int k = 0, n = split(line, f, 3);
        while (n == 3 && k < 3 && strcmp(f[0], cases[k]) != 0) {
            ++k;
        }
        if (n == 3 && k < 3) {
            snprintf(want, sizeof want, "block48_%s_%s.csv", cases[k], finest);
        }
        if (n != 3 || k == 3 || seen[k]++ || strcmp(f[1], finest) != 0 || strcmp(f[2], want) != 0) {
            fail("block48_reference.csv line %d: expected case,%s,block48_CASE_%s.csv once per case",
                 row, finest, finest);
        }
    }
    fclose(fp);
    if (!seen[0] || !seen[1] || !seen[2]) {
        fail("block48_reference.csv: a case is missing");
    }
}

/* Each row run,case,fx,fy,fz,rx,ry,rz: r = -f and |f| = 1 N; every level's
 * own run (named after the level) is listed with all three cases. */
static void check_reactions(char *const *levels, int nlevels)
{
    FILE *fp = open_data("block48_reactions.csv");
    if (fp == NULL) {
        return;
    }
    char line[1024];
    int row = 1, found[LIST_MAX] = {0};
    if (fgets(line, sizeof line, fp) == NULL || strcmp(line, "run,case,fx,fy,fz,rx,ry,rz\n") != 0) {
        fail("block48_reactions.csv line 1: header is not run,case,fx,fy,fz,rx,ry,rz");
    }
    while (fgets(line, sizeof line, fp) != NULL) {
        char *f[9];
        double v[6];
        ++row;
        int ok = split(line, f, 8) == 8;
        for (int k = 0; ok && k < 6; ++k) {
            ok = parse_num(f[2 + k], &v[k]);
        }
        if (!ok || fabs(norm3(v) - 1) > 1e-12 || fabs(v[0] + v[3]) > REACTION_TOL ||
            fabs(v[1] + v[4]) > REACTION_TOL || fabs(v[2] + v[5]) > REACTION_TOL) {
            fail("block48_reactions.csv line %d: reaction does not balance a 1 N force", row);
            continue;
        }
        for (int l = 0; l < nlevels; ++l) {
            found[l] += strcmp(f[0], levels[l]) == 0;
        }
    }
    fclose(fp);
    for (int l = 0; l < nlevels; ++l) {
        if (found[l] != 3) {
            fail("block48_reactions.csv: run %s has %d rows, expected 3", levels[l], found[l]);
        }
    }
}


static int split_list(char *s, char **items)
{
    int n = split(s, items, LIST_MAX);
    return n > LIST_MAX ? -1 : n;
}

/* Every level's files; symmetry at each; convergence of the last two. */
static void check_levels(char *const *levels, int n, double rms_bound, double n61_bound)
{
    static field f[LIST_MAX][3];
    int ok[LIST_MAX];
    for (int l = 0; l < n; ++l) {
        char suffix[PATH_LEN];
        snprintf(suffix, sizeof suffix, "_%s.csv", levels[l]);
        ok[l] = read_cases("block48_", suffix, f[l]) == 0;
        if (ok[l]) {
            check_symmetry(levels[l], f[l]);
        }
    }
    if (n < 2) {
        fail("convergence needs at least two levels");
    } else if (ok[n - 2] && ok[n - 1]) {
        check_convergence(levels[n - 2], levels[n - 1], f[n - 2], f[n - 1], rms_bound, n61_bound);
    }
}

/* The sweep's files; symmetry of each; nu = 0.49 is its level's run. */
static void check_sweep(char *const *nus, int n, const char *level)
{
    field f[3], base[3];
    char prefix[PATH_LEN], suffix[PATH_LEN];
    snprintf(suffix, sizeof suffix, "_%s.csv", level);
    int have_base = read_cases("block48_", suffix, base) == 0;
    for (int v = 0; v < n; ++v) {
        snprintf(prefix, sizeof prefix, "block48_nu%s_", nus[v]);
        if (read_cases(prefix, ".csv", f) != 0) {
            continue;
        }
        check_symmetry(prefix, f);
        if (strcmp(nus[v], "0.49") == 0 && have_base && memcmp(f, base, sizeof f) != 0) {
            fail("%s*.csv differ from the %s files of the same run", prefix, level);
        }
    }
}

int main(int argc, char **argv)
{
    char *levels[LIST_MAX + 1], *nus[LIST_MAX + 1];
    double rms_bound, n61_bound;
    int nl = argc == 7 ? split_list(argv[2], levels) : -1;
    int nn = argc == 7 ? split_list(argv[3], nus) : -1;
    if (nl < 1 || nn < 1 || !parse_num(argv[5], &rms_bound) || !parse_num(argv[6], &n61_bound)) {
        fprintf(stderr, "usage: check_data DIR LEVELS NUS SWEEP_LEVEL RMS_BOUND NODE61_BOUND\n");
        return 2;
    }
    data_dir = argv[1];
    check_levels(levels, nl, rms_bound, n61_bound);
    check_sweep(nus, nn, argv[4]);
    check_reference(levels[nl - 1]);
    check_reactions(levels, nl);
    if (failures > 0) {
        printf("check_data: %d check(s) failed in %s\n", failures, data_dir);
        return 1;
    }
    printf("check_data: %s: %d levels, %d Poisson ratios: format, symmetry, convergence, "
           "reactions ok\n", data_dir, nl, nn);
    return 0;
}
