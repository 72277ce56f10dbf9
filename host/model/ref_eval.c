/*
 * ref_eval.c — reference evaluator (see ref_eval.h): float arithmetic
 * emulated in double with a rounding after every operation, written from the
 * specification in docs/header-format.md rather than from target/src.
 */
#include "model/ref_eval.h"

#include <math.h>
#include <string.h>

#define TFIT_TERMS_MAX ((TFIT_MAX_DEGREE + 1) * (TFIT_MAX_DEGREE + 2) * (TFIT_MAX_DEGREE + 3) / 6)

/* Operation helpers: exact double result of two floats, rounded once to
 * float (round-to-nearest-even), counted. */
typedef struct arith {
    tf_opcount n;
} arith;

static float f_add(arith *c, float a, float b)
{
    c->n.add++;
    return (float)((double)a + (double)b);
}

static float f_sub(arith *c, float a, float b)
{
    c->n.add++;
    return (float)((double)a - (double)b);
}

static float f_mul(arith *c, float a, float b)
{
    c->n.mul++;
    return (float)((double)a * (double)b);
}

static void add_ops(tf_opcount *ops, const arith *c);

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

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static float float_of(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* 2^(target - e) for |v| in [2^e, 2^(e+1)): moves |v| into [2^target, 2^(target+1)). */
static float power_of_two_to(int target, float v)
{
    int e = (int)((bits_of(fabsf(v)) >> 23) & 0xff) - 127;
    return ldexpf(1.0f, target - e);
}

static void input_map(arith *c, const tf_model *m, const float in[3], float g[3], int *clamped,
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
        x[i] = f_mul(c, x[i], factor);
    }
    /* steps 4-5 */
    float d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = f_sub(c, x[i], x0[i]);
    }
    for (int r = 0; r < 3; ++r) {
        float s = f_add(c, f_mul(c, w[3 * r], d[0]), f_mul(c, w[3 * r + 1], d[1]));
        g[r] = f_add(c, s, f_mul(c, w[3 * r + 2], d[2]));
    }
    /* step 6 */
    float gmax = largest_magnitude(g);
    int far = gmax > 1.0f;
    float unit = far ? power_of_two_to(0, gmax) : 1.0f;
    for (int i = 0; i < 3; ++i) {
        g[i] = f_mul(c, g[i], unit);
    }
    /* steps 7-9 */
    float s2 = f_add(c, f_add(c, f_mul(c, g[0], g[0]), f_mul(c, g[1], g[1])), f_mul(c, g[2], g[2]));
    int outside = far || s2 > 1.0f;
    float s = outside ? s2 : 1.0f;
    float y = float_of(0x5f3759dfu - (bits_of(s) >> 1));
    for (int it = 0; it < 3; ++it) {
        float t = f_sub(c, 3.0f, f_mul(c, f_mul(c, s, y), y));
        y = f_mul(c, f_mul(c, 0.5f, y), t);
    }
    float scale = outside ? y : 1.0f;
    for (int i = 0; i < 3; ++i) {
        g[i] = f_mul(c, g[i], scale);
    }
    *clamped = outside;
}

/* T_0..T_p of one variable (§5.1): t_0 = 1, t_1 = g, t_k = (h t_{k-1}) - t_{k-2},
 * h = g + g. */
static void chebyshev(arith *c, uint32_t p, float g, float *t)
{
    t[0] = 1.0f;
    if (p == 0) {
        return;
    }
    t[1] = g;
    if (p >= 2) {
        float h = f_add(c, g, g);
        for (uint32_t k = 2; k <= p; ++k) {
            t[k] = f_sub(c, f_mul(c, h, t[k - 1]), t[k - 2]);
        }
    }
}

/* A product in which one factor is T_0 = 1 is exact: it is not performed
 * (and not counted, §6). */
static float f_mul_basis(arith *c, uint32_t ea, float a, uint32_t eb, float b)
{
    if (ea == 0) {
        return b;
    }
    if (eb == 0) {
        return a;
    }
    return f_mul(c, a, b);
}

/* phi = T_a(g0) (T_b(g1) T_c(g2)) for a + b + c <= p in graded order; the
 * inner product of each (b, c) is computed once and shared by every a. */
