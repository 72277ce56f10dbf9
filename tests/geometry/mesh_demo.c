/*
 * mesh_demo.c — an organ surface to a node cloud with tetrahedral cells,
 * measured: reads and checks the surface, meshes its volume, writes a .vtu
 * for ParaView, and prints counts, volumes, times and the inside test.
 *
 *   mesh_demo FILE --spacing H [--scale S] [--centre] [--rotate AX AY AZ DEG]
 *             [--translate X Y Z] [--grade X Y Z H0 R0 R1] [--vtu OUT.vtu]
 *             [--check] [--row LABEL] [--repeat N]
 *
 * --check exits 1 unless the cells' volume is within 1 % of the enclosed
 * volume and every interior node is inside the surface; --row prints the
 * numbers again as a markdown table row (docs/geometry.md); --repeat
 * meshes N times, requires the same bits each time and reports the median
 * time.  Exit 2: bad arguments or mesh file.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "geometry/surface_prepare.h"
#include "geometry/tetmesh_check.h"
#include "geometry/tetmesh_vtu.h"
#include "geometry/volume_mesh.h"

typedef struct args {
    const char *file, *vtu;
    tf_transform transform;
    tf_mesh_options mesh;
    int check;
    const char *row; /* label of a markdown table row to print, or NULL */
    int repeat;      /* mesh this many times (1 .. 15) */
} args;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int numbers(int argc, char **argv, int *i, double *x, int n)
{
    for (int k = 0; k < n; ++k) {
        char *end;
        if (++*i >= argc) {
            return -1;
        }
        x[k] = strtod(argv[*i], &end);
        if (*end != '\0' || end == argv[*i]) {
            return -1;
        }
    }
    return 0;
}

static int parse(int argc, char **argv, args *a)
{
    memset(a, 0, sizeof *a);
    a->transform = tf_transform_identity();
    a->repeat = 1;
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        double g[6];
        int bad = 0;
        if (strcmp(o, "--spacing") == 0) {
            bad = numbers(argc, argv, &i, &a->mesh.spacing, 1);
        } else if (strcmp(o, "--scale") == 0) {
            bad = numbers(argc, argv, &i, &a->transform.scale, 1);
        } else if (strcmp(o, "--centre") == 0) {
            a->transform.centre = 1;
        } else if (strcmp(o, "--rotate") == 0) {
            bad = numbers(argc, argv, &i, g, 4);
            memcpy(a->transform.axis, g, sizeof a->transform.axis);
            a->transform.angle_deg = g[3];
        } else if (strcmp(o, "--translate") == 0) {
            bad = numbers(argc, argv, &i, a->transform.translate, 3);
        } else if (strcmp(o, "--grade") == 0) {
            bad = numbers(argc, argv, &i, g, 6);
            a->mesh.graded = 1;
            memcpy(a->mesh.grade_at, g, sizeof a->mesh.grade_at);
            a->mesh.grade_spacing = g[3];
            a->mesh.grade_radius = g[4];
            a->mesh.grade_ramp = g[5];
        } else if (strcmp(o, "--vtu") == 0 && i + 1 < argc) {
            a->vtu = argv[++i];
        } else if (strcmp(o, "--row") == 0 && i + 1 < argc) {
            a->row = argv[++i];
        } else if (strcmp(o, "--repeat") == 0) {
            bad = numbers(argc, argv, &i, g, 1) || !(g[0] >= 1 && g[0] <= 15);
            a->repeat = bad ? 1 : (int)g[0];
        } else if (strcmp(o, "--check") == 0) {
            a->check = 1;
        } else if (o[0] != '-' && a->file == NULL) {
            a->file = o;
        } else {
            fprintf(stderr, "mesh_demo: unknown argument '%s'\n", o);
            return -1;
        }
        if (bad) {
            fprintf(stderr, "mesh_demo: %s: missing or bad number\n", o);
            return -1;
        }
    }
    if (a->file == NULL || a->mesh.spacing == 0) {
        fprintf(stderr, "usage: mesh_demo FILE --spacing H [--scale S] [--centre] "
                        "[--rotate AX AY AZ DEG] [--translate X Y Z] [--grade X Y Z H0 R0 R1] "
                        "[--vtu OUT.vtu] [--check] [--row LABEL] [--repeat N]\n");
        return -1;
    }
    return 0;
}

