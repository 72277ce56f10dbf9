/*
 * check_data.c — validates the committed linear CalculiX reference data of a
 * box scene (tests/calculix/data, block48 or beam40) without running
 * CalculiX:
 *
 *   - every displacement file is present, has the header
 *     node,x,y,z,ux,uy,uz and a row of finite numbers per output point
 *     (block48: 121, point N = i + 11 j + 1 at (4.8 i, 4.8 j, 6); beam40: 45,
 *     N = i + 9 j + 1 at (5 i, 5 j, 20)), with zero displacement on the
 *     clamped edges;
 *   - symmetries the mesh and the loads have exactly: block48's fy is fx
 *     mirrored about the diagonal x = y, fx is even/odd about the centre
 *     lines, fz symmetric about both centre lines and the diagonal; beam40's
 *     fx and fz are symmetric and fy antisymmetric about y = 10;
 *   - mesh convergence: between the two finest levels, the RMS change over
 *     the output points and the change at the load point are below the
 *     given bounds;
 *   - the reference list names the finest level's files;
 *   - the nu sweep at the reference nu is the same data as its level's files;
 *   - the load point's table (SCENE_nodeP.csv) holds each level's and case's
 *     load point as its file does;
 *   - every run's reaction total balances the applied 1 N force.
 *
 * usage: check_data SCENE DIR LEVELS NUS SWEEP_LEVEL RMS_BOUND POINT_BOUND
 *   SCENE    block48 or beam40
 *   LEVELS   comma list, coarse to fine (e.g. h2.4,h1.2,h0.6)
 *   NUS      comma list of the sweep's Poisson ratios (0,0.3,0.45,0.49,0.499),
 *            or "none"
 *   bounds   relative, e.g. 0.01 for 1 %
 * Prints one line per failed check; exits 1 if any failed, 2 on bad usage.
 */
#include "data_csv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LIST_MAX 8
/* CalculiX prints 7 significant digits: exact symmetries hold to that,
 * relative to the largest displacement of the field. */
#define SYM_TOL 1e-5
#define REACTION_TOL 1e-6

typedef struct {
    const char *name;
    grid_spec grid;
    int point;         /* index of the load point (patch centre) */
    int square;        /* block48: mirror planes x = 24, y = 24 and x = y */
    const char *nu;    /* Poisson's ratio of the levels */
} scene_spec;

static const scene_spec scenes[] = {
    {"block48", {11, 11, 4.8, 6.0, CLAMP_X0 | CLAMP_X1 | CLAMP_Y0 | CLAMP_Y1}, 60, 1, "0.49"},
    {"beam40", {9, 5, 5.0, 20.0, CLAMP_X0}, 24, 0, "0.45"},
};
static const scene_spec *sc;
static const char *const cases[3] = {"fx", "fy", "fz"};

/* DATA file name "SCENE_" + rest into buf. */
static const char *scene_file(char *buf, size_t size, const char *rest)
{
    snprintf(buf, size, "%s_%s", sc->name, rest);
    return buf;
}

/* Reads the three cases of the files named PREFIX CASE SUFFIX. */
static int read_cases(const char *prefix, const char *suffix, field c[3])
{
    int bad = 0;
    for (int k = 0; k < 3; ++k) {
        char name[PATH_LEN];
        snprintf(name, sizeof name, "%s%s%s", prefix, cases[k], suffix);
        bad |= read_field(name, &sc->grid, &c[k]) != 0;
    }
    return bad ? -1 : 0;
}

static int node_at(int i, int j) { return i + sc->grid.nx * j; }

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
    for (int j = 0; j < sc->grid.ny; ++j) {
        for (int i = 0; i < sc->grid.nx; ++i) {
            const double *a = g->u[node_at(i, j)], *b = f->u[node_at(j, i)];
            expect_equal(set, what, a[0], b[1], s);
            expect_equal(set, what, a[1], b[0], s);
            expect_equal(set, what, a[2], b[2], s);
        }
    }
}

/* Reflection about the centre line x = const (axis 0) or y = const (axis
 * 1): component k at the mirror node is sign[k] times component k here. */
