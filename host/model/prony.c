/*
 * prony.c — see prony.h.
 */
#include "model/prony.h"

#include <math.h>

float tf_prony_decay(double tick, double tau)
{
    return (float)exp(-tick / tau);
}

/* -ln(a) for a float a in (0, 1): 1 - a is exact in double (a has 24
 * bits), and log1p keeps its relative accuracy when it is small. */
static double realised_rate(float decay)
{
    return -log1p(-(1.0 - (double)decay));
}

double tf_prony_realised_tau(double tick, float decay)
{
    return tick / realised_rate(decay);
}

double tf_prony_hold_gain(float decay)
{
    const double one_minus_a = 1.0 - (double)decay; /* exact */
    if (decay <= 0.0f) {
        return 0.0; /* r = inf: the term settles within the tick */
    }
    return one_minus_a / realised_rate(decay);
}

double tf_prony_tick(const tf_model *m)
{
    return 1e-9 * (double)m->dims[3];
}

double tf_prony_set_term(tf_model *m, uint32_t k, double tau, double weight)
{
    const double tick = tf_prony_tick(m);
    float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + 2 * k;
    pt[0] = tf_prony_decay(tick, tau);
    pt[1] = (float)(weight * tf_prony_hold_gain(pt[0]));
    return tf_prony_realised_tau(tick, pt[0]);
}
