/*
 * regions.c — regions resolved against the node cloud (regions.h).
 */
#include "problem/regions.h"

#include <math.h>
#include <stdlib.h>

static double distance2(const double *x, const double *y)
{
    return (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
           (x[2] - y[2]) * (x[2] - y[2]);
}

static int in_region(const tf_cloud *c, const tf_region *r, size_t i, double tol)
{
    const double *x = c->xyz + 3 * i;
    switch (r->kind) {
    case TF_REGION_FACE:
        return fabs(x[tf_face_axis(r->face)] - tf_cloud_face_coord(c, r->face)) <= tol;
    case TF_REGION_PLANE:
        return fabs(x[r->axis] - r->at) <= tol;
    case TF_REGION_SPHERE:
        return distance2(x, r->centre) <= (r->radius + tol) * (r->radius + tol);
    case TF_REGION_NEAR:
        return i < c->n_surface &&
               distance2(x, r->centre) <= (r->radius + tol) * (r->radius + tol);
    case TF_REGION_SIDE:
        return (x[0] - r->centre[0]) * r->normal[0] + (x[1] - r->centre[1]) * r->normal[1] +
                   (x[2] - r->centre[2]) * r->normal[2] >=
               -tol * sqrt(r->normal[0] * r->normal[0] + r->normal[1] * r->normal[1] +
                           r->normal[2] * r->normal[2]);
    case TF_REGION_VERTICES:
        return 0; /* a list: resolved by whoever holds it */
    case TF_REGION_BOX:
        break;
    }
    for (int a = 0; a < 3; ++a) {
        if (x[a] < r->min[a] - tol || x[a] > r->max[a] + tol) {
            return 0;
        }
    }
    return 1;
}

int tf_region_nodes(const tf_cloud *c, const tf_region *r, uint32_t **nodes, size_t *n)
{
    double tol = tf_cloud_tol(c);
    *n = 0;
    *nodes = malloc((c->n + 1) * sizeof **nodes);
    if (*nodes == NULL) {
        return -1;
    }
    for (size_t i = 0; i < c->n; ++i) {
        if (in_region(c, r, i, tol)) {
            (*nodes)[(*n)++] = (uint32_t)i;
        }
    }
    return 0;
}
