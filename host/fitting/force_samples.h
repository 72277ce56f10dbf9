/*
 * force_samples.h — the forces a model is trained and judged on.
 *
 * Training forces fill the envelope ball: the six points where the ball
 * meets the axes (the seed's component loads at full strength, §4.2), then a
 * random-start Halton sequence in bases 2, 3, 5 kept where it falls inside
 * the ball (low discrepancy, so no region of the envelope is left unsampled).
 * Held-out forces are independent pseudo-random points, uniform in the ball,
 * never used by any fit.  Only +, -, *, / and comparisons are used, so the
 * same seed gives the same bits on every machine.
 */
#ifndef TF_FORCE_SAMPLES_H
#define TF_FORCE_SAMPLES_H

#include <stddef.h>
#include <stdint.h>

/* Fills train[n_train][3] and heldout[n_heldout][3] with forces in the ball
 * of the given radius around centre.  n_train >= 6. */
void tf_force_samples(const double centre[3], double radius, size_t n_train, size_t n_heldout,
                      uint64_t seed, double (*train)[3], double (*heldout)[3]);

/* Smallest distance between two points of a set (for tests and reports). */
double tf_force_samples_min_distance(const double (*p)[3], size_t n);

/* Rounds every component to the nearest float: forces as the firmware
 * receives them. */
void tf_forces_to_float(double (*v)[3], size_t n);

#endif /* TF_FORCE_SAMPLES_H */
