/*
 * rng.h — a small deterministic random generator (splitmix64) for load-case
 * design, golden vectors and tests: the same seed gives the same numbers on
 * every machine (integer arithmetic, exact conversions to double).
 */
#ifndef TF_RNG_H
#define TF_RNG_H

#include <stdint.h>

typedef struct tf_rng {
    uint64_t state;
} tf_rng;

static inline uint64_t tf_rng_next(tf_rng *r)
{
    uint64_t z = (r->state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 random bits. */
static inline double tf_rng_uniform(tf_rng *r)
{
    return (double)(tf_rng_next(r) >> 11) * 0x1p-53;
}

/* Uniform in [lo, hi). */
static inline double tf_rng_range(tf_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * tf_rng_uniform(r);
}

/* Uniform integer in [0, n). */
static inline uint32_t tf_rng_below(tf_rng *r, uint32_t n)
{
    return (uint32_t)((tf_rng_next(r) >> 32) * n >> 32);
}

#endif /* TF_RNG_H */
