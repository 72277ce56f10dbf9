/*
 * golden.c — golden input vectors (see golden.h).  Points are built in the
 * normalised space u (unit ball) and mapped back to raw inputs with the
 * inverse of the model's W, so they exercise every model's own envelope.
 */
#include "model/golden.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "base/rng.h"
#include "model/forms/form.h"
#include "model/forms/stateful.h"
#include "model/ref_eval.h"

/* Inverse of the model's W (3x3, from its float entries) by cofactors. */
static void w_inverse(const tf_model *m, double inv[9])
{
    double w[9];
    for (int i = 0; i < 9; ++i) {
        w[i] = (double)m->coef[3 + i];
    }
    double c0 = w[4] * w[8] - w[5] * w[7];
    double c1 = w[5] * w[6] - w[3] * w[8];
    double c2 = w[3] * w[7] - w[4] * w[6];
    double det = w[0] * c0 + w[1] * c1 + w[2] * c2;
    inv[0] = c0 / det;
    inv[1] = (w[2] * w[7] - w[1] * w[8]) / det;
    inv[2] = (w[1] * w[5] - w[2] * w[4]) / det;
    inv[3] = c1 / det;
    inv[4] = (w[0] * w[8] - w[2] * w[6]) / det;
    inv[5] = (w[2] * w[3] - w[0] * w[5]) / det;
    inv[6] = c2 / det;
    inv[7] = (w[1] * w[6] - w[0] * w[7]) / det;
    inv[8] = (w[0] * w[4] - w[1] * w[3]) / det;
}

typedef struct builder {
    float (*in)[3];
    size_t n;
    double inv[9];
    const float *x0;
} builder;

static void put(builder *b, float x, float y, float z)
{
    if (b->n < TF_GOLDEN_MAX) {
        b->in[b->n][0] = x;
        b->in[b->n][1] = y;
        b->in[b->n][2] = z;
        b->n++;
    }
}

/* Raw input x0 + W^-1 (scale u). */
static void put_u(builder *b, const double u[3], double scale)
{
    float x[3];
    for (int i = 0; i < 3; ++i) {
        double v = (double)b->x0[i];
        for (int k = 0; k < 3; ++k) {
            v += b->inv[3 * i + k] * u[k] * scale;
        }
        x[i] = (float)v;
    }
    put(b, x[0], x[1], x[2]);
}

static void random_unit(tf_rng *r, double u[3])
{
    double n2;
    do {
        for (int i = 0; i < 3; ++i) {
            u[i] = tf_rng_range(r, -1.0, 1.0);
        }
        n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    } while (n2 > 1.0 || n2 < 1e-6);
    double n = sqrt(n2);
    for (int i = 0; i < 3; ++i) {
        u[i] /= n;
    }
}

static float float_from_bits(uint32_t bits)
{
    float f;
    memcpy(&f, &bits, sizeof f);
    return f;
}

size_t tf_golden_inputs(const tf_model *m, uint64_t seed, float in[][3])
{
    builder b = {.in = in, .n = 0, .x0 = m->coef};
    tf_rng r = {seed};
    double u[3];
    w_inverse(m, b.inv);

    put(&b, 0.0f, 0.0f, 0.0f);
    put(&b, m->coef[0], m->coef[1], m->coef[2]); /* envelope centre */
    for (int k = 0; k < 24; ++k) {               /* inside, radius uniform in [0, 1) */
        random_unit(&r, u);
        put_u(&b, u, tf_rng_uniform(&r));
    }
    for (int axis = 0; axis < 3; ++axis) { /* on the boundary: +-axes ... */
        for (int sign = -1; sign <= 1; sign += 2) {
            double e[3] = {0, 0, 0};
            e[axis] = sign;
            put_u(&b, e, 1.0);
        }
    }
    for (int corner = 0; corner < 8; ++corner) { /* ... cube diagonals ... */
        double s = 1.0 / sqrt(3.0);
        double d[3] = {(corner & 1) ? s : -s, (corner & 2) ? s : -s, (corner & 4) ? s : -s};
        put_u(&b, d, 1.0);
    }
    for (int k = 0; k < 4; ++k) { /* ... random directions */
        random_unit(&r, u);
        put_u(&b, u, 1.0);
    }
    for (int k = 0; k < 4; ++k) { /* beyond: 10x and 1e30x */
        random_unit(&r, u);
        put_u(&b, u, 10.0);
        put_u(&b, u, 1e30);
    }
    put(&b, FLT_MAX, -FLT_MAX, FLT_MAX / 3);
    put(&b, -FLT_MAX, 0.0f, 0.0f);
    put(&b, 1e38f, 1e-38f, -1e38f);
    /* subnormal-sized and signed zeros */
    put(&b, 1e-40f, -1e-42f, float_from_bits(1u));
    put(&b, FLT_MIN, -FLT_MIN, 0.0f);
    put(&b, float_from_bits(0x80000001u), 0.0f, 0.0f);
    put(&b, -0.0f, -0.0f, -0.0f);
    /* NaN and Inf, alone and mixed with finite values */
    put(&b, NAN, 0.0f, 0.0f);
    put(&b, 0.0f, -NAN, 1.0f);
    put(&b, 0.25f, 0.5f, float_from_bits(0x7f800001u)); /* signalling NaN */
    put(&b, float_from_bits(0x7fc12345u), 0.0f, 0.0f);  /* NaN with payload */
    put(&b, INFINITY, 0.0f, 0.0f);
    put(&b, 0.0f, -INFINITY, 0.0f);
    put(&b, INFINITY, -INFINITY, NAN);
    put(&b, 0.5f, 0.5f, INFINITY);
    return b.n;
}

