/*
 * volume_mesh.h — a tetrahedral mesh of the volume a checked surface
 * encloses (surface_prepare.h), by gmsh: the surface's triangles become a
 * discrete surface entity, bounded as a surface loop into a volume, which
 * gmsh's Delaunay mesher fills (mesh.generate(3)).  The surface is not
 * remeshed: its vertices are nodes, its triangles are the faces of the
 * boundary tetrahedra, whatever the spacing.  The spacing sets the node
 * density inside, through a background size field: constant, or graded
 * towards a point with gmsh's Distance and Threshold fields.
 *
 * The result is checked before it is returned (tetmesh_check.h): every
 * tetrahedron positive, every surface vertex a node with unchanged
 * coordinates, the boundary faces exactly the surface's triangles.
 */
#ifndef TF_VOLUME_MESH_H
#define TF_VOLUME_MESH_H

#include "geometry/geom_msg.h"
#include "geometry/surface.h"
#include "geometry/tetmesh.h"

typedef struct tf_mesh_options {
    double spacing;       /* target node spacing inside, mm */
    int graded;           /* grade towards grade_at */
    double grade_at[3];   /* the contact site, mm */
    double grade_spacing; /* spacing within grade_radius of grade_at, mm */
    double grade_radius;  /* mm */
    double grade_ramp;    /* distance at which the spacing is back to `spacing`, mm */
    int refine_skin;      /* split the surface's triangles to the spacing first
                             (surface_refine.h; tf_problem_mesh_build does it) */
} tf_mesh_options;

/* The spacing the size field asks for at x, mm: `spacing`, or graded as
 * gmsh's Threshold field grades it (grade_spacing up to grade_radius from
 * grade_at, linear to spacing at grade_ramp). */
double tf_mesh_size_at(const tf_mesh_options *o, const double x[3]);

/* A refined skin's edges: split while longer than this times the size. */
#define TF_MESH_SKIN_RATIO 1.4142135623730951
/* ... into at most this many vertices. */
#define TF_MESH_MAX_SKIN_VERTICES 2000000

/* A closed surface inside the body that a mesh conforms to (a material
 * region's boundary, volume_mesh_tet10.h): it bounds a volume of its own
 * and is a hole of the body's.  Inner surfaces must not touch each other
 * or the body's surface. */
#define TF_MESH_MAX_INNER 8
typedef struct tf_mesh_inner {
    const tf_surface *surface; /* counter-clockwise seen from outside */
    double centre[3], radius;  /* a ball holding it, mm */
    double spacing;            /* mesh size within the ball, rising linearly to the
                                  body's spacing one radius further out, mm */
} tf_mesh_inner;

/* Largest number of tetrahedra a spacing may ask for (an estimate from the
 * volume, checked before meshing). */
#define TF_MESH_MAX_TETS 20000000.0

/* Returns TF_GEOM_OK, TF_GEOM_BAD_INPUT (options out of range) or
 * TF_GEOM_FAILED (the mesher failed, or its mesh failed a check), with
 * m->error set; t is empty on failure. */
int tf_volume_mesh(const tf_surface *s, const tf_mesh_options *o, tf_tetmesh *t,
                   tf_geom_msg *m);

/* The two steps of tf_volume_mesh that others reuse (volume_mesh_tet10.h):
 * the options' check (TF_GEOM_OK or TF_GEOM_BAD_INPUT with m->error), and
 * the model built and meshed in the current gmsh session, conforming to
 * the inner surfaces (volume 1 the body, volume k + 2 inner surface k; 0,
 * or gmsh's error code). */
int tf_volume_mesh_check_options(const tf_surface *s, const tf_mesh_options *o, tf_geom_msg *m);
int tf_volume_mesh_model(const tf_surface *s, const tf_mesh_options *o,
                         const tf_mesh_inner *inner, size_t n_inner);

#endif /* TF_VOLUME_MESH_H */
