/*
 * analytic.h — analytic solutions a problem may carry (problem.h,
 * tf_analytic; scene `reference:` section), to prescribe exact boundary
 * values and tractions and to measure a solver's error.  Solutions of linear
 * isotropic elasticity, with the problem's small-strain moduli.
 *
 * cantilever: Timoshenko-Goodier end-loaded beam (GUIDE §5) in plane
 * strain.  The beam runs along x from the bounding box's x- face (where the
 * exact displacement is imposed) to its x+ face (exact traction), y is
 * measured from the axis at the box's mid-height, D is the box's y extent,
 * and the end load P per unit thickness acts along +y.  Plane strain is the
 * 2-D formula with E -> E/(1-nu^2), nu -> nu/(1-nu); in 3-D it is exact with
 * u_z = 0 imposed on the z faces.
 *
 * linear: u = offset + gradient x (the patch test).
 */
#ifndef TF_ANALYTIC_H
#define TF_ANALYTIC_H

#include "problem/problem.h"

/* Displacement u (mm) and its gradient g[i*3+j] = du_i/dx_j at x; zero when
 * the problem has no analytic solution. */
void tf_analytic_eval(const tf_problem *p, const double x[3], double u[3], double g[9]);

/* Traction sigma(x) n on a face with outward normal along the face. */
void tf_analytic_traction(const tf_problem *p, tf_face face, const double x[3], double t[3]);

#endif /* TF_ANALYTIC_H */