static void chebyshev_basis(arith *c, uint32_t p, const float g[3], float *phi)
{
    float t[3][TFIT_MAX_DEGREE + 1];
    float inner[TFIT_MAX_DEGREE + 1][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        chebyshev(c, p, g[v], t[v]);
    }
    for (uint32_t b = 0; b <= p; ++b) {
        for (uint32_t e = 0; b + e <= p; ++e) {
            inner[b][e] = f_mul_basis(c, b, t[1][b], e, t[2][e]);
        }
    }
    uint32_t k = 0;
    for (uint32_t d = 0; d <= p; ++d) {
        for (uint32_t a = d + 1; a-- > 0;) {
            for (uint32_t b = d - a + 1; b-- > 0;) {
                uint32_t e = d - a - b;
                phi[k++] = f_mul_basis(c, a, t[0][a], b + e, inner[b][e]);
            }
        }
    }
}

/* sum_{k=1..n} coef_k T_k(x), n >= 0, by Clenshaw (§5.4): h = x + x,
 * b_{n+1} = b_{n+2} = +0, b_k = ((h b_{k+1}) - b_{k+2}) + coef_k for
 * k = n .. 1, result (x b_1) - b_2. */
static float clenshaw_tail(arith *c, const float *coef, uint32_t n, float x)
{
    float h = f_add(c, x, x);
    float b1 = 0.0f, b2 = 0.0f;
    for (uint32_t k = n; k >= 1; --k) {
        float b = f_add(c, f_sub(c, f_mul(c, h, b1), b2), coef[k]);
        b2 = b1;
        b1 = b;
    }
    return f_sub(c, f_mul(c, x, b1), b2);
}

/* sum_{k=0..n} coef_k T_k(x) (§5.4): tail + coef_0, n = 0 included. */
static float clenshaw(arith *c, const float *coef, uint32_t n, float x)
{
    return f_add(c, clenshaw_tail(c, coef, n, x), coef[0]);
}

static void eval_polynomial_rows(arith *c, const float *rows, uint32_t n_rows, uint32_t n_terms,
                                 const float *phi, float *out)
{
    for (uint32_t o = 0; o < n_rows; ++o) {
        const float *row = rows + (size_t)o * n_terms;
        float acc = row[0];
        for (uint32_t t = 1; t < n_terms; ++t) {
            acc = f_add(c, acc, f_mul(c, row[t], phi[t]));
        }
        out[o] = acc;
    }
}

static void eval_modal(arith *c, const tf_model *m, const float *phi, float *out)
{
    uint32_t t = tf_terms(m->dims[0]), r = m->dims[1];
    const float *amp = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *modes = amp + (size_t)r * t;
    float a[TFIT_MAX_RANK];
    eval_polynomial_rows(c, amp, r, t, phi, a);
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        const float *u = modes + (size_t)o * r;
        float acc = f_mul(c, u[0], a[0]);
        for (uint32_t k = 1; k < r; ++k) {
            acc = f_add(c, acc, f_mul(c, u[k], a[k]));
        }
        out[o] = acc;
    }
}

/* modal_q15 (§5.9): the amplitudes term by term (each mode's operations in
 * tfit_row's order), c_k = trunc(a_k v_k) saturated to [-8192, 8191], the
 * integer sums exactly (|sum| < 2^31 by the layout), one conversion and one
 * product by S per output.  The bias and the +16384 of the high halves
 * cancel, so the sum is taken directly over the decoded q. */
static void eval_modal_q15(arith *c, const tf_model *m, const float *phi, float *out)
{
    const uint32_t t = tf_terms(m->dims[0]), r = TFIT_MODAL_Q15_RANK;
    const float *at = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *v = at + (size_t)r * t;
    const float *rows = m->coef + m->n_coef - 3 * (size_t)m->n_out * TFIT_MODAL_Q15_WORDS;
    int32_t q[TFIT_MODAL_Q15_RANK];
    for (uint32_t k = 0; k < r; ++k) {
        float a = at[k];
        for (uint32_t j = 1; j < t; ++j) {
            a = f_add(c, a, f_mul(c, at[(size_t)j * r + k], phi[j]));
        }
        const float x = f_mul(c, a, v[k]);
        q[k] = x >= 8191.0f ? 8191 : x <= -8192.0f ? -8192 : (int32_t)x;
    }
    for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
        int64_t s = 0;
        for (uint32_t j = 0; j < TFIT_MODAL_Q15_WORDS; ++j) {
            const uint32_t w = bits_of(rows[(size_t)o * TFIT_MODAL_Q15_WORDS + j]);
            const int32_t lo = (int32_t)(int16_t)(uint16_t)(w & 0xffffu);
            const int32_t hi = (int32_t)(w >> 16) - 16384;
            s += (int64_t)lo * q[2 * j] + (int64_t)hi * q[2 * j + 1];
        }
        out[o] = f_mul(c, (float)(int32_t)s, v[r]);
    }
}

