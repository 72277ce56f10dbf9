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
 * training case.  Held-out cases are always solved directly, so the
 * held-out error also checks the superposition.  Any other solver solves
 * every case, one by one, as one case list (case_runner.h: training, the
 * three single-axis sets, held-out, the seed-table levels) with the
 * anchored continuation graph (case_graph.h), by the plan's runner: here,
 * or spread over MPI ranks (dist/), with the same bits.  Forces are rounded
 * to float first: the firmware receives float forces, and the comparison is
 * then at exactly the input the target evaluates.  Messages go to the
 * solver's context.
 */
#ifndef TF_FIT_CASES_H
#define TF_FIT_CASES_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/fitdata.h"
#include "fitting/plan.h"
#include "problem/problem.h"
#include "solvers/solver.h"

struct tf_histories; /* histories.h */
struct tf_cut_cases; /* cut_progress.h */

typedef struct tf_cases {
    tf_solver *solver;       /* what solved them (outlives the cases) */
    const tf_problem *problem;
    int contact;             /* contact site index */
    uint32_t contact_node;   /* its node index */
    /* The contact model's node id: the site's node number, or, when the site
     * is given by position and is one of the output points, that output's
     * number (outputs by position are numbered 1 ... n), so that firmware
     * finds the contact among the forward model's outputs by its id. */
    uint32_t contact_id;
    int affine;              /* the solver declared itself affine: unit responses exist */
    int superposed;          /* training cases from unit responses */
    size_t solves;           /* right-hand sides solved */
    tf_fitdata train, heldout, axis[3];
    /* Force histories and their responses when the body creeps (a
     * time-dependent solver): what the prony family fits; NULL otherwise.
     * Not owned. */
    const struct tf_histories *hist;
    /* Responses at a sequence of cut progress values when the plan asks
     * for them (cut_progress.h): what the cut family fits; NULL otherwise.
     * Not owned. */
    const struct tf_cut_cases *cut;
    /* Affine solvers: unit responses at the outputs (3 n_out) and the
     * contact site (3): u(f) = base + sum_k f_k unit[k]. */
    double *base, *unit[3], base_contact[3], unit_contact[3][3];
    /* Other solvers: the outputs at the seed-table forces
     * (tf_cases_level_force), 3 n_out per force, axis after axis. */
    double *table;
    /* storage behind the tf_fitdata views */
    uint32_t *node_ids;
    double (*rest)[3];
    void *blocks[24];
    int n_blocks;
} tf_cases;

/* Designs and solves the load cases of a fit of problem p (its outputs and
 * envelope) with a solver of it, as the plan says (contact site, n_train >=
 * 6 training and n_heldout held-out cases, seed, direct: solve every
 * training case even when the solver is affine; runner: where the cases of
 * a solver that is not affine are solved).  Returns 0, or -1 with a message
 * in the solver's context. */
int tf_cases_build(const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
                   tf_cases *c);
void tf_cases_free(tf_cases *c);

/* The response to force f: u (3 n_out) and the contact-site displacement
 * (either may be NULL), superposed from the unit responses when the solver
 * is affine, else solved.  Returns 0, or -1 with a message in the solver's
 * context. */
int tf_cases_response(tf_cases *c, const double f[3], double *u, double contact[3]);

/* The seed's force levels of its Table 3: 0.2 .. 1.0 of the envelope. */
#define TF_FAMILY_LEVELS 5

/* The seed's Table 3 forces (TF_FAMILY_LEVELS levels):
 * the envelope centre moved by level / LEVELS of the radius along axis a,
 * rounded to float (level 1 .. LEVELS). */
void tf_cases_level_force(const tf_fitdata *d, int a, int level, double f[3]);

/* The outputs' response (3 n_out) at tf_cases_level_force(a, level):
 * superposed, or solved with the other cases. */
void tf_cases_level_response(const tf_cases *c, int a, int level, double *u);

#endif /* TF_FIT_CASES_H */
