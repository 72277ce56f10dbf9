/*
 * region_calculix.c — a contact region's law against CalculiX at sites
 * never fitted (make region-calculix).
 *
 *   region_calculix SCENE FINEST.csv [COARSER.csv ...] [--assert PCT] [KEY=VALUE ...]
 *
 * The CSV files are CalculiX levels of the region's sites
 * (tests/calculix/region_dat.awk: at each site the patch-averaged
 * displacement under 1 N along x, y and z, over the same probe patch the
 * meshless fit loads), the finest first.  The region is fitted by tissuefit
 * fit's rule (region_models.c: at most TFIT_REGION_MAX_RANK modes, the
 * coupling stated, not a target), the meshless solve is run at the same
 * sites, and for each site, with C the CalculiX compliance (chart frame)
 * and K(g) the law's stiffness there:
 *
 *   law       ||K(g) C - I||_2: the law's force error at CalculiX's
 *             patch-averaged displacement of the worst force on the
 *             envelope's sphere, a fraction of its radius (the measure the
 *             fit's held-out error uses against the meshless solves);
 *   fit       ||K(g) C_s - I||_2, C_s the meshless solve's compliance: the
 *             same against the solve the law was fitted to;
 *   solve     ||C_s^-1 C - I||_2: the meshless solve's own force error
 *             against CalculiX (the discretisation);
 *   levels    ||C_k^-1 C - I||_2 for each coarser CalculiX level k: how
 *             well the reference itself is resolved;
 *
 * and each site's distance from the nearest site of the fitted grid; then
 * a second table of the compliances along the normal, the mean tangential
 * one and the trace, of every CalculiX level (the coarser as given, the
 * finest last), the meshless solve and the law.  The site points of the
 * data and of the meshless fit must agree to 1e-6 mm (exit 1 otherwise).
 * --assert PCT fails (exit 1) unless the law is within PCT % at every site.
 * Exit 2 on bad usage or input.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/context.h"
#include "fitting/region_fit.h"
#include "scene/scene.h"
#include "solvers/solver.h"
#include "tfit.h"

#define MAX_SITES 8
#define MAX_LEVELS 8

/* One CalculiX level: per site (a, b), its surface point and its
 * compliance (scene frame, row-major: C[3 i + j] the displacement along i
 * per unit force along j). */
typedef struct ccx_level {
    const char *path;
    int n;
    double ab[2 * MAX_SITES], x[3 * MAX_SITES], C[9 * MAX_SITES];
} ccx_level;

static int read_level(const char *path, ccx_level *lv)
{
    FILE *f = fopen(path, "r");
    char line[1024];
    int seen[MAX_SITES] = {0}, row = 1;
    *lv = (ccx_level){.path = path};
    if (f == NULL) {
        fprintf(stderr, "%s: cannot be opened\n", path);
        return -1;
    }
    if (fgets(line, sizeof line, f) == NULL || strcmp(line, "site,a,b,x,y,z,case,dx,dy,dz\n") != 0) {
        fprintf(stderr, "%s:1: not a region_dat.awk table (site,a,b,x,y,z,case,dx,dy,dz)\n", path);
        fclose(f);
        return -1;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        int k;
        double v[8];
        char c[8];
        ++row;
        if (sscanf(line, "%d,%lf,%lf,%lf,%lf,%lf,f%1[xyz],%lf,%lf,%lf", &k, &v[0], &v[1], &v[2],
                   &v[3], &v[4], c, &v[5], &v[6], &v[7]) != 10 ||
            k < 1 || k > MAX_SITES) {
            fprintf(stderr, "%s:%d: not site,a,b,x,y,z,f<x>,dx,dy,dz with site 1..%d\n", path,
                    row, MAX_SITES);
            fclose(f);
            return -1;
        }
        int j = c[0] - 'x', s = k - 1;
        memcpy(lv->ab + 2 * s, v, 2 * sizeof *v);
        memcpy(lv->x + 3 * s, v + 2, 3 * sizeof *v);
        for (int i = 0; i < 3; ++i) {
            lv->C[9 * s + 3 * i + j] = v[5 + i];
        }
        seen[s] |= 1 << j;
        lv->n = k > lv->n ? k : lv->n;
    }
    fclose(f);
    for (int s = 0; s < lv->n; ++s) {
        if (seen[s] != 7) {
            fprintf(stderr, "%s: site %d lacks a case of fx, fy, fz\n", path, s + 1);
            return -1;
        }
    }
    return lv->n > 0 ? 0 : -1;
}

/* R C R^T: a scene-frame compliance in the chart frame (R's rows e1, e2, n). */
static void to_chart(const double R[9], const double C[9], double out[9])
{
    double t[9];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            t[3 * i + j] = R[3 * i] * C[j] + R[3 * i + 1] * C[3 + j] + R[3 * i + 2] * C[6 + j];
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out[3 * i + j] = t[3 * i] * R[3 * j] + t[3 * i + 1] * R[3 * j + 1] + t[3 * i + 2] * R[3 * j + 2];
        }
    }
}

