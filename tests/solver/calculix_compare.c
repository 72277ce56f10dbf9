/*
 * calculix_compare.c — block48 (GUIDE §5) meshless solution against the
 * CalculiX reference (tests/calculix/data, produced by tests/calculix/).
 *
 *   calculix_compare [--data DIR] [--scene FILE] [--levels G1;G2;...] [--nu NU]
 *                    [--set KEY=VALUE]... [--max-err61 F] [--csv FILE] [--no-check]
 *
 * For each grid level (default 11,11,3;21,21,5;41,41,9) solves the three
 * unit load cases fx = (1,0,0), fy = (0,1,0), fz = (0,0,-1) N through one
 * factorisation and compares the displacement at the reference's 121
 * top-surface points, evaluated with the solver's field (so any grid, graded
 * or not, compares at the same points), with the reference named in
 * DIR/block48_reference.csv (header case,level,file).  With --nu it compares
 * against DIR/block48_nu<NU>_<case>.csv instead, with material.nu = NU.  The
 * scene (default tests/solver/block48_seed.yaml) may give its contact by node (then the
 * grid's top-centre node is set, which needs odd counts in x and y) or by
 * position.  --set overrides apply to every level.
 *
 * Prints level,grid,nodes,case,ux61,uy61,uz61,ref_ux61,ref_uy61,ref_uz61,
 * err61,rms,rms_rel,seconds,min_rcond where err61 = |u61 - ref| / |ref| at node 61
 * (24, 24, 6), rms the RMS of |u - ref| over the 121 points (mm), rms_rel
 * relative to the RMS of |ref|, seconds the wall time of the level's solver
 * (build and three solves), min_rcond the smallest reciprocal condition of
 * its local RPIM systems.  Exit 1 when, at the finest level, node 61 is
 * more than --max-err61 (default 0.03) off in any case, or the RMS error
 * grows from one level to the next (unless --no-check); a missing data file
 * is an error.
 */
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/blas_pin.h"
#include "base/context.h"
#include "scene/scene.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define TOP 121
#define MAX_LEVELS 8
#define MAX_SETS 16

static const char *const cases[3] = {"fx", "fy", "fz"};
static const double forces[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};

typedef struct reference {
    double x[TOP][3], u[TOP][3];
} reference;

typedef struct options {
    const char *data, *csv, *nu, *scene;
    const char *sets[MAX_SETS];
    int n_sets;
    char levels[MAX_LEVELS][32];
    int n_levels, check;
    double max_err61;
} options;

/* Reads a CalculiX CSV: header node,x,y,z,ux,uy,uz and 121 rows numbered
 * N = i + 11 j + 1. */
static int read_reference(const char *path, reference *r)
{
    FILE *fp = fopen(path, "r");
    if (fp == NULL) {
        fprintf(stderr, "calculix_compare: %s: %s\n", path, strerror(errno));
        return -1;
    }
    char line[512];
    int rows = 0, ok = fgets(line, sizeof line, fp) && strncmp(line, "node,x,y,z,ux,uy,uz", 19) == 0;
    while (ok && fgets(line, sizeof line, fp)) {
        unsigned node;
        double v[6];
        if (sscanf(line, "%u,%lf,%lf,%lf,%lf,%lf,%lf", &node, &v[0], &v[1], &v[2], &v[3], &v[4],
                   &v[5]) != 7 ||
            node < 1 || node > TOP) {
            ok = 0;
            break;
        }
        for (int a = 0; a < 3; ++a) {
            r->x[node - 1][a] = v[a];
            r->u[node - 1][a] = v[3 + a];
        }
        rows++;
    }
    fclose(fp);
    if (!ok || rows != TOP) {
        fprintf(stderr, "calculix_compare: %s: expected the header node,x,y,z,ux,uy,uz and %d rows\n",
                path, TOP);
        return -1;
    }
    return 0;
}

/* The reference file of a case: from block48_reference.csv, or the nu sweep. */
static int reference_path(const options *o, int c, char *path, size_t len)
{
    if (o->nu) {
        snprintf(path, len, "%s/block48_nu%s_%s.csv", o->data, o->nu, cases[c]);
        return 0;
    }
    char index[512], line[512];
    snprintf(index, sizeof index, "%s/block48_reference.csv", o->data);
    FILE *fp = fopen(index, "r");
    if (fp == NULL) {
        fprintf(stderr, "calculix_compare: %s: %s\n", index, strerror(errno));
        return -1;
    }
    int found = 0;
    while (!found && fgets(line, sizeof line, fp)) {
        char name[16], level[64], file[256];
        if (sscanf(line, "%15[^,],%63[^,],%255[^,\r\n]", name, level, file) == 3 &&
            strcmp(name, cases[c]) == 0) {
            const char *base = strrchr(file, '/');
            snprintf(path, len, "%s/%s", o->data, base ? base + 1 : file);
            found = 1;
        }
    }
    fclose(fp);
    if (!found) {
        fprintf(stderr, "calculix_compare: %s names no file for case %s\n", index, cases[c]);
    }
    return found ? 0 : -1;
}

