/*
 * tetmesh_check.c — the mesh fills its surface exactly (tetmesh_check.h).
 * Faces are matched by sorting: the four outward faces of every
 * tetrahedron and every surface triangle reversed (as if the outside were
 * a tetrahedron) must pair up, two by two, in opposite orientations.
 */
#include "geometry/tetmesh_check.h"

#include <stdlib.h>
#include <string.h>

#include "geometry/winding.h"

typedef struct face {
    size_t v[3];   /* sorted */
    int parity;    /* orientation: 0 when (v0 v1 v2) is an even permutation of v */
    int surface;   /* from a surface triangle */
} face;

/* The outward faces of a positively oriented tetrahedron (0 1 2 3). */
static const int tet_face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

static face make_face(size_t a, size_t b, size_t c, int surface)
{
    face f = {{a, b, c}, 0, surface};
    for (int i = 0; i < 3; ++i) {
        for (int j = 2; j > i; --j) {
            if (f.v[j - 1] > f.v[j]) {
                size_t x = f.v[j];
                f.v[j] = f.v[j - 1];
                f.v[j - 1] = x;
                f.parity ^= 1;
            }
        }
    }
    return f;
}

static int by_vertices(const void *pa, const void *pb)
{
    const face *a = pa, *b = pb;
    for (int k = 0; k < 3; ++k) {
        if (a->v[k] != b->v[k]) {
            return a->v[k] < b->v[k] ? -1 : 1;
        }
    }
    return 0;
}

static int same(const face *a, const face *b)
{
    return a->v[0] == b->v[0] && a->v[1] == b->v[1] && a->v[2] == b->v[2];
}

static int match_faces(const tf_tetmesh *t, tf_tetmesh_faults *f)
{
    size_t n = 4 * t->ntet + t->ntri, k = 0;
    face *all = malloc((n + 1) * sizeof *all);
    if (all == NULL) {
        return -1;
    }
    for (size_t e = 0; e < t->ntet; ++e) {
        const size_t *v = t->tet + 4 * e;
        for (int q = 0; q < 4; ++q) {
            all[k++] = make_face(v[tet_face[q][0]], v[tet_face[q][1]], v[tet_face[q][2]], 0);
        }
    }
    for (size_t r = 0; r < t->ntri; ++r) {
        const size_t *v = t->tri + 3 * r;
        all[k++] = make_face(v[0], v[2], v[1], 1);
    }
    qsort(all, n, sizeof *all, by_vertices);
    for (size_t i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && same(all + i, all + j); ++j) {
        }
        if (j - i == 1) {
            f->missing += all[i].surface;
            f->extra += !all[i].surface;
        } else if (j - i > 2 || all[i].parity == all[i + 1].parity ||
                   (all[i].surface && all[i + 1].surface)) {
            f->bad_faces++;
        }
    }
    free(all);
    return 0;
}

int tf_tetmesh_topology(const tf_tetmesh *t, const tf_surface *s, tf_tetmesh_faults *f)
{
    memset(f, 0, sizeof *f);
    unsigned char *used = calloc(t->nn + 1, 1);
    if (used == NULL) {
        return -1;
    }
    for (size_t e = 0; e < t->ntet; ++e) {
        f->nonpositive += !(t->tet_volume[e] > 0);
        for (int q = 0; q < 4; ++q) {
            used[t->tet[4 * e + q]] = 1;
        }
    }
    for (size_t i = 0; i < t->nn; ++i) {
        f->unused += !used[i];
    }
    free(used);
    for (size_t i = 0; i < s->nv; ++i) {
        const double *a = s->xyz + 3 * i, *b = t->xyz + 3 * i;
        f->moved += i >= t->nsurf || !(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
    }
    return match_faces(t, f);
}

int tf_tetmesh_check_topology(const tf_tetmesh *t, const tf_surface *s, tf_geom_msg *m)
{
    tf_tetmesh_faults f;
    if (tf_tetmesh_topology(t, s, &f) != 0) {
        return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
    }
    if (f.nonpositive || f.moved || f.unused || f.extra || f.missing || f.bad_faces) {
        return tf_geom_fail(m, TF_GEOM_FAILED,
                            "the volume mesh does not fill the surface exactly: %zu tetrahedra "
                            "of volume <= 0, %zu surface vertices moved or lost, %zu unused "
                            "nodes, %zu boundary faces that are no surface triangle, %zu "
                            "surface triangles that are no boundary face, %zu faces shared "
                            "wrongly",
                            f.nonpositive, f.moved, f.unused, f.extra, f.missing, f.bad_faces);
    }
    return TF_GEOM_OK;
}

void tf_tetmesh_inside(const tf_tetmesh *t, const tf_surface *s, tf_inside_report *r)
{
    memset(r, 0, sizeof *r);
    r->min_winding = 1;
    size_t n = t->nn > t->nsurf ? t->nn - t->nsurf : 0;
    double *w = malloc((n + 1) * sizeof *w);
    if (w == NULL) {
        r->outside = n; /* unverified counts as outside */
        r->min_winding = 0;
        return;
    }
    tf_winding_numbers(s, t->xyz + 3 * t->nsurf, n, w);
    r->tested = n;
    for (size_t k = 0; k < n; ++k) {
        r->outside += !(w[k] > 0.5);
        if (!(w[k] >= r->min_winding)) {
            r->min_winding = w[k];
            r->worst = t->nsurf + k;
        }
    }
    free(w);
}