size_t tf_golden_ticks(const tf_model *m, uint64_t seed, float in[][3])
{
    builder b = {.in = in, .n = 0, .x0 = m->coef};
    tf_rng r = {seed};
    double u[3], v[3];
    w_inverse(m, b.inv);

    put(&b, 0.0f, 0.0f, 0.0f);      /* 0: rest */
    random_unit(&r, u);
    for (int k = 1; k <= 10; ++k) { /* 1-10: press, to the boundary */
        put_u(&b, u, k / 10.0);
    }
    for (int k = 0; k < 8; ++k) { /* 11-18: hold on it */
        put_u(&b, u, 1.0);
    }
    for (int k = 5; k >= 0; --k) { /* 19-24: release */
        put_u(&b, u, k / 6.0);
    }
    for (int k = 0; k < 4; ++k) { /* 25-28: rest */
        put(&b, 0.0f, 0.0f, 0.0f);
    }
    for (int k = 0; k < 12; ++k) { /* 29-40: random inside */
        random_unit(&r, v);
        put_u(&b, v, tf_rng_uniform(&r));
    }
    random_unit(&r, v); /* 41-45: a glitch between equal forces (the state must not move) */
    put_u(&b, v, 0.7);
    put(&b, NAN, 0.0f, 0.0f);
    put_u(&b, v, 0.7);
    put(&b, 0.0f, -INFINITY, 1.0f);
    put_u(&b, v, 0.7);
    for (int k = 0; k < 2; ++k) { /* 46-49: beyond the envelope, 10x and 1e30x */
        random_unit(&r, v);
        put_u(&b, v, 10.0);
        put_u(&b, v, 1e30);
    }
    for (int axis = 0; axis < 3; ++axis) { /* 50-55: on the boundary, +-axes */
        for (int sign = -1; sign <= 1; sign += 2) {
            double e[3] = {0, 0, 0};
            e[axis] = sign;
            put_u(&b, e, 1.0);
        }
    }
    put(&b, FLT_MAX, -FLT_MAX, FLT_MAX / 3); /* 56-58: the largest floats */
    put(&b, -FLT_MAX, 0.0f, 0.0f);
    put(&b, 1e38f, 1e-38f, -1e38f);
    put(&b, 1e-40f, -1e-42f, float_from_bits(1u)); /* 59-61: subnormal and signed zeros */
    put(&b, float_from_bits(0x80000001u), 0.0f, 0.0f);
    put(&b, -0.0f, -0.0f, -0.0f);
    put(&b, float_from_bits(0x7f800001u), 0.25f, 0.5f); /* 62-65: NaN kinds, Inf */
    put(&b, float_from_bits(0x7fc12345u), 0.0f, 0.0f);
    put(&b, INFINITY, -INFINITY, NAN);
    put(&b, -NAN, 0.5f, 0.5f);
    for (int k = 0; k < 10; ++k) { /* 66-75: random inside, then back to rest */
        random_unit(&r, v);
        put_u(&b, v, tf_rng_uniform(&r));
    }
    put(&b, 0.0f, 0.0f, 0.0f);
    return b.n;
}

