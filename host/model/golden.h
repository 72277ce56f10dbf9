/*
 * golden.h — the input vectors of a model's golden set (docs/header-format.md
 * §7): zero, the envelope centre, random points inside the envelope, points
 * on its boundary, 10x and 1e30x beyond it, the largest floats, subnormal
 * forces, NaN and Inf.  Deterministic for a given seed.
 */
#ifndef TF_GOLDEN_H
#define TF_GOLDEN_H

#include <stddef.h>
#include <stdint.h>

#include "model/model.h"

#define TF_GOLDEN_MAX 80

/* Fills in[][3] (capacity TF_GOLDEN_MAX) and returns the count. */
size_t tf_golden_inputs(const tf_model *m, uint64_t seed, float in[][3]);

#endif /* TF_GOLDEN_H */
