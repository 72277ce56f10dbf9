/*
 * surface_vertices.c — fans of triangles about each vertex
 * (surface_vertices.h).  Each triangle (v, a, b) about v, its corners in
 * winding order starting at v, gives the link edge a -> b; on a closed,
 * consistently wound surface every link vertex starts one link edge and
 * ends one, so the link edges form cycles: one cycle is one disc, more are
 * that many fans pinched together at v.
 */
#include "geometry/surface_vertices.h"

#include <stdlib.h>

/* The link edge (a, b) of triangle t about vertex v. */
static void link_edge(const tf_surface *s, size_t t, size_t v, size_t *a, size_t *b)
{
    const size_t *c = s->tri + 3 * t;
    int k = c[0] == v ? 0 : c[1] == v ? 1 : 2;
    *a = c[(k + 1) % 3];
    *b = c[(k + 2) % 3];
}

/* The number of cycles among the link edges of the n triangles tris about
 * v; used[] (n entries) is scratch. */
static size_t fans_about(const tf_surface *s, size_t v, const size_t *tris, size_t n,
                         unsigned char *used)
{
    size_t fans = 0;
    for (size_t i = 0; i < n; ++i) {
        used[i] = 0;
    }
    for (size_t first = 0; first < n; ++first) {
        if (used[first]) {
            continue;
        }
        fans++;
        size_t a0, b;
        link_edge(s, tris[first], v, &a0, &b);
        used[first] = 1;
        for (int more = 1; more && b != a0;) { /* walk the cycle from a0 */
            more = 0;
            for (size_t j = 0; j < n; ++j) {
                size_t a, bj;
                link_edge(s, tris[j], v, &a, &bj);
                if (!used[j] && a == b) {
                    used[j] = 1;
                    b = bj;
                    more = 1;
                    break;
                }
            }
        }
    }
    return fans;
}

int tf_surface_vertex_fans(const tf_surface *s, tf_vertex_fault *f)
{
    f->count = f->v = f->fans = 0;
    size_t *start = calloc(s->nv + 2, sizeof *start), *tris = malloc((3 * s->nt + 1) * sizeof *tris);
    unsigned char *used = malloc(3 * s->nt + 1);
    if (start == NULL || tris == NULL || used == NULL) {
        free(start);
        free(tris);
        free(used);
        return -1;
    }
    for (size_t k = 0; k < 3 * s->nt; ++k) { /* triangles per vertex, as offsets */
        start[s->tri[k] + 2]++;
    }
    for (size_t v = 0; v < s->nv; ++v) {
        start[v + 2] += start[v + 1];
    }
    for (size_t t = 0; t < s->nt; ++t) {
        for (int k = 0; k < 3; ++k) {
            tris[start[s->tri[3 * t + (size_t)k] + 1]++] = t;
        }
    }
    for (size_t v = 0; v < s->nv; ++v) {
        size_t n = start[v + 1] - start[v];
        size_t fans = n ? fans_about(s, v, tris + start[v], n, used) : 1;
        if (fans > 1 && f->count++ == 0) {
            f->v = v;
            f->fans = fans;
        }
    }
    free(start);
    free(tris);
    free(used);
    return 0;
}
