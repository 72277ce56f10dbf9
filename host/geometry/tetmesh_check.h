/*
 * tetmesh_check.h — is a tetrahedral mesh exactly the volume its surface
 * encloses?
 *
 * Topology (cheap, run on every mesh by tf_volume_mesh): every tetrahedron
 * has positive volume; every surface vertex is a node at its coordinates
 * bit for bit; every node belongs to a tetrahedron; every face is shared by
 * two tetrahedra in opposite orientations, or is a face of one tetrahedron
 * that equals a surface triangle with the same (outward) orientation, and
 * every surface triangle is such a face.  A mesh that passes fills exactly
 * the region the surface bounds, so its cells' volume is the enclosed
 * volume up to rounding.
 *
 * Inside test (independent of the mesher's topology, costs nodes x
 * triangles): the generalised winding number of every interior node
 * with respect to the surface (winding.h) must exceed 1/2.
 */
#ifndef TF_TETMESH_CHECK_H
#define TF_TETMESH_CHECK_H

#include <stddef.h>

#include "geometry/geom_msg.h"
#include "geometry/surface.h"
#include "geometry/tetmesh.h"

typedef struct tf_tetmesh_faults {
    size_t nonpositive; /* tetrahedra of volume <= 0 */
    size_t moved;       /* surface vertices missing or not at their coordinates */
    size_t unused;      /* nodes of no tetrahedron */
    size_t extra;       /* faces of one tetrahedron that are no surface triangle */
    size_t missing;     /* surface triangles that are no tetrahedron's face */
    size_t bad_faces;   /* faces of three or more, or two not opposed */
} tf_tetmesh_faults;

/* Returns 0, or -1 when out of memory. */
int tf_tetmesh_topology(const tf_tetmesh *t, const tf_surface *s, tf_tetmesh_faults *f);

/* Runs tf_tetmesh_topology; TF_GEOM_OK, or TF_GEOM_FAILED with a message
 * counting each fault. */
int tf_tetmesh_check_topology(const tf_tetmesh *t, const tf_surface *s, tf_geom_msg *m);

typedef struct tf_inside_report {
    size_t tested;      /* interior nodes */
    size_t outside;     /* of which winding number <= 1/2 */
    double min_winding; /* smallest winding number among them (1 when none) */
    size_t worst;       /* node index of the smallest */
} tf_inside_report;

void tf_tetmesh_inside(const tf_tetmesh *t, const tf_surface *s, tf_inside_report *r);

#endif /* TF_TETMESH_CHECK_H */
