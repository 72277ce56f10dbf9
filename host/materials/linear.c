/*
 * linear.c — linear elasticity as a law: S = D eps, eps = sym(F - I),
 * D of elasticity.h (E, nu), W = S.eps / 2.  The Galerkin solvers assemble
 * D directly (its HOOKE capability at small strain); the law is what the
 * Newton and collocation solvers evaluate.
 */
#include "materials/elasticity.h"
#include "materials/kinematics.h"
#include "materials/laws.h"

static int eval(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W)
{
    (void)dt;
    (void)hold;
    (void)hnew;
    double d[36], eps[9], e[6];
    tf_dmatrix(p[TF_ELASTIC_E], p[TF_ELASTIC_NU], d);
    tf_small_strain(F, eps);
    tf_voigt_strain(eps, e);
    double w = 0;
    for (int r = 0; r < 6; ++r) {
        S[r] = 0;
        for (int c = 0; c < 6; ++c) {
            S[r] += d[6 * r + c] * e[c];
        }
        w += 0.5 * S[r] * e[r];
    }
    for (int k = 0; C && k < 36; ++k) {
        C[k] = d[k];
    }
    if (W) {
        *W = w;
    }
    return TF_MAT_OK;
}

const tf_law_ops tf_law_linear = {
    .name = "linear",
    .summary = "linear elasticity, small strain: S = D(E, nu) eps ([Zhou2017] eq 7)",
    .caps = TF_MATERIAL_ENERGY | TF_MATERIAL_HOOKE,
    .volume = TF_VOLUME_JACOBIAN,
    .n_params = TF_ELASTIC_PARAMS,
    .params = tf_elastic_params,
    .moduli = tf_elastic_moduli,
    .check = tf_elastic_check,
    .eval = eval,
};
