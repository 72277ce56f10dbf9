/*
 * resonant.c — see resonant.h.
 */
#include "model/resonant.h"

#include <math.h>

#define MODE_FLOATS 7

double tf_resonant_tick(const tf_model *m)
{
    return 1e-9 * (double)m->dims[3];
}

void tf_resonant_set_mode(tf_model *m, uint32_t k, double omega, double zeta,
                          const double w[3])
{
    double f[4];
    float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k;
    tf_resonant_transition(omega * tf_resonant_tick(m), zeta, f);
    for (int i = 0; i < 4; ++i) {
        pt[i] = (float)f[i];
    }
    for (int i = 0; i < 3; ++i) {
        pt[4 + i] = (float)w[i];
    }
}

/* The eigenvalues of F are exp(T (-zeta w +- i w sqrt(1 - zeta^2))): det F
 * gives zeta w, the trace the damped frequency (or, overdamped, the two
 * real rates, whose product is w^2 and sum 2 zeta w). */
void tf_resonant_get_mode(const tf_model *m, uint32_t k, double *omega, double *zeta,
                          double w[3])
{
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k;
    const double t = tf_resonant_tick(m), tr = (double)pt[0] + (double)pt[3];
    const double det = (double)pt[0] * pt[3] - (double)pt[1] * pt[2];
    const double disc = 0.25 * tr * tr - det;
    if (!(det > 0)) {
        *omega = *zeta = NAN;
    } else if (disc < 0) {
        const double sigma = -0.5 * log(det) / t, wd = acos(0.5 * tr / sqrt(det)) / t;
        *omega = sqrt(sigma * sigma + wd * wd);
        *zeta = sigma / *omega;
    } else {
        const double r1 = -log(0.5 * tr + sqrt(disc)) / t, r2 = -log(0.5 * tr - sqrt(disc)) / t;
        *omega = sqrt(r1 * r2);
        *zeta = 0.5 * (r1 + r2) / *omega;
    }
    for (int i = 0; i < 3; ++i) {
        w[i] = pt[4 + i];
    }
}

int tf_resonant_mode_check(const tf_model *m, uint32_t k, char *err, size_t errlen)
{
    return tf_resonant_floats_check(m->coef + TFIT_INPUT_MAP_FLOATS + MODE_FLOATS * k, m->name, k,
                                    err, errlen);
}
