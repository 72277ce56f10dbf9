/*
 * nist_fit.h — fit a NIST StRD problem from one of its starting points
 * through the fitting interface (fit.h) and score the result in correct
 * digits: LRE = -log10(|estimate - certified| / |certified|), the log
 * relative error, capped at 11 (the certified values carry 11 digits).
 */
#ifndef TF_NIST_FIT_H
#define TF_NIST_FIT_H

#include "base/context.h"
#include "numerics/lsfit.h"
#include "numerics/nist_models.h"
#include "numerics/nist_strd.h"

#define TF_LRE_CAP 11.0

typedef struct tf_nist_score {
    double estimate[TF_NIST_MAX_PAR];
    double lre[TF_NIST_MAX_PAR];
    double se[TF_NIST_MAX_PAR];     /* standard errors from the fit */
    double se_lre[TF_NIST_MAX_PAR]; /* against the certified standard deviations */
    double rss, rss_lre;
    double min_lre;                 /* over the parameters and the RSS */
    tf_stop stop;
    size_t iterations, evals, jac_evals;
} tf_nist_score;

/* The absolute error with which double precision can evaluate the RSS near
 * the certified minimum: 2 sqrt(RSS) d + d^2 with d = sqrt(n) eps max|y|,
 * the size of the rounding in the residual vector.  Only when the certified
 * RSS is itself at the rounding floor (Lanczos1: 1.4e-25) is this larger
 * than a 1e-6 relative error; the acceptance test then compares the RSS
 * with this bound instead of in digits. */
double tf_nist_rss_resolution(const tf_nist *d, const tf_nist_model *model);

/* LRE of estimate against certified, in [0, TF_LRE_CAP]; 0 when not finite. */
double tf_lre(double estimate, double certified);

/* The model for d's text; NULL with "PATH:LINE: ..." in ctx->err when unknown or
 * when the file's parameter or predictor count disagrees with it. */
const tf_nist_model *tf_nist_match(tf_ctx *ctx, const tf_nist *d, const char *path);

/* Reads DIR/NAME.dat and matches its model: 0, or -1 with a message. */
int tf_nist_load(tf_ctx *ctx, const char *dir, const char *name, tf_nist *d,
                 const tf_nist_model **model);

/* Tolerances of the certification runs (docs/lm.md): ftol = xtol = 1e-15,
 * gtol = 0, 10000 evaluations. */
void tf_nist_options(tf_lsfit_options *o, size_t n_par);

/* Fits d with model from start 1 or 2 using o (analytic Jacobian unless
 * finite_diff).  Returns 0 with the score, -1 with a message. */
int tf_nist_fit(tf_ctx *ctx, const tf_nist *d, const tf_nist_model *model, int start,
                const tf_lsfit_options *o, int finite_diff, tf_nist_score *s);

#endif /* TF_NIST_FIT_H */
