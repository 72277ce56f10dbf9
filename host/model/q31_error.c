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
#include <string.h>

#include "base/rng.h"
#include "model/basis.h"
#include "model/forms/form.h"
#include "model/forms/stateful.h"
#include "model/golden.h"
#include "model/ref_eval.h"

/* The exact model at x: g = W (x - x0), projected when |g| > 1, rows
 * summed over the Chebyshev terms T_a(g0) T_b(g1) T_c(g2) in the basis
 * order (tf_basis). */
static void exact_rows(const tf_model *m, const float *c, const double g[3], double *out)
{
    const int p = (int)m->dims[0];
    const uint32_t t = tf_terms((uint32_t)p);
    double phi[TFIT_Q31_MAX_DEGREE_TERMS];
    tf_basis((uint32_t)p, g, phi);
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        double s = 0;
        for (uint32_t i = 0; i < t; ++i) {
            s += (double)c[o * t + i] * phi[i];
        }
        out[o] = s;
    }
}

/* g = W (x - x0), projected onto the unit ball. */
static void exact_project(const tf_model *m, const double x[3], double g[3])
{
    double n2 = 0;
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
}

static void exact_eval(const tf_model *m, const double x[3], double *out)
{
    double g[3];
    exact_project(m, x, g);
    exact_rows(m, m->coef + TFIT_INPUT_MAP_FLOATS, g, out);
}

/* One tick of the exact prony model (header-format.md §5.6 in double, the
 * float a_k and D_k): state = gp[3] | z[K][3]. */
