/*
 * tetmesh.h — the meshless solver's view of an organ: a node cloud filling
 * a closed surface and the tetrahedra between the nodes, which are the
 * integration cells (tet_rules.h gives their Gauss points).
 *
 * Nodes 0 .. nsurf - 1 are the surface's vertices, in the surface's order
 * and with its coordinates bit for bit (the renderer's mesh); the interior
 * nodes follow.  source[i] maps a node to the vertex index in the file
 * (surface_read.h says which order that is), -1 for interior nodes.
 */
#ifndef TF_TETMESH_H
#define TF_TETMESH_H

#include <stddef.h>

typedef struct tf_tetmesh {
    size_t nn;         /* nodes */
    size_t nsurf;      /* of which the first nsurf are surface vertices */
    double *xyz;       /* 3 nn, mm */
    long *source;      /* nn: file vertex index, or -1 inside */
    size_t ntet;
    size_t *tet;       /* 4 ntet node indices, positively oriented */
    double *tet_volume;/* ntet, mm^3 */
    size_t ntri;
    size_t *tri;       /* 3 ntri node indices: the surface triangles, outward */
    size_t *tri_parent;/* ntri: the file's triangle each lies on when the skin
                          was refined (surface_refine.h), else NULL */
    double enclosed_volume; /* of the surface, mm^3 (divergence theorem) */
    double cells_volume;    /* sum of tet_volume, mm^3 */
} tf_tetmesh;

void tf_tetmesh_free(tf_tetmesh *t);

/* Signed volume of tetrahedron abcd: det[b - a, c - a, d - a] / 6. */
double tf_tet_volume(const double a[3], const double b[3], const double c[3], const double d[3]);

/* Fills tet_volume and cells_volume from xyz and tet. */
void tf_tetmesh_volumes(tf_tetmesh *t);

#endif /* TF_TETMESH_H */
