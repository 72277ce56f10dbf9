/*
 * regions.c — regions resolved against the node cloud (regions.h).
 */
#include "problem/regions.h"

#include <math.h>
#include <stdlib.h>

static int in_region(const tf_cloud *c, const tf_region *r, const double *x, double tol)
{
    switch (r->kind) {
    case TF_REGION_FACE:
        return fabs(x[tf_face_axis(r->face)] - tf_cloud_face_coord(c, r->face)) <= tol;
    case TF_REGION_PLANE:
        return fabs(x[r->axis] - r->at) <= tol;
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
        if (in_region(c, r, c->xyz + 3 * i, tol)) {
            (*nodes)[(*n)++] = (uint32_t)i;
        }
    }
    return 0;
}
