/*
 * passivity.h — is a contact inverse (displacement -> force) passive over its
 * envelope, and how stiff must the device be to render it?
 *
 * A haptic loop that renders f(delta) stays stable only if the law stores
 * energy rather than creating it: the symmetric part of its stiffness
 * J = df/d(delta) must be positive definite wherever the tool can be
 * (issue 14).  The check samples the envelope densely (a 0.1 grid of the
 * normalised ball |g| <= 1 and 1,000 points on its surface), evaluates J
 * exactly from the polynomial's tables (the float coefficients the device
 * holds, in double) and reports the smallest eigenvalue of sym(J) and the
 * largest ||J||_2 — the stiffness the device must render, N/mm.
 */
#ifndef TF_PASSIVITY_H
#define TF_PASSIVITY_H

#include <stddef.h>
#include <stdint.h>

#include "base/context.h"
#include "model/model.h"

typedef struct tf_passivity {
    double min_eig;       /* smallest eigenvalue of sym(J) over the samples, N/mm */
    double max_stiffness; /* largest ||J||_2 over the samples, N/mm */
    double worst_g[3];    /* normalised input where min_eig occurs */
    double worst_delta[3]; /* the same point as a contact displacement, mm */
    uint32_t samples;
} tf_passivity;

/* Samples the envelope of a contact model (TFIT_FAMILY_CONTACT).  Returns 0
 * when measured (passive or not: see out->min_eig), -1 with a message in ctx->err
 * when the model is not a contact model or LAPACK fails. */
int tf_passivity_measure(tf_ctx *ctx, const tf_model *m, tf_passivity *out);

/* Measures, stores the result in the model's metadata (it goes into the
 * header) and refuses a non-passive law: returns 0 when passive, 1 with a
 * message naming the model, the point and the eigenvalue when not, -1 on
 * failure. */
int tf_passivity_require(tf_ctx *ctx, tf_model *m);

#endif /* TF_PASSIVITY_H */
