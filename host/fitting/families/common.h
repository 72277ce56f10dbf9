/*
 * common.h — pieces shared by the family fitters: the normalised input
 * as the target will see it, design matrices, gathering cases.
 */
#ifndef TF_FAMILY_COMMON_H
#define TF_FAMILY_COMMON_H

#include <stddef.h>
#include <stdint.h>

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
int tf_family_lsq(const double *a, size_t m, size_t n, const double *y, size_t k, double *x,
                  char *err, size_t errlen);

/* Whether the selected inputs, normalised by the model's input map, cover
 * the envelope: their second-moment matrix (1/n) sum g g^T must have no
 * direction with RMS extent below 1e-3 (of the envelope radius).  Else -1 and
 * a TF_FAMILY_UNDETERMINED message naming the direction: a fit would be
 * determined by the cases but extrapolate wildly across the envelope. */
int tf_family_spans(const tf_model *m, const double (*x)[3], const size_t *idx, size_t n, char *err,
                    size_t errlen);

/* Copies node ids and sets the ball map of the data's force envelope. */
void tf_family_forward_setup(tf_model *model, const tf_fitdata *d);

/* A forward model of the given shape set up for d (tf_family_forward_setup),
 * refusing load cases that do not cover the envelope when its degree p > 0
 * (tf_family_spans).  NULL with a message on failure. */
tf_model *tf_family_forward_model(const char *name, tfit_family family, const uint32_t *dims,
                                  uint32_t n_dims, uint32_t p, const tf_fitdata *d,
                                  const size_t *idx, size_t m, char *err, size_t errlen);

#endif /* TF_FAMILY_COMMON_H */
