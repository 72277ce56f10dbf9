/*
 * cut_progress.h — the responses of a cut scene at a sequence of cut
 * progress values s in [0, 1] (docs/cutting.md, "Cut progress"): the
 * scene's cuts truncated at the fraction s of their path length (s = 0:
 * uncut), one solver of the truncated problem per s.  The solve is linear
 * in the force at each s, so three unit solves and one without force span
 * every force at that s: u(f, s) = base_s + sum_k f_k unit_s[k].  A solver
 * that is not affine is refused.
 *
 * The s values are in three disjoint sets: the knots s = i / K_max,
 * i = 0..K_max, that the cut family trains on (every K dividing K_max has
 * its knots among them); the validation values s = (i + 1/2) / K_max
 * between them, on which the number of intervals is chosen; and held-out
 * values drawn from the plan's seed, used for nothing but the reported
 * error.
 */
#ifndef TF_FIT_CUT_PROGRESS_H
#define TF_FIT_CUT_PROGRESS_H

#include <stddef.h>
#include <stdint.h>

#include "fitting/fitdata.h"
#include "fitting/plan.h"
#include "problem/problem.h"
#include "solvers/solver.h"

enum { TF_CUT_TRAIN, TF_CUT_VALIDATE, TF_CUT_HELDOUT };

typedef struct tf_cut_cases {
    size_t n;          /* s values */
    float *s;          /* n progress values (floats: the target's input) */
    int *role;         /* TF_CUT_TRAIN, _VALIDATE, _HELDOUT */
    uint32_t knots;    /* K_max: the train values are s = i / K_max */
    size_t rows;       /* 3 n_out */
    double *resp;      /* n x 4 x rows: base, then the unit responses e_x, e_y, e_z */
    double seconds;    /* the solves */
} tf_cut_cases;

/* Solves problem p at every s of the plan (every cut truncated at s by
 * tf_cut_truncate, meshfree/cut.h; plan->cut_intervals knots,
 * their midpoints, plan->cut_heldout held-out values) with solvers built
 * like `like` (its options), contact site plan->contact.  Returns 0, or -1
 * with a message in ctx. */
int tf_cut_cases_solve(const tf_problem *p, const tf_solver *like, const tf_fit_plan *plan,
                       tf_cut_cases *out);
void tf_cut_cases_free(tf_cut_cases *c);

/* u (rows) at force f and sample i: base + sum_k f_k unit[k]. */
void tf_cut_cases_response(const tf_cut_cases *c, size_t i, const double f[3], double *u);

/* Errors of a cut model (model/model.h, TFIT_FAMILY_CUT) at sample i and
 * the forces of d, each rounded to float as the target takes it, against
 * the superposed responses: the largest |error| and the sum of squared
 * errors over d->n_cases x rows values.  Returns 0, or -1 out of memory. */
struct tf_model;
int tf_cut_cases_errors(const struct tf_model *m, const tf_cut_cases *c, size_t i,
                        const tf_fitdata *d, double *max, double *sum2);

#endif /* TF_FIT_CUT_PROGRESS_H */
