/*
 * force_samples.c — see force_samples.h.
 */
#include "fitting/force_samples.h"

#include <math.h>

#include "base/rng.h"

/* Radical inverse of i in base b, in [0, 1). */
static double radical_inverse(uint64_t i, unsigned b)
{
    double inv = 1.0 / b, f = inv, r = 0.0;
    while (i > 0) {
        r += (double)(i % b) * f;
        i /= b;
        f *= inv;
    }
    return r;
}

static void put(double *dst, const double centre[3], double radius, const double u[3])
{
    for (int k = 0; k < 3; ++k) {
        dst[k] = centre[k] + radius * u[k];
    }
}

static int inside(const double u[3])
{
    return u[0] * u[0] + u[1] * u[1] + u[2] * u[2] <= 1.0;
}

void tf_force_samples(const double centre[3], double radius, size_t n_train, size_t n_heldout,
                      uint64_t seed, double (*train)[3], double (*heldout)[3])
{
    size_t n = 0;
    for (int axis = 0; axis < 3 && n < n_train; ++axis) {
        for (int sign = 1; sign >= -1 && n < n_train; sign -= 2) {
            double u[3] = {0, 0, 0};
            u[axis] = sign;
            put(train[n++], centre, radius, u);
        }
    }
    tf_rng r = {seed};
    uint64_t index = 1 + (tf_rng_next(&r) >> 44); /* random start, < 2^20 */
    while (n < n_train) {
        double u[3] = {2 * radical_inverse(index, 2) - 1, 2 * radical_inverse(index, 3) - 1,
                       2 * radical_inverse(index, 5) - 1};
        ++index;
        if (inside(u)) {
            put(train[n++], centre, radius, u);
        }
    }
    tf_rng h = {seed ^ 0x6a09e667f3bcc909ull};
    for (size_t m = 0; m < n_heldout;) {
        double u[3] = {tf_rng_range(&h, -1, 1), tf_rng_range(&h, -1, 1), tf_rng_range(&h, -1, 1)};
        if (inside(u)) {
            put(heldout[m++], centre, radius, u);
        }
    }
}

double tf_force_samples_min_distance(const double (*p)[3], size_t n)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = i + 1; j < n; ++j) {
            double d2 = 0;
            for (int k = 0; k < 3; ++k) {
                d2 += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
            }
            best = d2 < best ? d2 : best;
        }
    }
    return sqrt(best);
}

/* host.mk compiles this without SLP vectorization: GCC 12.2 at -O2 would
 * round only v[i][2] (tests/unit/fitting/test_toolchain.c). */
void tf_forces_to_float(double (*v)[3], size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            v[i][k] = (double)(float)v[i][k];
        }
    }
}
