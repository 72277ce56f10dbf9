/*
 * kinematics.c — strain measures and Voigt notation (kinematics.h).
 */
#include "materials/kinematics.h"

const int tf_voigt_i[6] = {0, 1, 2, 1, 0, 0};
const int tf_voigt_j[6] = {0, 1, 2, 2, 2, 1};

void tf_matmul3(const double a[9], const double b[9], double ab[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            ab[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
        }
    }
}

void tf_right_cauchy_green(const double F[9], double C[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            C[3 * i + j] = F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j];
        }
    }
}

void tf_green_lagrange(const double F[9], double E[9])
{
    /* (F^T F - I)/2 = (H + H^T + H^T H)/2 with H = F - I: no cancellation
     * of 1 - 1 when the strain is small. */
    double H[9];
    for (int k = 0; k < 9; ++k) {
        H[k] = F[k] - (k % 4 == 0);
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double hh = H[i] * H[j] + H[3 + i] * H[3 + j] + H[6 + i] * H[6 + j];
            E[3 * i + j] = 0.5 * (H[3 * i + j] + H[3 * j + i] + hh);
        }
    }
}

void tf_small_strain(const double F[9], double eps[9])
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            eps[3 * i + j] = 0.5 * (F[3 * i + j] + F[3 * j + i]) - (i == j);
        }
    }
}

void tf_voigt_stress(const double t[9], double v[6])
{
    for (int k = 0; k < 6; ++k) {
        v[k] = t[3 * tf_voigt_i[k] + tf_voigt_j[k]];
    }
}

void tf_voigt_strain(const double t[9], double v[6])
{
    for (int k = 0; k < 6; ++k) {
        v[k] = (k < 3 ? 1 : 2) * t[3 * tf_voigt_i[k] + tf_voigt_j[k]];
    }
}

void tf_tensor_strain(const double v[6], double t[9])
{
    for (int k = 0; k < 6; ++k) {
        double c = k < 3 ? v[k] : 0.5 * v[k];
        t[3 * tf_voigt_i[k] + tf_voigt_j[k]] = t[3 * tf_voigt_j[k] + tf_voigt_i[k]] = c;
    }
}

double tf_det3(const double a[9])
{
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
}

void tf_inverse_sym3(const double a[9], double det, double inv[9])
{
    double c[6] = {a[4] * a[8] - a[5] * a[7], a[0] * a[8] - a[2] * a[6],
                   a[0] * a[4] - a[1] * a[3], a[2] * a[3] - a[0] * a[5],
                   a[1] * a[5] - a[2] * a[4], a[2] * a[7] - a[1] * a[8]};
    for (int k = 0; k < 6; ++k) {
        inv[3 * tf_voigt_i[k] + tf_voigt_j[k]] = inv[3 * tf_voigt_j[k] + tf_voigt_i[k]] =
            c[k] / det;
    }
}
