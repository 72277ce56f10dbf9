/*
 * cases.h — the solved load cases behind a fit: training forces filling
 * the envelope, held-out forces never used by a fit (force_samples.h), the
 * displacements of the problem's output points and of the contact site, and
 * single-axis training cases for the zhou2017 family.
 *
 * When the solver declares its response affine in the contact force
 * (TF_SOLVER_AFFINE, solvers/solver.h: linear elasticity, the problem's
 * loads adding a constant), the training displacements come from
 * superposition of the unit responses, unless direct solves are asked for:
 * one solve with no contact force and three with unit forces span every
 * training case.  Any other solver solves every case.  Held-out cases are
 * always solved directly, so the held-out error also checks the
 * superposition.  Forces are rounded to float first: the firmware receives
 * float forces, and the comparison is then at exactly the input the target
 * evaluates.  Messages go to the solver's context.
 */
#ifndef TF_FIT_CASES_H
#define TF_FIT_CASES_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/fitdata.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef struct tf_cases {
    tf_solver *solver;       /* what solved them (outlives the cases) */
    const tf_problem *problem;
    int contact;             /* contact site index */
    uint32_t contact_node;   /* its node index */
    int affine;              /* the solver declared itself affine: unit responses exist */
    int superposed;          /* training cases from unit responses */
    size_t solves;           /* right-hand sides solved */
    tf_fitdata train, heldout, axis[3];
    /* Affine solvers: unit responses at the outputs (3 n_out) and the
     * contact site (3): u(f) = base + sum_k f_k unit[k]. */
    double *base, *unit[3], base_contact[3], unit_contact[3][3];
    /* storage behind the tf_fitdata views */
    uint32_t *node_ids;
    double (*rest)[3];
    void *blocks[16];
    int n_blocks;
} tf_cases;

/* Designs and solves the load cases of a fit (n_train >= 6) of problem p
 * (its outputs, contact site and envelope) with a solver of it.  direct != 0
 * solves every training case even when the solver is affine.  Returns 0, or
 * -1 with a message in the solver's context. */
int tf_cases_build(const tf_problem *p, tf_solver *solver, int contact, size_t n_train,
                   size_t n_heldout, uint64_t seed, int direct, tf_cases *c);
void tf_cases_free(tf_cases *c);

/* The response to force f: u (3 n_out) and the contact-site displacement
 * (either may be NULL), superposed from the unit responses when the solver
 * is affine, else solved.  Returns 0, or -1 with a message in the solver's
 * context. */
int tf_cases_response(tf_cases *c, const double f[3], double *u, double contact[3]);

#endif /* TF_FIT_CASES_H */
