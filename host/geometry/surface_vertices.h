/*
 * surface_vertices.h — is every vertex of a closed, consistently wound
 * surface a manifold vertex: do the triangles around it form one disc (one
 * fan closing on itself)?  Two closed surfaces joined at one vertex pass
 * every edge check (each edge has two triangles traversing it in opposite
 * directions) but their shared vertex has two fans: the volume mesher and
 * the winding numbers take such a pinch for one body.
 */
#ifndef TF_SURFACE_VERTICES_H
#define TF_SURFACE_VERTICES_H

#include <stddef.h>

#include "geometry/surface.h"

typedef struct tf_vertex_fault {
    size_t count; /* non-manifold vertices */
    size_t v;     /* the first (lowest index) */
    size_t fans;  /* how many separate fans of triangles meet there */
} tf_vertex_fault;

/* Counts the vertices whose triangles form more than one fan; the surface
 * must be closed with every edge shared by two triangles traversing it in
 * opposite directions (surface_edges.h).  Returns 0, or -1 when out of
 * memory. */
int tf_surface_vertex_fans(const tf_surface *s, tf_vertex_fault *f);

#endif /* TF_SURFACE_VERTICES_H */
