/*
 * fit_common.h — pieces shared by the family fitters: the normalised input
 * as the target will see it, design matrices, gathering cases.
 */
#ifndef TF_FIT_COMMON_H
#define TF_FIT_COMMON_H

#include <stddef.h>
#include <stdint.h>

#include "fitdata.h"
#include "model.h"

/* Terms of the largest basis the target accepts (TFIT_MAX_DEGREE). */
#define TFIT_MAX_TERMS_HOST \
    ((TFIT_MAX_DEGREE + 1) * (TFIT_MAX_DEGREE + 2) * (TFIT_MAX_DEGREE + 3) / 6)

/* g = W (x - x0) with the model's float input map, in double: the fit sees
 * the normalisation the target will apply. */
void tf_fit_normalise(const tf_model *m, const double x[3], double g[3]);

/* The m x T design matrix (column-major) of the degree-p basis at the
 * normalised inputs x[idx[i]] (idx NULL: i). */
double *tf_fit_design(const tf_model *m, const double (*x)[3], const size_t *idx, size_t n,
                      uint32_t p);

/* Case number i of a selection. */
static inline size_t tf_fit_case(const size_t *idx, size_t i)
{
    return idx != NULL ? idx[i] : i;
}

/* The m x 3 n_out matrix of the selected cases' displacements (row = case). */
double *tf_fit_gather_u(const tf_fitdata *d, const size_t *idx, size_t m);

/* Least squares for k right-hand sides (lsq.h): x (n x k) = argmin |A x - y|. */
int tf_fit_lsq(const double *a, size_t m, size_t n, const double *y, size_t k, double *x,
               char *err, size_t errlen);

/* Rounds every component to the nearest float (the firmware's input). */
void tf_round_to_float(double (*v)[3], size_t n);

/* Copies node ids and sets the ball map of the data's force envelope. */
void tf_fit_forward_setup(tf_model *model, const tf_fitdata *d);

#endif /* TF_FIT_COMMON_H */
