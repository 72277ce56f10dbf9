/*
 * nonlinear.h — the meshless Galerkin solver for any material law
 * (materials/material.h; the nonlinear ones are what it is for):
 * total-Lagrangian Newton-Raphson with the consistent tangent, load
 * stepping with automatic cuts and a line search (docs/solver.md,
 * "Nonlinear laws").  Registered as "rpim-newton" (RPIM shape functions)
 * and "efg-newton" (MLS, essential conditions in weak form);
 * rpim-galerkin and efg-galerkin (galerkin/galerkin.h) hand it every
 * problem whose material is not linear elastic, and the instance then
 * answers to the Newton solver's name.
 *
 * It asks the material only for its capabilities and quantities: its
 * kinematics, whether its tangent may be unsymmetric (GMRES instead of
 * Cholesky), its history and relaxation function, its volume measure (the
 * volumetric correction) and its initial moduli (the correction's modulus,
 * the weak boundary terms' scale).
 *
 * Capabilities: not affine (every case is solved, continuing from the
 * starting displacements a caller passes); a material with history makes
 * it TIME_DEPENDENT: tf_solver_history follows a force history from rest,
 * and tf_solver_solve gives the fully relaxed equilibrium.  Contact forces
 * are dead loads: fixed direction and total, spread over the patch's
 * reference area.
 */
#ifndef TF_NONLINEAR_H
#define TF_NONLINEAR_H

#include <stddef.h>

#include "base/context.h"
#include "solvers/solver.h"

extern const tf_solver_ops tf_rpim_newton_ops; /* "rpim-newton" */
extern const tf_solver_ops tf_efg_newton_ops;  /* "efg-newton": MLS shape functions */

/* The nonlinear solver of a problem (efg: MLS shape functions), with the
 * type above.  NULL with a message in ctx->err. */
tf_solver *tf_nonlinear_create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx,
                               int efg);

/* What the Newton solver did so far (NULL for another kind of solver). */
typedef struct tf_nonlinear_info {
    size_t steps, cuts, iterations;     /* load steps converged, halvings, Newton iterations */
    size_t residuals, tangents;         /* assemblies without and with the tangent */
    size_t factorisations, krylov;      /* numeric factorisations, Krylov iterations */
    size_t indefinite;                  /* of the factorisations, simplicial LDL^T ones of a
                                         * tangent that was not positive definite */
    size_t kept;                        /* of the factorisations, attempts that found the tangent
                                         * not positive definite: the older factor kept */
    size_t shifted;                     /* of the factorisations, those of a shifted tangent
                                         * (solver.newton.indefinite: shift), failed ones too */
    double shift;                       /* the current case's last positive definite shift
                                         * (0: none) */
    size_t patch_dofs, patches;         /* the patch tangent: |A|, block updates */
    size_t patch_kept;                  /* of the updates, not positive definite */
    double t_patch;                     /* s: its cell tangents and block updates */
    double t_gradients;                 /* s: shape functions and gradients (once) */
    double t_residual, t_tangent, t_factor, t_solve; /* s, wall */
    double nnz_l;                       /* entries in the factor */
    const char *ordering;
} tf_nonlinear_info;

int tf_nonlinear_info_of(const tf_solver *s, tf_nonlinear_info *info);

/* ---- time stepping beyond tf_solver_history (tissuefit solve) ---- */

/* Back to rest: no displacement, no history, no load. */
int tf_nonlinear_reset(tf_solver *s);

/* Equilibrium under the problem's loads and prescribed displacements
 * times scale plus force (N) at contact site contact (-1: none), dt
 * seconds after the current state (dt = 0: an instantaneous jump; elastic
 * laws ignore dt).  Returns 0, or -1 with a message naming the load step,
 * the force and the node or point. */
int tf_nonlinear_advance(tf_solver *s, double scale, int contact, const double force[3],
                         double dt);

/* The current state's displacements at the nodes (3N). */
int tf_nonlinear_displacements(tf_solver *s, double *u);

/* The force (N) the supports of fixed region `region` (problem.h order)
 * exert on the body in the current state: with weak essential conditions
 * the region's boundary terms, with elimination the residual at its
 * prescribed DOFs.  Returns 0, or -1 with a message. */
int tf_nonlinear_region_force(tf_solver *s, size_t region, double force[3]);

/* ---- stability of the current state (nl_stability.c) ---- */

/* The least eigenvalue mu_1 of K_t v = mu K_0 v (K_t the tangent at the
 * current state, K_0 at rest): 1 at rest, <= 0 at or past a limit or
 * bifurcation point.  Bracketed by Cholesky factorisations of
 * K_t - sigma K_0 (positive definite exactly when sigma < mu_1). */
typedef struct tf_nonlinear_stability {
    double lo, hi;         /* lo < mu_1 <= hi, hi - lo <= tol */
    double mu;             /* the Rayleigh quotient of the mode (inverse iteration) */
    int definite;          /* K_t itself is positive definite (mu_1 > 0) */
    size_t node;           /* the node that moves most in the mode */
    double dir[3];         /* the unit direction it moves in (sign arbitrary) */
    size_t factorisations; /* of the probe (the Newton solver's counters are unchanged) */
    double seconds;        /* wall */
} tf_nonlinear_stability;

/* The stability of the current state to within tol in mu (elastic laws
 * only; the state and the Newton solver's factors are unchanged).  Returns
 * 0, or -1 with a message. */
int tf_nonlinear_stability_of(tf_solver *s, double tol, tf_nonlinear_stability *out);

#endif /* TF_NONLINEAR_H */
