/*
 * q31_ref.c — the Q31 integer reference evaluator: docs/q31-format.md
 * §3-§5 written with plain 64-bit and 128-bit host arithmetic and ordinary
 * branches, independently of the target's mask-and-word implementation
 * (target/src/tfit_q31_*.c).  The golden vectors of every Q31 model come
 * from here.
 */
#include "model/q31.h"

/* floor(v / 2^k) — the specification's "shift right" everywhere (GCC and
 * clang define >> of a negative value as the arithmetic shift, i.e. floor;
 * this is host code). */
static int64_t floor_shift(__int128 v, int k)
{
    return (int64_t)(v >> k);
}

/* round(v / 2^k): halves go up (floor(v / 2^k + 1/2)). */
static int64_t round_shift(__int128 v, int k)
{
    return floor_shift(v + ((__int128)1 << (k - 1)), k);
}

static int bit_length(uint64_t v)
{
    int n = 0;
    while (v != 0) {
        ++n;
        v >>= 1;
    }
    return n;
}

/* §3.8: 1/sqrt(m / 2^30) in Q31, m in [2^30, 2^32). */
static uint32_t rsqrt_q31(uint32_t m)
{
    const uint64_t a = 0x88888889u, b = 0x13851eb8u;
    uint64_t y = a - (uint64_t)floor_shift((__int128)b * m, 30);
    for (int i = 0; i < 4; ++i) {
        uint64_t y2 = (uint64_t)floor_shift((__int128)y * y, 31);
        uint64_t t = (uint64_t)floor_shift((__int128)m * y2, 31);
        y = (uint64_t)floor_shift((__int128)y * (3 * ((uint64_t)1 << 30) - t), 31);
    }
    return (uint32_t)y;
}

/* §3: raw input (Q31 of 2^E_in) -> g (Q30) on the unit ball. */
static int project(const tf_q31 *q, const int32_t in[3], int32_t g[3])
{
    const int32_t *x0h = q->q, *w = q->q + 3;
    const int h = q->q[12];
    int64_t gh[3], s = 0;
    for (int i = 0; i < 3; ++i) {
        __int128 acc = 0;
        for (int j = 0; j < 3; ++j) {
            int64_t d = floor_shift(in[j], 1) - x0h[j];
            acc += (__int128)w[3 * i + j] * d;
        }
        gh[i] = round_shift(acc, 32);
        s += gh[i] * gh[i];
    }
    const int64_t one = (int64_t)1 << (60 - 2 * h);
    if (s <= one) {
        for (int i = 0; i < 3; ++i) {
            g[i] = (int32_t)(gh[i] * ((int64_t)1 << h));
        }
        return 0;
    }
    int above = bit_length((uint64_t)s) - 32;
    int e = above + (above & 1);
    uint32_t m = (uint32_t)floor_shift(s, e);
    uint32_t y = rsqrt_q31(m);
    int k = 16 + e / 2;
    for (int i = 0; i < 3; ++i) {
        g[i] = (int32_t)round_shift((__int128)gh[i] * y, k);
    }
    return 1;
}

/* §4: T_0 = 2^30, T_1 = g, T_k = round(g T_{k-1} / 2^29) - T_{k-2} per
 * variable; phi = round(T_a round(T_b T_c / 2^30) / 2^30), graded order,
 * a product with the factor T_0 = 2^30 being exact. */
static void basis(uint32_t p, const int32_t g[3], int32_t *phi)
{
    int64_t t[3][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        t[v][0] = (int64_t)1 << 30;
        t[v][1] = g[v];
        for (uint32_t k = 2; k <= p; ++k) {
            t[v][k] = round_shift((__int128)g[v] * t[v][k - 1], 29) - t[v][k - 2];
        }
    }
    uint32_t k = 0;
    for (int d = 0; d <= (int)p; ++d) {
        for (int a = d; a >= 0; --a) {
            for (int b = d - a; b >= 0; --b) {
                int64_t inner = round_shift((__int128)t[1][b] * t[2][d - a - b], 30);
                phi[k++] = (int32_t)round_shift((__int128)t[0][a] * inner, 30);
            }
        }
    }
}

/* §4-§5: the rows starting at row, at g. */
static void rows(const tf_q31 *q, const int32_t *row, const int32_t g[3], int32_t *out)
{
    int32_t phi[TFIT_Q31_MAX_DEGREE_TERMS];
    const uint32_t t = tf_terms(q->degree);
    basis(q->degree, g, phi);
    for (uint32_t o = 0; o < 3 * q->n_out; ++o, row += t + 1) {
        __int128 acc = 0;
        for (uint32_t k = 0; k < t; ++k) {
            acc += (__int128)row[1 + k] * phi[k];
        }
        out[o] = (int32_t)round_shift(acc, row[0]); /* §5 */
    }
}

tfit_status tf_q31_ref_eval(const tf_q31 *q, const int32_t in[3], int32_t *out, int32_t g_out[3])
{
    int32_t g[3];
    int clamped = project(q, in, g);
    rows(q, q->q + TFIT_Q31_MAP_WORDS, g, out);
    if (g_out != NULL) {
        for (int i = 0; i < 3; ++i) {
            g_out[i] = g[i];
        }
    }
    return clamped ? TFIT_CLAMPED : TFIT_OK;
}

/* §8: state = gp[3] (Q30) | z[K][3] (Q29); a_k in Q31, D_k in Q30. */
void tf_q31_ref_prony_reset(const tf_q31 *q, int32_t *state)
{
    const int32_t zero[3] = {0, 0, 0};
    project(q, zero, state);
    for (uint32_t w = 0; w < 3 * q->terms; ++w) {
        state[3 + w] = 0;
    }
}

/* z_ki <- round((a_k z_ki + D_k (g_i - gp_i)) / 2^31), kept modulo 2^32
 * (never needed for a state reached from rest: §8's bound);
 * h_i = g_i - 2 sum_k z_ki saturated to [-2^30, 2^30]; the rows at h. */
tfit_status tf_q31_ref_prony_step(const tf_q31 *q, int32_t *state, const int32_t in[3],
                                  int32_t *out)
{
    int32_t g[3], h[3];
    const int clamped = project(q, in, g);
    const int32_t *terms = q->q + TFIT_Q31_MAP_WORDS + 1;
    for (int i = 0; i < 3; ++i) {
        int64_t hi = g[i];
        for (uint32_t k = 0; k < q->terms; ++k) {
            const int64_t a = terms[2 * k], d = terms[2 * k + 1];
            int32_t *z = &state[3 + 3 * k + (uint32_t)i];
            const __int128 acc = (__int128)a * *z + (__int128)d * ((int64_t)g[i] - state[i]);
            *z = (int32_t)(uint32_t)(uint64_t)round_shift(acc, 31);
            hi -= 2 * (int64_t)*z;
        }
        const int64_t one = (int64_t)1 << 30;
        h[i] = (int32_t)(hi > one ? one : (hi < -one ? -one : hi));
    }
    for (int i = 0; i < 3; ++i) {
        state[i] = g[i];
    }
    rows(q, q->q + TFIT_Q31_MAP_WORDS + 1 + 2 * q->terms, h, out);
    return clamped ? TFIT_CLAMPED : TFIT_OK;
}
