/*
 * inputs_random.c — the seeded random inputs of issue 7 item 5 (inputs.h).
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "inputs.h"

/* log10 of the magnitudes drawn: the smallest subnormal to FLT_MAX. */
#define LOG10_MIN (-45.0)
#define LOG10_MAX 38.53
/* One component in NONFINITE_RATE is replaced by a NaN or an infinity. */
#define NONFINITE_RATE 32u

void stab_direction(tf_rng *r, double v[3])
{
    double s;
    do { /* uniform in the ball by rejection, then onto the sphere */
        for (int j = 0; j < 3; ++j) {
            v[j] = tf_rng_range(r, -1, 1);
        }
        s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    } while (s > 1 || s < 1e-6);
    s = sqrt(s);
    for (int j = 0; j < 3; ++j) {
        v[j] /= s;
    }
}

static double log_uniform(tf_rng *r, double lo, double hi)
{
    return pow(10, tf_rng_range(r, lo, hi));
}

static double random_sign(tf_rng *r)
{
    return (tf_rng_next(r) >> 63) ? -1.0 : 1.0;
}

/* Distance from the centre, in envelope units: mostly anywhere from a
 * thousandth of the envelope to a thousand times it, one in eight within
 * 2^-18 of the boundary, where the status changes. */
static double envelope_multiple(tf_rng *r)
{
    if (tf_rng_below(r, 8) == 0) {
        return 1 + tf_rng_range(r, -0x1p-18, 0x1p-18);
    }
    return log_uniform(r, -3, 3);
}

/* --- float ------------------------------------------------------------- */

static float nonfinite(tf_rng *r)
{
    static const uint32_t special[] = {0x7fc00000u, 0xffc00000u, 0x7f800001u,
                                       0x7f800000u, 0xff800000u};
    uint32_t u = special[tf_rng_below(r, sizeof special / sizeof special[0])];
    if (u == 0x7f800001u) { /* signalling NaN with a random payload */
        u |= (uint32_t)tf_rng_next(r) & 0x003fffffu;
    }
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* Half the inputs: a random direction times a magnitude anywhere from
 * 10^-45 to 10^38.5; one in eight: each component its own magnitude and
 * sign (after the projection, components 10^38 apart make the small ones
 * subnormal, which costs x86 about 80 times the normal time per
 * operation, hence the smaller share); the rest around the envelope. */
static void random_float_input(const stab_float *c, tf_rng *r, float x[3])
{
    double v[3];
    const uint32_t kind = tf_rng_below(r, 8);
    if (kind < 4) {
        stab_direction(r, v);
        const double m = log_uniform(r, LOG10_MIN, LOG10_MAX);
        for (int j = 0; j < 3; ++j) {
            x[j] = (float)(m * v[j]);
        }
    } else if (kind == 4) {
        for (int j = 0; j < 3; ++j) {
            x[j] = (float)(random_sign(r) * log_uniform(r, LOG10_MIN, LOG10_MAX));
        }
    } else {
        stab_direction(r, v);
        stab_float_along(c, v, envelope_multiple(r), x);
    }
    for (int j = 0; j < 3; ++j) {
        if (tf_rng_below(r, NONFINITE_RATE) == 0) {
            x[j] = nonfinite(r);
        }
    }
}

uint64_t stab_random_float(stab_float *c, uint64_t n, uint64_t seed)
{
    tf_rng r = {seed};
    uint64_t bad = 0;
    for (uint64_t i = 0; i < n; ++i) {
        float x[3];
        random_float_input(c, &r, x);
        bad += (uint64_t)stab_float_check(c, x);
    }
    return bad;
}

/* --- Q31 ---------------------------------------------------------------- */

static void random_q31_input(const stab_q31 *c, tf_rng *r, int32_t x[3])
{
    double v[3];
    switch (tf_rng_below(r, 4)) {
    case 0: /* any words */
        for (int j = 0; j < 3; ++j) {
            x[j] = (int32_t)(uint32_t)tf_rng_next(r);
        }
        break;
    case 1: /* magnitudes of every binade */
        for (int j = 0; j < 3; ++j) {
            x[j] = stab_q31_word(random_sign(r) * ldexp(1, (int)tf_rng_below(r, 32)) *
                                 tf_rng_range(r, 0.5, 1));
        }
        break;
    case 2: { /* around the envelope */
        stab_direction(r, v);
        stab_q31_along(c, v, envelope_multiple(r), x);
        break;
    }
    default: /* saturated components (a sensor reading beyond the range) */
        for (int j = 0; j < 3; ++j) {
            const uint32_t k = tf_rng_below(r, 3);
            x[j] = k == 0 ? INT32_MIN : k == 1 ? INT32_MAX : (int32_t)(uint32_t)tf_rng_next(r);
        }
        break;
    }
}

uint64_t stab_random_q31(stab_q31 *c, uint64_t n, uint64_t seed)
{
    tf_rng r = {seed};
    uint64_t bad = 0;
    for (uint64_t i = 0; i < n; ++i) {
        int32_t x[3];
        random_q31_input(c, &r, x);
        bad += (uint64_t)stab_q31_check(c, x);
    }
    return bad;
}
