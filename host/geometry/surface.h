/*
 * surface.h — a closed triangle surface (an organ's skin): the vertices the
 * renderer draws and the triangles between them, with each vertex's index
 * in the file it came from.
 */
#ifndef TF_SURFACE_H
#define TF_SURFACE_H

#include <stddef.h>

typedef struct tf_surface {
    size_t nv;      /* vertex count */
    double *xyz;    /* 3 nv coordinates */
    long *source;   /* per vertex: its index in the file as read (surface_read.h) */
    size_t nt;      /* triangle count */
    size_t *tri;    /* 3 nt vertex indices; counter-clockwise seen from outside
                       once tf_surface_prepare() has run */
    size_t *tri_parent; /* nt: the file's triangle each lies on, after
                           tf_surface_refine(); NULL: the file's own triangles */
} tf_surface;

/* Allocates room for nv vertices and nt triangles (contents undefined;
 * source[i] = i).  Returns 0, or -1 when out of memory (s is then empty). */
int tf_surface_alloc(tf_surface *s, size_t nv, size_t nt);
void tf_surface_free(tf_surface *s);

/* Signed enclosed volume (divergence theorem, sum over triangles of
 * det[a b c] / 6 taken about the bounding-box centre to limit
 * cancellation): positive when the triangles wind counter-clockwise seen
 * from outside. */
double tf_surface_volume(const tf_surface *s);

/* Triangle t's term of that sum about the point o: the signed volume of
 * the cone from o over the triangle, det[a - o, b - o, c - o] / 6. */
double tf_surface_cone_volume(const tf_surface *s, size_t t, const double o[3]);

/* The centre of the bounding box (the origin tf_surface_volume uses). */
void tf_surface_centre(const tf_surface *s, double o[3]);

double tf_surface_area(const tf_surface *s);

/* Axis-aligned bounding box of the vertices. */
void tf_surface_bbox(const tf_surface *s, double lo[3], double hi[3]);

/* Reverses every triangle's winding (v0 v1 v2 -> v0 v2 v1). */
void tf_surface_reverse(tf_surface *s);

/* Keeps the triangles whose keep[t] is non-zero and the vertices they use,
 * renumbered in their old order; source indices follow their vertices.
 * Returns 0, or -1 when out of memory (s unchanged). */
int tf_surface_select(tf_surface *s, const unsigned char *keep);

#endif /* TF_SURFACE_H */
