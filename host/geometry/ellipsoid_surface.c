/*
 * ellipsoid_surface.c — see ellipsoid_surface.h.
 */
#include "geometry/ellipsoid_surface.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct edge_key {
    size_t a, b; /* a < b */
    size_t slot; /* 3 t + k: edge k of triangle t (corners k, k + 1) */
} edge_key;

static int cmp_edge(const void *x, const void *y)
{
    const edge_key *p = x, *q = y;
    if (p->a != q->a) {
        return p->a < q->a ? -1 : 1;
    }
    return p->b < q->b ? -1 : p->b > q->b;
}

static void unit(double *v)
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k) {
        v[k] /= n;
    }
}

/* One halving on the unit sphere: each edge's midpoint (shared by its two
 * triangles) pushed out to the sphere, each triangle into four. */
static int split(tf_surface *s)
{
    size_t ne = 3 * s->nt, nv = s->nv;
    edge_key *e = malloc(ne * sizeof *e);
    size_t *mid = malloc(ne * sizeof *mid);
    tf_surface n;
    if (!e || !mid || tf_surface_alloc(&n, nv + ne / 2, 4 * s->nt) != 0) {
        free(e);
        free(mid);
        return -1;
    }
    for (size_t i = 0; i < ne; ++i) {
        size_t a = s->tri[i], b = s->tri[i % 3 == 2 ? i - 2 : i + 1];
        e[i] = (edge_key){a < b ? a : b, a < b ? b : a, i};
    }
    qsort(e, ne, sizeof *e, cmp_edge);
    memcpy(n.xyz, s->xyz, 3 * nv * sizeof *n.xyz);
    for (size_t i = 0; i < ne; ++i) {
        if (i == 0 || cmp_edge(&e[i], &e[i - 1]) != 0) {
            double *v = n.xyz + 3 * nv;
            for (int k = 0; k < 3; ++k) {
                v[k] = 0.5 * (s->xyz[3 * e[i].a + k] + s->xyz[3 * e[i].b + k]);
            }
            unit(v);
            ++nv;
        }
        mid[e[i].slot] = nv - 1;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        const size_t *c = s->tri + 3 * t, *m = mid + 3 * t; /* m[k]: between c[k], c[k+1] */
        size_t quad[4][3] = {{c[0], m[0], m[2]}, {m[0], c[1], m[1]}, {m[2], m[1], c[2]},
                             {m[0], m[1], m[2]}};
        memcpy(n.tri + 12 * t, quad, sizeof quad);
    }
    n.nv = nv;
    free(e);
    free(mid);
    tf_surface_free(s);
    *s = n;
    return 0;
}

/* The longest edge, on the unit sphere (a sphere's edges are its
 * ellipsoid's over the largest semi-axis at most). */
static double longest_edge(const tf_surface *s)
{
    double l = 0;
    for (size_t i = 0; i < 3 * s->nt; ++i) {
        const double *a = s->xyz + 3 * s->tri[i], *b = s->xyz + 3 * s->tri[i % 3 == 2 ? i - 2 : i + 1];
        l = fmax(l, sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                         (a[2] - b[2]) * (a[2] - b[2])));
    }
    return l;
}

static int icosahedron(tf_surface *s)
{
    const double g = (1 + sqrt(5.0)) / 2;
    const double v[12][3] = {{-1, g, 0}, {1, g, 0},  {-1, -g, 0}, {1, -g, 0},
                             {0, -1, g}, {0, 1, g},  {0, -1, -g}, {0, 1, -g},
                             {g, 0, -1}, {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    /* counter-clockwise seen from outside */
    const size_t f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    if (tf_surface_alloc(s, 12, 20) != 0) {
        return -1;
    }
    memcpy(s->xyz, v, sizeof v);
    memcpy(s->tri, f, sizeof f);
    for (size_t i = 0; i < 12; ++i) {
        unit(s->xyz + 3 * i);
    }
    return 0;
}

int tf_surface_ellipsoid(tf_surface *s, const double centre[3], const double radii[3],
                         double edge)
{
    memset(s, 0, sizeof *s);
    double r = 0;
    for (int a = 0; a < 3; ++a) {
        if (!(radii[a] > 0) || !isfinite(radii[a]) || !isfinite(centre[a])) {
            return -1;
        }
        r = fmax(r, radii[a]);
    }
    if (!(edge > 0) || !isfinite(edge)) {
        return -1;
    }
    if (icosahedron(s) != 0) {
        return -1;
    }
    for (int level = 0; longest_edge(s) * r > edge; ++level) {
        if (level == TF_ELLIPSOID_MAX_LEVEL || split(s) != 0) {
            tf_surface_free(s);
            return -1;
        }
    }
    for (size_t i = 0; i < s->nv; ++i) {
        for (int a = 0; a < 3; ++a) {
            s->xyz[3 * i + a] = centre[a] + radii[a] * s->xyz[3 * i + a];
        }
    }
    return 0;
}
