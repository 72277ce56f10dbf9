/*
 * common.h — pieces shared by the families (family.h): the normalised
 * input as the target will see it, design matrices, gathering cases, the
 * degree search by cross-validation, and the operations of the polynomial
 * families (every output a polynomial of degree dims[0] in the normalised
 * input: nodal, contact).
 */
#ifndef TF_FAMILY_COMMON_H
#define TF_FAMILY_COMMON_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/families/family.h"
#include "fitting/fitdata.h"
#include "model/model.h"

/* Terms of the largest basis the target accepts (TFIT_MAX_DEGREE). */
#define TF_FAMILY_MAX_TERMS \
    ((TFIT_MAX_DEGREE + 1) * (TFIT_MAX_DEGREE + 2) * (TFIT_MAX_DEGREE + 3) / 6)

/* g = W (x - x0) with the model's float input map, in double: the fit sees
 * the normalisation the target will apply. */
void tf_family_normalise(const tf_model *m, const double x[3], double g[3]);

/* The m x T design matrix (column-major) of the degree-p basis at the
 * normalised inputs x[idx[i]] (idx NULL: i). */
double *tf_family_design(const tf_model *m, const double (*x)[3], const size_t *idx, size_t n,
                         uint32_t p);

/* Case number i of a selection. */
static inline size_t tf_family_case(const size_t *idx, size_t i)
{
    return idx != NULL ? idx[i] : i;
}

/* The m x 3 n_out matrix of the selected cases' displacements (row = case). */
double *tf_family_gather_u(const tf_fitdata *d, const size_t *idx, size_t m);

/* Messages of fits the data cannot determine begin with this (so that
 * cross-validation can tell "this order is not supported by the cases" from
 * a failure). */
#define TF_FAMILY_UNDETERMINED "undetermined"

/* Least squares for k right-hand sides (lsq.h): x (n x k) = argmin |A x - y|.
 * A design of rank below n is refused (repeated or collinear load cases, or
 * too few cases for the order): -1 and a TF_FAMILY_UNDETERMINED message, never
 * a basic solution with coefficients silently set to zero. */
int tf_family_lsq(tf_ctx *ctx, const double *a, size_t m, size_t n, const double *y, size_t k,
                  double *x);

/* Whether the selected inputs, normalised by the model's input map, cover
 * the envelope: their second-moment matrix (1/n) sum g g^T must have no
 * direction with RMS extent below 1e-3 (of the envelope radius).  Else -1 and
 * a TF_FAMILY_UNDETERMINED message naming the direction: a fit would be
 * determined by the cases but extrapolate wildly across the envelope. */
int tf_family_spans(tf_ctx *ctx, const tf_model *m, const double (*x)[3], const size_t *idx,
                    size_t n);

/* Copies node ids and sets the ball map of the data's force envelope. */
void tf_family_forward_setup(tf_model *model, const tf_fitdata *d);

/* A forward model of the given shape set up for d (tf_family_forward_setup),
 * refusing load cases that do not cover the envelope when its degree p > 0
 * (tf_family_spans).  NULL with a message on failure. */
tf_model *tf_family_forward_model(tf_ctx *ctx, const char *name, tfit_family family,
                                  const uint32_t *dims, uint32_t n_dims, uint32_t p,
                                  const tf_fitdata *d, const size_t *idx, size_t m);

/* ---- order search ---------------------------------------------------- */

/* The smallest index in [lo, hi] whose value is within 2 % of the best
 * (plus 1e-6: below that a higher order buys nothing the float32 target can
 * show, in mm or N). */
uint32_t tf_family_cheapest_within(const double *v, uint32_t lo, uint32_t hi);

/* One fold of a stateful family's order search: fit order k on the
 * histories train[0 .. nt-1] and return the RMS error over valid[0 .. nv-1]
 * in *rms; non-zero when the fit fails (order k then has no CV error). */
typedef int (*tf_family_history_fold)(void *ctx, int k, const size_t *train, size_t nt,
                                      const size_t *valid, size_t nv, double *rms);

/* k-fold cross-validation over n histories (fold f validates i = f mod
 * folds) for orders 0 .. kmax: cv[k] the RMS over every validated history,
 * INFINITY when a fold's fit failed.  Returns 0, or -1 when out of memory.
 * The prony terms and the resonant modes share it. */
int tf_family_history_cv(size_t n, size_t folds, int kmax, tf_family_history_fold fold, void *ctx,
                         double *cv);

/* Cases in one training fold of c->train under the plan's k-fold split. */
size_t tf_family_fold_cases(const tf_cases *c, const tf_fit_plan *plan);

/* Degrees p in [lo, plan->max_degree] by cross-validation of f at orders
 * {p, extra}: cv[0..TFIT_MAX_DEGREE] (INFINITY where not tried: outside the
 * range, or more terms than a training fold has cases), the choice in
 * *best.  Returns 0, or -1 with a message (also when no degree is
 * determined). */
int tf_family_select_degree(tf_ctx *ctx, const tf_family *f, const tf_cases *c,
                            const tf_fit_plan *plan, uint32_t lo, uint32_t extra, double *cv,
                            uint32_t *best);

/* tf_family.select of a family searched by degree alone (orders {p}): the
 * degree p >= lo by cross-validation, then f's fit at p on every training
 * case into r->model. */
int tf_family_select_by_degree(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan, uint32_t lo,
                               tf_family_result *r);

/* tf_family.candidates of such a family: its fit at every degree p = lo ..
 * plan->max_degree whose terms the training cases determine. */
int tf_family_degree_candidates(tf_ctx *ctx, const tf_family *f, const tf_cases *c,
                                const tf_fit_plan *plan, uint32_t lo, tf_family_take take,
                                void *arg);

/* ---- operations shared by several families ------------------------------ */

/* tf_family.applicable of a family that describes any cases. */
int tf_family_always(tf_ctx *ctx, const tf_cases *c, const tf_fit_plan *plan);

/* "p=2": the degree dims[0]. */
void tf_family_degree_text(const tf_model *m, int style, char *buf, size_t n);
/* "p=2 r=3": the degree and the rank, dims[0] and dims[1] (modal families). */
void tf_family_rank_text(const tf_model *m, int style, char *buf, size_t n);

/* tf_family.f64_errors of the polynomial families: the same least squares
 * on every training case, kept in double, against the held-out cases. */
int tf_family_poly_f64_errors(tf_ctx *ctx, const tf_model *m, const tf_cases *c, double *max,
                              double *rms);

/* tf_family.cost from the model's layout: model.h's operation count and
 * table bytes, cost/cycles.h's estimates. */
void tf_family_layout_cost(const tf_model *m, tf_family_cost *out);

#endif /* TF_FAMILY_COMMON_H */
