/*
 * pipeline.h — from a problem and its solver to fitted models
 * (docs/fitting.md): load cases (cases.h), every applicable family fitted with its orders
 * chosen by k-fold cross-validation, held-out errors of the float32 target,
 * the seed's Table 3 view, and the modal error-versus-rank table.
 */
#ifndef TF_FIT_PIPELINE_H
#define TF_FIT_PIPELINE_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/cases.h"
#include "fitting/families/zhou2017.h"
#include "fitting/plan.h"
#include "model/model.h"
#include "problem/problem.h"
#include "solvers/solver.h"

#define TF_FIT_MAX_RANK 24 /* modal ranks searched (and tabulated) */
#define TF_FIT_LEVELS 5    /* the seed's force levels: 0.2 .. 1.0 of the envelope */

typedef struct tf_family_fit {
    int applicable;
    char why[320];           /* when not applicable */
    tf_model *model;         /* fitted on every training case */
    double cv[TFIT_MAX_DEGREE + 1];     /* CV RMS by degree (nodal, contact; modal at its rank) */
    double cv_rank[TF_FIT_MAX_RANK + 1];/* modal: CV RMS by rank at its degree */
    double heldout_max, heldout_rms, heldout_rel_max;
    double seconds;          /* order selection and fit */
    /* Forward families: force s e_a at the seed's levels s = 0.2 .. 1.0 of the
     * envelope radius (superposed response as the truth).  table3[a][c]: RMS
     * over points and levels of error_c / s (mm/N, seed Table 3);
     * deviation[a][c]: the mean error over the levels at each point (mm,
     * seed Figs 5-13), 3 x 3 x n_out. */
    double table3[3][3];
    double *deviation;
    tf_zhou_orders zhou;     /* zhou2017 */
    tf_zhou_cv *zhou_cv;
} tf_family_fit;

typedef struct tf_fit_outcome {
    tf_cases cases;
    tf_family_fit fam[5];    /* indexed by tfit_family (1..4) */
    double rank_max[TF_FIT_MAX_RANK + 1]; /* modal held-out max error by rank, at its degree */
    uint32_t rank_10um;      /* smallest rank within 10 um, 0 if none */
    double seconds_cases;
} tf_fit_outcome;

/* Runs the whole fit of problem p with a solver of it.  A family that does
 * not apply to the problem is marked so (why[]).  Returns 0; -2 when the
 * plan's forward family does not apply (a problem the user must change); -1
 * on any other failure; with the message in the solver's context. */
int tf_fit_run(const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
               tf_fit_outcome *out);
void tf_fit_outcome_free(tf_fit_outcome *out);

#endif /* TF_FIT_PIPELINE_H */
