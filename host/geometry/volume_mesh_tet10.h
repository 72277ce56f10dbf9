/*
 * volume_mesh_tet10.h — the finite-element reference's mesh of an organ
 * (tests/calculix/organ_deck.c): gmsh fills the surface exactly as
 * tf_volume_mesh does (same model, options and size field), refines the
 * result `refine` times by splitting every tetrahedron into eight (the
 * surface triangles into four, on their own planes, so the volume stays the
 * same polyhedron), and raises it to second order (gmsh's 10-node
 * tetrahedra).  The surface vertices keep their coordinates bit for bit;
 * vertex i of the surface is node vertex_node[i].  With inner surfaces
 * (volume_mesh.h, tf_mesh_inner: a material region's boundary) the mesh
 * conforms to them and each tetrahedron names its region.
 */
#ifndef TF_VOLUME_MESH_TET10_H
#define TF_VOLUME_MESH_TET10_H

#include <stddef.h>

#include "geometry/geom_msg.h"
#include "geometry/surface.h"
#include "geometry/volume_mesh.h"

typedef struct tf_tet10_mesh {
    size_t nn;
    double *xyz;          /* 3 nn, mm */
    size_t ntet;
    size_t *tet;          /* 10 node indices per tetrahedron in CalculiX's C3D10 order:
                             corners 0-3, then the nodes of edges 01, 12, 20, 03, 13, 23 */
    size_t *vertex_node;  /* nv: the node of each surface vertex */
    int *region;          /* ntet: 0 the body, k + 1 inside inner surface k */
} tf_tet10_mesh;

void tf_tet10_mesh_free(tf_tet10_mesh *q);

/* Returns TF_GEOM_OK, TF_GEOM_BAD_INPUT or TF_GEOM_FAILED (m->error). */
int tf_volume_mesh_tet10(const tf_surface *s, const tf_mesh_options *o,
                         const tf_mesh_inner *inner, size_t n_inner, unsigned refine,
                         tf_tet10_mesh *q, tf_geom_msg *m);

#endif /* TF_VOLUME_MESH_TET10_H */
