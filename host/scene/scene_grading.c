/*
 * scene_grading.c — attractors of a graded grid from the scene
 * (scene_grading.h).
 */
#include "scene/scene_grading.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "problem/nodes.h"

/* A patch: its face's plane along the normal, its extent in the face. */
static void patch(tf_cloud_grading *g, const sd_patch *p, const double lo[3], const double hi[3])
{
    int u, v, n = tf_face_axis((tf_face)p->face);
    double plane = tf_face_is_max((tf_face)p->face) ? hi[n] : lo[n];
    tf_face_axes((tf_face)p->face, &u, &v);
    tf_cloud_grading_add(g, n, plane, plane, lo[n], hi[n]);
    if (p->centre == NULL) {
        return; /* the whole face: no edge inside it */
    }
    double ext[2] = {0, 0};
    if (p->size) {
        ext[0] = 0.5 * p->size[0];
        ext[1] = 0.5 * p->size[1];
    } else if (p->radius) {
        ext[0] = ext[1] = *p->radius;
    }
    tf_cloud_grading_add(g, u, p->centre[0] - ext[0], p->centre[0] + ext[0], lo[u], hi[u]);
    tf_cloud_grading_add(g, v, p->centre[1] - ext[1], p->centre[1] + ext[1], lo[v], hi[v]);
}

static void point(tf_cloud_grading *g, const double *x, const double lo[3], const double hi[3])
{
    for (int a = 0; a < 3; ++a) {
        tf_cloud_grading_add(g, a, x[a], x[a], lo[a], hi[a]);
    }
}

static void fixed(tf_cloud_grading *g, const sd_fixed *f, const double lo[3], const double hi[3])
{
    if (f->face) {
        int a = tf_face_axis((tf_face)*f->face);
        double at = tf_face_is_max((tf_face)*f->face) ? hi[a] : lo[a];
        tf_cloud_grading_add(g, a, at, at, lo[a], hi[a]);
    } else if (f->plane) {
        int a = f->plane->axis;
        tf_cloud_grading_add(g, a, f->plane->at, f->plane->at, lo[a], hi[a]);
    } else if (f->box) {
        for (int a = 0; a < 3; ++a) { /* only where the box ends inside the body */
            if (f->box->min[a] > lo[a] || f->box->max[a] < hi[a]) {
                tf_cloud_grading_add(g, a, f->box->min[a], f->box->max[a], lo[a], hi[a]);
            }
        }
    }
}

int sd_grading(const sd_scene *doc, const double lo[3], const double hi[3], tf_cloud_grading *g,
               char *msg, size_t msglen)
{
    memset(g, 0, sizeof *g);
    for (int a = 0; a < 3; ++a) {
        g->ratio[a] = doc->geometry.grading ? doc->geometry.grading[a] : 1;
        if (!(g->ratio[a] >= 1 && g->ratio[a] <= 20)) {
            snprintf(msg, msglen,
                     "the ratio of the largest to the smallest spacing must lie in [1, 20] "
                     "(got %g along %c; 1 is a uniform axis)",
                     g->ratio[a], "xyz"[a]);
            return -1;
        }
    }
    if (doc->geometry.grading == NULL) {
        return 0;
    }
    for (unsigned k = 0; k < doc->fixed_count; ++k) {
        fixed(g, &doc->fixed[k], lo, hi);
    }
    for (unsigned k = 0; k < doc->loads_count; ++k) {
        if (doc->loads[k].patch) {
            patch(g, doc->loads[k].patch, lo, hi);
        }
        if (doc->loads[k].at) {
            point(g, doc->loads[k].at, lo, hi);
        }
    }
    for (unsigned k = 0; k < doc->contact_count; ++k) {
        if (doc->contact[k].patch) {
            patch(g, doc->contact[k].patch, lo, hi);
        }
        const sd_region *r = doc->contact[k].region;
        if (r && r->face) { /* the probe goes anywhere on it: only its face's plane */
            int n = tf_face_axis((tf_face)*r->face);
            double plane = tf_face_is_max((tf_face)*r->face) ? hi[n] : lo[n];
            tf_cloud_grading_add(g, n, plane, plane, lo[n], hi[n]);
        }
        if (doc->contact[k].at) {
            point(g, doc->contact[k].at, lo, hi);
        }
    }
    return 0;
}
