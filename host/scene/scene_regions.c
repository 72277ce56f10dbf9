/*
 * scene_regions.c — patches and outputs against the node cloud
 * (scene_regions.h).
 */
#include "scene/scene_regions.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "problem/mesh_geometry.h"
#include "problem/regions.h"

static int patch_fail(char *msg, size_t msglen, const char *what)
{
    snprintf(msg, msglen, "%s", what);
    return -1;
}

int sd_resolve_patch(const sd_patch *d, const tf_cloud *c, tf_patch *p, char *msg, size_t msglen)
{
    int u, v;
    p->face = (tf_face)d->face;
    tf_face_axes(p->face, &u, &v);
    p->shape = d->shape ? (tf_patch_shape)*d->shape
               : d->radius ? TF_PATCH_CIRCLE
               : d->size   ? TF_PATCH_RECT
                           : TF_PATCH_FACE;
    int wants_centre = p->shape != TF_PATCH_FACE;
    if ((d->centre != NULL) != wants_centre || (d->size != NULL) != (p->shape == TF_PATCH_RECT) ||
        (d->radius != NULL) != (p->shape == TF_PATCH_CIRCLE)) {
        return patch_fail(msg, msglen,
                          "a face patch takes no centre/size/radius; rect takes centre and "
                          "size; circle takes centre and radius");
    }
    double ext[2] = {0, 0}, tol = tf_cloud_tol(c);
    if (wants_centre) {
        p->centre[0] = d->centre[0];
        p->centre[1] = d->centre[1];
    }
    if (p->shape == TF_PATCH_RECT) {
        p->size[0] = d->size[0];
        p->size[1] = d->size[1];
        ext[0] = 0.5 * p->size[0];
        ext[1] = 0.5 * p->size[1];
        if (!(p->size[0] > 0 && p->size[1] > 0)) {
            return patch_fail(msg, msglen, "size must be positive (mm)");
        }
    } else if (p->shape == TF_PATCH_CIRCLE) {
        p->radius = *d->radius;
        ext[0] = ext[1] = p->radius;
        if (!(p->radius > 0)) {
            return patch_fail(msg, msglen, "radius must be positive (mm)");
        }
    }
    if (wants_centre && !(isfinite(p->centre[0]) && isfinite(p->centre[1]) && isfinite(ext[0]) &&
                          isfinite(ext[1]) && p->centre[0] - ext[0] >= c->lo[u] - tol &&
                          p->centre[0] + ext[0] <= c->hi[u] + tol &&
                          p->centre[1] - ext[1] >= c->lo[v] - tol &&
                          p->centre[1] + ext[1] <= c->hi[v] + tol)) {
        char what[192];
        snprintf(what, sizeof what, "the patch leaves its face (%c in [%g, %g], %c in [%g, %g])",
                 "xyz"[u], c->lo[u], c->hi[u], "xyz"[v], c->lo[v], c->hi[v]);
        return patch_fail(msg, msglen, what);
    }
    return 0;
}

static int outputs_fail(char *msg, size_t msglen, const char *what)
{
    snprintf(msg, msglen, "%s", what);
    return -1;
}

/* The file's vertices within radius of any contact point, ascending. */
static void near_contact(const tf_problem *s, double radius, tf_outputs *o)
{
    const tf_cloud *c = &s->cloud;
    for (size_t i = 0; i < tf_problem_mesh(s)->file_nv; ++i) {
        const double *x = c->xyz + 3 * i;
        for (size_t k = 0; k < s->n_contacts; ++k) {
            const double *y = s->contacts[k].at;
            double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                        (x[2] - y[2]) * (x[2] - y[2]);
            if (d2 <= radius * radius) {
                o->nodes[o->n_nodes++] = (uint32_t)i;
                break;
            }
        }
    }
}

/* The selections of organs: every vertex of the file, those near the
 * contact sites, or a list of them by their index in the file (a refined
 * skin's midpoints are not the renderer's). */
