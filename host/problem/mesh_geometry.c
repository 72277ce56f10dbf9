/*
 * mesh_geometry.c — an organ read, filled, checked (mesh_geometry.h).
 */
#include "problem/mesh_geometry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file_crc.h"
#include "geometry/surface_prepare.h"
#include "geometry/surface_read.h"
#include "geometry/surface_refine.h"
#include "geometry/tetmesh_check.h"

/* Read, clean, keep the file-frame coordinates, place, check (the steps of
 * tf_surface_load with a copy taken before the transform). */
static int load_surface(tf_mesh_geometry *g, tf_surface *s, tf_geom_msg *m)
{
    memset(s, 0, sizeof *s);
    int rc = tf_surface_read(g->path, s, m);
    rc = rc ? rc : tf_surface_clean(s, m);
    if (rc == TF_GEOM_OK) {
        g->file_xyz = malloc((3 * s->nv + 1) * sizeof *g->file_xyz);
        if (g->file_xyz == NULL) {
            rc = tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
        } else {
            memcpy(g->file_xyz, s->xyz, 3 * s->nv * sizeof *g->file_xyz);
        }
    }
    rc = rc ? rc : tf_transform_apply(&g->place, s, m);
    rc = rc ? rc : tf_surface_check_placed(s, m);
    return rc;
}

static double skin_size(const double x[3], const void *arg)
{
    return tf_mesh_size_at(arg, x);
}

/* The file's triangles kept; with refine_skin, the skin split to the
 * node spacing on the file's own planes (surface_refine.h). */
static int skin(tf_mesh_geometry *g, tf_surface *s, tf_geom_msg *m)
{
    g->file_nv = s->nv;
    g->file_nt = s->nt;
    g->file_tri = malloc((3 * s->nt + 1) * sizeof *g->file_tri);
    if (g->file_tri == NULL) {
        return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
    }
    memcpy(g->file_tri, s->tri, 3 * s->nt * sizeof *g->file_tri);
    if (!g->mesh.refine_skin) {
        return TF_GEOM_OK;
    }
    int rc = tf_volume_mesh_check_options(s, &g->mesh, m);
    return rc ? rc
              : tf_surface_refine(s, skin_size, &g->mesh, TF_MESH_SKIN_RATIO,
                                  TF_MESH_MAX_SKIN_VERTICES, m);
}

/* Acceptance 2, on every build. */
static int verify(tf_mesh_geometry *g, const tf_surface *s, tf_geom_msg *m)
{
    const tf_tetmesh *t = &g->tm;
    double rel = fabs(t->cells_volume - t->enclosed_volume) / t->enclosed_volume;
    if (!(rel <= TF_PROBLEM_MESH_VOLUME_TOL)) {
        return tf_geom_fail(m, TF_GEOM_FAILED,
                            "the tetrahedra's volume %g mm^3 differs from the enclosed %g mm^3 "
                            "by %.3g %% (at most %g %%)",
                            t->cells_volume, t->enclosed_volume, 100 * rel,
                            100 * TF_PROBLEM_MESH_VOLUME_TOL);
    }
    tf_inside_report r;
    tf_tetmesh_inside(t, s, &r);
    g->min_winding = r.min_winding;
    if (r.outside > 0) {
        const double *x = t->xyz + 3 * r.worst;
        return tf_geom_fail(m, TF_GEOM_FAILED,
                            "%zu of %zu interior nodes lie outside the surface (winding number "
                            "<= 1/2; the worst %g at (%g, %g, %g) mm)",
                            r.outside, r.tested, r.min_winding, x[0], x[1], x[2]);
    }
    return TF_GEOM_OK;
}

int tf_problem_mesh_build(tf_mesh_geometry *g, tf_geom_msg *m)
{
    tf_surface s;
    m->error[0] = m->notes[0] = '\0';
    memset(&g->tm, 0, sizeof g->tm);
    g->file_xyz = NULL;
    g->file_tri = NULL;
    int rc = load_surface(g, &s, m);
    snprintf(g->notes, sizeof g->notes, "%s", m->notes);
    if (rc == TF_GEOM_OK && tf_file_crc32(g->path, &g->file_crc32) != 0) {
        rc = tf_geom_fail(m, TF_GEOM_BAD_INPUT, "cannot read it again for its checksum");
    }
    rc = rc ? rc : skin(g, &s, m);
    rc = rc ? rc : tf_volume_mesh(&s, &g->mesh, &g->tm, m);
    rc = rc ? rc : verify(g, &s, m);
    tf_surface_free(&s);
    if (rc != TF_GEOM_OK) {
        tf_problem_mesh_free(g);
    }
    return rc;
}