static void exact_prony_step(const tf_model *m, double *state, const double x[3], double *out)
{
    double g[3], h[3];
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    exact_project(m, x, g);
    for (int i = 0; i < 3; ++i) {
        h[i] = g[i];
        for (uint32_t k = 0; k < m->dims[2]; ++k) {
            double *z = &state[3 + 3 * k + (uint32_t)i];
            *z = (double)pt[2 * k] * *z + (double)pt[2 * k + 1] * (g[i] - state[i]);
            h[i] -= *z;
        }
        h[i] = fmax(-1.0, fmin(1.0, h[i]));
    }
    for (int i = 0; i < 3; ++i) {
        state[i] = g[i];
    }
    exact_rows(m, pt + 2 * m->dims[2], h, out);
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

/* The errors of one evaluation: the Q31 and the float32 outputs against
 * the exact ones, into the running maxima. */
typedef struct error_run {
    const tf_q31 *q;
    size_t n;
    double *exact;
    float *fl;
    int32_t *yq;
    double qmax, fmax;
} error_run;

static void words_of(const tf_q31 *q, const float x[3], int32_t xq[3])
{
    for (int i = 0; i < 3; ++i) {
        xq[i] = tf_q31_from_value((double)x[i], q->in_exp);
    }
}

static void account(error_run *e)
{
    for (size_t o = 0; o < e->n; ++o) {
        e->qmax = fmax(e->qmax, fabs(tf_q31_to_value(e->yq[o], e->q->out_exp) - e->exact[o]));
        e->fmax = fmax(e->fmax, fabs((double)e->fl[o] - e->exact[o]));
    }
}

/* The prony model over a press-hold-release history from rest: a new
 * target every PRONY_SEGMENT ticks (three in four inside the envelope,
 * uniform in its volume, one in four on its boundary; every fourth back
 * to the centre), ramped over PRONY_RAMP ticks and held. */
#define PRONY_SEGMENT 1500u
#define PRONY_RAMP 100u
static void measure_prony(error_run *e, const tf_model *m, const double inv[9], tf_rng *r,
                          uint32_t n_ticks)
{
    const tf_q31 *q = e->q;
    double se[TFIT_PRONY_MAX_STATE];
    float sf[TF_STATEFUL_MAX_STATE];
    int32_t sq[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
    float from[3] = {m->coef[0], m->coef[1], m->coef[2]}, to[3];
    double x0[3] = {0, 0, 0};
    memcpy(to, from, sizeof to);
    tf_stateful_reset(m, sf);
    tf_q31_ref_prony_reset(q, sq);
    for (int i = 0; i < 3; ++i) {
        se[i] = 0;
    }
    exact_project(m, x0, se);
    for (uint32_t w = 0; w < 3 * m->dims[2]; ++w) {
        se[3 + w] = 0;
    }
    for (uint32_t t = 0; t < n_ticks; ++t) {
        const uint32_t seg = t / PRONY_SEGMENT, in_seg = t % PRONY_SEGMENT;
        if (in_seg == 0) {
            memcpy(from, to, sizeof to);
            if (seg % 4 == 3) {
                to[0] = m->coef[0], to[1] = m->coef[1], to[2] = m->coef[2];
            } else {
                envelope_point(m, inv, r, seg % 4 == 2 ? 1.0 : cbrt(tf_rng_uniform(r)), to);
            }
        }
        const double s = in_seg >= PRONY_RAMP ? 1.0 : (double)(in_seg + 1) / PRONY_RAMP;
        float x[3];
        for (int i = 0; i < 3; ++i) {
            x[i] = (float)((double)from[i] + s * ((double)to[i] - (double)from[i]));
        }
        const double xd[3] = {x[0], x[1], x[2]};
        int32_t xq[3];
        words_of(q, x, xq);
        exact_prony_step(m, se, xd, e->exact);
        tf_stateful_step(m, sf, x, e->fl, NULL);
        tf_q31_ref_prony_step(q, sq, xq, e->yq);
        account(e);
    }
}

/* The measurement's buffers (the exact, float32 and Q31 outputs) and W^-1;
 * -1 (the errors NAN) when out of memory or W is singular. */
static int run_open(error_run *e, tf_q31 *q, const tf_model *m, double inv[9])
{
    const size_t n = 3 * (size_t)m->n_out;
    q->added_error = q->float_error = NAN;
    *e = (error_run){.q = q, .n = n, .exact = malloc(n * sizeof *e->exact),
                     .fl = malloc(n * sizeof *e->fl), .yq = malloc(n * sizeof *e->yq),
                     .qmax = 0, .fmax = 0};
    if (e->exact == NULL || e->fl == NULL || e->yq == NULL || tf_envelope_inverse(m, inv) != 0) {
        free(e->exact), free(e->fl), free(e->yq);
        return -1;
    }
    return 0;
}

static void run_close(error_run *e, tf_q31 *q, uint32_t n_cases)
{
    q->added_error = e->qmax;
    q->float_error = e->fmax;
    q->error_cases = n_cases;
    free(e->exact), free(e->fl), free(e->yq);
}

void tf_q31_measure(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases)
{
    tf_form_of(m->family)->q31->measure(q, m, seed, n_cases);
}

/* The errors over n_cases seeded points of the envelope (three in four
 * uniform in its volume, one in four on its boundary), or for a prony
 * model n_cases ticks of a press-hold-release history from rest. */
static void measure(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases, int ticks)
{
    double inv[9];
    error_run e;
    tf_rng r = {seed};
    if (run_open(&e, q, m, inv) != 0) {
        return;
    }
    if (ticks) {
        measure_prony(&e, m, inv, &r, n_cases);
    }
    for (uint32_t c = 0; !ticks && c < n_cases; ++c) {
        float x[3];
        int32_t xq[3];
        envelope_point(m, inv, &r, c % 4 == 3 ? 1.0 : cbrt(tf_rng_uniform(&r)), x);
        const double xd[3] = {x[0], x[1], x[2]};
        words_of(q, x, xq);
        exact_eval(m, xd, e.exact);
        tf_ref_eval(m, x, e.fl, NULL);
        tf_q31_ref_eval(q, xq, e.yq, NULL);
        account(&e);
    }
    run_close(&e, q, n_cases);
}

void tf_q31_measure_points(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases)
{
    measure(q, m, seed, n_cases, 0);
}

void tf_q31_measure_ticks(tf_q31 *q, const tf_model *m, uint64_t seed, uint32_t n_cases)
{
    measure(q, m, seed, n_cases * TF_Q31_PRONY_TICKS_PER_CASE, 1);
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
    size_t nf = tf_golden_design(m, seed, fin), n = 0; /* prony: one tick sequence */
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