static void check_reflection(const char *set, const char *what, const field *f, int axis,
                             const double sign[3])
{
    int nx = sc->grid.nx, ny = sc->grid.ny;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            int m = axis == 0 ? node_at(nx - 1 - i, j) : node_at(i, ny - 1 - j);
            for (int k = 0; k < 3; ++k) {
                expect_equal(set, what, f->u[m][k], sign[k] * f->u[node_at(i, j)][k], f->max_abs);
            }
        }
    }
}

static void check_symmetry(const char *set, const field c[3])
{
    /* A force along +x is reversed by the mirror x -> 48 - x, kept by
     * y -> 48 - y; a force along -z is kept by both; a force along +y is
     * reversed by y -> 20 - y (beam40). */
    static const double fx_x[3] = {1, -1, -1}, fx_y[3] = {1, -1, 1};
    static const double fz_x[3] = {-1, 1, 1}, fz_y[3] = {1, -1, 1}, fy_y[3] = {-1, 1, -1};
    if (!sc->square) {
        check_reflection(set, "fx symmetry about y = 10", &c[0], 1, fx_y);
        check_reflection(set, "fy antisymmetry about y = 10", &c[1], 1, fy_y);
        check_reflection(set, "fz symmetry about y = 10", &c[2], 1, fz_y);
        return;
    }
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
        double rms = field_change(&fc[k], &ff[k], -1), n61 = field_change(&fc[k], &ff[k], sc->point);
        printf("  %s %s -> %s: RMS change %.3f %% (bound %.3g %%), node %d %.3f %% (bound %.3g %%)\n",
               cases[k], coarse, fine, 100 * rms, 100 * rms_bound, sc->point + 1, 100 * n61,
               100 * n61_bound);
        if (!(rms < rms_bound) || !(n61 < n61_bound)) {
            fail("%s %s -> %s: mesh-convergence change above its bound", cases[k], coarse, fine);
        }
    }
}

/* SCENE_reference.csv names, for each case, the finest level's file. */
static void check_reference(const char *finest)
{
    char table[PATH_LEN];
    FILE *fp = open_table(scene_file(table, sizeof table, "reference.csv"), "case,level,file");
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
            snprintf(want, sizeof want, "%s_%s_%s.csv", sc->name, cases[k], finest);
        }
        if (n != 3 || k == 3 || seen[k]++ || strcmp(f[1], finest) != 0 || strcmp(f[2], want) != 0) {
            fail("%s line %d: expected case,%s,%s_CASE_%s.csv once per case", table, row, finest,
                 sc->name, finest);
        }
    }
    fclose(fp);
    if (!seen[0] || !seen[1] || !seen[2]) {
        fail("%s: a case is missing", table);
    }
}

/* Each row run,case,fx,fy,fz,rx,ry,rz: r = -f and |f| = 1 N; every level's
 * own run (named after the level) is listed with all three cases. */
static void check_reactions(char *const *levels, int nlevels)
{
    char table[PATH_LEN];
    FILE *fp = open_table(scene_file(table, sizeof table, "reactions.csv"), "run,case,fx,fy,fz,rx,ry,rz");
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
            fail("%s line %d: reaction does not balance a 1 N force", table, row);
            continue;
        }
        for (int l = 0; l < nlevels; ++l) {
            found[l] += strcmp(f[0], levels[l]) == 0;
        }
    }
    fclose(fp);
    for (int l = 0; l < nlevels; ++l) {
        if (found[l] != 3) {
            fail("%s: run %s has %d rows, expected 3", table, levels[l], found[l]);
        }
    }
}

static int split_list(char *s, char **items)
{
    int n = split(s, items, LIST_MAX);
    return n > LIST_MAX ? -1 : n;
}

/* The load point's table (SCENE_nodeP.csv) has, for every level and case,
 * the load point's row of that level's file: a field file swapped for
 * another level's is caught even with only two levels. */
