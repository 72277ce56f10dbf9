/*
 * lm_box.h — the box of a bounded Levenberg–Marquardt fit, for lm.c:
 * clamping a point into it and projecting a trial step onto it.
 */
#ifndef TF_LM_BOX_H
#define TF_LM_BOX_H

#include <stddef.h>

/* v clamped into [lo, hi] (lo, hi may be -+INFINITY). */
double tf_lm_box_clamp(double v, double lo, double hi);

/* pt[j] = p[j] + step[j] clamped into [lower[j], upper[j]] (lower, upper:
 * NULL or n bounds).  Returns 1 when a bound cut the step in some
 * component, 0 when pt is p + step as the arithmetic computes it.
 *
 * Only a bound makes a step "projected": that (p + step) - p differs from
 * step in the last bits, as it does for nearly every step, is rounding of
 * the trial point, not a projection (lm.c uses the cancellation-free
 * predicted reduction of the damped step unless this returns 1). */
int tf_lm_box_trial(size_t n, const double *lower, const double *upper, const double *p,
                    const double *step, double *pt);

#endif /* TF_LM_BOX_H */
