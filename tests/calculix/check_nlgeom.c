/*
 * check_nlgeom.c — validates the committed large-deformation (NLGEOM)
 * CalculiX reference of block48 (tests/calculix/data/block48_nl_*.csv,
 * written by run_nlgeom.sh) without running CalculiX:
 *
 *   - every study run (material x path x level) is logged in
 *     block48_nl_runs.csv with the study's element, and reached a load factor
 *     in (0, 1];
 *   - every run's curve (block48_nl_curves.csv) has the printed load levels
 *     k / K, k = 1 .. floor(reached K), in order; the applied force is the
 *     load factor times one force (the path's, for the study runs); the
 *     reaction balances it (|r + f| <= REACTION_TOL); node 61's displacement
 *     along the force grows strictly with the load (monotone curve);
 *   - the study runs' final fields (block48_nl_MAT_PATH_LEVEL.csv) are
 *     output-grid files whose node 61 is the curve's last point, with the
 *     symmetries of the path: a (normal) about both centre lines and the
 *     diagonal, b and c (force in the x-z plane) about y = 24;
 *   - convergence: between the two finest levels, node 61's displacement
 *     changes by less than CONV_BOUND (relative) at every load level up to
 *     the load factor CONV_FACTOR that both reached (the change over all
 *     load levels is printed too: under the largest loads the patch's
 *     elements distort and the levels part, docs/calculix-reference.md);
 *   - the small-load limit: a run at the fraction s of a path's force, in one
 *     increment, gives s times the linear solution of the same mesh and
 *     element (block48_nl_linear.csv) within SMALL_SLOPE x s (relative): the
 *     difference is the nonlinearity, so it must shrink with s.
 *
 *   - graded levels (optional): every run MATERIAL:PATH[:FACTOR] on every
 *     graded level is a study run as above, and node 61 of the two finest
 *     graded levels changes by less than GRADED_BOUND at every load level
 *     up to FACTOR (default 1).
 *
 * usage: check_nlgeom DIR LEVELS MATERIALS PATHS K ELEMENT CONV_BOUND CONV_FACTOR SMALL_SLOPE
 *                     [GRADED_LEVELS GRADED_RUNS GRADED_BOUND]
 *   LEVELS     comma list coarse to fine (h2.4,h1.2,h0.8)
 *   MATERIALS  comma list (neohooke,svk)
 *   PATHS      comma list NAME:FX:FY:FZ (a:0:0:-3,b:1:0:0,c:1:0:-3)
 *   K          printed load levels per path
 * Prints one line per failed check; exits 1 if any failed, 2 on bad usage.
 */
#include "data_csv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LIST_MAX 8
#define MAX_RUNS 256
#define MAX_LEVELS 64
#define NAME_LEN 64
/* The reaction balances the applied force to the Newton tolerance (1e-6 of
 * the average nodal force) and CalculiX's 7 printed digits. */
#define REACTION_TOL 1e-4
#define SYM_TOL 1e-5

typedef struct {
    char name[NAME_LEN], material[NAME_LEN], element[NAME_LEN], path[NAME_LEN];
    int divisions, layers;
    double reached;
    int levels; /* curve rows */
    double factor[MAX_LEVELS], f[MAX_LEVELS][3], u[MAX_LEVELS][3], r[MAX_LEVELS][3];
} run;

typedef struct {
    char name[NAME_LEN];
    double force[3];
} path;

static const grid_spec block48 = {11, 11, 4.8, 6.0, CLAMP_X0 | CLAMP_X1 | CLAMP_Y0 | CLAMP_Y1};
static run runs[MAX_RUNS];
static int nruns;

static void copy_name(char *dst, const char *src)
{
    if (snprintf(dst, NAME_LEN, "%s", src) >= NAME_LEN) {
        fail("name too long: %s", src);
    }
}

/* nl_MATERIAL_PATH_LEVEL, the study run's name */
static void run_name(char *dst, const char *material, const char *path_name, const char *level)
{
    if (snprintf(dst, NAME_LEN, "nl_%s_%s_%s", material, path_name, level) >= NAME_LEN) {
        fail("run name too long: nl_%s_%s_%s", material, path_name, level);
    }
}