/* zhou2017: p coefficients for every (axis, component) pair first, then the
 * nodes; the per-output sum order is S_x, + S_y, + S_z (§5.3). */
static void eval_zhou2017(arith *c, const tf_model *m, const float g[3], float *out)
{
    const uint32_t *dm = m->dims;
    const float *q = m->coef + TFIT_INPUT_MAP_FLOATS;
    const float *xy = m->coef + m->n_coef - 2 * m->n_out;
    float t[3];
    float p[9][2 * TFIT_ZHOU_MAX_ORDER + 1];

    for (int a = 0; a < 3; ++a) {
        float d = clenshaw(c, q, dm[a], g[a]);
        q += dm[a] + 1;
        t[a] = f_mul(c, d, *q++);
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = dm[3 + 3 * pair], by = dm[4 + 3 * pair], k = dm[5 + 3 * pair];
        for (uint32_t i = 0; i <= ax + by; ++i, q += k + 1) {
            p[pair][i] = clenshaw(c, q, k, t[pair / 3]);
        }
    }
    for (int pair = 0; pair < 9; ++pair) {
        uint32_t ax = dm[3 + 3 * pair], by = dm[4 + 3 * pair];
        int comp = pair % 3;
        for (uint32_t j = 0; j < m->n_out; ++j) {
            float s = clenshaw(c, p[pair], ax, xy[2 * j]);
            if (by > 0) {
                s = f_add(c, s, clenshaw_tail(c, p[pair] + ax, by, xy[2 * j + 1]));
            }
            float *dst = &out[3 * j + comp];
            *dst = pair < 3 ? s : f_add(c, *dst, s);
        }
    }
}

void tf_ref_input(const tf_model *m, const float in[3], float g[3], int *clamped, int *bad,
                  tf_opcount *ops)
{
    arith c = {{0, 0, 0}};
    input_map(&c, m, in, g, clamped, bad);
    add_ops(ops, &c);
}

/* The family's part (§5) at the projected input g, into out. */
static void eval_family(arith *c, const tf_model *m, const float g[3], float *out)
{
    if (m->family == TFIT_FAMILY_ZHOU2017) {
        eval_zhou2017(c, m, g, out);
    } else {
        float phi[TFIT_TERMS_MAX];
        chebyshev_basis(c, m->dims[0], g, phi);
        if (m->family == TFIT_FAMILY_MODAL) {
            eval_modal(c, m, phi, out);
        } else if (m->family == TFIT_FAMILY_MODAL_Q15) {
            eval_modal_q15(c, m, phi, out);
        } else {
            eval_polynomial_rows(c, m->coef + TFIT_INPUT_MAP_FLOATS, 3 * m->n_out,
                                 tf_terms(m->dims[0]), phi, out);
        }
    }
}

static void add_ops(tf_opcount *ops, const arith *c)
{
    if (ops != NULL) {
        ops->add += c->n.add;
        ops->mul += c->n.mul;
        ops->div += c->n.div;
    }
}

/* h_i beyond [-1, 1] -> +-1 with its sign (§5.6; never NaN here). */
static float clamp_unit(float h)
{
    return fabsf(h) > 1.0f ? copysignf(1.0f, h) : h;
}

/* The prony filter (§5.6): d_i = g_i - gp_i; per term k and axis i
 * z_ki = (a_k z_ki) + (D_k d_i) and h_i = h_i - z_ki from h_i = g_i; the
 * state becomes {g, z} unless the input was bad. */
