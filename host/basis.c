/*
 * basis.c — see basis.h.
 */
#include "basis.h"

void tf_basis(uint32_t p, const double g[3], double *phi)
{
    uint32_t t = 0;
    for (uint32_t d = 0; d <= p; ++d) {
        for (int a = (int)d; a >= 0; --a) {
            for (int b = (int)d - a; b >= 0; --b) {
                int c = (int)d - a - b;
                double v = 1;
                for (int k = 0; k < a; ++k) {
                    v *= g[0];
                }
                for (int k = 0; k < b; ++k) {
                    v *= g[1];
                }
                for (int k = 0; k < c; ++k) {
                    v *= g[2];
                }
                phi[t++] = v;
            }
        }
    }
}

void tf_powers(uint32_t n, double x, double *out)
{
    out[0] = 1;
    for (uint32_t k = 1; k <= n; ++k) {
        out[k] = out[k - 1] * x;
    }
}
