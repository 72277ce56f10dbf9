/*
 * surface_prepare.h — a mesh file to a checked, closed, outward-wound
 * surface in millimetres, or a clear refusal.  In order:
 *
 *  1. read (surface_read.h);
 *  2. refuse a triangle that names one vertex twice;
 *     drop vertices no triangle uses (note);
 *  3. refuse an open surface (an edge of one triangle), a non-manifold
 *     edge (three or more triangles) or inconsistent winding (two triangles
 *     traverse an edge the same way);
 *  4. pieces: keep the largest (by enclosed volume) and drop the others
 *     with a note when each of them encloses under 1 % of it (the liver.vtk
 *     specks); refuse otherwise (two organs in one file, or a cavity);
 *  5. inward winding (negative enclosed volume): reverse every triangle
 *     (note); refuse zero volume;
 *  6. transform (transform.h);
 *  7. refuse absurd units: the largest bounding-box extent under 1 mm or
 *     over 1 m after scaling;
 *  8. refuse self-intersections (self_intersect.h).
 *
 * Messages name vertices and triangles by their index in the file as read
 * (0-based, surface_read.h) and give coordinates in file units before step
 * 6, millimetres after.
 */
#ifndef TF_SURFACE_PREPARE_H
#define TF_SURFACE_PREPARE_H

#include "geometry/geom_msg.h"
#include "geometry/surface.h"
#include "geometry/transform.h"

/* Smallest and largest accepted bounding-box extent after scaling, mm. */
#define TF_SURFACE_MIN_MM 1.0
#define TF_SURFACE_MAX_MM 1000.0

/* Largest volume of a dropped piece, as a fraction of the kept one. */
#define TF_SURFACE_SPECK 0.01

/* Steps 1-8.  Returns TF_GEOM_OK (s holds the surface; m->notes the
 * repairs), TF_GEOM_BAD_INPUT or TF_GEOM_FAILED (m->error; s empty). */
int tf_surface_load(const char *path, const tf_transform *t, tf_surface *s, tf_geom_msg *m);

/* Steps 2-5 on a surface in memory. */
int tf_surface_clean(tf_surface *s, tf_geom_msg *m);

/* Steps 7-8 on a placed surface. */
int tf_surface_check_placed(const tf_surface *s, tf_geom_msg *m);

#endif /* TF_SURFACE_PREPARE_H */