static void prony_filter(arith *c, const tf_model *m, const float g[3], int bad, float *state,
                         float h[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    const uint32_t words = TFIT_PRONY_STATE_WORDS(m->dims[2]);
    float next[TFIT_PRONY_MAX_STATE], d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = f_sub(c, g[i], state[i]);
        h[i] = g[i];
        next[i] = g[i];
    }
    for (uint32_t k = 0; k < m->dims[2]; ++k) {
        for (int i = 0; i < 3; ++i) {
            float z = f_add(c, f_mul(c, pt[2 * k], state[3 + 3 * k + i]), f_mul(c, pt[2 * k + 1], d[i]));
            next[3 + 3 * k + i] = z;
            h[i] = f_sub(c, h[i], z);
        }
    }
    for (int i = 0; i < 3; ++i) {
        h[i] = clamp_unit(h[i]);
    }
    if (!bad) {
        memcpy(state, next, words * sizeof *state);
    }
}

/* The resonant filter (§5.8, tfit_resonant.c): per mode k and axis i
 * e1 = s - d_i, s' = (f11 e1) + (f12 v), v' = (f21 e1) + (f22 v),
 * h_i = h_i + w_ki s'; the state becomes {g, s', v'} unless the input was
 * bad. */
static void resonant_filter(arith *c, const tf_model *m, const float g[3], int bad, float *state,
                            float h[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    const uint32_t words = TFIT_RESONANT_STATE_WORDS(m->dims[2]);
    float next[TFIT_RESONANT_MAX_STATE], d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = f_sub(c, g[i], state[i]);
        h[i] = g[i];
        next[i] = g[i];
    }
    for (uint32_t k = 0; k < m->dims[2]; ++k, pt += 7) {
        const float *q = state + 3 + 6 * k;
        float *qn = next + 3 + 6 * k;
        for (int i = 0; i < 3; ++i) {
            const float e1 = f_sub(c, q[i], d[i]);
            qn[i] = f_add(c, f_mul(c, pt[0], e1), f_mul(c, pt[1], q[3 + i]));
            qn[3 + i] = f_add(c, f_mul(c, pt[2], e1), f_mul(c, pt[3], q[3 + i]));
            h[i] = f_add(c, h[i], f_mul(c, pt[4 + i], qn[i]));
        }
    }
    for (int i = 0; i < 3; ++i) {
        h[i] = clamp_unit(h[i]);
    }
    if (!bad) {
        memcpy(state, next, words * sizeof *state);
    }
}

void tf_ref_stateful_reset(const tf_model *m, float *state)
{
    const float zero[3] = {0, 0, 0};
    int clamped, bad;
    const uint32_t words = m->family == TFIT_FAMILY_RESONANT
                               ? TFIT_RESONANT_STATE_WORDS(m->dims[2])
                               : TFIT_PRONY_STATE_WORDS(m->dims[2]);
    tf_ref_input(m, zero, state, &clamped, &bad, NULL);
    for (uint32_t w = 3; w < words; ++w) {
        state[w] = 0.0f;
    }
}