/* The self-test inputs, from the golden design (fixed seed, independent of
 * the header's): four random points inside the envelope, a cube diagonal on
 * its boundary (|g| = 1 to rounding, so the clamp decision itself is
 * tested), and three points beyond it, 10x, 1e30x and 10x again (the
 * Newton step and the power-of-two scalings).  At each the target folds
 * the status and every output into one CRC; at TFIT_CHECK_FAR generated
 * inputs far beyond it, the projected g into a second (tfit_check.c). */
const size_t tf_golden_pick_points[TFIT_CHECK_INPUTS] = {2, 3, 4, 5, 32, 44, 45, 46};
/* A stateful model's, a tick sequence from rest (tf_golden_ticks): the
 * press from 0.1 to 0.4 of the radius, the boundary, a random point, a NaN
 * tick (the skip), and the 10x and 1e30x points beyond the envelope. */
const size_t tf_golden_pick_ticks[TFIT_CHECK_INPUTS] = {1, 2, 3, 4, 11, 29, 42, 47};
#define CHECK_SEED 0x7466u

int tf_check_vector(const tf_model *m, uint32_t check[TFIT_CHECK_WORDS])
{
    float in[TF_GOLDEN_MAX][3];
    const tf_form *f = tf_form_of(m->family);
    const size_t n = 3 * (size_t)m->n_out;
    float *out = malloc(n * sizeof *out);
    if (out == NULL) {
        return -1;
    }
    /* a stateful model's state (tfit_check.c folds its words in) */
    float st[TF_STATEFUL_MAX_STATE];
    const uint32_t words = f->filter != NULL ? tf_stateful_words(m) : f->state_words;
    f->golden_inputs(m, CHECK_SEED, in);
    memset(st, 0, sizeof st);
    if (f->filter != NULL) {
        tf_stateful_reset(m, st);
    }
    uint32_t crc = (uint32_t)crc32(0L, Z_NULL, 0);
    for (int k = 0; k < TFIT_CHECK_INPUTS; ++k) {
        const float *x = in[f->check_pick[k]];
        memcpy(check + 3 * k, x, 3 * sizeof *check);
        /* the status, a stateful model's new state, the outputs */
        crc = tf_crc32_u32(crc, (uint32_t)(int32_t)f->check_step(m, st, k, x, out));
        for (uint32_t w = 0; w < words; ++w) {
            uint32_t bits;
            memcpy(&bits, &st[w], sizeof bits);
            crc = tf_crc32_u32(crc, bits);
        }
        for (size_t o = 0; o < n; ++o) {
            uint32_t w;
            memcpy(&w, &out[o], sizeof w);
            crc = tf_crc32_u32(crc, w);
        }
    }
    check[3 * TFIT_CHECK_INPUTS] = crc;
    /* the far inputs: g, as tfit_check.c's far_input() generates them (or
     * what the form folds for them) */
    uint32_t state = 1u;
    crc = (uint32_t)crc32(0L, Z_NULL, 0);
    for (int k = 0; k < TFIT_CHECK_FAR; ++k) {
        float x[3], g[3];
        int clamped, bad;
        for (int i = 0; i < 3; ++i) {
            state = state * 1664525u + 1013904223u;
            x[i] = (float)((int32_t)(state >> 8) - 0x800000) * 0x1p77f; /* exact */
        }
        if (f->check_far != NULL) {
            crc = f->check_far(m, st, check, x, crc);
            continue;
        }
        tf_ref_input(m, x, g, &clamped, &bad, NULL);
        for (int i = 0; i < 3; ++i) {
            uint32_t w;
            memcpy(&w, &g[i], sizeof w);
            crc = tf_crc32_u32(crc, w);
        }
    }
    check[3 * TFIT_CHECK_INPUTS + 1] = crc;
    free(out);
    return 0;
}

uint32_t tf_model_crc32_checked(const tf_model *m, const uint32_t check[TFIT_CHECK_WORDS])
{
    uint32_t crc = tf_model_crc32(m);
    for (int i = 0; i < TFIT_CHECK_WORDS; ++i) {
        crc = tf_crc32_u32(crc, check[i]);
    }
    return crc;
}

size_t tf_golden_design(const tf_model *m, uint64_t seed, float in[][3])
{
    return tf_form_of(m->family)->golden_inputs(m, seed, in);
}
