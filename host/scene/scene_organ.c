/*
 * scene_organ.c — organs in scenes (scene_organ.h).
 */
#include "scene/scene_organ.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "problem/mesh_geometry.h"

#define fail sd_fail

static int finite3(const double *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* The mesh file: as given when absolute, else beside the scene file. */
static int mesh_path(const char *scene, const char *file, char *out, size_t outlen)
{
    const char *slash = strrchr(scene, '/');
    int n = file[0] == '/' || slash == NULL
                ? snprintf(out, outlen, "%s", file)
                : snprintf(out, outlen, "%.*s/%s", (int)(slash - scene), scene, file);
    return n > 0 && (size_t)n < outlen ? 0 : -1;
}

static int placement(const sd_surface *d, tf_transform *t, sd_issue *is)
{
    *t = tf_transform_identity();
    t->scale = d->scale ? *d->scale : 1.0;
    if (!(isfinite(t->scale) && t->scale > 0)) {
        return fail(is, "geometry.surface.scale",
                    "must be a positive number (millimetres per file unit)");
    }
    t->centre = d->centre && *d->centre;
    if (d->rotate) {
        memcpy(t->axis, d->rotate->axis, sizeof t->axis);
        t->angle_deg = d->rotate->angle;
        if (!finite3(t->axis) || !isfinite(t->angle_deg)) {
            return fail(is, "geometry.surface.rotate", "axis and angle must be finite");
        }
        double n2 = t->axis[0] * t->axis[0] + t->axis[1] * t->axis[1] + t->axis[2] * t->axis[2];
        if (!(n2 > 0) || !isfinite(n2)) { /* a zero axis was skipped without a word */
            return fail(is, "geometry.surface.rotate.axis",
                        "[%g, %g, %g] gives no direction: a rotation needs a non-zero axis",
                        t->axis[0], t->axis[1], t->axis[2]);
        }
    }
    if (d->translate) {
        memcpy(t->translate, d->translate, sizeof t->translate);
        if (!finite3(t->translate)) {
            return fail(is, "geometry.surface.translate", "must be finite (mm)");
        }
    }
    return 0;
}

static int mesh_options(const sd_scene *doc, tf_mesh_options *o, sd_issue *is)
{
    const sd_geometry *g = &doc->geometry;
    memset(o, 0, sizeof *o);
    o->spacing = *g->spacing;
    o->refine_skin = g->refine_skin != NULL && *g->refine_skin;
    if (!(isfinite(o->spacing) && o->spacing > 0)) {
        return fail(is, "geometry.spacing", "must be a positive number of mm");
    }
    if (g->refine == NULL) {
        return 0;
    }
    const sd_refine *d = g->refine;
    o->graded = 1;
    o->grade_spacing = d->spacing;
    o->grade_radius = d->radius;
    o->grade_ramp = d->ramp;
    if (d->at) {
        memcpy(o->grade_at, d->at, sizeof o->grade_at);
    } else if (doc->contact_count > 0 && doc->contact[0].site) {
        memcpy(o->grade_at, doc->contact[0].site->point, sizeof o->grade_at);
    } else {
        return fail(is, "geometry.refine",
                    "give at: [x, y, z] (there is no contact site with a point to refine "
                    "towards)");
    }
    return 0;
}

/* The field a geometry message belongs to. */
static const char *field_of(int rc, const char *msg)
{
    if (rc == TF_GEOM_BAD_INPUT && strncmp(msg, "spacing", 7) == 0) {
        return "geometry.spacing";
    }
    if (rc == TF_GEOM_BAD_INPUT && strncmp(msg, "grading", 7) == 0) {
        return "geometry.refine"; /* the geometry layer calls it grading */
    }
    if (rc == TF_GEOM_BAD_INPUT && strncmp(msg, "the refined skin", 16) == 0) {
        return "geometry.refine_skin";
    }
    if (strncmp(msg, "absurd size", 11) == 0) {
        return "geometry.surface.scale";
    }
    return "geometry.surface.file";
}

int sd_organ_geometry(const sd_scene *doc, tf_problem *s, sd_issue *is)
{
    const sd_geometry *g = &doc->geometry;
    if (g->grid || g->grading || g->jitter || g->seed) {
        return fail(is, "geometry",
                    "grid, grading, jitter and seed belong to a box, not to a surface (a "
                    "surface refines towards a point with refine)");
    }
    if (g->spacing == NULL) {
        return fail(is, "geometry",
                    "a surface needs spacing: the interior node spacing in mm");
    }
    tf_mesh_geometry *m = calloc(1, sizeof *m);
    if (m == NULL) {
        return fail(is, "geometry", "out of memory");
    }
    s->geometry.kind = TF_GEOMETRY_MESH;
    s->geometry.as.mesh = m;
    snprintf(m->file, sizeof m->file, "%s", g->surface->file);
    if (mesh_path(s->source, m->file, m->path, sizeof m->path) != 0) {
        return fail(is, "geometry.surface.file", "path too long");
    }
    if (placement(g->surface, &m->place, is) != 0 || mesh_options(doc, &m->mesh, is) != 0) {
        return -1;
    }
    tf_geom_msg msg;
    int rc = tf_problem_mesh_build(m, &msg);
    if (rc != TF_GEOM_OK) {
        return fail(is, field_of(rc, msg.error), "%s: %s", m->path, msg.error);
    }
    if (tf_problem_mesh_cloud(m, &s->cloud) != 0) {
        return fail(is, "geometry", "out of memory");
    }
    return 0;
}

int sd_organ_site(const sd_site *d, const tf_problem *s, const char *path, tf_patch *p,
                  uint32_t *node, sd_issue *is)
{
    const tf_mesh_geometry *m = tf_problem_mesh(s);
    char where[160];
    snprintf(where, sizeof where, "%s.site", path);
    if (m == NULL) {
        return fail(is, where, "a site lies on an organ's surface (geometry.surface); a box "
                                  "takes node and patch");
    }
    if (!finite3(d->point) || !(isfinite(d->radius) && d->radius > 0)) {
        return fail(is, where, "needs a finite point (mm) and a positive radius (mm)");
    }
    *node = tf_problem_mesh_nearest_vertex(m, d->point);
    int rc = tf_problem_mesh_site(m, *node, d->radius, p);
    if (rc < 0) {
        return fail(is, where, "out of memory");
    }
    if (rc > 0) {
        const double *x = m->tm.xyz + 3 * (size_t)*node;
        return fail(is, where,
                    "no surface triangle has its centroid within %g mm of the surface "
                    "vertex nearest the point, %g mm away at (%g, %g, %g) mm: raise the radius",
                    d->radius,
                    sqrt((x[0] - d->point[0]) * (x[0] - d->point[0]) +
                            (x[1] - d->point[1]) * (x[1] - d->point[1]) +
                            (x[2] - d->point[2]) * (x[2] - d->point[2])),
                    x[0], x[1], x[2]);
    }
    return 0;
}

int sd_organ_vertices(const uint32_t *v, size_t n, const tf_problem *s, const char *path,
                      uint32_t *nodes, sd_issue *is)
{
    const tf_mesh_geometry *m = tf_problem_mesh(s);
    if (m == NULL) {
        return fail(is, path, "vertices name an organ's surface vertices (geometry.surface)");
    }
    if (m->mesh.refine_skin) {
        return fail(is, path,
                    "a list of the file's vertices leaves the refined skin's vertices between "
                    "them out (geometry.refine_skin): give the region as a sphere, side or near");
    }
    for (size_t k = 0; k < n; ++k) {
        long i = tf_problem_mesh_vertex_node(m, (long)v[k]);
        if (i < 0) {
            return fail(is, path,
                        "vertex %u is not a vertex of the surface read from %s (indices "
                        "start at 0, in the order docs/scene-format.md describes)",
                        v[k], m->file);
        }
        nodes[k] = (uint32_t)i;
    }
    return 0;
}