/* ||A B - I||_2 */
static double off_identity(const double A[9], const double B[9])
{
    double M[9];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            M[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j] - (i == j);
        }
    }
    return tf_mat3_norm2(M);
}

/* ||C - C^T||_F / ||C||_F */
static double asymmetry(const double C[9])
{
    double d = 0, n = 0;
    for (int k = 0; k < 9; ++k) {
        double t = C[k] - C[3 * (k % 3) + k / 3];
        d += t * t;
        n += C[k] * C[k];
    }
    return sqrt(d / n);
}

typedef struct options {
    const char *scene, *csv[MAX_LEVELS], *sets[16];
    int n_csv;
    size_t n_sets;
    double bound; /* %, < 0: none */
} options;

static int parse(int argc, char **argv, options *o)
{
    *o = (options){.bound = -1};
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--assert") == 0 && i + 1 < argc) {
            char *end;
            o->bound = strtod(argv[++i], &end);
            if (*end || !(o->bound > 0)) {
                return -1;
            }
        } else if (strchr(argv[i], '=') != NULL && o->n_sets < 16) {
            o->sets[o->n_sets++] = argv[i];
        } else if (o->scene == NULL) {
            o->scene = argv[i];
        } else if (o->n_csv < MAX_LEVELS) {
            o->csv[o->n_csv++] = argv[i];
        } else {
            return -1;
        }
    }
    return o->scene && o->n_csv > 0 ? 0 : -1;
}

/* The distance from (a, b) to the nearest site of lv's grid. */
static double nearest_fitted(const tf_region_result *res, const tf_region_level *lv, double a,
                             double b)
{
    double best = INFINITY;
    for (size_t k = 0; k < (size_t)lv->nx * lv->ny; ++k) {
        const double *g = res->sites.ab + 2 * lv->train[k];
        best = fmin(best, hypot(g[0] - a, g[1] - b));
    }
    return best;
}

/* Of a chart-frame compliance: part 0 along the normal, 1 the mean of the
 * two tangential ones, 2 the trace. */
static double component(const double C[9], int part)
{
    return part == 0 ? C[8] : part == 1 ? 0.5 * (C[0] + C[4]) : C[0] + C[4] + C[8];
}

