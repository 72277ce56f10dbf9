/*
 * nodes.h — node clouds.  Today a box filled with a regular grid of nodes
 * (optionally jittered inside); a surface mesh with a node spacing will
 * produce the same structure.
 */
#ifndef TF_NODES_H
#define TF_NODES_H

#include <stddef.h>
#include <stdint.h>

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
    double spacing[3]; /* nominal nodal spacing per axis, mm */
    double lo[3], hi[3];
    unsigned grid[3];  /* nodes per axis */
} tf_cloud;

/* Fills a box [lo, hi] with grid[0] x grid[1] x grid[2] nodes (each >= 2),
 * numbered top layer first (problem.h).  Interior nodes are moved by up to
 * jitter x spacing along each axis (uniform, from seed); nodes on the
 * boundary stay on it.  Returns 0, or -1 when out of memory. */
int tf_cloud_box(tf_cloud *c, const double lo[3], const double hi[3], const unsigned grid[3],
                 double jitter, uint64_t seed);
void tf_cloud_free(tf_cloud *c);

/* Index of the grid node (i, j, k), k = 0 at the bottom. */
size_t tf_cloud_index(const tf_cloud *c, unsigned i, unsigned j, unsigned k);

/* Geometric tolerance for "on a face / plane": 1e-9 of the box diagonal. */
double tf_cloud_tol(const tf_cloud *c);

/* Coordinate of a face's plane. */
double tf_cloud_face_coord(const tf_cloud *c, tf_face f);

#endif /* TF_NODES_H */
