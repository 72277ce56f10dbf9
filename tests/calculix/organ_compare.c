/*
 * organ_compare.c — an organ's displacements against the CalculiX
 * reference (docs/validation.md §14, and §18 for material regions).
 *
 *   organ_compare REFERENCE.csv SCENE [BOUND[,L2]] [--set KEY=VALUE]...
 *                                                 the meshless solve
 *   organ_compare REFERENCE.csv --csv LEVEL.csv    a coarser CalculiX level
 *   organ_compare --signal OVER BESIDE OVER.csv BESIDE.csv [OVER.csv BESIDE.csv]...
 *                 [--bound B] [--bound-u U]        a stiff region's signal
 *
 * REFERENCE.csv and LEVEL.csv come from organ_dat.awk (vertex,x,y,z,case,
 * ux,uy,uz,contact for the unit forces fx, fy, fz at the scene's output
 * vertices and its contact vertex).  The meshless side solves the scene's three unit
 * forces at its first contact site.  For each case it prints
 *
 *   contact: |u - u_ref| / |u_ref| at the contact vertex;
 *   outputs: the relative L2 error over the output vertices,
 *            sqrt(sum |u - u_ref|^2 / sum |u_ref|^2);
 *   worst:   max over the vertices of |u - u_ref|, over max |u_ref|.
 *
 * With BOUND (a fraction, or CONTACT,L2: two), exits 1 when the contact or
 * the outputs' error exceeds it; the worst vertex is reported, not bounded: it sits
 * at the edge of the loaded patch, where the traction jumps and both
 * discretisations differ most (docs/validation.md §14).
 * A markdown row per case goes to stdout.  Exit 2 on bad input.
 *
 * --signal: what a probe feels of a stiff material region (an inclusion).
 * OVER and BESIDE are two scenes of the same body pressed at two sites
 * (over the inclusion and away from it), each CSV pair a CalculiX level of
 * them, finest first.  At each site the contact vertex's compliance
 * C (3 x 3, mm/N: column c the displacement under 1 N along c) gives the
 * stiffness along the site's outward normal n (the area-weighted normal of
 * its patch), k = 1 / (n . C n) N/mm: pressed to the same depth d along n,
 * the probe feels F = k d, so the difference it feels between the sites is
 * dk = k_over - k_beside per mm.  A row per CalculiX level and one for the
 * meshless solves; with --bound, exits 1 when the meshless dk is off the
 * finest level's by more than B (relative); then both meshless solves
 * against the finest level as above (--bound-u bounds OVER's: the surface
 * over the inclusion; BESIDE's is reported).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "problem/mesh_geometry.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define MAX_ROWS 100000

typedef struct rows {
    size_t n;
    long vertex[MAX_ROWS];
    int kase[MAX_ROWS]; /* 0 fx, 1 fy, 2 fz */
    int contact[MAX_ROWS];
    double x[MAX_ROWS][3], u[MAX_ROWS][3];
} rows;

static int read_rows(const char *path, rows *r)
{
    FILE *f = fopen(path, "r");
    char line[512], name[8];
    if (f == NULL || fgets(line, sizeof line, f) == NULL ||
        strcmp(line, "vertex,x,y,z,case,ux,uy,uz,contact\n") != 0) {
        fprintf(stderr, "organ_compare: %s: not an organ_dat.awk CSV\n", path);
        if (f) {
            fclose(f);
        }
        return -1;
    }
    r->n = 0;
    while (fgets(line, sizeof line, f) != NULL && r->n < MAX_ROWS) {
        size_t k = r->n;
        if (sscanf(line, "%ld,%lf,%lf,%lf,%7[^,],%lf,%lf,%lf,%d", &r->vertex[k], &r->x[k][0],
                   &r->x[k][1], &r->x[k][2], name, &r->u[k][0], &r->u[k][1], &r->u[k][2],
                   &r->contact[k]) != 9 ||
            strlen(name) != 2 || name[0] != 'f' || name[1] < 'x' || name[1] > 'z') {
            fprintf(stderr, "organ_compare: %s:%zu: bad row\n", path, k + 2);
            fclose(f);
            return -1;
        }
        r->kase[k] = name[1] - 'x';
        r->n++;
    }
    fclose(f);
    return r->n > 0 ? 0 : -1;
}

