/*
 * surface_read.h — a triangle surface from a mesh file, read by maintained
 * libraries: OBJ, STL, PLY and OFF through assimp, legacy VTK (ASCII or
 * binary POLYDATA / UNSTRUCTURED_GRID) through gmsh.  Coordinates are in
 * file units (no transform, no checks: surface_prepare.h does both); an
 * OBJ's are the file's own digits (obj_digits.h), STL, PLY and OFF pass
 * through assimp's float32.
 *
 * The vertex order, and so `source`, is the reader's:
 *  - VTK (gmsh): the file's point order (source = point index, 0-based);
 *  - OBJ/STL/PLY/OFF (assimp): the order in which the face list first uses
 *    each distinct position (assimp's JoinIdenticalVertices after every
 *    attribute but the position is removed).  For OBJ this is NOT the order
 *    of the `v` lines in general; a renderer that loads the file with
 *    assimp sees the same order.
 */
#ifndef TF_SURFACE_READ_H
#define TF_SURFACE_READ_H

#include "geometry/geom_msg.h"
#include "geometry/surface.h"

/* The largest mesh file read: 16 MiB holds about 300,000 triangles as OBJ,
 * ten times the vertices a tissue model's cloud uses (the shipped organs'
 * files are under 1 MiB). */
#define TF_SURFACE_MAX_BYTES ((size_t)16 << 20)

/* By extension (case-insensitive).  Only a regular file of at most
 * TF_SURFACE_MAX_BYTES is handed to a reader.  Returns TF_GEOM_OK,
 * TF_GEOM_BAD_INPUT (unreadable file, not a regular file, too large,
 * unknown format, faces that are not triangles, no triangles) or
 * TF_GEOM_FAILED (out of memory), with m->error set. */
int tf_surface_read(const char *path, tf_surface *s, tf_geom_msg *m);

int tf_surface_read_assimp(const char *path, tf_surface *s, tf_geom_msg *m);
int tf_surface_read_gmsh(const char *path, tf_surface *s, tf_geom_msg *m);

#endif /* TF_SURFACE_READ_H */
