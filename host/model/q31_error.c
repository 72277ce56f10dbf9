/*
 * q31_error.c — what the Q31 form costs in accuracy, and its golden inputs.
 *
 * The error is measured against the exact model: the float coefficients
 * evaluated in double precision (projection included) at the float input.
 * The Q31 result includes every rounding of the Q31 path, the rounding of
 * the input to its Q31 word included; the float32 path's error on the same
 * points is measured beside it, so the header can say what Q31 adds.
 */
#include "model/q31.h"

#include <math.h>
#include <stdlib.h>

#include "model/basis.h"
#include "model/golden.h"
#include "model/ref_eval.h"
#include "base/rng.h"

/* The exact model at x: g = W (x - x0), projected when |g| > 1, rows
 * summed over the Chebyshev terms T_a(g0) T_b(g1) T_c(g2) in the basis
 * order (tf_basis). */
static void exact_eval(const tf_model *m, const double x[3], double *out)
{
    double g[3], n2 = 0;
    for (int i = 0; i < 3; ++i) {
        g[i] = 0;
        for (int j = 0; j < 3; ++j) {
            g[i] += (double)m->coef[3 + 3 * i + j] * (x[j] - (double)m->coef[j]);
        }
        n2 += g[i] * g[i];
    }
    if (n2 > 1) {
        for (int i = 0; i < 3; ++i) {
            g[i] /= sqrt(n2);
        }
    }
    const int p = (int)m->dims[0];
    const uint32_t t = tf_terms((uint32_t)p);
    double phi[TFIT_Q31_MAX_DEGREE_TERMS];
    tf_basis((uint32_t)p, g, phi);
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        double s = 0;
        for (uint32_t i = 0; i < t; ++i) {
            s += (double)c[o * t + i] * phi[i];
        }
        out[o] = s;
    }
}

/* A point of the envelope x0 + W^-1 u, |u| = radius. */
static void envelope_point(const tf_model *m, const double inv[9], tf_rng *r, double radius,
                           float x[3])
{
    double u[3], n2;
    do {
        for (int i = 0; i < 3; ++i) {
            u[i] = tf_rng_range(r, -1, 1);
        }
        n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    } while (n2 > 1 || n2 < 1e-6);
    for (int i = 0; i < 3; ++i) {
        double v = (double)m->coef[i];
        for (int k = 0; k < 3; ++k) {
            v += inv[3 * i + k] * u[k] / sqrt(n2) * radius;
        }
        x[i] = (float)v;
    }
}

void tf_q31_measure(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases)
{
    double inv[9];
    const size_t n = 3 * (size_t)m->n_out;
    double *exact = malloc(n * sizeof *exact);
    float *fl = malloc(n * sizeof *fl);
    int32_t *yq = malloc(n * sizeof *yq);
    tf_rng r = {seed};
    q->added_error = q->float_error = NAN;
    if (exact == NULL || fl == NULL || yq == NULL || tf_envelope_inverse(m, inv) != 0) {
        free(exact), free(fl), free(yq);
        return;
    }
    double qmax = 0, fmax_ = 0;
    for (uint32_t c = 0; c < n_cases; ++c) {
        float x[3];
        /* three in four uniform in the volume, one in four on the boundary */
        envelope_point(m, inv, &r, c % 4 == 3 ? 1.0 : cbrt(tf_rng_uniform(&r)), x);
        const double xd[3] = {x[0], x[1], x[2]};
        const int32_t xq[3] = {tf_q31_from_value(xd[0], q->in_exp),
                               tf_q31_from_value(xd[1], q->in_exp),
                               tf_q31_from_value(xd[2], q->in_exp)};
        exact_eval(m, xd, exact);
        tf_ref_eval(m, x, fl, NULL);
        tf_q31_ref_eval(q, xq, yq, NULL);
        for (size_t o = 0; o < n; ++o) {
            qmax = fmax(qmax, fabs(tf_q31_to_value(yq[o], q->out_exp) - exact[o]));
            fmax_ = fmax(fmax_, fabs((double)fl[o] - exact[o]));
        }
    }
    q->added_error = qmax;
    q->float_error = fmax_;
    q->error_cases = n_cases;
    free(exact), free(fl), free(yq);
}

static void put(int32_t in[][3], size_t *n, int32_t a, int32_t b, int32_t c)
{
    if (*n < TF_Q31_GOLDEN_MAX) {
        in[*n][0] = a, in[*n][1] = b, in[*n][2] = c;
        ++*n;
    }
}

size_t tf_q31_golden_inputs(const tf_q31 *q, const tf_model *m, uint64_t seed, int32_t in[][3])
{
    float fin[TF_GOLDEN_MAX][3];
    size_t nf = tf_golden_inputs(m, seed, fin), n = 0;
    for (size_t v = 0; v < nf; ++v) {
        if (isfinite(fin[v][0]) && isfinite(fin[v][1]) && isfinite(fin[v][2])) {
            put(in, &n, tf_q31_from_value(fin[v][0], q->in_exp),
                tf_q31_from_value(fin[v][1], q->in_exp), tf_q31_from_value(fin[v][2], q->in_exp));
        }
    }
    /* the extreme words and their neighbours */
    put(in, &n, INT32_MIN, INT32_MIN, INT32_MIN);
    put(in, &n, INT32_MAX, INT32_MAX, INT32_MAX);
    put(in, &n, INT32_MAX, INT32_MIN, 0);
    put(in, &n, INT32_MIN, 0, INT32_MAX);
    put(in, &n, INT32_MIN + 1, INT32_MAX - 1, -1);
    put(in, &n, 1, -1, 1);
    put(in, &n, -1, -1, -1);
    /* the centre word itself, and one step either side of it */
    int32_t c0 = q->q[0] * 2, c1 = q->q[1] * 2, c2 = q->q[2] * 2;
    put(in, &n, c0, c1, c2);
    put(in, &n, c0 + 1, c1 - 1, c2 + 1);
    return n;
}
