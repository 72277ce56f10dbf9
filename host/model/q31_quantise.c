/*
 * q31_quantise.c — a nodal, contact or prony model to its Q31 table
 * (docs/q31-format.md §2): the input and output exponents, the projection's
 * headroom H, W and the centre in their fixed-point formats, and each row's
 * coefficients with the shift that brings its sum to the output format.
 */
#include "model/q31.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "model/forms/form.h"
#include "model/forms/stateful.h"

#define MAX_H 14
/* The largest a_k word: 2^31 - 2^14 (tfit_q31_check.c). */
#define TFIT_Q31_PRONY_A_MAX 2147467264.0

/* Smallest integer e with v <= 2^e (v > 0). */
static int ceil_log2(double v)
{
    int e;
    double f = frexp(v, &e); /* v = f 2^e, f in [0.5, 1) */
    return f == 0.5 ? e - 1 : e;
}

int tf_envelope_inverse(const tf_model *m, double inv[9])
{
    double w[9];
    lapack_int ipiv[3];
    for (int i = 0; i < 9; ++i) {
        w[i] = (double)m->coef[3 + i];
        inv[i] = i % 4 == 0 ? 1.0 : 0.0;
    }
    return LAPACKE_dgesv(LAPACK_ROW_MAJOR, 3, 3, w, 3, ipiv, inv, 3) == 0 ? 0 : -1;
}

/* Half-widths of the envelope's bounding box: |x_j - x0_j| <= r_j inside
 * |W (x - x0)| <= 1, r_j = |row j of W^-1|. */
static int box_half_widths(const tf_model *m, double r[3])
{
    double inv[9];
    if (tf_envelope_inverse(m, inv) != 0) {
        return -1;
    }
    for (int j = 0; j < 3; ++j) {
        r[j] = sqrt(inv[3 * j] * inv[3 * j] + inv[3 * j + 1] * inv[3 * j + 1] +
                    inv[3 * j + 2] * inv[3 * j + 2]);
    }
    return 0;
}

static int quantise_map(tf_ctx *ctx, const tf_model *m, tf_q31 *q)
{
    double r[3], box = 0, wsum = 0;
    if (box_half_widths(m, r) != 0) {
        return tf_fail(ctx, "model '%s': no Q31 form: envelope matrix W is singular", m->name);
    }
    for (int j = 0; j < 3; ++j) {
        box = fmax(box, fabs((double)m->coef[j]) + r[j]);
    }
    q->in_exp = ceil_log2(box) + 1; /* the envelope fills at most half the range */
    for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int j = 0; j < 3; ++j) {
            s += fabs((double)m->coef[3 + 3 * i + j]);
        }
        wsum = fmax(wsum, s);
    }
    /* |g| <= sum_j |W_ij| |x_j - x0_j| <= wsum (1.5 + 2^-30) 2^E_in <= 2^(H-2) */
    int h = ceil_log2(wsum * (1.5 + 0x1p-30) * ldexp(1.0, q->in_exp)) + 2;
    h = h < 2 ? 2 : h;
    if (h > MAX_H) {
        return tf_fail(
            ctx,
            "model '%s': no Q31 form: the envelope is too elongated for the projection's "
            "%d-bit headroom (needs %d)",
            m->name, MAX_H, h);
    }
    int32_t *map = q->q;
    const int sw = q->in_exp + 32 - h;
    for (int j = 0; j < 3; ++j) {
        map[j] = (int32_t)llrint(ldexp((double)m->coef[j], 30 - q->in_exp));
    }
    for (int i = 0; i < 9; ++i) {
        double v = rint(ldexp((double)m->coef[3 + i], sw));
        if (fabs(v) > 0x1p30) {
            return tf_fail(ctx, "model '%s': no Q31 form: W entry %d out of range", m->name, i);
        }
        map[3 + i] = (int32_t)v;
    }
    map[12] = h;
    return 0;
}

/* Rows: B_o = sum |C_o|; f_o = ceil log2 B_o; E_out = max f_o + 4;
 * f_o >= E_out - 33; c = round(C 2^(30 - f_o)); s_o = 29 + E_out - f_o. */
static void quantise_rows(const tf_model *m, tf_q31 *q)
{
    const uint32_t t = tf_terms(q->degree), rows = 3 * q->n_out;
    const float *c = m->coef + TFIT_INPUT_MAP_FLOATS;
    int *f = malloc(rows * sizeof *f);
    int fmax_ = INT32_MIN;
    for (uint32_t o = 0; o < rows; ++o) {
        double b = 0;
        for (uint32_t k = 0; k < t; ++k) {
            b += fabs((double)c[o * t + k]);
        }
        f[o] = b > 0 ? ceil_log2(b) : INT32_MIN;
        fmax_ = f[o] > fmax_ ? f[o] : fmax_;
    }
    q->out_exp = fmax_ == INT32_MIN ? 0 : fmax_ + 4;
    int32_t *row = q->q + TFIT_Q31_MAP_WORDS;
    for (uint32_t o = 0; o < rows; ++o, row += t + 1) {
        int fo = f[o] < q->out_exp - 33 ? q->out_exp - 33 : f[o];
        row[0] = 29 + q->out_exp - fo;
        for (uint32_t k = 0; k < t; ++k) {
            row[1 + k] = (int32_t)llrint(ldexp((double)c[o * t + k], 30 - fo));
        }
    }
    free(f);
}

/* A prony model's terms (q31-format.md §8): a_k = round(a 2^31) (exact for
 * a float a >= 1/2), D_k = round(D 2^30); -1 when a term is outside the
 * range whose bound §8 proves. */
