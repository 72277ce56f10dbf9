/*
 * inputs_extreme.c — the fixed extreme inputs of issue 7 item 2 (inputs.h).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "inputs.h"

#define N_RANDOM_DIRECTIONS 64
#define DIRECTION_SEED 7

/* Envelope multiples: on the boundary, just inside and outside it, 10x and
 * 1e30x beyond (as far as the input type reaches). */
static const double reach_factors[] = {1.0, 1.0 - 0x1p-20, 1.0 + 0x1p-20, 10.0, 1e30};
enum { N_FACTORS = sizeof reach_factors / sizeof reach_factors[0] };

static float from_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* The 26 directions to the faces, edges and corners of a cube, then
 * N_RANDOM_DIRECTIONS seeded ones; returns the count. */
static int directions(double v[][3])
{
    int n = 0;
    for (; n < 26; ++n) {
        stab_cube_direction(n, v[n]);
    }
    tf_rng r = {DIRECTION_SEED};
    for (int k = 0; k < N_RANDOM_DIRECTIONS; ++k) {
        stab_direction(&r, v[n++]);
    }
    return n;
}

enum { N_DIRECTIONS = 26 + N_RANDOM_DIRECTIONS };

/* --- float ------------------------------------------------------------- */

/* Signed zeros give the +0 result exactly; subnormal-sized inputs (and the
 * smallest normal) give it within the clamp's tolerance. */
static uint64_t float_tiny(stab_float *c)
{
    static const float tiny[] = {0.0f, 1e-40f, 0x1p-149f, FLT_MIN};
    uint64_t n = 0;
    float *y0 = malloc(3 * c->m->n_out * sizeof *y0);
    if (y0 == NULL) {
        return 1;
    }
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    n += (uint64_t)stab_float_check(c, zero);
    memcpy(y0, c->y, 3 * c->m->n_out * sizeof *y0);
    for (size_t k = 0; k < sizeof tiny / sizeof tiny[0]; ++k) {
        for (int signs = 0; signs < 27; ++signs) { /* each component -t, 0 or t */
            const float x[3] = {tiny[k] * (float)(signs % 3 - 1),
                                tiny[k] * (float)(signs / 3 % 3 - 1),
                                tiny[k] * (float)(signs / 9 - 1)};
            n += (uint64_t)stab_float_check(c, x);
            const double dev = stab_float_deviation(c, c->y, y0);
            if ((k == 0 && dev != 0) || !(dev <= STAB_FLOAT_TOL_ULPS)) {
                fprintf(stderr, "%s: input {%a, %a, %a}: %.3g ulps from the result at zero\n",
                        c->label, (double)x[0], (double)x[1], (double)x[2], dev);
                c->st.failures++;
                n++;
            }
        }
    }
    free(y0);
    return n;
}

static uint64_t float_directions(stab_float *c)
{
    double v[N_DIRECTIONS][3];
    const int nd = directions(v);
    uint64_t n = 0;
    for (int k = 0; k < nd; ++k) {
        for (int f = 0; f < N_FACTORS; ++f) {
            float x[3];
            stab_float_along(c, v[k], reach_factors[f], x);
            n += (uint64_t)stab_float_check(c, x);
        }
    }
    return n;
}

/* FLT_MAX and the 2^64 threshold of header-format.md §4 step 3 in every
 * combination of signs and zeros. */
static uint64_t float_huge(stab_float *c)
{
    static const float huge[] = {FLT_MAX, 0x1p64f, 0x1.000002p64f, 0x1.fffffep63f, 0x1p65f, 1e38f};
    uint64_t n = 0;
    for (size_t k = 0; k < sizeof huge / sizeof huge[0]; ++k) {
        for (int signs = 0; signs < 27; ++signs) {
            const float x[3] = {huge[k] * (float)(signs % 3 - 1), huge[k] * (float)(signs / 3 % 3 - 1),
                                huge[k] * (float)(signs / 9 - 1)};
            n += (uint64_t)stab_float_check(c, x);
        }
    }
    const float mixed[][3] = {{FLT_MAX, 1.0f, 1e-40f}, {-FLT_MAX, 0x1p64f, 1.0f}, {1e38f, -1e38f, 1e-30f}};
    for (size_t k = 0; k < sizeof mixed / sizeof mixed[0]; ++k) {
        n += (uint64_t)stab_float_check(c, mixed[k]);
    }
    return n;
}

