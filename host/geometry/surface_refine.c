/*
 * surface_refine.c — longest-edge bisection of a closed surface
 * (surface_refine.h).
 */
#include "geometry/surface_refine.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The growing surface and, per triangle edge i (from vertex i to i + 1),
 * the triangle across it, and the file's triangle each lies on. */
typedef struct work {
    size_t nv, nt;
    size_t cap_xyz, cap_source, cap_tri, cap_nb, cap_parent; /* entries allocated */
    double *xyz;
    long *source;
    size_t *tri, *nb, *parent;
} work;

static double len2(const work *w, size_t a, size_t b)
{
    const double *p = w->xyz + 3 * a, *q = w->xyz + 3 * b;
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
           (p[2] - q[2]) * (p[2] - q[2]);
}

/* Edges in a total order (length, then the vertex numbers), so that a
 * longest-edge path strictly ascends and ends. */
static int longer(const work *w, size_t a, size_t b, size_t c, size_t d)
{
    double l = len2(w, a, b), m = len2(w, c, d);
    if (l != m) {
        return l > m;
    }
    size_t lo1 = a < b ? a : b, hi1 = a < b ? b : a, lo2 = c < d ? c : d, hi2 = c < d ? d : c;
    return lo1 != lo2 ? lo1 > lo2 : hi1 > hi2;
}

static unsigned longest(const work *w, size_t t)
{
    const size_t *v = w->tri + 3 * t;
    unsigned best = 0;
    for (unsigned i = 1; i < 3; ++i) {
        if (longer(w, v[i], v[(i + 1) % 3], v[best], v[(best + 1) % 3])) {
            best = i;
        }
    }
    return best;
}

typedef struct half {
    size_t lo, hi, t;
    unsigned i;
} half;

static int by_edge(const void *x, const void *y)
{
    const half *a = x, *b = y;
    if (a->lo != b->lo) {
        return a->lo < b->lo ? -1 : 1;
    }
    return a->hi < b->hi ? -1 : a->hi > b->hi;
}

/* Pairs the half-edges; -1 when an edge is not shared by exactly two. */
static int adjacency(work *w)
{
    size_t n = 3 * w->nt;
    half *h = malloc((n + 1) * sizeof *h);
    if (h == NULL) {
        return -1;
    }
    for (size_t t = 0; t < w->nt; ++t) {
        for (unsigned i = 0; i < 3; ++i) {
            size_t a = w->tri[3 * t + i], b = w->tri[3 * t + (i + 1) % 3];
            h[3 * t + i] = (half){a < b ? a : b, a < b ? b : a, t, i};
        }
    }
    qsort(h, n, sizeof *h, by_edge);
    int bad = n % 2 != 0;
    for (size_t k = 0; k < n && !bad; k += 2) {
        bad = by_edge(h + k, h + k + 1) != 0 || (k + 2 < n && by_edge(h + k + 1, h + k + 2) == 0);
        if (!bad) {
            w->nb[3 * h[k].t + h[k].i] = h[k + 1].t;
            w->nb[3 * h[k + 1].t + h[k + 1].i] = h[k].t;
        }
    }
    free(h);
    return bad ? -1 : 0;
}

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) {
        return 0;
    }
    size_t cap2 = 2 * need;
    void *q = realloc(*p, cap2 * size);
    if (q == NULL) {
        return -1;
    }
    *p = q;
    *cap = cap2;
    return 0;
}

/* Room for one more vertex and two more triangles. */
static int reserve(work *w)
{
    size_t v = w->nv + 1, t = w->nt + 2;
    return grow((void **)&w->xyz, &w->cap_xyz, 3 * v, sizeof *w->xyz) ||
           grow((void **)&w->source, &w->cap_source, v, sizeof *w->source) ||
           grow((void **)&w->tri, &w->cap_tri, 3 * t, sizeof *w->tri) ||
           grow((void **)&w->nb, &w->cap_nb, 3 * t, sizeof *w->nb) ||
           grow((void **)&w->parent, &w->cap_parent, t, sizeof *w->parent);
}

/* In triangle t, the neighbour across its edge from a to b becomes u. */
static void relink(work *w, size_t t, size_t a, size_t b, size_t u)
{
    for (unsigned k = 0; k < 3; ++k) {
        if (w->tri[3 * t + k] == a && w->tri[3 * t + (k + 1) % 3] == b) {
            w->nb[3 * t + k] = u;
        }
    }
}

static void set_tri(work *w, size_t t, size_t a, size_t b, size_t c, size_t na, size_t nb,
                    size_t nc)
{
    size_t *v = w->tri + 3 * t, *n = w->nb + 3 * t;
    v[0] = a, v[1] = b, v[2] = c;
    n[0] = na, n[1] = nb, n[2] = nc;
}

/* Splits the edge shared by t (its edge i, a -> b, third vertex c) and n
 * (its edge j, b -> a, third vertex d) at its midpoint m: t = (a m c),
 * t2 = (m b c), n = (b m d), n2 = (m a d), every winding kept. */
