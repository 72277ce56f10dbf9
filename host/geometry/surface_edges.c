/*
 * surface_edges.c — edge use counts and directions (surface_edges.h): the
 * 3 nt directed edges sorted by their undirected key, then each run of one
 * key is one edge.
 */
#include "geometry/surface_edges.h"

#include <stdlib.h>
#include <string.h>

typedef struct half_edge {
    size_t lo, hi; /* undirected key */
    size_t tri;
    int forward;   /* traversed lo -> hi */
} half_edge;

static int by_key(const void *pa, const void *pb)
{
    const half_edge *a = pa, *b = pb;
    if (a->lo != b->lo) {
        return a->lo < b->lo ? -1 : 1;
    }
    if (a->hi != b->hi) {
        return a->hi < b->hi ? -1 : 1;
    }
    return a->tri < b->tri ? -1 : a->tri > b->tri;
}

static void record(tf_edge_fault *f, const half_edge *run, size_t n)
{
    if (f->count++ == 0) {
        f->v[0] = run[0].lo;
        f->v[1] = run[0].hi;
        f->tri[0] = run[0].tri;
        f->tri[1] = n > 1 ? run[1].tri : run[0].tri;
    }
}

int tf_surface_edges(const tf_surface *s, tf_edge_report *r)
{
    memset(r, 0, sizeof *r);
    half_edge *h = malloc((3 * s->nt + 1) * sizeof *h);
    if (h == NULL) {
        return -1;
    }
    for (size_t t = 0; t < s->nt; ++t) {
        for (int k = 0; k < 3; ++k) {
            size_t a = s->tri[3 * t + k], b = s->tri[3 * t + (k + 1) % 3];
            half_edge e = {a < b ? a : b, a < b ? b : a, t, a < b};
            h[3 * t + k] = e;
        }
    }
    qsort(h, 3 * s->nt, sizeof *h, by_key);
    for (size_t i = 0, j; i < 3 * s->nt; i = j) {
        for (j = i + 1; j < 3 * s->nt && h[j].lo == h[i].lo && h[j].hi == h[i].hi; ++j) {
        }
        r->edges++;
        if (j - i == 1) {
            record(&r->open, h + i, 1);
        } else if (j - i > 2) {
            record(&r->nonmanifold, h + i, j - i);
        } else if (h[i].forward == h[i + 1].forward) {
            record(&r->flipped, h + i, 2);
        }
    }
    free(h);
    return 0;
}
