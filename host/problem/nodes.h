/*
 * nodes.h — node clouds.  Today a box filled with a grid of nodes, uniform
 * or graded along each axis (optionally jittered inside); or an organ's
 * mesh vertices (problem/mesh_geometry.c: no grid lines, its index space
 * (x - lo) / spacing).
 *
 * Index space: a box grid's node (i, j, k) sits at index coordinates
 * (i, j, k) (before jitter), and the map between a coordinate and its
 * fractional index is linear between grid lines.  On a uniform grid it is
 * (x - lo) / spacing; on a graded grid it straightens the grading, so that
 * support domains of a fixed size in index space hold the same number of
 * nodes everywhere (meshfree/shape.c).
 */
#ifndef TF_NODES_H
#define TF_NODES_H

#include <stddef.h>
#include <stdint.h>

#include "problem/grading.h"

/* Faces of a box, named in scene files "x-", "x+", "y-", "y+", "z-", "z+". */
typedef enum tf_face {
    TF_FACE_XMIN,
    TF_FACE_XMAX,
    TF_FACE_YMIN,
    TF_FACE_YMAX,
    TF_FACE_ZMIN,
    TF_FACE_ZMAX,
} tf_face;

static inline int tf_face_axis(tf_face f) { return (int)f / 2; }
static inline int tf_face_is_max(tf_face f) { return (int)f % 2; }
/* The in-face axes (u, v): (x, y) on z faces, (y, z) on x faces, (x, z) on y faces. */
void tf_face_axes(tf_face f, int *u, int *v);

typedef struct tf_cloud {
    size_t n;          /* node count */
    double *xyz;       /* 3 n coordinates, node index order, mm */
    double spacing[3]; /* nominal (mean) nodal spacing per axis, mm */
    double lo[3], hi[3];
    unsigned grid[3];  /* nodes per axis (a box; 0 for an organ's mesh) */
    size_t n_surface;  /* an organ's mesh: nodes 0 .. n_surface - 1 are its surface
                          vertices; 0 for a box */
    double *axis[3];   /* the grid lines: grid[a] coordinates per axis, ascending, mm
                          (NULL for an organ's mesh) */
    int graded;        /* some axis is not uniform (0 for an organ's mesh) */
} tf_cloud;

/* Fills a box [lo, hi] with grid[0] x grid[1] x grid[2] nodes (each >= 2),
 * numbered top layer first (problem.h), on a uniform grid.  Interior nodes
 * are moved by up to jitter x spacing along each axis (uniform, from seed);
 * nodes on the boundary stay on it.  Returns 0, or -1 when out of memory. */
int tf_cloud_box(tf_cloud *c, const double lo[3], const double hi[3], const unsigned grid[3],
                 double jitter, uint64_t seed);
/* The same on the graded grid g describes (NULL: uniform, the same bits as
 * tf_cloud_box); jitter is then a fraction of the smaller neighbouring
 * interval along each axis. */
int tf_cloud_box_graded(tf_cloud *c, const double lo[3], const double hi[3],
                        const unsigned grid[3], double jitter, uint64_t seed,
                        const tf_cloud_grading *g);
void tf_cloud_free(tf_cloud *c);

/* Fractional grid index of coordinate x along axis a (clamped to the box),
 * and the coordinate of a fractional index (the index map above). */
double tf_cloud_to_index(const tf_cloud *c, int a, double x);
double tf_cloud_from_index(const tf_cloud *c, int a, double xi);

/* The nodal spacing per axis around x: the grid interval that holds x (the
 * nominal spacing on a uniform grid). */
void tf_cloud_local_spacing(const tf_cloud *c, const double x[3], double h[3]);

/* Index of the grid node (i, j, k), k = 0 at the bottom. */
size_t tf_cloud_index(const tf_cloud *c, unsigned i, unsigned j, unsigned k);

/* Geometric tolerance for "on a face / plane": 1e-9 of the box diagonal. */
double tf_cloud_tol(const tf_cloud *c);

/* Coordinate of a face's plane. */
double tf_cloud_face_coord(const tf_cloud *c, tf_face f);

#endif /* TF_NODES_H */
