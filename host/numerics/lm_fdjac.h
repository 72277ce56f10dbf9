/*
 * lm_fdjac.h — difference Jacobian (forward or central) for lm.c, when the
 * caller gives no analytic one.
 */
#ifndef TF_LM_FDJAC_H
#define TF_LM_FDJAC_H

#include <stddef.h>

#include "numerics/lm_callbacks.h"

typedef struct tf_fdjac {
    tf_lm_residual_fn residual;
    void *ctx;
    size_t m, n;
    const double *lower, *upper; /* NULL or n bounds: steps stay inside */
    const double *typical;       /* n typical magnitudes, > 0 */
    int central;                 /* central differences (2 evaluations a column) */
} tf_fdjac;

/* jac[i + j*m] ~ d r_i / d p_j at p, where r = residual(p).  pt (n), rt
 * and rt2 (m) are scratch; *evals is incremented per residual evaluation.
 * Returns 0, -1 when the callback failed, 1 when a column could not be
 * made finite on either side of p. */
int tf_fdjac_eval(const tf_fdjac *fd, const double *p, const double *r, double *jac, double *pt,
                  double *rt, double *rt2, size_t *evals);

#endif /* TF_LM_FDJAC_H */