static void bisect(work *w, size_t t, unsigned i, size_t n, unsigned j)
{
    const size_t *T = w->tri + 3 * t, *N = w->tri + 3 * n;
    size_t a = T[i], b = T[(i + 1) % 3], c = T[(i + 2) % 3], d = N[(j + 2) % 3];
    size_t X = w->nb[3 * t + (i + 1) % 3], Y = w->nb[3 * t + (i + 2) % 3];
    size_t Z = w->nb[3 * n + (j + 1) % 3], W = w->nb[3 * n + (j + 2) % 3];
    size_t m = w->nv++, t2 = w->nt, n2 = w->nt + 1;
    w->nt += 2;
    for (int k = 0; k < 3; ++k) {
        w->xyz[3 * m + (size_t)k] = 0.5 * (w->xyz[3 * a + (size_t)k] + w->xyz[3 * b + (size_t)k]);
    }
    w->source[m] = -1;
    w->parent[t2] = w->parent[t];
    w->parent[n2] = w->parent[n];
    set_tri(w, t, a, m, c, n2, t2, Y);
    set_tri(w, t2, m, b, c, n, X, t);
    set_tri(w, n, b, m, d, t2, n2, W);
    set_tri(w, n2, m, a, d, t, Z, n);
    relink(w, X, c, b, t2);
    relink(w, Z, d, a, n2);
}

/* One bisection on t's longest-edge propagation path: walk across longest
 * edges until two triangles share theirs, and split that edge. */
static void lepp_step(work *w, size_t t)
{
    for (;;) {
        unsigned i = longest(w, t);
        size_t n = w->nb[3 * t + i];
        unsigned j = longest(w, n);
        const size_t *T = w->tri + 3 * t, *N = w->tri + 3 * n;
        if (N[j] == T[(i + 1) % 3] && N[(j + 1) % 3] == T[i]) {
            bisect(w, t, i, n, j);
            return;
        }
        t = n;
    }
}

static int too_long(const work *w, size_t t, tf_size_at size, const void *arg, double ratio)
{
    unsigned i = longest(w, t);
    size_t a = w->tri[3 * t + i], b = w->tri[3 * t + (i + 1) % 3];
    double mid[3];
    for (int k = 0; k < 3; ++k) {
        mid[k] = 0.5 * (w->xyz[3 * a + (size_t)k] + w->xyz[3 * b + (size_t)k]);
    }
    double h = ratio * size(mid, arg);
    return len2(w, a, b) > h * h;
}

static void work_free(work *w)
{
    free(w->xyz);
    free(w->source);
    free(w->tri);
    free(w->nb);
    free(w->parent);
}

static int start(work *w, const tf_surface *s)
{
    memset(w, 0, sizeof *w);
    w->nv = s->nv;
    w->nt = s->nt;
    w->cap_xyz = 3 * s->nv + 3;
    w->cap_source = s->nv + 1;
    w->cap_tri = w->cap_nb = 3 * s->nt + 6;
    w->cap_parent = s->nt + 2;
    w->parent = malloc(w->cap_parent * sizeof *w->parent);
    w->xyz = malloc(w->cap_xyz * sizeof *w->xyz);
    w->source = malloc(w->cap_source * sizeof *w->source);
    w->tri = malloc(w->cap_tri * sizeof *w->tri);
    w->nb = malloc(w->cap_nb * sizeof *w->nb);
    if (w->xyz == NULL || w->source == NULL || w->tri == NULL || w->nb == NULL ||
        w->parent == NULL) {
        return -1;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        w->parent[t] = s->tri_parent != NULL ? s->tri_parent[t] : t;
    }
    memcpy(w->xyz, s->xyz, 3 * s->nv * sizeof *w->xyz);
    memcpy(w->source, s->source, s->nv * sizeof *w->source);
    memcpy(w->tri, s->tri, 3 * s->nt * sizeof *w->tri);
    return 0;
}

int tf_surface_refine(tf_surface *s, tf_size_at size, const void *arg, double ratio,
                      size_t max_nv, tf_geom_msg *m)
{
    work w;
    if (start(&w, s) != 0) {
        work_free(&w);
        return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
    }
    if (adjacency(&w) != 0) {
        work_free(&w);
        return tf_geom_fail(m, TF_GEOM_FAILED, "skin refinement: the surface is not closed "
                                               "(an edge not shared by two triangles)");
    }
    for (size_t t = 0; t < w.nt; ++t) {
        while (too_long(&w, t, size, arg, ratio)) {
            if (w.nv >= max_nv) {
                double at[3]; /* a vertex of the triangle still too coarse */
                memcpy(at, w.xyz + 3 * w.tri[3 * t], sizeof at);
                work_free(&w);
                return tf_geom_fail(m, TF_GEOM_BAD_INPUT,
                                    "the refined skin would hold more than %zu vertices (%g mm "
                                    "wanted at (%g, %g, %g) mm): use a larger spacing",
                                    max_nv, size(at, arg), at[0], at[1], at[2]);
            }
            if (reserve(&w) != 0) {
                work_free(&w);
                return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
            }
            lepp_step(&w, t);
        }
    }
    free(s->xyz);
    free(s->source);
    free(s->tri);
    free(s->tri_parent);
    free(w.nb);
    s->xyz = w.xyz;
    s->source = w.source;
    s->tri = w.tri;
    s->tri_parent = w.parent;
    s->nv = w.nv;
    s->nt = w.nt;
    return TF_GEOM_OK;
}
