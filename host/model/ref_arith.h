/*
 * ref_arith.h — the pieces of the reference evaluator (ref_eval.h) that
 * every form's evaluation is written with: float arithmetic emulated in
 * double with one rounding per operation, counted (GUIDE §4: double has
 * more than 2*24+2 bits, so this equals IEEE binary32 arithmetic exactly
 * for +, -, *), the input projection (docs/header-format.md §4), the
 * Chebyshev basis (§5.1), Clenshaw's recurrence (§5.4) and polynomial rows
 * (§5.2).  Written from the specification, independently of target/src.
 * Inline: the reference runs for every held-out case of every fit.
 */
#ifndef TF_REF_ARITH_H
#define TF_REF_ARITH_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "model/model.h"

#define TF_REF_TERMS_MAX                                                                           \
    ((TFIT_MAX_DEGREE + 1) * (TFIT_MAX_DEGREE + 2) * (TFIT_MAX_DEGREE + 3) / 6)

/* The operations of one evaluation, counted as they are performed. */
typedef struct tf_arith {
    tf_opcount n;
} tf_arith;

static inline float tf_ref_add(tf_arith *c, float a, float b)
{
    c->n.add++;
    return (float)((double)a + (double)b);
}

static inline float tf_ref_sub(tf_arith *c, float a, float b)
{
    c->n.add++;
    return (float)((double)a - (double)b);
}

static inline float tf_ref_mul(tf_arith *c, float a, float b)
{
    c->n.mul++;
    return (float)((double)a * (double)b);
}

static inline uint32_t tf_ref_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static inline float tf_ref_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* Adds c's count to *ops (ops may be NULL). */
static inline void tf_ref_count(tf_opcount *ops, const tf_arith *c)
{
    if (ops != NULL) {
        ops->add += c->n.add;
        ops->mul += c->n.mul;
        ops->div += c->n.div;
    }
}

/* h beyond [-1, 1] -> +-1 with its sign (§5.6; never NaN here). */
static inline float tf_ref_clamp_unit(float h)
{
    return fabsf(h) > 1.0f ? copysignf(1.0f, h) : h;
}

/* Projection of the raw input in[3] onto the unit ball (§4): g, whether it
 * was projected (*clamped) and whether it held a NaN or Inf (*bad). */
void tf_ref_project(tf_arith *c, const tf_model *m, const float in[3], float g[3], int *clamped,
                    int *bad);

/* phi = T_a(g0) (T_b(g1) T_c(g2)) for a + b + c <= p in graded order (§5.1). */
void tf_ref_basis(tf_arith *c, uint32_t p, const float g[3], float *phi);

/* sum_{k=1..n} coef_k T_k(x), n >= 0, by Clenshaw (§5.4), and the full
 * series sum_{k=0..n} (tail + coef_0). */
float tf_ref_clenshaw_tail(tf_arith *c, const float *coef, uint32_t n, float x);
float tf_ref_clenshaw(tf_arith *c, const float *coef, uint32_t n, float x);

/* n_rows rows of n_terms coefficients at the basis phi, each summed left to
 * right (§5.2). */
void tf_ref_rows(tf_arith *c, const float *rows, uint32_t n_rows, uint32_t n_terms,
                 const float *phi, float *out);

#endif /* TF_REF_ARITH_H */
