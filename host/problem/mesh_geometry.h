/*
 * mesh_geometry.h — an organ as a problem's geometry (problem.h,
 * TF_GEOMETRY_MESH): the surface file read, checked and placed
 * (geometry/surface_prepare.h), its volume filled with gmsh tetrahedra that
 * keep every surface vertex as a node (geometry/volume_mesh.h), and the two
 * checks of issue 15 acceptance 2 on every build: the cells' volume within
 * 1 % of the enclosed volume, and no interior node outside the surface
 * (winding number > 1/2).  Plus what the scene needs from the organ: its
 * node cloud, the surface vertex nearest a point
 * and the surface triangles of a contact site.
 */
#ifndef TF_MESH_GEOMETRY_H
#define TF_MESH_GEOMETRY_H

#include <stddef.h>
#include <stdint.h>

#include "geometry/geom_msg.h"
#include "problem/problem.h"

/* Largest |cells - enclosed| / enclosed volume accepted (acceptance 2). */
#define TF_PROBLEM_MESH_VOLUME_TOL 0.01

/* Builds g->tm, g->file_xyz, g->min_winding and g->notes from
 * g->path, g->place and g->mesh (filled by the caller).  Returns
 * TF_GEOM_OK, TF_GEOM_BAD_INPUT (an unusable file or option) or
 * TF_GEOM_FAILED, with m->error; g owns nothing on failure. */
int tf_problem_mesh_build(tf_mesh_geometry *g, tf_geom_msg *m);

/* The node cloud of the organ (a copy of the mesh's nodes; spacing: the
 * interior spacing on every axis).  Returns 0, or -1 when out of memory. */
int tf_problem_mesh_cloud(const tf_mesh_geometry *g, tf_cloud *c);

/* The file's vertex (node index; not a refined skin's midpoint) nearest p,
 * ties to the lowest index. */
uint32_t tf_problem_mesh_nearest_vertex(const tf_mesh_geometry *g, const double p[3]);

/* The node of the surface vertex whose index in the mesh file is `source`,
 * or -1 when the file has no such vertex (or it was dropped as a speck). */
long tf_problem_mesh_vertex_node(const tf_mesh_geometry *g, long source);

/* A contact site: the surface triangles whose file triangle's centroid
 * lies within radius of the surface vertex `centre` (a triangle partly
 * inside the ball counts when its centroid does, so the loaded area is a
 * union of whole file triangles, whatever the skin's refinement), into p (shape TF_PATCH_SURFACE, its own triangle list, their
 * total area).  Returns 0, 1 when no triangle qualifies, -1 when out of
 * memory. */
int tf_problem_mesh_site(const tf_mesh_geometry *g, uint32_t centre, double radius, tf_patch *p);

#endif /* TF_MESH_GEOMETRY_H */
