/*
 * inputs.h — the inputs of issue 7 items 2 and 5, fed to the invariant
 * checks of invariants.h.
 *
 *   item 2 (stab_extremes_*): zero and signed zeros, subnormal-sized
 *   inputs, points exactly on the envelope boundary and 10x and 1e30x
 *   beyond it in 90 directions, FLT_MAX and the 2^64 rescaling threshold
 *   of header-format.md §4 step 3, NaN (quiet, negative, signalling, with
 *   payload) and +-Inf alone and mixed; Q31: zero, +-1 words, boundary
 *   words and saturated words.  Tiny inputs must also give the zero
 *   input's result (within the same tolerance as the clamp).
 *
 *   item 5 (stab_random_*): n seeded random inputs of any magnitude
 *   (10^-45 .. 10^38.5, random signs and directions; around the envelope;
 *   NaN and Inf mixed in), or of any int32 words for Q31.
 *
 * Each returns the number of invariant violations.
 */
#ifndef STAB_INPUTS_H
#define STAB_INPUTS_H

#include <stdint.h>

#include "invariants.h"
#include "base/rng.h"

uint64_t stab_extremes_float(stab_float *c);
uint64_t stab_extremes_q31(stab_q31 *c);

uint64_t stab_random_float(stab_float *c, uint64_t n, uint64_t seed);
uint64_t stab_random_q31(stab_q31 *c, uint64_t n, uint64_t seed);

/* A direction uniform on the unit sphere. */
void stab_direction(tf_rng *r, double v[3]);

#endif /* STAB_INPUTS_H */
