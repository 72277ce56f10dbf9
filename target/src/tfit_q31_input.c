/*
 * tfit_q31_input.c — the Q31 input map and branch-free envelope projection
 * (docs/q31-format.md §3, steps numbered as there).
 *
 * map = x0h[3] (Q30 of 2^E_in), W[9] (row-major), H.  The raw input x is
 * Q31 of 2^E_in; g comes out in Q30 (1.0 = 2^30) on the unit ball.
 */
#include "tfit_q31_internal.h"

/* 1/sqrt(u) on [1, 4): y0 = a - b u (a = 16/15, b = 0.1525; 8.7 % worst
 * relative error), then four Newton steps; y in Q31, u = m / 2^30. */
#define RSQRT_A 0x88888889u
#define RSQRT_B 0x13851eb8u
#define THREE_Q30 0xc0000000u
#define NEWTON_STEPS 4u

static uint32_t rsqrt_q31(uint32_t m)
{
    uint32_t y = RSQRT_A - q_shr64_lo(q_umul(RSQRT_B, m), 30u);
    for (uint32_t i = 0u; i < NEWTON_STEPS; ++i) {
        const uint32_t y2 = q_shr64_lo(q_umul(y, y), 31u);
        const uint32_t t = q_shr64_lo(q_umul(m, y2), 31u);
        y = q_shr64_lo(q_umul(y, THREE_Q30 - t), 31u);
    }
    return y;
}

uint32_t tfit_q31_input_map(const int32_t *map, const int32_t x[3], int32_t g[3])
{
    const int32_t *x0h = map, *w = map + 3;
    const uint32_t h = (uint32_t)map[12];
    int32_t d[3], gh[3];

    /* 1-2: halve the input (x_j >> 1, floor) and subtract the centre. */
    for (int j = 0; j < 3; ++j) {
        d[j] = q_sra32((uint32_t)x[j], 1u) - x0h[j];
    }
    /* 3-4: G = W d exactly in 64 bits; gh = round(G / 2^32) in Q(30-H). */
    for (int i = 0; i < 3; ++i) {
        uint64_t acc = q_smul(w[3 * i], d[0]);
        acc += q_smul(w[3 * i + 1], d[1]);
        acc += q_smul(w[3 * i + 2], d[2]);
        gh[i] = (int32_t)q_hi(acc + 0x80000000u);
    }
    /* 5: |g|^2 > 1 ?  S = sum gh^2, ONE = 2^(60 - 2H) = 2^32 * 2^(28 - 2H). */
    uint64_t s = q_smul(gh[0], gh[0]);
    s += q_smul(gh[1], gh[1]);
    s += q_smul(gh[2], gh[2]);
    const uint64_t one = q_words(1u << (28u - 2u * h), 0u);
    const uint32_t out = q_negative(q_hi(one - s));

    /* 7: S' = out ? S : ONE >= 2^32; m = S' / 2^e in [2^30, 2^32), e even. */
    const uint32_t s_hi = q_select(out, q_hi(s), q_hi(one));
    const uint32_t s_lo = q_select(out, q_lo(s), 0u);
    const uint32_t above = q_bit_length(s_hi); /* n - 32 */
    const uint32_t e = above + (above & 1u);
    const uint32_t m = (s_lo >> e) | (s_hi << (32u - e));

    /* 8-9: y = 1/sqrt(m / 2^30); the projection is gh y / 2^(16 + e/2). */
    const uint32_t y = rsqrt_q31(m);
    const uint32_t k = 16u + e / 2u;
    for (int i = 0; i < 3; ++i) {
        const uint32_t proj = q_shr64_lo(q_sumul(gh[i], y) + (1u << (k - 1u)), k);
        const uint32_t plain = (uint32_t)gh[i] << h; /* 6 */
        g[i] = (int32_t)q_select(out, proj, plain);  /* 10 */
    }
    return out;
}
