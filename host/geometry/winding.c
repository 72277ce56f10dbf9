/*
 * winding.c — generalised winding numbers (winding.h).
 */
#include "geometry/winding.h"

#include <math.h>

#include "geometry/vec3.h"

/* Signed solid angle of triangle abc seen from the origin (corners given
 * relative to the point), Van Oosterom and Strackee. */
static double solid_angle(const double a[3], const double b[3], const double c[3])
{
    double la = tf_v3_norm(a), lb = tf_v3_norm(b), lc = tf_v3_norm(c);
    double den = la * lb * lc + tf_v3_dot(a, b) * lc + tf_v3_dot(b, c) * la +
                 tf_v3_dot(c, a) * lb;
    return 2 * atan2(tf_v3_det(a, b, c), den);
}

double tf_winding_number(const tf_surface *s, const double p[3])
{
    double sum = 0;
    for (size_t t = 0; t < s->nt; ++t) {
        double r[3][3];
        for (int k = 0; k < 3; ++k) {
            const double *x = s->xyz + 3 * s->tri[3 * t + k];
            for (int a = 0; a < 3; ++a) {
                r[k][a] = x[a] - p[a];
            }
        }
        sum += solid_angle(r[0], r[1], r[2]);
    }
    return sum / (4 * M_PI);
}

void tf_winding_numbers(const tf_surface *s, const double *p, size_t n, double *w)
{
    long count = (long)n;
#pragma omp parallel for schedule(dynamic, 16)
    for (long k = 0; k < count; ++k) {
        w[k] = tf_winding_number(s, p + 3 * k);
    }
}