static int organ_outputs(const sd_outputs *d, const tf_problem *s, tf_outputs *o, char *msg,
                         size_t msglen)
{
    const tf_mesh_geometry *m = tf_problem_mesh(s);
    if (m == NULL) {
        return outputs_fail(msg, msglen,
                            "select: surface, near-contact and vertices need an organ "
                            "(geometry.surface)");
    }
    if (o->kind == TF_OUT_SURFACE) {
        for (size_t i = 0; i < m->file_nv; ++i) {
            o->nodes[o->n_nodes++] = (uint32_t)i;
        }
    } else if (o->kind == TF_OUT_NEAR_CONTACT) {
        if (!(isfinite(*d->radius) && *d->radius >= 0) || s->n_contacts == 0) {
            return outputs_fail(msg, msglen,
                                "near-contact needs a contact site and a finite radius >= 0 (mm)");
        }
        near_contact(s, *d->radius, o);
    } else {
        for (unsigned k = 0; k < d->vertices_count; ++k) {
            long i = tf_problem_mesh_vertex_node(m, (long)d->vertices[k]);
            if (i < 0) {
                snprintf(msg, msglen, "vertex %u is not a vertex of the surface read from %s",
                         d->vertices[k], m->file);
                return -1;
            }
            o->nodes[o->n_nodes++] = (uint32_t)i;
        }
    }
    return 0;
}

/* Point j of a lattice: count[a] points evenly from min to max per axis
 * (x fastest; a count of 1 sits at min, the last point exactly at max). */
static void lattice_point(const sd_lattice *l, size_t j, double x[3])
{
    size_t ijk[3] = {j % l->count[0], j / l->count[0] % l->count[1],
                     j / ((size_t)l->count[0] * l->count[1])};
    for (int a = 0; a < 3; ++a) {
        unsigned m = l->count[a];
        x[a] = m == 1 || ijk[a] == 0 ? l->min[a]
               : ijk[a] + 1 == m     ? l->max[a]
                                     : l->min[a] + (double)ijk[a] * (l->max[a] - l->min[a]) / (m - 1);
    }
}

/* select: points — a list of points, or a lattice of them. */
static int output_points(const sd_outputs *d, const tf_problem *s, tf_outputs *o, char *msg,
                         size_t msglen)
{
    const sd_lattice *l = d->lattice;
    if ((d->points != NULL) == (l != NULL)) {
        return outputs_fail(msg, msglen, "select: points takes points (a list) or lattice, not both");
    }
    size_t n = l ? (size_t)l->count[0] * l->count[1] * l->count[2] : d->points_count;
    if (n == 0 || n > 100000) {
        return outputs_fail(msg, msglen, "1 to 100000 points (a lattice counts >= 1 per axis)");
    }
    o->points = malloc(3 * n * sizeof *o->points);
    o->nodes = malloc(n * sizeof *o->nodes);
    if (o->points == NULL || o->nodes == NULL) {
        return outputs_fail(msg, msglen, "out of memory");
    }
    double tol = tf_cloud_tol(&s->cloud);
    for (size_t j = 0; j < n; ++j) {
        double *x = o->points + 3 * j;
        if (l) {
            lattice_point(l, j, x);
        } else {
            memcpy(x, d->points[j], 3 * sizeof *x);
        }
        for (int a = 0; a < 3; ++a) {
            if (!(isfinite(x[a]) && x[a] >= s->cloud.lo[a] - tol && x[a] <= s->cloud.hi[a] + tol)) {
                snprintf(msg, msglen, "point %zu (%g, %g, %g) mm is not inside the body", j + 1,
                         x[0], x[1], x[2]);
                return -1;
            }
        }
        o->nodes[j] = tf_problem_nearest_node(s, x);
    }
    o->n_nodes = n;
    return 0;
}

/* select: contact — the contact points (a site given by node: its node). */
static int contact_points(const tf_problem *s, tf_outputs *o, char *msg, size_t msglen)
{
    int by_position = 0;
    for (size_t k = 0; k < s->n_contacts; ++k) {
        o->nodes[o->n_nodes++] = s->contacts[k].node;
        by_position |= !s->contacts[k].by_node;
    }
    if (by_position && o->n_nodes > 0) {
        o->points = malloc(3 * o->n_nodes * sizeof *o->points);
        if (o->points == NULL) {
            return outputs_fail(msg, msglen, "out of memory");
        }
        for (size_t k = 0; k < o->n_nodes; ++k) {
            memcpy(o->points + 3 * k, s->contacts[k].at, 3 * sizeof *o->points);
        }
    }
    return 0;
}

