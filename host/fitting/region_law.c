/*
 * region_law.c — the region contact law's potential basis, coefficients
 * and double-precision evaluation (region_law.h).
 */
#include "fitting/region_law.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "numerics/grid_spline.h"

size_t tf_region_terms(unsigned P)
{
    return (size_t)(P + 3) * (P + 2) * (P + 1) / 6 - 4;
}

void tf_region_exponents(unsigned P, unsigned (*ex)[3])
{
    size_t t = 0;
    for (unsigned d = 2; d <= P; ++d) {
        for (unsigned i = d + 1; i-- > 0;) {
            for (unsigned j = d - i + 1; j-- > 0;) {
                ex[t][0] = i;
                ex[t][1] = j;
                ex[t][2] = d - i - j;
                t++;
            }
        }
    }
}

/* x^k, and 0 for a negative k (a derivative's vanished power). */
static double power(double x, int k)
{
    double p = 1;
    for (int i = 0; i < k; ++i) {
        p *= x;
    }
    return k < 0 ? 0 : p;
}

void tf_region_monomials(unsigned P, const double v[3], double *m, double (*dm)[3])
{
    unsigned ex[TF_REGION_MAX_TERMS][3];
    size_t T = tf_region_terms(P);
    tf_region_exponents(P, ex);
    for (size_t t = 0; t < T; ++t) {
        int e[3] = {(int)ex[t][0], (int)ex[t][1], (int)ex[t][2]};
        double p[3] = {power(v[0], e[0]), power(v[1], e[1]), power(v[2], e[2])};
        m[t] = p[0] * p[1] * p[2];
        if (dm != NULL) {
            dm[t][0] = e[0] * power(v[0], e[0] - 1) * p[1] * p[2];
            dm[t][1] = e[1] * p[0] * power(v[1], e[1] - 1) * p[2];
            dm[t][2] = e[2] * p[0] * p[1] * power(v[2], e[2] - 1);
        }
    }
}

void tf_region_quadratic_coefs(const double K[9], double s_u, double e[6])
{
    double s2 = s_u * s_u;
    e[0] = K[0] / (2 * s2);
    e[1] = K[1] / s2;
    e[2] = K[2] / s2;
    e[3] = K[4] / (2 * s2);
    e[4] = K[5] / s2;
    e[5] = K[8] / (2 * s2);
}

void tf_region_quadratic_stiffness(const double e[6], double s_u, double K[9])
{
    double s2 = s_u * s_u;
    K[0] = 2 * e[0] * s2;
    K[4] = 2 * e[3] * s2;
    K[8] = 2 * e[5] * s2;
    K[1] = K[3] = e[1] * s2;
    K[2] = K[6] = e[2] * s2;
    K[5] = K[7] = e[4] * s2;
}

void tf_region_law_force(const tf_region_law *law, double a, double b, const double u[3],
                         double F[3], double *h)
{
    double c[1 + TF_REGION_MAX_TERMS], m[TF_REGION_MAX_TERMS], dm[TF_REGION_MAX_TERMS][3];
    double v[3] = {law->s_u * u[0], law->s_u * u[1], law->s_u * u[2]};
    tf_spline_eval(law->nx, law->ny, 1 + law->T, law->ctrl, a / law->h[0], b / law->h[1], c, NULL,
                   NULL);
    tf_region_monomials(law->P, v, m, dm);
    for (int k = 0; k < 3; ++k) {
        double g = 0;
        for (size_t t = 0; t < law->T; ++t) {
            g += c[1 + t] * dm[t][k];
        }
        F[k] = law->s_u * g;
    }
    if (h != NULL) {
        *h = c[0];
    }
}

void tf_region_law_stiffness(const tf_region_law *law, double a, double b, double K[9])
{
    double c[1 + TF_REGION_MAX_TERMS];
    tf_spline_eval(law->nx, law->ny, 1 + law->T, law->ctrl, a / law->h[0], b / law->h[1], c, NULL,
                   NULL);
    tf_region_quadratic_stiffness(c + 1, law->s_u, K);
}