static int quantise_terms(tf_ctx *ctx, const tf_model *m, int32_t *t)
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        const double a = rint(ldexp((double)pt[2 * k], 31));
        const double d = rint(ldexp((double)pt[2 * k + 1], 30));
        if (!(a >= 0 && a <= TFIT_Q31_PRONY_A_MAX && fabs(d) <= 0x1p30)) {
            return tf_fail(
                ctx,
                "model '%s': no Q31 form: term %u (a = %.9g, D = %.9g) outside 0 <= a <= 1 - "
                "2^-17, |D| <= 1",
                m->name, k, (double)pt[2 * k], (double)pt[2 * k + 1]);
        }
        t[2 * k] = (int32_t)a;
        t[2 * k + 1] = (int32_t)d;
    }
    return 0;
}

/* The prony form: the static map's nodal form with K and the terms
 * inserted after the input map. */
tf_q31 *tf_q31_quantise_prony(tf_ctx *ctx, const tf_model *m)
{
    if (m->dims[1] != 0) {
        tf_fail(ctx, "model '%s': no Q31 form for a prony model with a modal static map", m->name);
        return NULL;
    }
    const uint32_t terms = m->dims[2], extra = 1 + 2 * terms;
    /* the nodal model of the input map and the static rows (the static
     * view's own first 12 floats are not the input map) */
    tf_model v = tf_stateful_static_view(m);
    float *coef = malloc(v.n_coef * sizeof *coef);
    if (coef == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    memcpy(coef, m->coef, TFIT_INPUT_MAP_FLOATS * sizeof *coef);
    memcpy(coef + TFIT_INPUT_MAP_FLOATS, v.coef + TFIT_INPUT_MAP_FLOATS,
           (v.n_coef - TFIT_INPUT_MAP_FLOATS) * sizeof *coef);
    v.coef = coef;
    tf_q31 *q = tf_q31_quantise_rows(ctx, &v);
    free(coef);
    if (q == NULL) {
        return NULL;
    }
    q->node_ids = m->node_ids;
    int32_t *t = calloc(q->n_words + extra, sizeof *t);
    if (t == NULL || quantise_terms(ctx, m, t + TFIT_Q31_MAP_WORDS + 1) != 0) {
        if (t == NULL) {
            tf_fail(ctx, "out of memory");
        }
        free(t);
        tf_q31_free(q);
        return NULL;
    }
    memcpy(t, q->q, TFIT_Q31_MAP_WORDS * sizeof *t);
    t[TFIT_Q31_MAP_WORDS] = (int32_t)terms;
    memcpy(t + TFIT_Q31_MAP_WORDS + extra, q->q + TFIT_Q31_MAP_WORDS,
           (q->n_words - TFIT_Q31_MAP_WORDS) * sizeof *t);
    free(q->q);
    q->q = t;
    q->n_words += extra;
    q->terms = terms;
    q->family = m->family; /* the prony model's: its rows were quantised as a nodal model */
    return q;
}

tf_q31 *tf_q31_quantise(tf_ctx *ctx, const tf_model *m)
{
    const tf_form *f = tf_form_of(m->family);
    if (f == NULL || f->q31 == NULL) {
        tf_fail(ctx, "model '%s': no Q31 form for family %d (its form has none)", m->name,
                (int)m->family);
        return NULL;
    }
    return f->q31->quantise(ctx, m);
}

tf_q31 *tf_q31_quantise_rows(tf_ctx *ctx, const tf_model *m)
{
    tf_q31 *q = calloc(1, sizeof *q);
    if (q == NULL) {
        tf_fail(ctx, "out of memory");
        return NULL;
    }
    q->family = m->family;
    q->n_out = m->n_out;
    q->degree = m->dims[0];
    q->n_words = TFIT_Q31_MAP_WORDS + 3 * m->n_out * (tf_terms(q->degree) + 1);
    q->q = calloc(q->n_words, sizeof *q->q);
    q->node_ids = m->node_ids;
    q->added_error = q->float_error = NAN;
    if (q->q == NULL || quantise_map(ctx, m, q) != 0) {
        if (q->q == NULL) {
            tf_fail(ctx, "out of memory");
        }
        tf_q31_free(q);
        return NULL;
    }
    quantise_rows(m, q);
    return q;
}

void tf_q31_free(tf_q31 *q)
{
    if (q != NULL) {
        free(q->q);
        free(q);
    }
}

uint32_t tf_q31_crc32(const tf_q31 *q)
{
    uint32_t crc = (uint32_t)crc32(0L, Z_NULL, 0);
    const uint32_t head[5] = {TFIT_Q31_API_VERSION, (uint32_t)q->family, q->n_out, q->degree,
                              q->n_words};
    for (int i = 0; i < 5; ++i) {
        crc = tf_crc32_u32(crc, head[i]);
    }
    for (uint32_t i = 0; i < q->n_words; ++i) {
        crc = tf_crc32_u32(crc, (uint32_t)q->q[i]);
    }
    for (uint32_t i = 0; i < q->n_out; ++i) {
        crc = tf_crc32_u32(crc, q->node_ids[i]);
    }
    return crc;
}

int32_t tf_q31_from_value(double v, int e)
{
    double w = rint(ldexp(v, 31 - e));
    return w >= 0x1p31 ? INT32_MAX : (w < -0x1p31 ? INT32_MIN : (int32_t)w);
}

double tf_q31_to_value(int32_t w, int e)
{
    return ldexp((double)w, e - 31);
}
