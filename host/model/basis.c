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

/* T_k'(x) by differentiating the recurrence: T_k' = 2 T_{k-1} + 2 x T_{k-1}' - T_{k-2}'. */
static void chebyshev_deriv(uint32_t n, double x, const double *t, double *dt)
{
    dt[0] = 0;
    if (n >= 1) {
        dt[1] = 1;
    }
    for (uint32_t k = 2; k <= n; ++k) {
        dt[k] = 2 * t[k - 1] + 2 * x * dt[k - 1] - dt[k - 2];
    }
}

/* The term order of header-format.md §5.1 in one place: both the basis and
 * its gradient walk it. */
static void walk(uint32_t p, const double t[3][TFIT_MAX_DEGREE + 1],
                 const double dt[3][TFIT_MAX_DEGREE + 1], double *phi, double (*dphi)[3])
{
    uint32_t k = 0;
    for (uint32_t d = 0; d <= p; ++d) {
        for (int a = (int)d; a >= 0; --a) {
            for (int b = (int)d - a; b >= 0; --b, ++k) {
                const int c = (int)d - a - b;
                phi[k] = t[0][a] * (t[1][b] * t[2][c]);
                if (dphi != NULL) {
                    dphi[k][0] = dt[0][a] * t[1][b] * t[2][c];
                    dphi[k][1] = t[0][a] * dt[1][b] * t[2][c];
                    dphi[k][2] = t[0][a] * t[1][b] * dt[2][c];
                }
            }
        }
    }
}

void tf_basis(uint32_t p, const double g[3], double *phi)
{
    double t[3][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        tf_chebyshev(p, g[v], t[v]);
    }
    walk(p, (const double(*)[TFIT_MAX_DEGREE + 1])t, NULL, phi, NULL);
}

void tf_basis_grad(uint32_t p, const double g[3], double *phi, double (*dphi)[3])
{
    double t[3][TFIT_MAX_DEGREE + 1], dt[3][TFIT_MAX_DEGREE + 1];
    for (int v = 0; v < 3; ++v) {
        tf_chebyshev(p, g[v], t[v]);
        chebyshev_deriv(p, g[v], t[v], dt[v]);
    }
    walk(p, (const double(*)[TFIT_MAX_DEGREE + 1])t, (const double(*)[TFIT_MAX_DEGREE + 1])dt,
         phi, dphi);
}
