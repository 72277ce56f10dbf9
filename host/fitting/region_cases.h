/*
 * region_cases.h — a contact region's load cases for a solver that is not
 * affine (a nonlinear law): every (site, force) is solved, one case list
 * per site through the case runner (case_runner.h), so that the cases can
 * be spread over MPI ranks like any fit's.
 *
 * The cases act on a problem of the region's sites: a copy of the scene's
 * problem whose contact sites are the probe's patch at each site (its
 * contact k is site k), from which the solver is built.  Each site's list
 * holds the same forces, with the anchored continuation graph
 * (case_graph.h), and keeps every DOF: the patch-averaged displacement is
 * the solver's field averaged over the patch's points, the work-conjugate
 * of a uniform traction's resultant under dead loading.  The potential of
 * a site is then fitted by least squares on its gradient
 * (tf_region_potential_fit): every case gives three equations.
 */
#ifndef TF_REGION_CASES_H
#define TF_REGION_CASES_H

#include <stddef.h>

#include "base/context.h"
#include "fitting/case_runner.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef struct tf_region_cases {
    tf_problem problem;      /* the scene's problem with the sites as its contacts (storage
                                other than the contacts is the scene's: never release it) */
    const tf_contact_region *region;
    size_t n_sites;
    double *ab;              /* 2 n_sites, chart coordinates, mm */
    size_t n_force;
    double (*force)[3];      /* the forces of every site, chart frame, N */
    double (*force_scene)[3];/* the same in the scene frame (what the solver applies) */
    long *from;              /* the continuation graph */
    size_t *keep;            /* every DOF */
} tf_region_cases;

/* The cases of contact region `contact` of p at the sites ab (2 n) under
 * the forces (chart frame).  Returns 0, or -1 with the message. */
int tf_region_cases_build(tf_ctx *ctx, const tf_problem *p, int contact, const double *ab,
                          size_t n, const double (*force)[3], size_t n_force, tf_region_cases *c);
void tf_region_cases_free(tf_region_cases *c);

/* The case list of one site (its contact index is the site's). */
void tf_region_cases_list(const tf_region_cases *c, size_t site, tf_case_list *l);

/* The patch-averaged displacement (chart frame) at a site of a solution u
 * (3N): the solver's field averaged over the patch's points.  Returns 0,
 * or -1 with the message. */
int tf_region_cases_average(tf_ctx *ctx, const tf_solver *s, const tf_region_cases *c,
                            size_t site, const double *u, double out[3]);

/* The potential of degree P in v = s_u u (region_law.h) whose gradient
 * best fits the forces F (chart frame, N) at the patch-averaged
 * displacements u (mm) of m cases: least squares on s_u grad_v E = F, three
 * equations per case.  e holds tf_region_terms(P) coefficients; rms (may be
 * NULL): the residual's root mean square per case, N.  Returns 0, or -1
 * with the message. */
int tf_region_potential_fit(tf_ctx *ctx, unsigned P, double s_u, const double (*u)[3],
                            const double (*F)[3], size_t m, double *e, double *rms);

/* The force of potential e at displacement u: s_u grad_v E. */
void tf_region_potential_force(unsigned P, double s_u, const double *e, const double u[3],
                               double F[3]);

/* The smallest eigenvalue of the potential's Hessian in u at u (N/mm):
 * > 0 where the potential is strictly convex. */
double tf_region_potential_min_curvature(unsigned P, double s_u, const double *e,
                                         const double u[3]);

#endif /* TF_REGION_CASES_H */
