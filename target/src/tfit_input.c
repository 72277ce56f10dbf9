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

/* Start for 1/sqrt(s) from the bit pattern of s (relative error <= 3.5 %
 * for every positive float), then three Newton steps
 * y <- (y/2)(3 - s y y), each squaring the error. */
#define RSQRT_MAGIC 0x5f3759dfu

static inline float newton_rsqrt_step(float s, float y)
{
    float t = s * y;
    t = t * y;
    t = 3.0f - t;
    return (0.5f * y) * t;
}

static float rsqrt(float s)
{
    float y = tfit_float(RSQRT_MAGIC - (tfit_bits(s) >> 1));
    y = newton_rsqrt_step(s, y);
    y = newton_rsqrt_step(s, y);
    return newton_rsqrt_step(s, y);
}

/* The power of two 2^(e - E) for a float with biased exponent E (bits of
 * a positive float): multiplying by it is exact and brings the float into
 * [2^(e-127), 2^(e-126)).  Only meaningful when the result is normal, which
 * the callers guarantee where they use it. */
static inline uint32_t exponent_scale(uint32_t e, uint32_t magnitude_bits)
{
    return (e + 127u - (magnitude_bits >> 23)) << 23;
}

static uint32_t max_abs_bits(float a, float b, float c)
{
    return tfit_umax(tfit_umax(tfit_bits(a) & ABS_MASK, tfit_bits(b) & ABS_MASK),
                     tfit_bits(c) & ABS_MASK);
}

/* Row i of g = W d, summed as ((W_i0 d0 + W_i1 d1) + W_i2 d2). */
static inline float w_row(const float *w, const float d[3])
{
    return (w[0] * d[0] + w[1] * d[1]) + w[2] * d[2];
}

/* The component loops are written out: three iterations of a loop cost more
 * in counter and branch than in arithmetic (docs/firmware.md). */
uint32_t tfit_input_map(const float *map, const float x_in[3], float g_out[3], uint32_t *bad)
{
    const float *x0 = map;
    const float *w = map + 3;

    /* 1-2: NaN or Inf anywhere (a magnitude with all exponent bits set) ->
     * flag, and continue from a zero input. */
    const uint32_t in_max = max_abs_bits(x_in[0], x_in[1], x_in[2]);
    const uint32_t nonfinite = tfit_mask(in_max >= EXP_MASK);
    *bad = nonfinite;

    /* 3: inputs beyond 2^64 are scaled by a power of two to a largest
     * component in [2^64, 2^65) (keeps W x finite); the others are
     * multiplied by exactly 1. */
    const uint32_t xmax = in_max & ~nonfinite;
    const uint32_t big = tfit_mask(xmax > BITS_2P64);
    const float to_2p64 = tfit_float((exponent_scale(191u, xmax) & big) | (BITS_ONE & ~big));
    const float x[3] = {tfit_masked(x_in[0], ~nonfinite) * to_2p64,
                        tfit_masked(x_in[1], ~nonfinite) * to_2p64,
                        tfit_masked(x_in[2], ~nonfinite) * to_2p64};

    /* 4-5: g = W (x - x0). */
    const float d[3] = {x[0] - x0[0], x[1] - x0[1], x[2] - x0[2]};
    float g[3] = {w_row(w, d), w_row(w + 3, d), w_row(w + 6, d)};

    /* 6: beyond the unit cube, a power of two brings the largest component
     * into [1, 2): the squared norm below cannot overflow. */
    const uint32_t gmax = max_abs_bits(g[0], g[1], g[2]);
    const uint32_t far = tfit_mask(gmax > BITS_ONE);
    const float to_unit = tfit_float((exponent_scale(127u, gmax) & far) | (BITS_ONE & ~far));
    g[0] = g[0] * to_unit;
    g[1] = g[1] * to_unit;
    g[2] = g[2] * to_unit;

    /* 7-9: outside the ball -> multiply by 1/|g| (s is then in [1, 12)). */
    const float s = (g[0] * g[0] + g[1] * g[1]) + g[2] * g[2];
    const uint32_t out = far | tfit_mask(s > 1.0f);
    const float y = tfit_select(out, rsqrt(tfit_select(out, s, 1.0f)), 1.0f);
    g_out[0] = g[0] * y;
    g_out[1] = g[1] * y;
    g_out[2] = g[2] * y;
    return out;
}