double tf_region_law_min_stiffness(const tf_region_law *law)
{
    size_t n = (size_t)(law->nx + 2) * (law->ny + 2);
    double least = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        double K[9], lam[3];
        tf_region_quadratic_stiffness(law->ctrl + i * (1 + law->T) + 1, law->s_u, K);
        tf_sym3_eigenvalues(K, lam);
        least = fmin(least, lam[0]);
    }
    return least;
}

double tf_region_law_min_stiffness_sampled(const tf_region_law *law, unsigned per_cell)
{
    double least = INFINITY;
    unsigned na = (law->nx - 1) * per_cell, nb = (law->ny - 1) * per_cell;
    for (unsigned j = 0; j <= nb; ++j) {
        for (unsigned i = 0; i <= na; ++i) {
            double K[9], lam[3];
            tf_region_law_stiffness(law, i * law->h[0] / per_cell, j * law->h[1] / per_cell, K);
            tf_sym3_eigenvalues(K, lam);
            least = fmin(least, lam[0]);
        }
    }
    return least;
}

void tf_region_law_free(tf_region_law *law)
{
    free(law->ctrl);
    law->ctrl = NULL;
}

size_t tf_region_law_floats(const tf_region_law *law)
{
    return 12 + 4 + (size_t)(law->nx + 2) * (law->ny + 2) * (1 + law->T);
}

void tf_sym3_eigenvalues(const double A[9], double lam[3])
{
    double a[9];
    memcpy(a, A, sizeof a);
    for (int sweep = 0; sweep < 50; ++sweep) {
        double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
        if (off <= 1e-30 * (a[0] * a[0] + a[4] * a[4] + a[8] * a[8])) {
            break;
        }
        static const int pq[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        for (int r = 0; r < 3; ++r) {
            int p = pq[r][0], q = pq[r][1];
            double apq = a[3 * p + q];
            if (apq == 0) {
                continue;
            }
            double theta = (a[3 * q + q] - a[3 * p + p]) / (2 * apq);
            double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
            double c = 1 / sqrt(t * t + 1), s = t * c;
            for (int k = 0; k < 3; ++k) { /* columns p, q */
                double akp = a[3 * k + p], akq = a[3 * k + q];
                a[3 * k + p] = c * akp - s * akq;
                a[3 * k + q] = s * akp + c * akq;
            }
            for (int k = 0; k < 3; ++k) { /* rows p, q */
                double apk = a[3 * p + k], aqk = a[3 * q + k];
                a[3 * p + k] = c * apk - s * aqk;
                a[3 * q + k] = s * apk + c * aqk;
            }
        }
    }
    lam[0] = a[0];
    lam[1] = a[4];
    lam[2] = a[8];
    for (int i = 0; i < 3; ++i) { /* ascending */
        for (int j = i + 1; j < 3; ++j) {
            if (lam[j] < lam[i]) {
                double t = lam[i];
                lam[i] = lam[j];
                lam[j] = t;
            }
        }
    }
}

int tf_mat3_inverse(const double A[9], double inv[9])
{
    double c[9] = {A[4] * A[8] - A[5] * A[7], A[2] * A[7] - A[1] * A[8], A[1] * A[5] - A[2] * A[4],
                   A[5] * A[6] - A[3] * A[8], A[0] * A[8] - A[2] * A[6], A[2] * A[3] - A[0] * A[5],
                   A[3] * A[7] - A[4] * A[6], A[1] * A[6] - A[0] * A[7], A[0] * A[4] - A[1] * A[3]};
    double det = A[0] * c[0] + A[1] * c[3] + A[2] * c[6];
    if (!(fabs(det) > 0) || !isfinite(det)) {
        return -1;
    }
    for (int k = 0; k < 9; ++k) {
        inv[k] = c[k] / det;
    }
    return 0;
}
