/*
 * lm_box.c — clamping and step projection for bounded LM fits (see
 * lm_box.h).
 */
#include "numerics/lm_box.h"

#include <math.h>

double tf_lm_box_clamp(double v, double lo, double hi)
{
    return fmin(fmax(v, lo), hi);
}

int tf_lm_box_trial(size_t n, const double *lower, const double *upper, const double *p,
                    const double *step, double *pt)
{
    int cut = 0;
    for (size_t j = 0; j < n; ++j) {
        double t = p[j] + step[j];
        pt[j] = tf_lm_box_clamp(t, lower != NULL ? lower[j] : -INFINITY,
                                upper != NULL ? upper[j] : INFINITY);
        cut |= pt[j] != t;
    }
    return cut;
}
