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

/* A stateful model's golden design: one tick sequence from rest (press to
 * the envelope's boundary, hold, release, rest, random forces inside,
 * NaN/Inf ticks between equal forces, forces beyond the envelope, the
 * largest and subnormal floats), at most TF_GOLDEN_MAX ticks.  Returns the
 * count. */
size_t tf_golden_ticks(const tf_model *m, uint64_t seed, float in[][3]);

/* The self-test inputs' indices in each design (a form names its design
 * and these: model/forms/form.h). */
extern const size_t tf_golden_pick_points[TFIT_CHECK_INPUTS];
extern const size_t tf_golden_pick_ticks[TFIT_CHECK_INPUTS];

/* The golden design of any model: its form's (tf_golden_ticks for a
 * stateful model, else tf_golden_inputs). */
size_t tf_golden_design(const tf_model *m, uint64_t seed, float in[][3]);

/* The self-test every emitted model carries (docs/header-format.md §8;
 * tfit_model_check() evaluates it): TFIT_CHECK_INPUTS inputs (bits), then
 * the CRC-32 of the status and every output's bits at each, in order, from
 * the reference evaluator.  Returns -1 when out of memory. */
int tf_check_vector(const tf_model *m, uint32_t check[TFIT_CHECK_WORDS]);

/* The model's CRC-32 as the target computes it: tf_model_crc32() continued
 * over the self-test vector. */
uint32_t tf_model_crc32_checked(const tf_model *m, const uint32_t check[TFIT_CHECK_WORDS]);

#endif /* TF_GOLDEN_H */