typedef struct result {
    double u61[3], ref61[3], err61, rms, rms_rel;
} result;

/* The solution at the reference points against the reference. */
static void compare(const double (*u)[3], const reference *r, result *out)
{
    double e2 = 0, r2 = 0;
    for (int n = 0; n < TOP; ++n) {
        double d2 = 0, q2 = 0;
        for (int a = 0; a < 3; ++a) {
            double d = u[n][a] - r->u[n][a];
            d2 += d * d;
            q2 += r->u[n][a] * r->u[n][a];
            if (n == 60) {
                out->u61[a] = u[n][a];
                out->ref61[a] = r->u[n][a];
            }
        }
        if (n == 60) {
            out->err61 = sqrt(d2 / q2);
        }
        e2 += d2;
        r2 += q2;
    }
    out->rms = sqrt(e2 / TOP);
    out->rms_rel = sqrt(e2 / r2);
}

/* The scene at one grid; a contact given by node moves to the top centre. */
static tf_scene *level_scene(const options *o, const char *grid)
{
    char set_grid[64], set_node[64], set_nu[64];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[MAX_SETS + 3];
    int n = 0;
    snprintf(set_grid, sizeof set_grid, "geometry.grid=%s", grid);
    snprintf(set_nu, sizeof set_nu, "material.nu=%s", o->nu ? o->nu : "0.49");
    sets[n++] = set_grid;
    sets[n++] = set_nu;
    for (int k = 0; k < o->n_sets; ++k) {
        sets[n++] = o->sets[k];
    }
    tf_scene *s = tf_scene_load(&ctx, o->scene, sets, (size_t)n);
    if (s != NULL && s->problem.n_contacts > 0 && s->problem.contacts[0].by_node) {
        const unsigned *g = s->problem.cloud.grid;
        if (g[0] % 2 == 0 || g[1] % 2 == 0) {
            fprintf(stderr, "calculix_compare: %s gives its contact by node: grid %s has no top "
                            "centre node (give odd counts, or a scene with the contact by position)\n",
                    o->scene, grid);
            tf_scene_free(s);
            return NULL;
        }
        snprintf(set_node, sizeof set_node, "contact.0.node=%u", g[0] / 2 + g[0] * (g[1] / 2) + 1);
        sets[n++] = set_node;
        tf_scene_free(s);
        s = tf_scene_load(&ctx, o->scene, sets, (size_t)n);
    }
    if (s == NULL) {
        fprintf(stderr, "calculix_compare: %s\n", ctx.err);
    }
    return s;
}

/* Solves one level for the three cases and evaluates them at the reference
 * points: u[c][n][a]. */
