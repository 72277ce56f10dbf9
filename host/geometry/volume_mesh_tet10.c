/*
 * volume_mesh_tet10.c — refined second-order meshes of an organ for the
 * finite-element reference (volume_mesh_tet10.h).
 */
#include "geometry/volume_mesh_tet10.h"

#include <gmshc.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/gmsh_session.h"

#define GMSH_TET10 11

/* CalculiX's C3D10 edges, in its order of the nodes 5 to 10. */
static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

void tf_tet10_mesh_free(tf_tet10_mesh *q)
{
    free(q->xyz);
    free(q->tet);
    free(q->vertex_node);
    free(q->region);
    memset(q, 0, sizeof *q);
}

typedef struct by_position {
    const double *xyz;
    size_t i;
} by_position;

static int cmp_position(const void *a, const void *b)
{
    const double *p = ((const by_position *)a)->xyz, *q = ((const by_position *)b)->xyz;
    for (int k = 0; k < 3; ++k) {
        if (p[k] != q[k]) {
            return p[k] < q[k] ? -1 : 1;
        }
    }
    return 0;
}

/* vertex_node[i]: the node at surface vertex i's coordinates, bit for bit
 * (gmsh keeps the discrete surface's nodes; refining may renumber them). */
static int match_vertices(const tf_surface *s, tf_tet10_mesh *q, tf_geom_msg *m)
{
    by_position *key = malloc((q->nn + 1) * sizeof *key);
    q->vertex_node = malloc((s->nv + 1) * sizeof *q->vertex_node);
    if (key == NULL || q->vertex_node == NULL) {
        free(key);
        return tf_geom_fail(m, TF_GEOM_FAILED, "out of memory");
    }
    for (size_t i = 0; i < q->nn; ++i) {
        key[i] = (by_position){q->xyz + 3 * i, i};
    }
    qsort(key, q->nn, sizeof *key, cmp_position);
    for (size_t v = 0; v < s->nv; ++v) {
        by_position want = {s->xyz + 3 * v, 0};
        by_position *hit = bsearch(&want, key, q->nn, sizeof *key, cmp_position);
        if (hit == NULL) {
            free(key);
            return tf_geom_fail(m, TF_GEOM_FAILED,
                                "surface vertex %zu is no node of the refined mesh", v);
        }
        q->vertex_node[v] = hit->i;
    }
    free(key);
    return TF_GEOM_OK;
}

static double dist2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

/* One element from gmsh's node order into CalculiX's: the corners first,
 * then for each C3D10 edge the mid node nearest its midpoint (an edge node
 * of a straight-sided element sits at the midpoint). */
static void reorder(const tf_tet10_mesh *q, const size_t *g, size_t *out)
{
    memcpy(out, g, 4 * sizeof *out);
    for (int e = 0; e < 6; ++e) {
        const double *a = q->xyz + 3 * g[edge[e][0]], *b = q->xyz + 3 * g[edge[e][1]];
        double mid[3] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
        double best = INFINITY;
        for (int k = 4; k < 10; ++k) {
            double d = dist2(q->xyz + 3 * g[k], mid);
            if (d < best) {
                best = d;
                out[4 + e] = g[k];
            }
        }
    }
}

/* The 10-node tetrahedra of volume `tag` appended to q (node tags through
 * index), region[e] = region. */
static int collect_volume(tf_tet10_mesh *q, int tag, int region, const size_t *index)
{
    int ierr = 0;
    size_t *etag = NULL, ne = 0, *en = NULL, nen = 0;
    gmshModelMeshGetElementsByType(GMSH_TET10, &etag, &ne, &en, &nen, tag, 0, 1, &ierr);
    size_t first = q->ntet, n = nen / 10;
    size_t *tet = ierr ? NULL : realloc(q->tet, (10 * (first + n) + 1) * sizeof *tet);
    int *reg = tet ? realloc(q->region, (first + n + 1) * sizeof *reg) : NULL;
    if (tet) {
        q->tet = tet;
    }
    if (reg) {
        q->region = reg;
        for (size_t e = 0; e < n; ++e) {
            size_t g[10];
            for (int k = 0; k < 10; ++k) {
                g[k] = index[en[10 * e + (size_t)k]];
            }
            reorder(q, g, q->tet + 10 * (first + e));
            q->region[first + e] = region;
        }
        q->ntet += n;
    }
    gmshFree(etag);
    gmshFree(en);
    return reg == NULL;
}

static int collect(const tf_surface *s, size_t n_inner, tf_tet10_mesh *q, tf_geom_msg *m)
{
    int ierr = 0;
    size_t *ntag = NULL, nnode = 0, ncoord = 0, npar = 0;
    double *coord = NULL, *par = NULL;
    gmshModelMeshGetNodes(&ntag, &nnode, &coord, &ncoord, &par, &npar, -1, -1, 0, 0, &ierr);
    size_t maxtag = 0;
    for (size_t k = 0; k < nnode; ++k) {
        maxtag = ntag[k] > maxtag ? ntag[k] : maxtag;
    }
    size_t *index = malloc((maxtag + 1) * sizeof *index);
    q->nn = nnode;
    q->xyz = malloc((3 * nnode + 1) * sizeof *q->xyz);
    int rc = ierr ? tf_gmsh_fail(m, TF_GEOM_FAILED, "reading gmsh's second-order mesh")
             : !index || !q->xyz ? tf_geom_fail(m, TF_GEOM_FAILED, "out of memory")
                                 : TF_GEOM_OK;
    for (size_t k = 0; rc == TF_GEOM_OK && k < nnode; ++k) {
        index[ntag[k]] = k;
        memcpy(q->xyz + 3 * k, coord + 3 * k, 3 * sizeof *q->xyz);
    }
    /* volume 1 is the body (region 0), volume k + 2 inner surface k */
    for (size_t v = 0; rc == TF_GEOM_OK && v <= n_inner; ++v) {
        size_t before = q->ntet;
        if (collect_volume(q, (int)v + 1, (int)v, index) != 0) {
            rc = tf_gmsh_fail(m, TF_GEOM_FAILED, "reading gmsh's 10-node tetrahedra");
        } else if (q->ntet == before) {
            rc = tf_geom_fail(m, TF_GEOM_FAILED, "gmsh made no 10-node tetrahedra in volume %zu",
                              v + 1);
        }
    }
    rc = rc ? rc : match_vertices(s, q, m);
    free(index);
    gmshFree(ntag);
    gmshFree(coord);
    gmshFree(par);
    return rc;
}

int tf_volume_mesh_tet10(const tf_surface *s, const tf_mesh_options *o,
                         const tf_mesh_inner *inner, size_t n_inner, unsigned refine,
                         tf_tet10_mesh *q, tf_geom_msg *m)
{
    memset(q, 0, sizeof *q);
    int rc = tf_volume_mesh_check_options(s, o, m);
    if (rc) {
        return rc;
    }
    tf_gmsh_begin();
    int ierr = tf_volume_mesh_model(s, o, inner, n_inner);
    for (unsigned k = 0; ierr == 0 && k < refine; ++k) {
        gmshModelMeshRefine(&ierr);
    }
    if (ierr == 0) {
        gmshModelMeshSetOrder(2, &ierr);
    }
    rc = ierr ? tf_gmsh_fail(m, TF_GEOM_FAILED, "gmsh could not mesh, refine or raise the order")
              : collect(s, n_inner, q, m);
    tf_gmsh_end();
    if (rc) {
        tf_tet10_mesh_free(q);
    }
    return rc;
}