static run *find_run(const char *name)
{
    for (int k = 0; k < nruns; ++k) {
        if (strcmp(runs[k].name, name) == 0) {
            return &runs[k];
        }
    }
    return NULL;
}

/* block48_nl_runs.csv: run,material,element,path,divisions,layers,symmetry,
 * elements,nodes,dofs,increments,cutbacks,iterations,reached,threads,
 * seconds,max_rss_mb */
static void read_runs(void)
{
    FILE *fp = open_table("block48_nl_runs.csv",
                          "run,material,element,path,divisions,layers,symmetry,elements,nodes,dofs,"
                          "increments,cutbacks,iterations,reached,threads,seconds,max_rss_mb");
    if (fp == NULL) {
        return;
    }
    char line[1024];
    for (int row = 2; fgets(line, sizeof line, fp) != NULL; ++row) {
        char *f[18];
        double v[10];
        int ok = split(line, f, 17) == 17 && nruns < MAX_RUNS && find_run(f[0]) == NULL;
        for (int k = 0; ok && k < 10; ++k) {
            ok = parse_num(f[7 + k], &v[k]);
        }
        double n, l;
        ok = ok && parse_num(f[4], &n) && parse_num(f[5], &l) && v[6] > 0 && v[6] <= 1;
        if (!ok) {
            fail("block48_nl_runs.csv line %d: not a run row (17 fields, reached in (0, 1], new name)", row);
            continue;
        }
        run *r = &runs[nruns++];
        copy_name(r->name, f[0]);
        copy_name(r->material, f[1]);
        copy_name(r->element, f[2]);
        copy_name(r->path, f[3]);
        r->divisions = (int)n;
        r->layers = (int)l;
        r->reached = v[6];
    }
    fclose(fp);
}