/* NaN of every kind and +-Inf in each position, the other components
 * ordinary, tiny or huge; then all three non-finite. */
static uint64_t float_nonfinite(stab_float *c)
{
    static const uint32_t special[] = {0x7fc00000u, 0xffc00000u, 0x7f800001u, 0x7fa5a5a5u,
                                       0x7f800000u, 0xff800000u};
    static const float other[] = {0.0f, -1.0f, 1e-40f, FLT_MAX};
    enum { N_SPECIAL = sizeof special / sizeof special[0] };
    uint64_t n = 0;
    for (int s = 0; s < N_SPECIAL; ++s) {
        for (int pos = 0; pos < 3; ++pos) {
            for (size_t o = 0; o < sizeof other / sizeof other[0]; ++o) {
                float x[3] = {other[o], other[o], other[o]};
                x[pos] = from_bits(special[s]);
                n += (uint64_t)stab_float_check(c, x);
            }
        }
        const float all[3] = {from_bits(special[s]), from_bits(special[(s + 1) % N_SPECIAL]),
                              from_bits(special[(s + 2) % N_SPECIAL])};
        n += (uint64_t)stab_float_check(c, all);
    }
    return n;
}

uint64_t stab_extremes_float(stab_float *c)
{
    return float_tiny(c) + float_directions(c) + float_huge(c) + float_nonfinite(c);
}

/* --- Q31 ---------------------------------------------------------------- */

/* The zero word, and the +-1 words (the Q31 analogue of a subnormal-sized
 * force) within the clamp's tolerance of it. */
static uint64_t q31_tiny(stab_q31 *c)
{
    uint64_t n = 0;
    int32_t *y0 = malloc(3 * c->m->n_out * sizeof *y0);
    if (y0 == NULL) {
        return 1;
    }
    const int32_t zero[3] = {0, 0, 0};
    n += (uint64_t)stab_q31_check(c, zero);
    memcpy(y0, c->y, 3 * c->m->n_out * sizeof *y0);
    for (int signs = 0; signs < 27; ++signs) {
        const int32_t x[3] = {signs % 3 - 1, signs / 3 % 3 - 1, signs / 9 - 1};
        n += (uint64_t)stab_q31_check(c, x);
        const double dev = stab_q31_deviation(c, c->y, y0);
        if (!(dev <= c->tol)) {
            fprintf(stderr, "%s: input {%d, %d, %d}: %.0f LSB from the result at zero\n", c->label,
                    x[0], x[1], x[2], dev);
            c->st.failures++;
            n++;
        }
    }
    free(y0);
    return n;
}

/* Boundary words, and 10x and 1e30x beyond, converted with saturation as
 * the firmware's conversion does. */
static uint64_t q31_directions(stab_q31 *c)
{
    double v[N_DIRECTIONS][3];
    const int nd = directions(v);
    uint64_t n = 0;
    for (int k = 0; k < nd; ++k) {
        for (int f = 0; f < N_FACTORS; ++f) {
            int32_t x[3];
            stab_q31_along(c, v[k], reach_factors[f], x);
            n += (uint64_t)stab_q31_check(c, x);
        }
    }
    return n;
}

/* Every combination of INT32_MIN, INT32_MAX and a small word. */
static uint64_t q31_saturated(stab_q31 *c)
{
    static const int32_t small[] = {0, -1, 1};
    uint64_t n = 0;
    for (size_t k = 0; k < sizeof small / sizeof small[0]; ++k) {
        const int32_t w[3] = {INT32_MIN, small[k], INT32_MAX};
        for (int pick = 0; pick < 27; ++pick) {
            const int32_t x[3] = {w[pick % 3], w[pick / 3 % 3], w[pick / 9]};
            n += (uint64_t)stab_q31_check(c, x);
        }
    }
    return n;
}

uint64_t stab_extremes_q31(stab_q31 *c)
{
    return q31_tiny(c) + q31_directions(c) + q31_saturated(c);
}
