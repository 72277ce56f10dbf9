/*
 * ref_arith.c — see ref_arith.h: the projection, the basis, Clenshaw and
 * polynomial rows of the reference evaluator, written from
 * docs/header-format.md rather than from target/src.
 */
#include "model/ref_arith.h"

static float largest_magnitude(const float v[3])
{
    float m = fabsf(v[0]);
    for (int i = 1; i < 3; ++i) {
        if (fabsf(v[i]) > m) {
            m = fabsf(v[i]);
        }
    }
    return m;
}

/* 2^(target - e) for |v| in [2^e, 2^(e+1)): moves |v| into [2^target, 2^(target+1)). */
static float power_of_two_to(int target, float v)
{
    int e = (int)((tf_ref_bits(fabsf(v)) >> 23) & 0xff) - 127;
    return ldexpf(1.0f, target - e);
}

void tf_ref_project(tf_arith *c, const tf_model *m, const float in[3], float g[3], int *clamped,
                    int *bad)
{
    const float *x0 = m->coef, *w = m->coef + 3;
    float x[3];

    /* §4 steps 1-2 */
    *bad = !(isfinite(in[0]) && isfinite(in[1]) && isfinite(in[2]));
    for (int i = 0; i < 3; ++i) {
        x[i] = *bad ? 0.0f : in[i];
    }
    /* step 3 */
    float big = largest_magnitude(x);
    float factor = big > 0x1p64f ? power_of_two_to(64, big) : 1.0f;
    for (int i = 0; i < 3; ++i) {
        x[i] = tf_ref_mul(c, x[i], factor);
    }
    /* steps 4-5 */
    float d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = tf_ref_sub(c, x[i], x0[i]);
    }
    for (int r = 0; r < 3; ++r) {
        float s = tf_ref_add(c, tf_ref_mul(c, w[3 * r], d[0]), tf_ref_mul(c, w[3 * r + 1], d[1]));
        g[r] = tf_ref_add(c, s, tf_ref_mul(c, w[3 * r + 2], d[2]));
    }
    /* step 6 */
    float gmax = largest_magnitude(g);
    int far = gmax > 1.0f;
    float unit = far ? power_of_two_to(0, gmax) : 1.0f;
    for (int i = 0; i < 3; ++i) {
        g[i] = tf_ref_mul(c, g[i], unit);
    }
    /* steps 7-9 */
    float s2 = tf_ref_add(c, tf_ref_add(c, tf_ref_mul(c, g[0], g[0]), tf_ref_mul(c, g[1], g[1])),
                          tf_ref_mul(c, g[2], g[2]));
    int outside = far || s2 > 1.0f;
    float s = outside ? s2 : 1.0f;
    float y = tf_ref_float(0x5f3759dfu - (tf_ref_bits(s) >> 1));
    for (int it = 0; it < 3; ++it) {
        float t = tf_ref_sub(c, 3.0f, tf_ref_mul(c, tf_ref_mul(c, s, y), y));
        y = tf_ref_mul(c, tf_ref_mul(c, 0.5f, y), t);
    }
    float scale = outside ? y : 1.0f;
    for (int i = 0; i < 3; ++i) {
        g[i] = tf_ref_mul(c, g[i], scale);
    }
    *clamped = outside;
}

/* T_0..T_p of one variable (§5.1): t_0 = 1, t_1 = g, t_k = (h t_{k-1}) - t_{k-2},
 * h = g + g. */
static void chebyshev(tf_arith *c, uint32_t p, float g, float *t)
{
    t[0] = 1.0f;
    if (p == 0) {
        return;
    }
    t[1] = g;
    if (p >= 2) {
        float h = tf_ref_add(c, g, g);
        for (uint32_t k = 2; k <= p; ++k) {
            t[k] = tf_ref_sub(c, tf_ref_mul(c, h, t[k - 1]), t[k - 2]);
        }
    }
}

/* A product in which one factor is T_0 = 1 is exact: it is not performed
 * (and not counted, §6). */
static float mul_basis(tf_arith *c, uint32_t ea, float a, uint32_t eb, float b)
{
    if (ea == 0) {
        return b;
    }
    if (eb == 0) {
        return a;
    }
    return tf_ref_mul(c, a, b);
}

/* The inner product of each (b, c) is computed once and shared by every a. */
void tf_ref_basis(tf_arith *c, uint32_t p, const float g[3], float *phi)
{
    float t[3][TFIT_MAX_DEGREE + 1];
    float inner[TFIT_MAX_DEGREE + 1][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        chebyshev(c, p, g[v], t[v]);
    }
    for (uint32_t b = 0; b <= p; ++b) {
        for (uint32_t e = 0; b + e <= p; ++e) {
            inner[b][e] = mul_basis(c, b, t[1][b], e, t[2][e]);
        }
    }
    uint32_t k = 0;
    for (uint32_t d = 0; d <= p; ++d) {
        for (uint32_t a = d + 1; a-- > 0;) {
            for (uint32_t b = d - a + 1; b-- > 0;) {
                uint32_t e = d - a - b;
                phi[k++] = mul_basis(c, a, t[0][a], b + e, inner[b][e]);
            }
        }
    }
}

/* h = x + x, b_{n+1} = b_{n+2} = +0, b_k = ((h b_{k+1}) - b_{k+2}) + coef_k
 * for k = n .. 1, result (x b_1) - b_2. */
float tf_ref_clenshaw_tail(tf_arith *c, const float *coef, uint32_t n, float x)
{
    float h = tf_ref_add(c, x, x);
    float b1 = 0.0f, b2 = 0.0f;
    for (uint32_t k = n; k >= 1; --k) {
        float b = tf_ref_add(c, tf_ref_sub(c, tf_ref_mul(c, h, b1), b2), coef[k]);
        b2 = b1;
        b1 = b;
    }
    return tf_ref_sub(c, tf_ref_mul(c, x, b1), b2);
}

float tf_ref_clenshaw(tf_arith *c, const float *coef, uint32_t n, float x)
{
    return tf_ref_add(c, tf_ref_clenshaw_tail(c, coef, n, x), coef[0]);
}

void tf_ref_rows(tf_arith *c, const float *rows, uint32_t n_rows, uint32_t n_terms,
                 const float *phi, float *out)
{
    for (uint32_t o = 0; o < n_rows; ++o) {
        const float *row = rows + (size_t)o * n_terms;
        float acc = row[0];
        for (uint32_t t = 1; t < n_terms; ++t) {
            acc = tf_ref_add(c, acc, tf_ref_mul(c, row[t], phi[t]));
        }
        out[o] = acc;
    }
}
