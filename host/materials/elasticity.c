/*
 * elasticity.c — isotropic D matrix, strains, stresses (elasticity.h).
 */
#include "materials/elasticity.h"

tf_lame tf_lame_from(double young, double poisson)
{
    tf_lame l;
    l.lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
    l.mu = young / (2 * (1 + poisson));
    return l;
}

void tf_dmatrix(double young, double poisson, double d[36])
{
    double f = young / ((1 + poisson) * (1 - 2 * poisson));
    double d11 = f * (1 - poisson), d12 = f * poisson, g = 0.5 * (d11 - d12);
    for (int k = 0; k < 36; ++k) {
        d[k] = 0;
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            d[6 * i + j] = i == j ? d11 : d12;
        }
        d[6 * (i + 3) + i + 3] = g;
    }
}

void tf_strain(const double g[9], double eps[6])
{
    eps[0] = g[0];
    eps[1] = g[4];
    eps[2] = g[8];
    eps[3] = g[5] + g[7]; /* gamma_yz */
    eps[4] = g[2] + g[6]; /* gamma_xz */
    eps[5] = g[1] + g[3]; /* gamma_xy */
}

void tf_stress(const tf_lame *l, const double g[9], double sigma[9])
{
    double tr = g[0] + g[4] + g[8];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            sigma[3 * i + j] = l->mu * (g[3 * i + j] + g[3 * j + i]) + (i == j ? l->lambda * tr : 0);
        }
    }
}
