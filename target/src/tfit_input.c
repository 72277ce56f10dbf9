/*
 * tfit_input.c — input validation and the branch-free envelope projection.
 *
 * The fitted envelope is the ellipsoid { x : |W (x - x0)| <= 1 }.  Inputs
 * inside it map to g = W (x - x0) unchanged; inputs outside are projected
 * radially onto its boundary, g / |g|, so a polynomial is never extrapolated
 * into the actuator.  The steps below are numbered as in
 * docs/header-format.md §4; the host reference evaluator follows them
 * operation for operation.
 */
#include "tfit_internal.h"

#define EXP_MASK 0x7f800000u
#define ABS_MASK 0x7fffffffu
#define BITS_ONE 0x3f800000u  /* 1.0f */
#define BITS_2P64 0x5f800000u /* 2^64 */

/* Linear start for 1/sqrt(s) on [1, 3] (relative error <= 7.3 %), then three
 * Newton steps y <- (y/2)(3 - s y y), each squaring the error. */
#define RSQRT_A 0x1.2bp+0f  /* 1.16796875 */
#define RSQRT_B 0x1.bp-3f   /* 0.2109375 */

static inline float newton_rsqrt_step(float s, float y)
{
    float t = s * y;
    t = t * y;
    t = 3.0f - t;
    return (0.5f * y) * t;
}

static float rsqrt_1_3(float s)
{
    float y = RSQRT_A - RSQRT_B * s;
    y = newton_rsqrt_step(s, y);
    y = newton_rsqrt_step(s, y);
    return newton_rsqrt_step(s, y);
}

static uint32_t max_abs_bits(const float v[3])
{
    uint32_t m = tfit_bits(v[0]) & ABS_MASK;
    m = tfit_umax(m, tfit_bits(v[1]) & ABS_MASK);
    return tfit_umax(m, tfit_bits(v[2]) & ABS_MASK);
}

static uint32_t nonfinite_mask(float v)
{
    return tfit_mask((tfit_bits(v) & EXP_MASK) == EXP_MASK);
}

/* Row i of g = W d, summed as ((W_i0 d0 + W_i1 d1) + W_i2 d2). */
static inline float w_row(const float *w, const float d[3])
{
    return (w[0] * d[0] + w[1] * d[1]) + w[2] * d[2];
}

/* The component loops are written out: three iterations of a loop cost more
 * in counter and branch than in arithmetic (docs/firmware.md). */
uint32_t tfit_input_map(const float *map, const float x_in[3], float g[3], uint32_t *bad)
{
    const float *x0 = map;
    const float *w = map + 3;
    float x[3];

    /* 1-2: NaN or Inf anywhere -> flag, and continue from a zero input. */
    const uint32_t nonfinite =
        nonfinite_mask(x_in[0]) | nonfinite_mask(x_in[1]) | nonfinite_mask(x_in[2]);
    x[0] = tfit_masked(x_in[0], ~nonfinite);
    x[1] = tfit_masked(x_in[1], ~nonfinite);
    x[2] = tfit_masked(x_in[2], ~nonfinite);
    *bad = nonfinite;

    /* 3: inputs beyond 2^64 are rescaled to max component 2^64 (keeps W x
     * finite); dividing and multiplying by 1 leaves the others exact. */
    uint32_t big = tfit_mask(max_abs_bits(x) > BITS_2P64);
    float div = tfit_select(big, tfit_float(max_abs_bits(x)), 1.0f);
    float mul = tfit_select(big, 0x1p64f, 1.0f);
    x[0] = (x[0] / div) * mul;
    x[1] = (x[1] / div) * mul;
    x[2] = (x[2] / div) * mul;

    /* 4-5: g = W (x - x0). */
    const float d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    g[0] = w_row(w, d);
    g[1] = w_row(w + 3, d);
    g[2] = w_row(w + 6, d);

    /* 6: scale by the largest component when it exceeds 1 (no overflow in
     * the squared norm, whatever the magnitude). */
    uint32_t far = tfit_mask(max_abs_bits(g) > BITS_ONE);
    float m = tfit_select(far, tfit_float(max_abs_bits(g)), 1.0f);
    g[0] = g[0] / m;
    g[1] = g[1] / m;
    g[2] = g[2] / m;

    /* 7-9: |h|^2 > 1 -> multiply by 1/|h| (now s is in (1, 3]). */
    float s = (g[0] * g[0] + g[1] * g[1]) + g[2] * g[2];
    uint32_t out = tfit_mask(s > 1.0f);
    float y = tfit_select(out, rsqrt_1_3(tfit_select(out, s, 1.0f)), 1.0f);
    g[0] = g[0] * y;
    g[1] = g[1] * y;
    g[2] = g[2] * y;
    return far | out;
}
