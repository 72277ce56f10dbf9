/*
 * lm_callbacks.h — the caller's residual and Jacobian for the
 * Levenberg-Marquardt core (lm.h), alone so that the core's parts
 * (lm_fdjac.h, ...) can name them without including lm.h, which includes
 * them.
 */
#ifndef TF_LM_CALLBACKS_H
#define TF_LM_CALLBACKS_H

/* r[0..m-1] = residuals at p[0..n-1].  Non-finite residuals are allowed
 * (they mark points outside the model's domain).  Return 0, or non-zero to
 * abort the fit (TF_STOP_CALLBACK). */
typedef int (*tf_lm_residual_fn)(void *ctx, const double *p, double *r);
/* jac[i + j*m] = d r_i / d p_j at p (column-major, m x n).  Return 0 or
 * non-zero to abort. */
typedef int (*tf_lm_jacobian_fn)(void *ctx, const double *p, double *jac);

#endif /* TF_LM_CALLBACKS_H */
