/*
 * discretisation_self.h — the solve's error against the physics measured by
 * the tool itself, for a scene with no finer reference solution.
 *
 * The scene is solved on three clouds: a coarser one, its own and a finer
 * one, the nodal spacing h times r, 1 and 1/r (r = 4/3; a box: every axis's
 * intervals, rounded so that a contact site given by node number stays a
 * node at the same point; an organ: the interior spacing, its surface
 * vertices staying the file's; an absolute RBF d_c with the spacing).  Each
 * cloud takes the same load cases at the contact site — a linear solve the
 * three unit forces, any other the six forces of the envelope's radius along
 * +-x, +-y, +-z from its centre, solved from rest (Newton's load steps; a
 * time-dependent solver's fully relaxed equilibrium) — and its displacement
 * field is evaluated at the scene's outputs and the contact point.  With the
 * differences D_c = u(rh) - u(h) and D_f = u(h) - u(h/r) over all of those,
 * the error u(h) - u is taken as C h^p (Richardson): the observed order p
 * solves
 *
 *     |D_c| / |D_f| = (r_c^p - 1) / (1 - r_f^-p)        (L2 norms)
 *
 * (r_c, r_f the levels' actual spacing ratios), and the error estimate is
 * E = D_f / (1 - r_f^-p), p taken between TF_SELF_ORDER_MIN and
 * TF_SELF_ORDER_MAX: an order observed beyond the cap (common before the
 * asymptotic range) would make the estimate smaller, and where none is
 * observed, or one below first order (the differences do not shrink: on an
 * organ, the scatter between unstructured clouds can outweigh the trend),
 * first order is taken, which makes it larger.  E then takes the place of a reference's difference
 * (discretisation.h): for a linear solve a bound over the force envelope,
 * linear in the force; otherwise the largest component over the six cases;
 * and the contact site's relative error.  The coarser pair's estimate,
 * D_c / (r_c^p - 1), bounded the same way, is stated beside it: the two
 * agree where the levels are in the asymptotic range, and their spread is
 * the estimate's own uncertainty.
 *
 * When the coarser cloud fails (its solve, a contact node no coarser grid
 * keeps, its set-up), the scene's cloud, h/r and h/r^2 are solved instead:
 * the same extrapolation gives the error of the h/r cloud, and the scene's
 * is its difference from the extrapolated solution (self_shifted, and the
 * short reason in self_shifted_why).  When a cloud's solve fails (Newton
 * past a limit point, a body that inverts) with the six forces of a
 * nonlinear solve at the envelope's radius, they are tried again at 0.75
 * and 0.5 of it (the figure's reach, discretisation.h); failing there too,
 * the measurement ends with the reason, and the header says "not measured".
 */
#ifndef TF_DISCRETISATION_SELF_H
#define TF_DISCRETISATION_SELF_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/discretisation.h"
#include "solvers/solver.h"

#define TF_SELF_FACTOR (4.0 / 3.0)
#define TF_SELF_ORDER_MIN 1.0
#define TF_SELF_ORDER_MAX 4.0
#define TF_SELF_MAX_CASES 6

/* The scene's problem with its nodal spacing times f, from whoever read
 * the scene (scene/scene_levels.h says how a box and an organ scale): make
 * returns it, or NULL with a message; release frees it. */
typedef struct tf_rescale {
    const tf_problem *(*make)(void *user, tf_ctx *ctx, double f);
    void (*release)(void *user, const tf_problem *p);
    void *user;
} tf_rescale;

/* Solves the coarser and finer clouds (one at a time) and s (problem p's
 * solver, the scene's own cloud), and fills out (source "self-measured",
 * the self_* fields, cases).  Returns 0; 1 when the scene cannot be
 * measured this way, the reason in ctx->err (a contact site that moves with
 * the cloud, clouds that give the same outputs); -1 with a message when a
 * finer cloud fails to build or solve. */
int tf_discretisation_self(tf_ctx *ctx, const tf_rescale *re, tf_solver *s, const tf_problem *p,
                           int contact, tf_discretisation *out);

#endif /* TF_DISCRETISATION_SELF_H */
