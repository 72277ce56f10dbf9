/*
 * reference.h — analytic solutions that verification scenes are checked
 * against (scene `reference:` section).
 *
 * cantilever: Timoshenko-Goodier end-loaded beam (GUIDE §5) in plane
 * strain.  The beam runs along x from the box's x- face (where the exact
 * displacement is imposed) to its x+ face (exact traction), y is measured
 * from the axis at the box's mid-height, D is the box's y extent, and the
 * end load P per unit thickness acts along +y.  Plane strain is the 2-D
 * formula with E -> E/(1-nu^2), nu -> nu/(1-nu); in 3-D it is exact with
 * u_z = 0 imposed on the z faces.
 *
 * linear: u = offset + gradient x (the patch test).
 */
#ifndef TF_REFERENCE_H
#define TF_REFERENCE_H

#include "scene/scene.h"

/* Displacement u (mm) and its gradient g[i*3+j] = du_i/dx_j at x. */
void tf_reference_eval(const tf_scene *s, const double x[3], double u[3], double g[9]);

/* Traction sigma(x) n on a face with outward normal along the face. */
void tf_reference_traction(const tf_scene *s, tf_face face, const double x[3], double t[3]);

#endif /* TF_REFERENCE_H */