static int solve_level(const options *o, const char *grid, const reference *ref, tf_scene **scene,
                       double (*u)[TOP][3], double *seconds, double *rcond)
{
    unsigned g[3];
    if (sscanf(grid, "%u,%u,%u", &g[0], &g[1], &g[2]) != 3) {
        fprintf(stderr, "calculix_compare: bad grid '%s'\n", grid);
        return -1;
    }
    if ((*scene = level_scene(o, grid)) == NULL) {
        return -1;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    const tf_problem *p = &(*scene)->problem;
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    double *full = sv ? malloc(9 * p->cloud.n * sizeof *full) : NULL;
    int rc = full ? tf_solver_solve(sv, 0, forces, 3, NULL, full) : -1;
    *seconds = omp_get_wtime() - t0;
    const tf_galerkin_info *gi = sv ? tf_galerkin_info_of(sv) : NULL;
    *rcond = gi ? gi->st.min_rcond : NAN;
    double grad[TOP * 9];
    for (int c = 0; rc == 0 && c < 3; ++c) {
        rc = tf_solver_field(&ctx, sv, full + (size_t)c * 3 * p->cloud.n, &ref[c].x[0][0], TOP,
                             &u[c][0][0], grad);
    }
    if (rc != 0) {
        fprintf(stderr, "calculix_compare: %s\n", full || !sv ? ctx.err : "out of memory");
    }
    free(full);
    tf_solver_destroy(sv);
    return rc;
}

static int parse(int argc, char **argv, options *o)
{
    const char *levels = "11,11,3;21,21,5;41,41,9";
    o->data = "tests/calculix/data";
    o->scene = "tests/solver/block48_seed.yaml";
    o->check = 1;
    o->max_err61 = 0.03;
    for (int k = 1; k < argc; ++k) {
        if (strcmp(argv[k], "--no-check") == 0) {
            o->check = 0;
        } else if (k + 1 < argc && strcmp(argv[k], "--data") == 0) {
            o->data = argv[++k];
        } else if (k + 1 < argc && strcmp(argv[k], "--scene") == 0) {
            o->scene = argv[++k];
        } else if (k + 1 < argc && strcmp(argv[k], "--levels") == 0) {
            levels = argv[++k];
        } else if (k + 1 < argc && strcmp(argv[k], "--nu") == 0) {
            o->nu = argv[++k];
        } else if (k + 1 < argc && strcmp(argv[k], "--csv") == 0) {
            o->csv = argv[++k];
        } else if (k + 1 < argc && strcmp(argv[k], "--max-err61") == 0) {
            o->max_err61 = atof(argv[++k]);
        } else if (k + 1 < argc && strcmp(argv[k], "--set") == 0 && o->n_sets < MAX_SETS) {
            o->sets[o->n_sets++] = argv[++k];
        } else {
            fprintf(stderr, "usage: calculix_compare [--data DIR] [--scene FILE] [--levels G;G;...] "
                            "[--nu NU] [--set KEY=VALUE]... [--max-err61 F] [--csv FILE] "
                            "[--no-check]\n");
            return -1;
        }
    }
    for (const char *p = levels; *p && o->n_levels < MAX_LEVELS; p += strcspn(p, ";"), p += *p == ';') {
        snprintf(o->levels[o->n_levels++], sizeof o->levels[0], "%.*s", (int)strcspn(p, ";"), p);
    }
    return o->n_levels > 0 ? 0 : -1;
}

int main(int argc, char **argv)
{
    options o = {0};
    static reference ref[3];
    tf_blas_pin(argv);
    if (parse(argc, argv, &o) != 0) {
        return 2;
    }
    for (int c = 0; c < 3; ++c) {
        char path[768];
        if (reference_path(&o, c, path, sizeof path) != 0 || read_reference(path, &ref[c]) != 0) {
            return 1;
        }
    }
    FILE *csv = o.csv ? fopen(o.csv, "w") : NULL;
    const char *header = "level,grid,nodes,case,ux61,uy61,uz61,ref_ux61,ref_uy61,ref_uz61,err61,"
                         "rms,rms_rel,seconds,min_rcond\n";
    printf("%s", header);
    if (csv) {
        fputs(header, csv);
    }
    int bad = 0;
    double prev[3] = {INFINITY, INFINITY, INFINITY};
    for (int l = 0; l < o.n_levels; ++l) {
        tf_scene *s = NULL;
        static double u[3][TOP][3];
        double seconds = 0, rcond = NAN;
        if (solve_level(&o, o.levels[l], ref, &s, u, &seconds, &rcond) != 0) {
            tf_scene_free(s);
            return 1;
        }
        for (int c = 0; c < 3; ++c) {
            result r = {{0, 0, 0}, {0, 0, 0}, 0, 0, 0};
            const tf_problem *p = &s->problem;
            compare((const double(*)[3])u[c], &ref[c], &r);
            char row[512];
            snprintf(row, sizeof row,
                     "%d,%ux%ux%u,%zu,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.4f,%.4g,%.4f,%.2f,%.2g\n", l,
                     p->cloud.grid[0], p->cloud.grid[1], p->cloud.grid[2], p->cloud.n, cases[c],
                     r.u61[0], r.u61[1], r.u61[2], r.ref61[0], r.ref61[1], r.ref61[2], r.err61,
                     r.rms, r.rms_rel, seconds, rcond);
            printf("%s", row);
            fflush(stdout);
            if (csv) {
                fputs(row, csv);
            }
            if (o.check && r.rms > prev[c]) {
                fprintf(stderr, "FAIL: case %s: the RMS error grows from level %d to %d\n",
                        cases[c], l - 1, l);
                bad = 1;
            }
            if (o.check && l == o.n_levels - 1 && r.err61 > o.max_err61) {
                fprintf(stderr, "FAIL: case %s: node 61 is %.2f %% off at the finest level "
                                "(bound %.2f %%)\n",
                        cases[c], 100 * r.err61, 100 * o.max_err61);
                bad = 1;
            }
            prev[c] = r.rms;
        }
        tf_scene_free(s);
    }
    if (csv) {
        fclose(csv);
    }
    return bad;
}
