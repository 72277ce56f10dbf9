/*
 * scene_regions.c — patches and outputs against the node cloud
 * (scene_regions.h).
 */
#include "scene/scene_regions.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int sd_resolve_outputs(const sd_outputs *d, const tf_problem *s, tf_outputs *o, char *msg,
                       size_t msglen)
{
    o->kind = (tf_output_kind)d->select;
    int has_nodes = d->nodes != NULL || d->nodes_count > 0;
    if (o->kind == TF_OUT_NODES && d->nodes_count == 0) {
        return outputs_fail(msg, msglen, "select: nodes needs a non-empty nodes list");
    }
    if ((d->face != NULL) != (o->kind == TF_OUT_FACE) ||
        (d->box != NULL) != (o->kind == TF_OUT_BOX) || has_nodes != (o->kind == TF_OUT_NODES)) {
        return outputs_fail(msg, msglen,
                            "select: face takes face, box takes box, nodes takes nodes; all "
                            "and contact take nothing else");
    }
    size_t n = s->cloud.n;
    o->nodes = malloc((n > d->nodes_count ? n : d->nodes_count) * sizeof *o->nodes + 1);
    if (o->nodes == NULL) {
        return outputs_fail(msg, msglen, "out of memory");
    }
    o->n_nodes = 0;
    if (o->kind == TF_OUT_ALL) {
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
    } else {
        for (size_t k = 0; k < s->n_contacts; ++k) {
            o->nodes[o->n_nodes++] = s->contacts[k].node;
        }
    }
    if (o->n_nodes == 0) {
        return outputs_fail(msg, msglen, "the selection holds no node: nothing to output");
    }
    return 0;
}
