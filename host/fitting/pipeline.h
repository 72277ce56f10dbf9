/*
 * pipeline.h — from a problem and its solver to fitted models
 * (docs/fitting.md): load cases (cases.h), then every registered family
 * (families/family.h) that applies, its orders chosen by k-fold
 * cross-validation, its held-out errors of the float32 target and, for
 * forward families, the seed's Table 3 view.
 */
#ifndef TF_FIT_PIPELINE_H
#define TF_FIT_PIPELINE_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/cases.h"
#include "fitting/cut_progress.h"
#include "fitting/families/family.h"
#include "fitting/histories.h"
#include "fitting/plan.h"
#include "model/model.h"
#include "problem/problem.h"
#include "solvers/solver.h"

typedef struct tf_fit_outcome {
    tf_cases cases;
    /* A time-dependent solver's force histories (the plan's tick, counts
     * and length), which cases.hist points to; has_hist 0 otherwise. */
    tf_histories hist;
    int has_hist;
    /* The plan's cut progress responses (cut_progress.h), which cases.cut
     * points to; has_cut 0 otherwise. */
    tf_cut_cases cut;
    int has_cut;
    size_t n_families;
    tf_family_result *fam; /* one per registered family, in the registry's order */
    double seconds_cases;
} tf_fit_outcome;

/* Runs the whole fit of problem p with a solver of it (and, when the solver
 * is time-dependent, its force histories).  A family that does
 * not apply to the problem is marked so (why[]).  When the plan's contact
 * is a contact region, the plan's family fits the region's models instead
 * (its `region` operation, families/family.h) and no load case is solved.
 * Returns 0; -2 when the plan's forward family does not apply, or cannot
 * fit the region (a problem the user must change); -1 on any other failure;
 * with the message in ctx->err (usually the context the solver was created
 * with). */
int tf_fit_run(tf_ctx *ctx, const tf_problem *p, tf_solver *solver, const tf_fit_plan *plan,
               tf_fit_outcome *out);
void tf_fit_outcome_free(tf_fit_outcome *out);

/* The result of family f in an outcome (NULL when f is not registered). */
const tf_family_result *tf_fit_result_of(const tf_fit_outcome *o, const tf_family *f);

/* The model the fit emits for a kind: the plan's forward family, or the
 * first applicable inverse family (NULL when none). */
tf_model *tf_fit_emitted(const tf_fit_outcome *o, const tf_fit_plan *plan, tf_family_kind kind);

/* Whether the displacements of cases d leave the range the scene's law
 * describes: more than a tenth of the body's thickness under a small-strain
 * law, or more than the body's size under any.  Writes the sentence into
 * buf (empty when neither holds) and the largest displacement component
 * into *peak; returns the sentence's length.  tf_fit_run prints it as a
 * warning; the header and the report carry it. */
size_t tf_fit_law_range(const tf_problem *p, const tf_fitdata *d, double *peak, char *buf,
                        size_t n);

#endif /* TF_FIT_PIPELINE_H */
