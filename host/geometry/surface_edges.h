/*
 * surface_edges.h — is a triangle surface closed and consistently wound?
 * Every edge must belong to exactly two triangles that traverse it in
 * opposite directions.
 */
#ifndef TF_SURFACE_EDGES_H
#define TF_SURFACE_EDGES_H

#include <stddef.h>

#include "geometry/surface.h"

typedef struct tf_edge_fault {
    size_t count;     /* edges with this fault */
    size_t v[2];      /* the first one's vertices (lowest vertex pair) */
    size_t tri[2];    /* one or two triangles on it */
} tf_edge_fault;

typedef struct tf_edge_report {
    size_t edges;              /* distinct edges */
    tf_edge_fault open;        /* used by one triangle */
    tf_edge_fault nonmanifold; /* used by three or more */
    tf_edge_fault flipped;     /* two triangles traverse it the same way */
} tf_edge_report;

/* Returns 0, or -1 when out of memory. */
int tf_surface_edges(const tf_surface *s, tf_edge_report *r);

#endif /* TF_SURFACE_EDGES_H */
