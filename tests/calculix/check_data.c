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
#include "data_csv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define GRID 11
#define LIST_MAX 8
/* CalculiX prints 7 significant digits: exact symmetries hold to that,
 * relative to the largest displacement of the field. */
#define SYM_TOL 1e-5
#define REACTION_TOL 1e-6

static const grid_spec block48 = {GRID, GRID, 4.8, 6.0, CLAMP_X0 | CLAMP_X1 | CLAMP_Y0 | CLAMP_Y1};
static const char *const cases[3] = {"fx", "fy", "fz"};

/* Reads the three cases of the files named PREFIX CASE SUFFIX. */
static int read_cases(const char *prefix, const char *suffix, field c[3])
{
    int bad = 0;
    for (int k = 0; k < 3; ++k) {
        char name[PATH_LEN];
        snprintf(name, sizeof name, "%s%s%s", prefix, cases[k], suffix);
        bad |= read_field(name, &block48, &c[k]) != 0;
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

static void check_convergence(const char *coarse, const char *fine, const field fc[3],
                              const field ff[3], double rms_bound, double n61_bound)
{
    for (int k = 0; k < 3; ++k) {
        double rms = field_change(&fc[k], &ff[k], -1), n61 = field_change(&fc[k], &ff[k], 60);
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
    FILE *fp = open_table("block48_reference.csv", "case,level,file");
    if (fp == NULL) {
        return;
    }
    char line[1024], want[PATH_LEN];
    int seen[3] = {0, 0, 0}, row = 1;
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
    FILE *fp = open_table("block48_reactions.csv", "run,case,fx,fy,fz,rx,ry,rz");
    if (fp == NULL) {
        return;
    }
    char line[1024];
    int row = 1, found[LIST_MAX] = {0};
    while (fgets(line, sizeof line, fp) != NULL) {
        char *f[9];
        double v[6];
        ++row;
        int ok = split(line, f, 8) == 8;
        for (int k = 0; ok && k < 6; ++k) {
            ok = parse_num(f[2 + k], &v[k]);
        }
        double size = ok ? sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) : 0;
        if (!ok || fabs(size - 1) > 1e-12 || fabs(v[0] + v[3]) > REACTION_TOL ||
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
