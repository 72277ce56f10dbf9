/*
 * problem.c — what a problem owns and a few questions about it (problem.h).
 */
#include "problem/problem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tf_problem_mesh_free(tf_mesh_geometry *g)
{
    tf_tetmesh_free(&g->tm);
    free(g->file_xyz);
    free(g->file_tri);
    g->file_xyz = NULL;
    g->file_tri = NULL;
}

void tf_patch_release(tf_patch *p)
{
    free(p->tri);
    free(p->pts);
    p->tri = NULL;
    p->pts = NULL;
    p->n_tri = p->n_pts = 0;
}

void tf_problem_release(tf_problem *p)
{
    tf_cloud_free(&p->cloud);
    for (size_t k = 0; p->fixed && k < p->n_fixed; ++k) {
        free(p->fixed[k].nodes);
    }
    free(p->fixed);
    for (size_t k = 0; p->loads && k < p->n_loads; ++k) {
        tf_patch_release(&p->loads[k].patch);
    }
    free(p->loads);
    for (size_t k = 0; p->contacts && k < p->n_contacts; ++k) {
        tf_patch_release(&p->contacts[k].patch);
        tf_region_chart *ch = &p->contacts[k].region.chart;
        free(ch->tri);
        free(ch->q);
        free(ch->graph);
    }
    free(p->contacts);
    if (p->geometry.kind == TF_GEOMETRY_MESH && p->geometry.as.mesh != NULL) {
        tf_problem_mesh_free(p->geometry.as.mesh);
        free(p->geometry.as.mesh);
    }
    free(p->outputs.nodes);
    free(p->outputs.points);
    free(p->cuts);
    tf_history_release(&p->history);
    memset(p, 0, sizeof *p);
}

uint32_t tf_problem_nearest_node(const tf_problem *p, const double x[3])
{
    uint32_t best = 0;
    double d2 = INFINITY;
    for (size_t i = 0; i < p->cloud.n; ++i) {
        const double *y = p->cloud.xyz + 3 * i;
        double e = (y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
                   (y[2] - x[2]) * (y[2] - x[2]);
        if (e < d2) {
            d2 = e;
            best = (uint32_t)i;
        }
    }
    return best;
}

int tf_problem_contact(const tf_problem *p, const char *name)
{
    for (size_t k = 0; k < p->n_contacts; ++k) {
        if (strcmp(p->contacts[k].name, name) == 0) {
            return (int)k;
        }
    }
    return -1;
}

void tf_problem_bounds(const tf_problem *p, double lo[3], double hi[3])
{
    switch (p->geometry.kind) {
    case TF_GEOMETRY_BOX:
        memcpy(lo, p->geometry.as.box.min, 3 * sizeof *lo);
        memcpy(hi, p->geometry.as.box.max, 3 * sizeof *hi);
        return;
    case TF_GEOMETRY_MESH:
        break; /* the nodes' bounding box: the surface vertices are nodes */
    }
    memcpy(lo, p->cloud.lo, 3 * sizeof *lo);
    memcpy(hi, p->cloud.hi, 3 * sizeof *hi);
}

void tf_problem_fixed_dofs(const tf_problem *p, unsigned char *mask)
{
    memset(mask, 0, 3 * p->cloud.n);
    for (size_t r = 0; r < p->n_fixed; ++r) {
        const tf_fixed *fx = &p->fixed[r];
        for (size_t q = 0; q < fx->n_nodes; ++q) {
            for (int a = 0; a < 3; ++a) {
                if (fx->components & (1u << a)) {
                    mask[3 * (size_t)fx->nodes[q] + (size_t)a] = 1;
                }
            }
        }
    }
}

int tf_problem_unloaded(const tf_problem *p)
{
    if (p->n_loads > 0) {
        return 0;
    }
    for (size_t r = 0; r < p->n_fixed; ++r) {
        const tf_fixed *fx = &p->fixed[r];
        for (int a = 0; a < 3; ++a) {
            if ((fx->components & (1u << a)) && (fx->exact || fx->value[a] != 0)) {
                return 0;
            }
        }
    }
    return 1;
}

void tf_problem_patch_centre(const tf_patch *patch, const tf_cloud *c, double x[3])
{
    int u, v, n = tf_face_axis(patch->face);
    switch (patch->shape) {
    case TF_PATCH_POINT:
        memcpy(x, c->xyz + 3 * (size_t)patch->node, 3 * sizeof *x);
        return;
    case TF_PATCH_AT:
    case TF_PATCH_SURFACE: /* the site's centre, a surface vertex */
    case TF_PATCH_POINTS:  /* the site's point on the surface */
        memcpy(x, patch->at, 3 * sizeof *x);
        return;
    case TF_PATCH_FACE:
    case TF_PATCH_RECT:
    case TF_PATCH_CIRCLE:
        break;
    }
    tf_face_axes(patch->face, &u, &v);
    x[n] = tf_cloud_face_coord(c, patch->face);
    x[u] = patch->shape == TF_PATCH_FACE ? 0.5 * (c->lo[u] + c->hi[u]) : patch->centre[0];
    x[v] = patch->shape == TF_PATCH_FACE ? 0.5 * (c->lo[v] + c->hi[v]) : patch->centre[1];
}
