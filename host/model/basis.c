/*
 * basis.c — see basis.h.
 */
#include "model/basis.h"

#include "model/model.h"

void tf_chebyshev(uint32_t n, double x, double *out)
{
    out[0] = 1;
    if (n >= 1) {
        out[1] = x;
    }
    for (uint32_t k = 2; k <= n; ++k) {
        out[k] = 2 * x * out[k - 1] - out[k - 2];
    }
}

void tf_basis(uint32_t p, const double g[3], double *phi)
{
    double t[3][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        tf_chebyshev(p, g[v], t[v]);
    }
    uint32_t k = 0;
    for (uint32_t d = 0; d <= p; ++d) {
        for (int a = (int)d; a >= 0; --a) {
            for (int b = (int)d - a; b >= 0; --b) {
                phi[k++] = t[0][a] * (t[1][b] * t[2][(int)d - a - b]);
            }
        }
    }
}