/* Row of (vertex, case) in r, or -1. */
static long find(const rows *r, long vertex, int kase)
{
    for (size_t k = 0; k < r->n; ++k) {
        if (r->vertex[k] == vertex && r->kase[k] == kase) {
            return (long)k;
        }
    }
    return -1;
}

static double norm3(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* A box scene's node at x (to 1e-9 mm), or -1. */
static long node_at(const tf_problem *p, const double *x)
{
    for (size_t i = 0; i < p->cloud.n; ++i) {
        const double *y = p->cloud.xyz + 3 * i;
        if (fabs(x[0] - y[0]) <= 1e-9 && fabs(x[1] - y[1]) <= 1e-9 && fabs(x[2] - y[2]) <= 1e-9) {
            return (long)i;
        }
    }
    return -1;
}

static int patch_normal(const tf_problem *p, double n[3]);

/* The meshless displacements at the reference's rows, into cand; with
 * normal, the outward unit normal of the scene's first contact patch. */
static int meshless(const char *scene, const char *const *sets, size_t n_sets, const rows *ref,
                    rows *cand, double *normal)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = tf_scene_load(&ctx, scene, sets, n_sets);
    if (s == NULL) {
        fprintf(stderr, "organ_compare: %s\n", ctx.err);
        return -1;
    }
    const tf_problem *p = &s->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    size_t n3 = 3 * p->cloud.n;
    double *u = malloc(3 * n3 * sizeof *u);
    const double f[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    int rc = sv && u && tf_solver_solve(sv, 0, f, 3, NULL, u) == 0 ? 0 : -1;
    if (rc != 0) {
        fprintf(stderr, "organ_compare: %s: %s\n", scene, ctx.err);
    } else if (normal && patch_normal(p, normal) != 0) {
        fprintf(stderr, "organ_compare: %s: its contact site has no surface or face patch\n",
                scene);
        rc = -1;
    }
    if (rc == 0 && m != NULL) { /* the cloud, for a convergence table */
        fprintf(stderr, "organ_compare: %s: %zu nodes, %zu on the surface (%zu the file's)\n",
                scene, p->cloud.n, p->cloud.n_surface, m->file_nv);
    }
    *cand = *ref;
    for (size_t k = 0; rc == 0 && k < ref->n; ++k) {
        /* an organ's vertex index in its file; a box's node at the row's
         * position (whatever the grid) */
        long node = m ? tf_problem_mesh_vertex_node(m, ref->vertex[k]) : node_at(p, ref->x[k]);
        if (node < 0) {
            fprintf(stderr, "organ_compare: vertex %ld (%g, %g, %g) is not in %s\n", ref->vertex[k],
                    ref->x[k][0], ref->x[k][1], ref->x[k][2], scene);
            rc = -1;
            break;
        }
        memcpy(cand->u[k], u + (size_t)ref->kase[k] * n3 + 3 * (size_t)node, sizeof cand->u[k]);
    }
    for (size_t k = 0; rc == 0 && k < ref->n; ++k) {
        uint32_t contact = p->contacts[0].node;
        if (ref->contact[k] && (m ? ref->vertex[k] != m->tm.source[contact]
                                  : node_at(p, ref->x[k]) != (long)contact)) {
            fprintf(stderr, "organ_compare: the reference's contact vertex %ld is not %s's\n",
                    ref->vertex[k], scene);
            rc = -1;
        }
    }
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
    return rc;
}

/* The table of cand against ref (a row per case); cand's rows are ref's in
 * order (a meshless solve) or found by vertex (level, another CalculiX
 * level).  1 when the contact and L2 errors are within bound, 0 when not,
 * -1 when cand lacks a vertex. */
static int compare(const rows *ref, const rows *cand, int level, double bound, double bound_l2)
{
    int ok = 1;
    printf("| case | |u_ref| at the contact vertex (mm/N) | contact error | outputs: L2 error | "
           "worst vertex: max |du| / max |u_ref| |\n|---|---:|---:|---:|---:|\n");
    for (int c = 0; c < 3; ++c) {
        double top = 0, worst = 0, uc = 0, ec = NAN, e2 = 0, r2 = 0;
        for (size_t k = 0; k < ref->n; ++k) {
            if (ref->kase[k] != c) {
                continue;
            }
            long j = level ? find(cand, ref->vertex[k], c) : (long)k;
            if (j < 0) {
                fprintf(stderr, "organ_compare: the level lacks vertex %ld\n", ref->vertex[k]);
                return -1;
            }
            double d[3] = {cand->u[j][0] - ref->u[k][0], cand->u[j][1] - ref->u[k][1],
                           cand->u[j][2] - ref->u[k][2]};
            top = fmax(top, norm3(ref->u[k]));
            worst = fmax(worst, norm3(d));
            e2 += d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            r2 += ref->u[k][0] * ref->u[k][0] + ref->u[k][1] * ref->u[k][1] +
                  ref->u[k][2] * ref->u[k][2];
            if (ref->contact[k]) {
                uc = norm3(ref->u[k]);
                ec = norm3(d) / uc;
            }
        }
        double l2 = sqrt(e2 / r2);
        printf("| f%c | %.4g | %.3g %% | %.3g %% | %.3g %% |\n", 'x' + c, uc, 100 * ec, 100 * l2,
               100 * worst / top);
        ok &= ec <= bound && l2 <= bound_l2;
    }
    if (!ok) {
        printf("beyond the bound of %g %% (contact), %g %% (L2)\n", 100 * bound, 100 * bound_l2);
    }
    return ok;
}

/* The outward unit normal of a scene's first contact patch (a box's face,
 * or the area-weighted normal of an organ's patch triangles). */
static int patch_normal(const tf_problem *p, double n[3])
{
    const tf_patch *pt = p->n_contacts ? &p->contacts[0].patch : NULL;
    const double *x = p->cloud.xyz;
    n[0] = n[1] = n[2] = 0;
    if (pt && pt->shape == TF_PATCH_RECT) {
        n[tf_face_axis(pt->face)] = tf_face_is_max(pt->face) ? 1 : -1;
    }
    for (size_t t = 0; pt && pt->shape == TF_PATCH_SURFACE && t < pt->n_tri; ++t) {
        const double *a = x + 3 * (size_t)pt->tri[3 * t], *b = x + 3 * (size_t)pt->tri[3 * t + 1],
                     *c = x + 3 * (size_t)pt->tri[3 * t + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        n[0] += u[1] * v[2] - u[2] * v[1];
        n[1] += u[2] * v[0] - u[0] * v[2];
        n[2] += u[0] * v[1] - u[1] * v[0];
    }
    double len = norm3(n);
    for (int a = 0; a < 3 && len > 0; ++a) {
        n[a] /= len;
    }
    return len > 0 ? 0 : -1;
}

/* Stiffness along n at the contact vertex of rows r: 1 / (n . C n). */
static double normal_stiffness(const rows *r, const double n[3])
{
    double cn = 0;
    int found = 0;
    for (size_t k = 0; k < r->n; ++k) {
        if (r->contact[k]) { /* column kase of C, times n[kase], dotted with n */
            cn += n[r->kase[k]] * (n[0] * r->u[k][0] + n[1] * r->u[k][1] + n[2] * r->u[k][2]);
            found |= 1 << r->kase[k];
        }
    }
    return found == 7 && cn > 0 ? 1 / cn : NAN;
}

/* One row of the signal table: the two sites' stiffness and their
 * difference, against the finest level's difference *ref (set by the
 * first row).  Returns dk. */
static double signal_row(const char *name, const rows *over, const rows *beside,
                         const double n[2][3], double *ref)
{
    double k0 = normal_stiffness(over, n[0]), k1 = normal_stiffness(beside, n[1]);
    double dk = k0 - k1;
    if (isnan(*ref)) {
        *ref = dk;
    }
    printf("| %s | %.5g | %.5g | %.5g | %.3g %% | %+.3g %% |\n", name, k0, k1, dk, 100 * dk / k1,
           100 * (dk - *ref) / *ref);
    return dk;
}

static int signal(int argc, char **argv)
{
    static rows fin[2], lev[2], cand[2];
    double bound = INFINITY, bound_u = INFINITY, n[2][3], ref = NAN;
    while (argc >= 2 && strncmp(argv[argc - 2], "--bound", 7) == 0) {
        *(strcmp(argv[argc - 2], "--bound-u") == 0 ? &bound_u : &bound) = atof(argv[argc - 1]);
        argc -= 2;
    }
    if (argc < 6 || (argc - 4) % 2 != 0) {
        fprintf(stderr, "usage: organ_compare --signal OVER BESIDE OVER.csv BESIDE.csv "
                        "[OVER.csv BESIDE.csv]... [--bound B] [--bound-u U]\n");
        return 2;
    }
    /* the finest level, and the meshless solves at its rows */
    for (int site = 0; site < 2; ++site) {
        if (read_rows(argv[4 + site], &fin[site]) != 0 ||
            meshless(argv[2 + site], NULL, 0, &fin[site], &cand[site], n[site]) != 0) {
            return 2;
        }
    }
    printf("| solve | k over (N/mm) | k beside (N/mm) | dk (N/mm) | dk / k beside | dk vs finest |\n"
           "|---|---:|---:|---:|---:|---:|\n");
    for (int i = 4; i < argc; i += 2) {
        rows *r = i == 4 ? fin : lev;
        if ((i > 4 && (read_rows(argv[i], &r[0]) != 0 || read_rows(argv[i + 1], &r[1]) != 0)) ||
            !isfinite(normal_stiffness(&r[0], n[0])) || !isfinite(normal_stiffness(&r[1], n[1]))) {
            fprintf(stderr, "organ_compare: %s, %s: no contact compliance\n", argv[i], argv[i + 1]);
            return 2;
        }
        signal_row(argv[i], &r[0], &r[1], n, &ref);
    }
    double dk = signal_row("meshless", &cand[0], &cand[1], n, &ref);
    int ok = fabs(dk - ref) <= bound * fabs(ref);
    if (!ok) {
        printf("the meshless dk is beyond %g %% of the finest level's\n", 100 * bound);
    }
    for (int site = 0; site < 2; ++site) {
        printf("\nmeshless %s against the finest level:\n\n", argv[2 + site]);
        int c = compare(&fin[site], &cand[site], 0, site == 0 ? bound_u : INFINITY,
                        site == 0 ? bound_u : INFINITY);
        if (c < 0) {
            return 2;
        }
        ok &= c;
    }
    return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--signal") == 0) {
        return signal(argc, argv);
    }
    static rows ref, cand;
    const char *sets[32];
    size_t n_sets = 0;
    int args = argc;
    while (args >= 5 && strcmp(argv[args - 2], "--set") == 0 && n_sets < 32) {
        sets[n_sets++] = argv[args - 1];
        args -= 2;
    }
    if (args < 3 || args > 4 || read_rows(argv[1], &ref) != 0) {
        fprintf(stderr, "usage: organ_compare REFERENCE.csv SCENE [BOUND[,L2]] [--set K=V]... | "
                        "REFERENCE.csv --csv LEVEL.csv\n");
        return 2;
    }
    int level = strcmp(argv[2], "--csv") == 0;
    if (level ? args != 4 || read_rows(argv[3], &cand) != 0
              : meshless(argv[2], sets, n_sets, &ref, &cand, NULL) != 0) {
        return 2;
    }
    /* BOUND, or CONTACT,L2 */
    const char *b = !level && args == 4 ? argv[3] : NULL, *comma = b ? strchr(b, ',') : NULL;
    double bound = b ? atof(b) : INFINITY, bound_l2 = comma ? atof(comma + 1) : bound;
    int ok = compare(&ref, &cand, level, bound, bound_l2);
    return ok < 0 ? 2 : ok ? 0 : 1;
}