int tf_problem_mesh_cloud(const tf_mesh_geometry *g, tf_cloud *c)
{
    const tf_tetmesh *t = &g->tm;
    memset(c, 0, sizeof *c);
    c->xyz = malloc((3 * t->nn + 1) * sizeof *c->xyz);
    if (c->xyz == NULL) {
        return -1;
    }
    memcpy(c->xyz, t->xyz, 3 * t->nn * sizeof *c->xyz);
    c->n = t->nn;
    c->n_surface = t->nsurf;
    for (int a = 0; a < 3; ++a) {
        c->spacing[a] = g->mesh.spacing;
        c->lo[a] = INFINITY;
        c->hi[a] = -INFINITY;
    }
    for (size_t i = 0; i < t->nn; ++i) {
        for (int a = 0; a < 3; ++a) {
            c->lo[a] = fmin(c->lo[a], t->xyz[3 * i + (size_t)a]);
            c->hi[a] = fmax(c->hi[a], t->xyz[3 * i + (size_t)a]);
        }
    }
    return 0;
}

static double dist2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

uint32_t tf_problem_mesh_nearest_vertex(const tf_mesh_geometry *g, const double p[3])
{
    uint32_t best = 0;
    double d = INFINITY;
    for (size_t i = 0; i < g->file_nv; ++i) {
        double e = dist2(g->tm.xyz + 3 * i, p);
        if (e < d) {
            d = e;
            best = (uint32_t)i;
        }
    }
    return best;
}

long tf_problem_mesh_vertex_node(const tf_mesh_geometry *g, long source)
{
    for (size_t i = 0; i < g->tm.nsurf; ++i) {
        if (g->tm.source[i] == source) {
            return (long)i;
        }
    }
    return -1;
}

static double triangle_area(const double *a, const double *b, const double *c)
{
    double u[3], v[3], n[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* The centroid of the file's triangle that surface triangle k lies on (on
 * a refined skin, a site is the same union of the file's triangles as on
 * the file's own: the load does not change with the resolution). */
static void file_centroid(const tf_mesh_geometry *g, size_t k, double m[3])
{
    const tf_tetmesh *t = &g->tm;
    const size_t *v = t->tri_parent != NULL ? g->file_tri + 3 * t->tri_parent[k] : t->tri + 3 * k;
    const double *a = t->xyz + 3 * v[0], *b = t->xyz + 3 * v[1], *c = t->xyz + 3 * v[2];
    for (int q = 0; q < 3; ++q) {
        m[q] = (a[q] + b[q] + c[q]) / 3;
    }
}

int tf_problem_mesh_site(const tf_mesh_geometry *g, uint32_t centre, double radius, tf_patch *p)
{
    const tf_tetmesh *t = &g->tm;
    const double *o = t->xyz + 3 * (size_t)centre;
    memset(p, 0, sizeof *p);
    p->shape = TF_PATCH_SURFACE;
    p->node = centre;
    p->radius = radius;
    memcpy(p->at, o, sizeof p->at);
    p->tri = malloc((3 * t->ntri + 1) * sizeof *p->tri);
    if (p->tri == NULL) {
        return -1;
    }
    for (size_t k = 0; k < t->ntri; ++k) {
        const size_t *v = t->tri + 3 * k;
        const double *a = t->xyz + 3 * v[0], *b = t->xyz + 3 * v[1], *c = t->xyz + 3 * v[2];
        double m[3];
        file_centroid(g, k, m);
        if (dist2(m, o) <= radius * radius) {
            for (int q = 0; q < 3; ++q) {
                p->tri[3 * p->n_tri + (size_t)q] = (uint32_t)v[q];
            }
            p->n_tri++;
            p->area += triangle_area(a, b, c);
        }
    }
    return p->n_tri > 0 ? 0 : 1;
}