tfit_status tf_ref_stateful_step(const tf_model *m, float *state, const float in[3], float *out,
                                 tf_opcount *ops)
{
    if (m->family == TFIT_FAMILY_PRONY) {
        return tf_ref_prony_step(m, state, in, out, ops);
    }
    arith c = {{0, 0, 0}};
    float g[3], h[3];
    int clamped, bad;
    input_map(&c, m, in, g, &clamped, &bad);
    resonant_filter(&c, m, g, bad, state, h);
    tf_model v = tf_stateful_static_view(m);
    eval_family(&c, &v, h, out);
    if (bad) {
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            out[o] = 0.0f;
        }
    }
    add_ops(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

void tf_ref_prony_reset(const tf_model *m, float *state)
{
    const float zero[3] = {0, 0, 0};
    int clamped, bad;
    tf_ref_input(m, zero, state, &clamped, &bad, NULL);
    for (uint32_t w = 3; w < TFIT_PRONY_STATE_WORDS(m->dims[2]); ++w) {
        state[w] = 0.0f;
    }
}

tfit_status tf_ref_prony_step(const tf_model *m, float *state, const float in[3], float *out,
                              tf_opcount *ops)
{
    arith c = {{0, 0, 0}};
    float g[3], h[3];
    int clamped, bad;
    input_map(&c, m, in, g, &clamped, &bad);
    prony_filter(&c, m, g, bad, state, h);
    tf_model v = tf_prony_static_view(m);
    eval_family(&c, &v, h, out);
    if (bad) {
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            out[o] = 0.0f;
        }
    }
    add_ops(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

tfit_status tf_ref_eval(const tf_model *m, const float in[3], float *out, tf_opcount *ops)
{
    if (m->family == TFIT_FAMILY_CUT) { /* the scene's cuts in full, as its other cases */
        return tf_ref_eval_cut(m, in, 1.0f, out, ops);
    }
    if (tf_model_stateful(m)) { /* relaxed: the force held for ever */
        float state[TFIT_RESONANT_MAX_STATE];
        int clamped, bad;
        tf_ref_stateful_reset(m, state);
        tf_ref_input(m, in, state, &clamped, &bad, NULL); /* gp = g: no increment, at rest */
        return tf_ref_stateful_step(m, state, in, out, ops);
    }
    arith c = {{0, 0, 0}};
    float g[3];
    int clamped, bad;
    input_map(&c, m, in, g, &clamped, &bad);
    eval_family(&c, m, g, out);
    if (bad) {
        for (uint32_t o = 0; o < 3 * m->n_out; ++o) {
            out[o] = 0.0f;
        }
    }
    add_ops(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

/* §5.7: s clamped onto [0, 1] (NaN/Inf: bad, taken as 0), t = s K,
 * j = min(trunc t, K - 1), w = t - j; per output a + w (b - a) with a, b
 * the rows of knots j and j + 1. */
tfit_status tf_ref_eval_cut(const tf_model *m, const float in[3], float s, float *out,
                            tf_opcount *ops)
{
    arith c = {{0, 0, 0}};
    float g[3], phi[TFIT_TERMS_MAX];
    int clamped, bad;
    input_map(&c, m, in, g, &clamped, &bad);
    const int s_bad = !isfinite(s);
    float sc = s_bad ? 0.0f : s;
    if (sc < 0.0f || sc > 1.0f) {
        clamped = 1;
        sc = sc < 0.0f ? 0.0f : 1.0f;
    }
    bad = bad || s_bad;
    const uint32_t k = m->dims[1], p = m->dims[0], terms = tf_terms(p);
    const float t = f_mul(&c, sc, (float)k);
    uint32_t j = (uint32_t)floor((double)t);
    j = j > k - 1 ? k - 1 : j;
    const float w = f_sub(&c, t, (float)j);
    chebyshev_basis(&c, p, g, phi);
    const size_t rows = 3 * (size_t)m->n_out;
    const float *a = m->coef + TFIT_INPUT_MAP_FLOATS + (size_t)j * rows * terms;
    float xa, xb;
    for (size_t o = 0; o < rows; ++o) {
        eval_polynomial_rows(&c, a + o * terms, 1, terms, phi, &xa);
        eval_polynomial_rows(&c, a + (rows + o) * terms, 1, terms, phi, &xb);
        const float v = f_add(&c, xa, f_mul(&c, w, f_sub(&c, xb, xa)));
        out[o] = bad ? 0.0f : v;
    }
    add_ops(ops, &c);
    return bad ? TFIT_ERR_INPUT : (clamped ? TFIT_CLAMPED : TFIT_OK);
}

void tf_ref_run(const tf_model *m, const float (*in)[3], size_t n, int32_t *status, float *out)
{
    if (m->family == TFIT_FAMILY_CUT) { /* at the golden progress of each vector (tfit.h) */
        static const uint32_t s_bits[16] = TFIT_CUT_GOLDEN_S_BITS;
        for (size_t v = 0; v < n; ++v) {
            status[v] = (int32_t)tf_ref_eval_cut(m, in[v], float_of(s_bits[v & 15]),
                                                 out + v * 3 * (size_t)m->n_out, NULL);
        }
        return;
    }
    float state[TFIT_RESONANT_MAX_STATE];
    const size_t n_out = 3 * (size_t)m->n_out;
    if (tf_model_stateful(m)) {
        tf_ref_stateful_reset(m, state);
    }
    for (size_t v = 0; v < n; ++v) {
        status[v] = (int32_t)(tf_model_stateful(m)
                                  ? tf_ref_stateful_step(m, state, in[v], out + v * n_out, NULL)
                                  : tf_ref_eval(m, in[v], out + v * n_out, NULL));
    }
}
