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

static float rsqrt_1_3(float s)
{
    float y = RSQRT_A - RSQRT_B * s;
    for (int i = 0; i < 3; ++i) {
        float t = s * y;
        t = t * y;
        t = 3.0f - t;
        y = (0.5f * y) * t;
    }
    return y;
}

static uint32_t max_abs_bits(const float v[3])
{
    uint32_t m = tfit_bits(v[0]) & ABS_MASK;
    m = tfit_umax(m, tfit_bits(v[1]) & ABS_MASK);
    return tfit_umax(m, tfit_bits(v[2]) & ABS_MASK);
}

uint32_t tfit_input_map(const float *map, const float x_in[3], float g[3], uint32_t *bad)
{
    const float *x0 = map;
    const float *w = map + 3;
    float x[3];

    /* 1-2: NaN or Inf anywhere -> flag, and continue from a zero input. */
    uint32_t nonfinite = 0u;
    for (int i = 0; i < 3; ++i) {
        nonfinite |= tfit_mask((tfit_bits(x_in[i]) & EXP_MASK) == EXP_MASK);
    }
    for (int i = 0; i < 3; ++i) {
        x[i] = tfit_float(tfit_bits(x_in[i]) & ~nonfinite);
    }
    *bad = nonfinite;

    /* 3: inputs beyond 2^64 are rescaled to max component 2^64 (keeps W x
     * finite); dividing and multiplying by 1 leaves the others exact. */
    uint32_t big = tfit_mask(max_abs_bits(x) > BITS_2P64);
    float div = tfit_select(big, tfit_float(max_abs_bits(x)), 1.0f);
    float mul = tfit_select(big, 0x1p64f, 1.0f);
    for (int i = 0; i < 3; ++i) {
        x[i] = (x[i] / div) * mul;
    }

    /* 4-5: g = W (x - x0). */
    float d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = x[i] - x0[i];
    }
    for (int i = 0; i < 3; ++i) {
        g[i] = (w[3 * i] * d[0] + w[3 * i + 1] * d[1]) + w[3 * i + 2] * d[2];
    }

    /* 6: scale by the largest component when it exceeds 1 (no overflow in
     * the squared norm, whatever the magnitude). */
    uint32_t far = tfit_mask(max_abs_bits(g) > BITS_ONE);
    float m = tfit_select(far, tfit_float(max_abs_bits(g)), 1.0f);
    for (int i = 0; i < 3; ++i) {
        g[i] = g[i] / m;
    }

    /* 7-9: |h|^2 > 1 -> multiply by 1/|h| (now s is in (1, 3]). */
    float s = (g[0] * g[0] + g[1] * g[1]) + g[2] * g[2];
    uint32_t out = tfit_mask(s > 1.0f);
    float y = tfit_select(out, rsqrt_1_3(tfit_select(out, s, 1.0f)), 1.0f);
    for (int i = 0; i < 3; ++i) {
        g[i] = g[i] * y;
    }
    return far | out;
}
