/*
 * region_models.h — a contact region's two device models from its fit:
 * the law (TFIT_FAMILY_REGION) and the surface for the current contact
 * (TFIT_FAMILY_REGION_SURFACE, p = 1 with site modes: the two-instrument
 * form), built from the last spacing of tf_region_fit (region_fit.h) with
 * the numbers their header states.
 *
 * What the models state (tf_model's metadata), all measured at the cell
 * centres of the last spacing's grid, sites never fitted, solved for real
 * (region_fit.h defines the errors), on the fit in double:
 *
 *   law      held-out max = force x R_F (N: the worst force error over the
 *            envelope's sphere at the true patch-averaged displacement),
 *            RMS over the cell centres likewise, relative max = force;
 *   surface  held-out max = surface x peak (mm), RMS likewise, relative
 *            max = surface (of the peak displacement);
 *
 * and in fit_note: the site spacing and count and why the density rule
 * stopped there (the targets met, or the cap), the rank, the
 * two-instrument coupling error and its pairs, the rest surface's height
 * error, the smallest stiffness (passivity) and the regeneration time.
 */
#ifndef TF_REGION_MODELS_H
#define TF_REGION_MODELS_H

#include "base/context.h"
#include "fitting/region_fit.h"
#include "model/model.h"
#include "problem/problem.h"
#include "solvers/solver.h"

/* Fits contact region `contact` of p with solver s (tf_region_fit, the
 * default targets) and builds its law and surface (names law_name and
 * surf_name).  Refuses, with a "not yet: ..." message, what the region
 * fit does not cover: a solver that is not affine (a nonlinear law), an
 * envelope not centred on zero (-2 then: a scene the tool cannot fit).
 * Returns 0 with *law and *surf owned by the caller, or -1 with the
 * message. */
int tf_region_models(tf_ctx *ctx, tf_solver *s, const tf_problem *p, int contact,
                     const char *law_name, const char *surf_name, tf_model **law,
                     tf_model **surf);

/* The law and the surface of one fitted spacing lv of contact region
 * `contact` of p as device models (no datasheet notes).  Returns 0 with
 * *law and *surf owned by the caller, or -1 with the message. */
int tf_region_level_models(tf_ctx *ctx, const tf_problem *p, int contact,
                           const tf_region_level *lv, const char *law_name,
                           const char *surf_name, tf_model **law, tf_model **surf);

#endif /* TF_REGION_MODELS_H */