/* A path's last component. */
static const char *base(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* The table and the largest law error over the sites. */
static double compare(const options *o, const ccx_level *lv, const tf_region_chart *chart,
                      const tf_region_result *res, const tf_region_sites *ms)
{
    const tf_region_level *last = &res->level[res->n_levels - 1];
    double worst = 0;
    printf("| site | (a, b) mm | nearest fitted site | law vs CalculiX | fit: law vs solve | "
           "solve vs CalculiX |");
    for (int k = 1; k < o->n_csv; ++k) {
        printf(" CalculiX %s vs finest |", base(lv[k].path));
    }
    printf("\n|---|---|---|---|---|---|");
    for (int k = 1; k < o->n_csv; ++k) {
        printf("---|");
    }
    printf("\n");
    for (int s = 0; s < lv[0].n; ++s) {
        const double a = lv[0].ab[2 * s], b = lv[0].ab[2 * s + 1];
        double C[9], K[9], Cs_inv[9];
        to_chart(chart->R, lv[0].C + 9 * s, C);
        tf_region_law_stiffness(&last->law, a, b, K);
        tf_mat3_inverse(ms->C + 9 * s, Cs_inv);
        double e_law = off_identity(K, C);
        worst = fmax(worst, e_law);
        printf("| %d | (%g, %g) | %.2f mm | %.2f %% | %.2f %% | %.2f %% |", s + 1, a, b,
               nearest_fitted(res, last, a, b), 100 * e_law, 100 * off_identity(K, ms->C + 9 * s),
               100 * off_identity(Cs_inv, C));
        for (int k = 1; k < o->n_csv; ++k) {
            double Ck[9], Ck_inv[9];
            to_chart(chart->R, lv[k].C + 9 * s, Ck);
            tf_mat3_inverse(Ck, Ck_inv);
            printf(" %.2f %% |", 100 * off_identity(Ck_inv, C));
        }
        printf("\n");
    }
    /* Which way each is off: the compliance along the chart's normal, the
     * mean of the two tangential ones and the trace (a finite-element
     * solve is too stiff: its compliance rises as the mesh is refined). */
    printf("\n| site | normal compliance (mm/N): CalculiX");
    for (int j = 1; j <= o->n_csv; ++j) { /* the others as given, the finest last */
        printf(" %s%s", j == 1 ? "" : "/ ", base(lv[j % o->n_csv].path));
    }
    printf(" / meshless solve / law | tangential, the same | trace, the same |\n|---|---|---|---|\n");
    for (int s = 0; s < lv[0].n; ++s) {
        double K[9], Ci[9];
        tf_region_law_stiffness(&last->law, lv[0].ab[2 * s], lv[0].ab[2 * s + 1], K);
        tf_mat3_inverse(K, Ci);
        printf("| %d |", s + 1);
        for (int part = 0; part < 3; ++part) {
            for (int j = 1; j <= o->n_csv; ++j) {
                double C[9];
                to_chart(chart->R, lv[j % o->n_csv].C + 9 * s, C);
                printf(" %.4g /", component(C, part));
            }
            printf(" %.4g / %.4g |", component(ms->C + 9 * s, part), component(Ci, part));
        }
        printf("\n");
    }
    return worst;
}

/* The levels' sites agree with the finest's to 1e-9 mm. */
static int same_sites(const ccx_level *lv, int n)
{
    for (int k = 1; k < n; ++k) {
        int bad = lv[k].n != lv[0].n;
        for (int i = 0; i < 2 * lv[0].n && !bad; ++i) {
            bad = fabs(lv[k].ab[i] - lv[0].ab[i]) > 1e-9;
        }
        if (bad) {
            fprintf(stderr, "%s: its sites are not those of %s\n", lv[k].path, lv[0].path);
            return -1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    options o;
    ccx_level lv[MAX_LEVELS];
    if (parse(argc, argv, &o) != 0) {
        fprintf(stderr, "usage: region_calculix SCENE FINEST.csv [COARSER.csv ...] [--assert PCT] "
                        "[KEY=VALUE ...]\n");
        return 2;
    }
    for (int k = 0; k < o.n_csv; ++k) {
        if (read_level(o.csv[k], &lv[k]) != 0) {
            return 2;
        }
    }
    if (same_sites(lv, o.n_csv) != 0) {
        return 2;
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *sc = tf_scene_load(&ctx, o.scene, o.sets, o.n_sets);
    if (sc == NULL) {
        fprintf(stderr, "%s\n", ctx.err);
        return 2;
    }
    tf_problem *p = &sc->problem;
    if (p->n_contacts == 0 || p->contacts[0].region.kind == TF_CONTACT_REGION_NONE) {
        fprintf(stderr, "%s: contact 0 is not a region\n", o.scene);
        return 2;
    }
    ctx.level = TF_LOG_WARN;
    const tf_contact_region *r = &p->contacts[0].region;
    double t0 = omp_get_wtime();
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    tf_region_targets tg = tf_region_targets_default();
    tg.max_rank = TFIT_REGION_MAX_RANK; /* tissuefit fit's rule (region_models.c) */
    tg.coupling = INFINITY;
    tf_region_result res;
    tf_region_sites ms;
    if (sv == NULL || tf_region_fit(&ctx, sv, p, 0, &tg, &res) != 0 ||
        tf_region_sites_solve(&ctx, sv, p, r, lv[0].ab, (size_t)lv[0].n, NULL, 0, &ms) != 0) {
        fprintf(stderr, "%s\n", ctx.err);
        return 1;
    }
    const tf_region_level *last = &res.level[res.n_levels - 1];
    printf("%s: %zu nodes; the law of tissuefit fit's rule: %u x %u sites, %.3g mm apart "
           "(%s); held out at its %zu cell centres: %.2f %% of the envelope radius; %.0f s\n\n",
           p->name, p->cloud.n, last->nx, last->ny, last->h[0], res.why, last->n_check,
           100 * last->force, omp_get_wtime() - t0);
    double gap = 0;
    for (int s = 0; s < lv[0].n; ++s) { /* the deck's site points are the meshless fit's */
        gap = fmax(gap, sqrt((ms.x[3 * s] - lv[0].x[3 * s]) * (ms.x[3 * s] - lv[0].x[3 * s]) +
                             (ms.x[3 * s + 1] - lv[0].x[3 * s + 1]) * (ms.x[3 * s + 1] - lv[0].x[3 * s + 1]) +
                             (ms.x[3 * s + 2] - lv[0].x[3 * s + 2]) * (ms.x[3 * s + 2] - lv[0].x[3 * s + 2])));
    }
    double worst = compare(&o, lv, &r->chart, &res, &ms), asym = 0;
    for (int s = 0; s < lv[0].n; ++s) {
        asym = fmax(asym, asymmetry(lv[0].C + 9 * s));
    }
    printf("\nforce errors: ||A C - I||_2 over the envelope's sphere, a fraction of its radius; "
           "CalculiX's compliances symmetric to %.1e (Maxwell-Betti), its site points %.1e mm "
           "from the meshless fit's\n", asym, gap);
    int bad = o.bound > 0 && !(100 * worst <= o.bound);
    if (o.bound > 0) {
        printf("%s: the law within %.2f %% of CalculiX at every site (bound %g %%)\n",
               bad ? "FAILED" : "ok", 100 * worst, o.bound);
    }
    if (gap > 1e-6) {
        printf("FAILED: the data's site points are %.3g mm from the meshless fit's (stale data?)\n", gap);
        bad = 1;
    }
    tf_region_sites_free(&ms);
    tf_region_result_free(&res);
    tf_solver_destroy(sv);
    tf_scene_free(sc);
    return bad;
}