static void check_point_table(char *const *levels, int n, field f[][3], const int *ok)
{
    char table[PATH_LEN], rest[32];
    snprintf(rest, sizeof rest, "node%d.csv", sc->point + 1);
    FILE *fp = open_table(scene_file(table, sizeof table, rest), "run,element,nu,divisions,layers,load,case,ux,uy,uz");
    if (fp == NULL) {
        return;
    }
    int seen[LIST_MAX][3] = {{0}};
    char line[1024];
    while (fgets(line, sizeof line, fp) != NULL) {
        char *w[11];
        double u[3];
        if (split(line, w, 10) != 10 || strcmp(w[5], "patch") != 0 || !parse_num(w[7], &u[0]) ||
            !parse_num(w[8], &u[1]) || !parse_num(w[9], &u[2])) {
            continue;
        }
        for (int l = 0; l < n; ++l) {
            for (int c = 0; c < 3 && strcmp(w[0], levels[l]) == 0; ++c) {
                if (strcmp(w[6], cases[c]) != 0 || !ok[l]) {
                    continue;
                }
                const double *fu = f[l][c].u[sc->point];
                seen[l][c] = 1;
                if (fabs(fu[0] - u[0]) + fabs(fu[1] - u[1]) + fabs(fu[2] - u[2]) > 1e-9 * f[l][c].max_abs) {
                    fail("%s: %s %s differs from point %d of the %s file", table, levels[l], cases[c],
                         sc->point + 1, cases[c]);
                }
            }
        }
    }
    fclose(fp);
    for (int l = 0; l < n; ++l) {
        for (int c = 0; c < 3; ++c) {
            if (ok[l] && !seen[l][c]) {
                fail("%s: no %s %s row", table, levels[l], cases[c]);
            }
        }
    }
}

/* Every level's files; symmetry at each; the load point's table;
 * convergence of the last two. */
static void check_levels(char *const *levels, int n, double rms_bound, double n61_bound)
{
    static field f[LIST_MAX][3];
    int ok[LIST_MAX];
    for (int l = 0; l < n; ++l) {
        char prefix[PATH_LEN], suffix[PATH_LEN];
        snprintf(suffix, sizeof suffix, "_%s.csv", levels[l]);
        ok[l] = read_cases(scene_file(prefix, sizeof prefix, ""), suffix, f[l]) == 0;
        if (ok[l]) {
            check_symmetry(levels[l], f[l]);
        }
    }
    check_point_table(levels, n, f, ok);
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
    int have_base = n > 0 && read_cases(scene_file(prefix, sizeof prefix, ""), suffix, base) == 0;
    for (int v = 0; v < n; ++v) {
        snprintf(prefix, sizeof prefix, "%s_nu%s_", sc->name, nus[v]);
        if (read_cases(prefix, ".csv", f) != 0) {
            continue;
        }
        check_symmetry(prefix, f);
        if (strcmp(nus[v], sc->nu) == 0 && have_base && memcmp(f, base, sizeof f) != 0) {
            fail("%s*.csv differ from the %s files of the same run", prefix, level);
        }
    }
}

int main(int argc, char **argv)
{
    char *levels[LIST_MAX + 1], *nus[LIST_MAX + 1];
    double rms_bound, n61_bound;
    for (size_t k = 0; argc == 8 && k < sizeof scenes / sizeof scenes[0]; ++k) {
        sc = strcmp(argv[1], scenes[k].name) == 0 ? &scenes[k] : sc;
    }
    int nl = argc == 8 ? split_list(argv[3], levels) : -1;
    int nn = argc == 8 ? (strcmp(argv[4], "none") == 0 ? 0 : split_list(argv[4], nus)) : -1;
    if (sc == NULL || nl < 1 || nn < 0 || !parse_num(argv[6], &rms_bound) ||
        !parse_num(argv[7], &n61_bound)) {
        fprintf(stderr, "usage: check_data SCENE DIR LEVELS NUS|none SWEEP_LEVEL RMS_BOUND POINT_BOUND\n");
        return 2;
    }
    data_dir = argv[2];
    check_levels(levels, nl, rms_bound, n61_bound);
    check_sweep(nus, nn, argv[5]);
    check_reference(levels[nl - 1]);
    check_reactions(levels, nl);
    if (failures > 0) {
        printf("check_data: %d check(s) failed in %s\n", failures, data_dir);
        return 1;
    }
    printf("check_data: %s %s: %d levels, %d Poisson ratios: format, symmetry, convergence, "
           "reactions ok\n", sc->name, data_dir, nl, nn);
    return 0;
}