static void print_mesh(const args *a, const tf_surface *s, const tf_tetmesh *t, double t_load,
                       double t_mesh)
{
    double err = (t->cells_volume - t->enclosed_volume) / t->enclosed_volume;
    printf("%s: spacing %g mm%s\n", a->file, a->mesh.spacing, a->mesh.graded ? " (graded)" : "");
    printf("  surface   %zu vertices, %zu triangles, enclosed volume %.6g mm^3 "
           "(read+check %.2f s)\n",
           s->nv, s->nt, t->enclosed_volume, t_load);
    printf("  mesh      %zu nodes (%zu surface + %zu interior), %zu tetrahedra (%.2f s%s)\n",
           t->nn, t->nsurf, t->nn - t->nsurf, t->ntet, t_mesh,
           a->repeat > 1 ? ", median of the runs" : "");
    printf("  cells     volume %.6g mm^3, relative to the enclosed volume %+.2e\n",
           t->cells_volume, err);
}

static int same_mesh(const tf_tetmesh *a, const tf_tetmesh *b)
{
    return a->nn == b->nn && a->ntet == b->ntet &&
           memcmp(a->xyz, b->xyz, 3 * a->nn * sizeof *a->xyz) == 0 &&
           memcmp(a->tet, b->tet, 4 * a->ntet * sizeof *a->tet) == 0;
}

static int by_value(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return a < b ? -1 : a > b;
}

/* Meshes a.repeat times (each run must give the same bits); *seconds is
 * the median time. */
static int mesh_timed(const args *a, const tf_surface *s, tf_tetmesh *t, double *seconds,
                      tf_geom_msg *m)
{
    double times[16];
    int rc = TF_GEOM_OK;
    for (int k = 0; k < a->repeat && rc == TF_GEOM_OK; ++k) {
        tf_tetmesh again;
        double t0 = now();
        rc = tf_volume_mesh(s, &a->mesh, k ? &again : t, m);
        times[k] = now() - t0;
        if (k && rc == TF_GEOM_OK) {
            if (!same_mesh(t, &again)) {
                rc = tf_geom_fail(m, TF_GEOM_FAILED, "run %d gave a different mesh", k + 1);
            }
            tf_tetmesh_free(&again);
        }
    }
    if (rc != TF_GEOM_OK) {
        tf_tetmesh_free(t); /* emptied by a failed first run, the first mesh after that */
    }
    qsort(times, (size_t)a->repeat, sizeof *times, by_value);
    *seconds = times[a->repeat / 2];
    return rc;
}

static int report(const args *a, const tf_surface *s, const tf_tetmesh *t, double t_load,
                  double t_mesh)
{
    print_mesh(a, s, t, t_load, t_mesh);
    double t0 = now();
    tf_inside_report in;
    tf_tetmesh_inside(t, s, &in);
    printf("  inside    %zu of %zu interior nodes outside (winding number <= 1/2); smallest "
           "winding number %.6f (%.2f s)\n",
           in.outside, in.tested, in.min_winding, now() - t0);
    double err = (t->cells_volume - t->enclosed_volume) / t->enclosed_volume;
    if (a->row) {
        printf("| %s | %g | %zu | %zu | %zu | %zu | %.6g | %+.1e | %zu | %.2f | %.2f |\n", a->row,
               a->mesh.spacing, t->nsurf, t->nn - t->nsurf, t->nn, t->ntet, t->enclosed_volume,
               err, in.outside, t_load, t_mesh);
    }
    if (a->check && (!(err <= 0.01 && err >= -0.01) || in.outside > 0)) {
        fprintf(stderr, "mesh_demo: %s: FAILED: volume error %.2e, %zu nodes outside\n", a->file,
                err, in.outside);
        return TF_GEOM_FAILED;
    }
    return TF_GEOM_OK;
}

int main(int argc, char **argv)
{
    args a;
    if (parse(argc, argv, &a) != 0) {
        return 2;
    }
    tf_geom_msg m;
    tf_surface s;
    tf_tetmesh t;
    double t0 = now(), t_mesh = 0;
    int rc = tf_surface_load(a.file, &a.transform, &s, &m);
    double t_load = now() - t0;
    if (rc == TF_GEOM_OK) {
        fputs(m.notes, stdout);
        rc = mesh_timed(&a, &s, &t, &t_mesh, &m);
    }
    if (rc != TF_GEOM_OK) {
        fprintf(stderr, "mesh_demo: %s: %s\n", a.file, m.error);
        tf_surface_free(&s);
        return rc;
    }
    rc = report(&a, &s, &t, t_load, t_mesh);
    if (a.vtu && tf_tetmesh_save_vtu(a.vtu, &t, &m) != TF_GEOM_OK) {
        fprintf(stderr, "mesh_demo: %s\n", m.error);
        rc = TF_GEOM_FAILED;
    }
    tf_tetmesh_free(&t);
    tf_surface_free(&s);
    return rc;
}
