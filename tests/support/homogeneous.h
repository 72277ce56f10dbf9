/*
 * homogeneous.h — homogeneous tests of the nonlinear solver against closed
 * forms (issue 13, acceptance 1), shared by the unit test and the study
 * (tests/solver/homogeneous.c, `make nonlinear-validation`).
 *
 * A cube [0, 10]^3 mm of jittered nodes on rollers (u_x = 0 on x-, u_y = 0
 * on y-, u_z = 0 on z-) in uniaxial stress along x: the x+ face is moved
 * (stretch control) or pulled by a uniform traction (force control).
 * Essential conditions by Nitsche's method with VCI-corrected gradients:
 * with both, a linear-complete basis reproduces the homogeneous field
 * exactly (docs/validation.md).
 */
#ifndef TF_HOMOGENEOUS_H
#define TF_HOMOGENEOUS_H

#include <stddef.h>

#include "base/context.h"
#include "materials/material.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define HOMOG_L 10.0   /* cube edge, mm */
#define HOMOG_XPLUS 3  /* fixed region index of the x+ face (stretch control) */

/* The closed form of uniaxial stress at axial stretch lam: the lateral
 * stretch (S_yy = S_zz = 0, a scalar Newton iteration on the law itself)
 * and the nominal stress P_xx (MPa).  Small-strain laws: lam = 1 + eps,
 * lateral 1 + eps_t, P = sigma_xx.  Returns 0, or -1. */
int homog_uniaxial(const tf_material *m, double lam, double *lateral, double *p);

/* The cube's scene: method "rpim-galerkin" or "efg-galerkin", material as
 * YAML flow text, stretch control (x+ moved by (lam_max - 1) L times the
 * load factor) or force control (a traction of total force_max N along x
 * on x+ times the load factor), extra "--set" overrides. */
tf_scene *homog_scene(tf_ctx *ctx, const char *method, const char *material, int stretch,
                      double lam_max, double force_max, const char *const *sets, size_t n_sets);

/* Largest |u - u_exact| over the nodes relative to the largest |u_exact|,
 * u_exact the homogeneous field of axial stretch lam and lateral stretch
 * lat. */
double homog_field_error(const tf_problem *p, const double *u, double lam, double lat);

#endif /* TF_HOMOGENEOUS_H */
