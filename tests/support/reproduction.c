/*
 * reproduction.c — linear reproduction error of shape functions
 * (reproduction.h).
 */
#include "reproduction.h"

#include <math.h>

double tf_test_reproduction_error(const double *xyz, const uint32_t *idx, size_t n,
                                  const double *phi, const double *dphi, const double x[3],
                                  double L)
{
    double s = -1, sx[3] = {-x[0], -x[1], -x[2]}, ds[3] = {0, 0, 0}, dsx[9], err;
    for (int k = 0; k < 9; ++k) {
        dsx[k] = -(k % 4 == 0);
    }
    for (size_t i = 0; i < n; ++i) {
        const double *xi = xyz + 3 * (size_t)idx[i];
        s += phi[i];
        for (int a = 0; a < 3; ++a) {
            sx[a] += phi[i] * xi[a];
            ds[a] += dphi[a * n + i];
            for (int b = 0; b < 3; ++b) {
                dsx[3 * a + b] += dphi[a * n + i] * xi[b];
            }
        }
    }
    err = fabs(s);
    for (int a = 0; a < 3; ++a) {
        err = fmax(err, fmax(fabs(sx[a]) / L, fabs(ds[a]) * L));
    }
    for (int k = 0; k < 9; ++k) {
        err = fmax(err, fabs(dsx[k]));
    }
    return err;
}
