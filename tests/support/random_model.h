/*
 * random_model.h — random models for the bit-exact and property tests:
 * every family, sizes up to the build's capacity, ellipsoidal envelopes with
 * offsets, and coefficients spread over many binades (down to subnormals),
 * scaled by powers of two until the model is emittable; region laws and
 * surfaces through random_region.h.
 */
#ifndef TF_RANDOM_MODEL_H
#define TF_RANDOM_MODEL_H

#include "model/model.h"
#include "base/rng.h"

/* family 0 picks one of the stateless families at random (prony only when
 * asked for).  small != 0 keeps tables short (for
 * emitted headers).  Returns NULL only when out of memory. */
tf_model *tf_random_model(tf_rng *r, const char *name, tfit_family family, int small);
/* The same with the family, dims and n_out given (random map and tables). */
tf_model *tf_random_model_of(tf_rng *r, const char *name, tfit_family f, const uint32_t *dims,
                             uint32_t n_dims, uint32_t n_out);

/* A random Q31 input word: anywhere, near zero, at the int32 limits, or
 * within 2^29 (the Q31 tests). */
int32_t tf_random_q31_word(tf_rng *r);

#endif /* TF_RANDOM_MODEL_H */
