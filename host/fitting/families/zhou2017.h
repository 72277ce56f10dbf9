/*
 * zhou2017.h — the seed-000 model (Zhou et al. 2017, §3), fitted the way
 * the seed fits it, in three least-squares stages:
 *   1. eqs 40-42: contact displacement d_a as a polynomial of order lambda_a
 *      in the force component a alone, from load cases along axis a;
 *   2. eq 44:     for every such case and displacement component c, the
 *      separable surface p_0 + p_1 X + ... + p_A X^A + p_{A+1} Y + ... +
 *      p_{A+B} Y^B over the output points (X, Y normalised to [-1, 1]);
 *   3. eq 46:     each surface coefficient as a polynomial of order k in the
 *      normalised contact displacement t_a = d_a s_a.
 * A displacement under a general force is the superposition of the three
 * axes (eq 38).  Orders come from cross-validation, as in the seed (which
 * used 1stOpt): lambda over load cases, (A, B) over output points, k over
 * load cases.
 */
#ifndef TF_ZHOU2017_H
#define TF_ZHOU2017_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "fitting/fitdata.h"
#include "model/model.h"

typedef struct tf_zhou_orders {
    uint32_t lambda[3];              /* per force axis */
    uint32_t a[9], b[9], k[9];       /* per (force axis, component), row-major */
} tf_zhou_orders;

/* s_a for the stored contact law r[0..lambda] of one axis: (1 - 2^-16) /
 * sum |r_k|, rounded towards zero, so that t_a = d_a s_a lies in [-1, 1]
 * for every input (docs/header-format.md §5.4). */
float tf_zhou_scale(const float *r, uint32_t lambda);

/* Cross-validation curves behind the chosen orders (for the report). */
typedef struct tf_zhou_cv {
    double lambda_rms[3][TFIT_MAX_DEGREE + 1];                         /* mm */
    double surface_rms[9][TFIT_ZHOU_MAX_ORDER + 1][TFIT_ZHOU_MAX_ORDER + 1]; /* mm */
    double beta_rms[9][5];                                             /* mm */
} tf_zhou_cv;

/* Refuses data the seed's model cannot describe: output points off one
 * plane z = const, or an envelope not centred at zero force. */
int tf_zhou_applicable(tf_ctx *ctx, const tf_fitdata *d);

/* axis[a]: load cases with the force along axis a only (same outputs). */
tf_model *tf_zhou_fit(tf_ctx *ctx, const tf_fitdata *const axis[3], const tf_zhou_orders *o,
                      const char *name);

/* Chooses the orders by k-fold cross-validation; cv may be NULL. */
int tf_zhou_select(tf_ctx *ctx, const tf_fitdata *const axis[3], unsigned folds, uint64_t seed,
                   tf_zhou_orders *o, tf_zhou_cv *cv);

#endif /* TF_ZHOU2017_H */