int sd_resolve_outputs(const sd_outputs *d, const tf_problem *s, tf_outputs *o, char *msg,
                       size_t msglen)
{
    o->kind = (tf_output_kind)d->select;
    o->points = NULL;
    int organ = o->kind == TF_OUT_SURFACE || o->kind == TF_OUT_NEAR_CONTACT ||
                o->kind == TF_OUT_VERTICES;
    if ((d->radius != NULL) != (o->kind == TF_OUT_NEAR_CONTACT) ||
        (d->vertices_count > 0) != (o->kind == TF_OUT_VERTICES)) {
        return outputs_fail(msg, msglen,
                            "select: near-contact takes radius, vertices takes vertices (a "
                            "non-empty list); the others take neither");
    }
    if (o->kind == TF_OUT_FACE && tf_problem_mesh(s) != NULL) {
        return outputs_fail(msg, msglen, "an organ has no box faces: select surface, "
                                         "near-contact, vertices or points");
    }
    int has_nodes = d->nodes != NULL || d->nodes_count > 0;
    int has_points = d->points != NULL || d->lattice != NULL;
    if (o->kind == TF_OUT_NODES && d->nodes_count == 0) {
        return outputs_fail(msg, msglen, "select: nodes needs a non-empty nodes list");
    }
    if ((d->face != NULL) != (o->kind == TF_OUT_FACE) ||
        (d->box != NULL) != (o->kind == TF_OUT_BOX) || has_nodes != (o->kind == TF_OUT_NODES) ||
        has_points != (o->kind == TF_OUT_POINTS)) {
        return outputs_fail(msg, msglen,
                            "select: face takes face, box takes box, nodes takes nodes, points "
                            "takes points or lattice; all and contact take nothing else");
    }
    if (o->kind == TF_OUT_POINTS) {
        return output_points(d, s, o, msg, msglen);
    }
    size_t n = s->cloud.n, list = d->nodes_count + d->vertices_count;
    o->nodes = malloc((n > list ? n : list) * sizeof *o->nodes + 1);
    if (o->nodes == NULL) {
        return outputs_fail(msg, msglen, "out of memory");
    }
    o->n_nodes = 0;
    if (organ) {
        if (organ_outputs(d, s, o, msg, msglen) != 0) {
            return -1;
        }
    } else if (o->kind == TF_OUT_ALL) {
        for (size_t i = 0; i < n; ++i) {
            o->nodes[o->n_nodes++] = (uint32_t)i;
        }
    } else if (o->kind == TF_OUT_FACE || o->kind == TF_OUT_BOX) {
        tf_region r = {.kind = o->kind == TF_OUT_FACE ? TF_REGION_FACE : TF_REGION_BOX};
        if (d->face) {
            r.face = (tf_face)*d->face;
        } else {
            memcpy(r.min, d->box->min, sizeof r.min);
            memcpy(r.max, d->box->max, sizeof r.max);
        }
        free(o->nodes);
        if (tf_region_nodes(&s->cloud, &r, &o->nodes, &o->n_nodes) != 0) {
            return outputs_fail(msg, msglen, "out of memory");
        }
    } else if (o->kind == TF_OUT_NODES) {
        for (unsigned k = 0; k < d->nodes_count; ++k) {
            if (d->nodes[k] < 1 || d->nodes[k] > n) {
                snprintf(msg, msglen, "node %u does not exist (nodes are numbered 1 to %zu)",
                         d->nodes[k], n);
                return -1;
            }
            o->nodes[o->n_nodes++] = d->nodes[k] - 1;
        }
    } else if (contact_points(s, o, msg, msglen) != 0) {
        return -1;
    }
    if (o->n_nodes == 0) {
        char where[320];
        sd_body_extent(s, where, sizeof where);
        snprintf(msg, msglen, "the selection holds no node: nothing to output; %s", where);
        return -1;
    }
    /* Points (select: points, contacts by position) are the field there,
     * wherever they lie; nodes of an organ must be the file's vertices. */
    for (size_t k = 0; tf_problem_mesh(s) != NULL && o->points == NULL && k < o->n_nodes; ++k) {
        if (o->nodes[k] >= tf_problem_mesh(s)->file_nv) {
            snprintf(msg, msglen,
                     "node %u is not a vertex of the mesh file: outputs of an organ are the "
                     "file's vertices (the renderer has no other)",
                     o->nodes[k] + 1);
            return -1;
        }
    }
    return 0;
}

void sd_body_extent(const tf_problem *s, char *buf, size_t len)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->cloud.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = fmin(lo[a], s->cloud.xyz[3 * i + (size_t)a]);
            hi[a] = fmax(hi[a], s->cloud.xyz[3 * i + (size_t)a]);
        }
    }
    snprintf(buf, len,
             "the body's nodes span x [%g, %g], y [%g, %g], z [%g, %g] mm%s", lo[0], hi[0],
             lo[1], hi[1], lo[2], hi[2],
             tf_problem_mesh(s) != NULL
                 ? " (is the mesh in other units than mm? geometry.surface.scale gives mm "
                   "per file unit)"
                 : "");
}