/* block48_nl_curves.csv: run,factor,fx,fy,fz,ux,uy,uz,rx,ry,rz */
static void read_curves(void)
{
    FILE *fp = open_table("block48_nl_curves.csv", "run,factor,fx,fy,fz,ux,uy,uz,rx,ry,rz");
    if (fp == NULL) {
        return;
    }
    char line[1024];
    for (int row = 2; fgets(line, sizeof line, fp) != NULL; ++row) {
        char *f[12];
        double v[10];
        int ok = split(line, f, 11) == 11;
        for (int k = 0; ok && k < 10; ++k) {
            ok = parse_num(f[1 + k], &v[k]);
        }
        run *r = ok ? find_run(f[0]) : NULL;
        if (r == NULL || r->levels == MAX_LEVELS) {
            fail("block48_nl_curves.csv line %d: not a curve row of a logged run", row);
            continue;
        }
        int k = r->levels++;
        r->factor[k] = v[0];
        for (int c = 0; c < 3; ++c) {
            r->f[k][c] = v[1 + c];
            r->u[k][c] = v[4 + c];
            r->r[k][c] = v[7 + c];
        }
    }
    fclose(fp);
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* One run's curve: levels k / K in order, one force direction scaled by the
 * factor (force_out), balanced reactions, growing displacement along it.
 * K = 1 for the small-load runs. */
static void check_curve(const run *r, int levels_k, double force_out[3])
{
    int want = (int)floor(r->reached * levels_k + 1e-9);
    if (r->levels != want) {
        fail("%s: %d load levels in the curve, %d expected from reached = %g", r->name, r->levels,
             want, r->reached);
        return;
    }
    for (int c = 0; c < 3; ++c) {
        force_out[c] = r->levels > 0 ? r->f[0][c] / r->factor[0] : 0;
    }
    double prev = 0;
    for (int k = 0; k < r->levels; ++k) {
        if (fabs(r->factor[k] - (double)(k + 1) / levels_k) > 1e-9) {
            fail("%s: load level %d has factor %g, expected %d/%d", r->name, k + 1, r->factor[k],
                 k + 1, levels_k);
        }
        for (int c = 0; c < 3; ++c) {
            if (fabs(r->f[k][c] - r->factor[k] * force_out[c]) > 1e-9 ||
                fabs(r->r[k][c] + r->f[k][c]) > REACTION_TOL) {
                fail("%s: level %d: force not on the path, or reaction %g does not balance %g", r->name,
                     k + 1, r->r[k][c], r->f[k][c]);
                return;
            }
        }
        double along = dot3(r->u[k], force_out);
        if (!(along > prev)) {
            fail("%s: level %d: displacement along the force does not grow (%g after %g)", r->name,
                 k + 1, along, prev);
        }
        prev = along;
    }
}

static int same_force(const double a[3], const double b[3])
{
    return fabs(a[0] - b[0]) < 1e-9 && fabs(a[1] - b[1]) < 1e-9 && fabs(a[2] - b[2]) < 1e-9;
}

static int node_at(int i, int j) { return i + 11 * j; }

/* Path a: symmetric about x = 24, y = 24 and x = y (a normal force);
 * b, c (force in the x-z plane): symmetric about y = 24. */
static void check_field_symmetry(const char *name, const field *fd, int normal)
{
    for (int j = 0; j < 11; ++j) {
        for (int i = 0; i < 11; ++i) {
            const double *u = fd->u[node_at(i, j)], *my = fd->u[node_at(i, 10 - j)];
            double d = fmax(fmax(fabs(my[0] - u[0]), fabs(my[1] + u[1])), fabs(my[2] - u[2]));
            if (normal) {
                const double *mx = fd->u[node_at(10 - i, j)], *dg = fd->u[node_at(j, i)];
                d = fmax(d, fmax(fmax(fabs(mx[0] + u[0]), fabs(mx[1] - u[1])), fabs(mx[2] - u[2])));
                d = fmax(d, fmax(fmax(fabs(dg[0] - u[1]), fabs(dg[1] - u[0])), fabs(dg[2] - u[2])));
            }
            if (d > SYM_TOL * fd->max_abs) {
                fail("%s: symmetry broken by %.3g mm at node %d", name, d, node_at(i, j) + 1);
                return;
            }
        }
    }
}

/* One study run: logged, with the element and the path's force; its final
 * field. */
static void check_study_run(const char *material, const path *pa, const char *level,
                            const char *element)
{
    char name[NAME_LEN];
    run_name(name, material, pa->name, level);
    const run *r = find_run(name);
    if (r == NULL || strcmp(r->element, element) != 0 || strcmp(r->path, pa->name) != 0 ||
        strcmp(r->material, material) != 0 || r->levels == 0) {
        fail("%s: missing, empty or not a %s run of path %s", name, element, pa->name);
        return;
    }
    double per_unit[3];
    for (int c = 0; c < 3; ++c) {
        per_unit[c] = r->f[0][c] / r->factor[0];
    }
    if (!same_force(per_unit, pa->force)) {
        fail("%s: the force is not path %s's", name, pa->name);
    }
    field fd;
    char file[NAME_LEN + 16];
    snprintf(file, sizeof file, "block48_%s.csv", name);
    if (read_field(file, &block48, &fd) != 0) {
        return;
    }
    const double *last = r->u[r->levels - 1];
    if (memcmp(fd.u[60], last, sizeof fd.u[60]) != 0) {
        fail("%s: node 61 is not the curve's last point", file);
    }
    check_field_symmetry(file, &fd, pa->force[0] == 0 && pa->force[1] == 0);
}

/* The study runs: every level x material x path. */
static void check_study(char *const *levels, int nl, char *const *mats, int nm, const path *paths,
                        int np, const char *element)
{
    for (int l = 0; l < nl; ++l) {
        for (int m = 0; m < nm; ++m) {
            for (int p = 0; p < np; ++p) {
                check_study_run(mats[m], &paths[p], levels[l], element);
            }
        }
    }
}

/* Node 61 of one material and path on two levels at every load level both
 * reached: held to BOUND up to the load factor MAX_FACTOR, reported beyond. */
static void check_pair(const char *material, const char *path_name, const char *coarse,
                       const char *fine, double bound, double max_factor)
{
    char a[NAME_LEN], b[NAME_LEN];
    run_name(a, material, path_name, coarse);
    run_name(b, material, path_name, fine);
    const run *rc = find_run(a), *rf = find_run(b);
    if (rc == NULL || rf == NULL) {
        return; /* reported by check_study_run */
    }
    int n = rc->levels < rf->levels ? rc->levels : rf->levels, held = 0;
    double worst = 0, worst_all = 0;
    for (int k = 0; k < n; ++k) {
        double d[3] = {rf->u[k][0] - rc->u[k][0], rf->u[k][1] - rc->u[k][1],
                       rf->u[k][2] - rc->u[k][2]};
        double rel = sqrt(dot3(d, d) / dot3(rf->u[k], rf->u[k]));
        worst_all = fmax(worst_all, rel);
        if (rf->factor[k] <= max_factor + 1e-9) {
            worst = fmax(worst, rel);
            ++held;
        }
    }
    printf("  %s path %s, %s -> %s: node 61 changes by at most %.2f %% up to load factor %g "
           "(bound %.3g %%), %.2f %% over all %d common load levels\n", material, path_name, coarse,
           fine, 100 * worst, max_factor, 100 * bound, 100 * worst_all, n);
    if (held == 0 || !(worst < bound)) {
        fail("%s path %s: %s -> %s above the convergence bound", material, path_name, coarse, fine);
    }
}

/* The two finest uniform levels, every material and path. */
static void check_convergence(const char *coarse, const char *fine, char *const *mats, int nm,
                              const path *paths, int np, double bound, double max_factor)
{
    for (int m = 0; m < nm; ++m) {
        for (int p = 0; p < np; ++p) {
            check_pair(mats[m], paths[p].name, coarse, fine, bound, max_factor);
        }
    }
}

/* The graded levels (coarse to fine) and their runs MATERIAL:PATH[:FACTOR]:
 * every run a study run, and node 61 of the two finest graded levels within
 * BOUND up to the run's FACTOR (default 1; SVK's compressive paths stop at
 * a limit point). */
static void check_graded(char *const *levels, int nl, char *const *items, int ni,
                         const path *paths, int np, const char *element, double bound)
{
    for (int i = 0; i < ni; ++i) {
        char item[NAME_LEN];
        copy_name(item, items[i]);
        char *material = strtok(item, ":"), *path_name = strtok(NULL, ":"), *fac = strtok(NULL, ":");
        double factor = 1;
        const path *pa = NULL;
        for (int p = 0; path_name != NULL && p < np; ++p) {
            pa = strcmp(paths[p].name, path_name) == 0 ? &paths[p] : pa;
        }
        if (material == NULL || pa == NULL || (fac != NULL && !parse_num(fac, &factor))) {
            fail("graded run %s: not MATERIAL:PATH[:FACTOR] of a known path", items[i]);
            continue;
        }
        for (int l = 0; l < nl; ++l) {
            check_study_run(material, pa, levels[l], element);
        }
        check_pair(material, pa->name, levels[nl - 2], levels[nl - 1], bound, factor);
    }
}

/* block48_nl_linear.csv rows of run NAME: node 61 for fx and fz. */
static int read_linear(const char *name, double ufx[3], double ufz[3])
{
    FILE *fp = open_table("block48_nl_linear.csv", "run,element,divisions,layers,case,ux,uy,uz");
    if (fp == NULL) {
        return -1;
    }
    char line[1024];
    int got = 0;
    while (fgets(line, sizeof line, fp) != NULL) {
        char *f[9];
        if (split(line, f, 8) != 8 || strcmp(f[0], name) != 0) {
            continue;
        }
        double *dst = strcmp(f[4], "fx") == 0 ? ufx : strcmp(f[4], "fz") == 0 ? ufz : NULL;
        for (int c = 0; dst != NULL && c < 3; ++c) {
            got += parse_num(f[5 + c], &dst[c]);
        }
    }
    fclose(fp);
    return got == 6 ? 0 : -1;
}

/* Every run whose path is NAME_sS: S times the linear solution of its mesh
 * (u = Fx u_fx - Fz u_fz, the fz case being the force (0, 0, -1)). */
static void check_small(double slope)
{
    int seen = 0;
    for (int k = 0; k < nruns; ++k) {
        const run *r = &runs[k];
        const char *s = strstr(r->path, "_s");
        if (s == NULL || r->levels != 1) {
            continue;
        }
        /* nl_MATERIAL_PATH_LEVEL_sS: the level is the fourth word */
        char words[NAME_LEN], lin[2 * NAME_LEN + 16], *w = words;
        double ufx[3], ufz[3], scale = atof(s + 2);
        copy_name(words, r->name);
        for (int k2 = 0; k2 < 3 && w != NULL; ++k2) {
            w = strchr(w, '_') != NULL ? strchr(w, '_') + 1 : NULL;
        }
        if (w != NULL && strchr(w, '_') != NULL) {
            *strchr(w, '_') = '\0';
        }
        snprintf(lin, sizeof lin, "linear_%s_%s", w != NULL ? w : "?", r->element);
        if (read_linear(lin, ufx, ufz) != 0) {
            fail("%s: no linear run %s in block48_nl_linear.csv", r->name, lin);
            continue;
        }
        double want[3], d[3];
        for (int c = 0; c < 3; ++c) {
            want[c] = r->f[0][0] * ufx[c] - r->f[0][2] * ufz[c];
            d[c] = r->u[0][c] - want[c];
        }
        double rel = sqrt(dot3(d, d) / dot3(want, want));
        ++seen;
        printf("  %s: |u - u_linear| / |u_linear| = %.2e at %g of the force (bound %.2e)\n", r->name,
               rel, scale, slope * scale);
        if (!(scale > 0) || !(rel <= slope * scale)) {
            fail("%s: the small-load limit is not the linear solution", r->name);
        }
    }
    if (seen == 0) {
        fail("no small-load run");
    }
}

static int split_list(char *s, char **items)
{
    int n = split(s, items, LIST_MAX);
    return n > LIST_MAX ? -1 : n;
}

static int parse_paths(char *s, path *paths)
{
    char *items[LIST_MAX + 1];
    int n = split_list(s, items);
    for (int p = 0; p < n; ++p) {
        char *name = strtok(items[p], ":"), *c[3] = {strtok(NULL, ":"), strtok(NULL, ":"), strtok(NULL, ":")};
        if (name == NULL || c[2] == NULL || strtok(NULL, ":") != NULL) {
            return -1;
        }
        copy_name(paths[p].name, name);
        for (int k = 0; k < 3; ++k) {
            if (!parse_num(c[k], &paths[p].force[k])) {
                return -1;
            }
        }
    }
    return n;
}

int main(int argc, char **argv)
{
    char *levels[LIST_MAX + 1], *mats[LIST_MAX + 1], *graded[LIST_MAX + 1], *items[LIST_MAX + 1];
    path paths[LIST_MAX];
    double k_levels, conv_bound, conv_factor, slope, graded_bound = 0;
    int args = argc == 10 || argc == 13;
    int nl = args ? split_list(argv[2], levels) : -1;
    int nm = args ? split_list(argv[3], mats) : -1;
    int np = args ? parse_paths(argv[4], paths) : -1;
    int ng = argc == 13 ? split_list(argv[10], graded) : 0;
    int ni = argc == 13 ? split_list(argv[11], items) : 0;
    if (nl < 2 || nm < 1 || np < 1 || !parse_num(argv[5], &k_levels) || k_levels < 1 ||
        k_levels > MAX_LEVELS || !parse_num(argv[7], &conv_bound) || !parse_num(argv[8], &conv_factor) ||
        !parse_num(argv[9], &slope) ||
        (argc == 13 && (ng < 2 || ni < 1 || !parse_num(argv[12], &graded_bound)))) {
        fprintf(stderr, "usage: check_nlgeom DIR LEVELS MATERIALS PATHS K ELEMENT CONV_BOUND CONV_FACTOR "
                        "SMALL_SLOPE [GRADED_LEVELS GRADED_RUNS GRADED_BOUND]\n");
        return 2;
    }
    data_dir = argv[1];
    read_runs();
    read_curves();
    for (int k = 0; k < nruns; ++k) {
        double force[3];
        check_curve(&runs[k], strstr(runs[k].path, "_s") != NULL ? 1 : (int)k_levels, force);
    }
    check_study(levels, nl, mats, nm, paths, np, argv[6]);
    check_convergence(levels[nl - 2], levels[nl - 1], mats, nm, paths, np, conv_bound, conv_factor);
    check_small(slope);
    if (ng > 0) {
        check_graded(graded, ng, items, ni, paths, np, argv[6], graded_bound);
    }
    if (failures > 0) {
        printf("check_nlgeom: %d check(s) failed in %s\n", failures, data_dir);
        return 1;
    }
    printf("ok: check_nlgeom: %s: %d runs, %d levels x %d materials x %d paths: curves, reactions, "
           "fields, convergence, small-load limit ok\n", data_dir, nruns, nl, nm, np);
    return 0;
}
