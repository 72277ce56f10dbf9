/*
 * neohooke.c — compressible neo-Hookean solid with exactly the energy of
 * CalculiX's *HYPERELASTIC, NEO HOOKE (CalculiX CrunchiX User's Manual,
 * keyword *HYPERELASTIC: U = C10 (I1bar - 3) + (J - 1)^2 / D1 with
 * I1bar = III_C^(-1/3) I_C, J = III_C^(1/2)), written with mu = 2 C10 and
 * the bulk modulus K = 2/D1:
 *
 *   W = mu/2 (J^(-2/3) I1 - 3) + K/2 (J - 1)^2,   I1 = tr C,  C = F^T F.
 *
 * With dJ/dC = J/2 C^-1, dI1/dC = I and dC^-1/dC = -I_C^-1, where
 * (I_C^-1)_ijkl = (C^-1_ik C^-1_jl + C^-1_il C^-1_jk)/2 (standard results,
 * e.g. Holzapfel, Nonlinear Solid Mechanics, ch. 6), S = 2 dW/dC and
 * C = 4 d^2W/dC dC are
 *
 *   S = mu J^(-2/3) (I - I1/3 C^-1) + K J (J - 1) C^-1,
 *   C = 2mu/3 J^(-2/3) [ (I1/3) C^-1 x C^-1 - I x C^-1 - C^-1 x I
 *                        + I1 I_C^-1 ]
 *       + K J (2J - 1) C^-1 x C^-1 - 2 K J (J - 1) I_C^-1.
 *
 * At F = I this is lambda I x I + 2 mu I_sym with lambda = K - 2mu/3: the
 * linear D of the same E and nu.
 */
#include <math.h>

#include "materials/elasticity.h"
#include "materials/kinematics.h"
#include "materials/laws.h"

static void tangent(double mu, double kappa, double J, double j23, double I1, const double ci[9],
                    double C[36])
{
    double a = 2 * mu / 3 * j23, b = kappa * J * (2 * J - 1), c = 2 * kappa * J * (J - 1);
    for (int p = 0; p < 6; ++p) {
        int i = tf_voigt_i[p], j = tf_voigt_j[p];
        for (int q = 0; q < 6; ++q) {
            int k = tf_voigt_i[q], l = tf_voigt_j[q];
            double cc = ci[3 * i + j] * ci[3 * k + l];
            double isym = 0.5 * (ci[3 * i + k] * ci[3 * j + l] + ci[3 * i + l] * ci[3 * j + k]);
            double dc = (i == j) * ci[3 * k + l] + ci[3 * i + j] * (k == l);
            C[6 * p + q] = a * (I1 / 3 * cc - dc + I1 * isym) + b * cc - c * isym;
        }
    }
}

int tf_neohooke_eval(double mu, double kappa, const double F[9], double S[6], double C[36],
                     double *W)
{
    double J = tf_det3(F);
    if (!(J > 0)) {
        return TF_MAT_INVERTED;
    }
    double cg[9], ci[9], s[9];
    tf_right_cauchy_green(F, cg);
    tf_inverse_sym3(cg, J * J, ci);
    double I1 = cg[0] + cg[4] + cg[8], j13 = cbrt(J), j23 = 1 / (j13 * j13);
    for (int k = 0; k < 9; ++k) {
        s[k] = mu * j23 * ((k % 4 == 0) - I1 / 3 * ci[k]) + kappa * J * (J - 1) * ci[k];
    }
    tf_voigt_stress(s, S);
    if (C) {
        tangent(mu, kappa, J, j23, I1, ci, C);
    }
    if (W) {
        *W = 0.5 * mu * (j23 * I1 - 3) + 0.5 * kappa * (J - 1) * (J - 1);
    }
    return TF_MAT_OK;
}

void tf_neohooke_constants(double young, double poisson, double *c10, double *d1)
{
    tf_lame l = tf_lame_from(young, poisson);
    *c10 = l.mu / 2;
    *d1 = 2 / (l.lambda + 2 * l.mu / 3);
}

static int eval(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W)
{
    (void)dt;
    (void)hold;
    (void)hnew;
    tf_lame l = tf_lame_from(p[TF_ELASTIC_E], p[TF_ELASTIC_NU]);
    return tf_neohooke_eval(l.mu, l.lambda + 2 * l.mu / 3, F, S, C, W);
}

const tf_law_ops tf_law_neohooke = {
    .name = "neo-hookean",
    .summary = "compressible neo-Hookean, CalculiX's NEO HOOKE energy with C10 = mu/2, "
               "D1 = 2/K of E and nu",
    .caps = TF_MATERIAL_FINITE | TF_MATERIAL_ENERGY,
    .volume = TF_VOLUME_JACOBIAN,
    .n_params = TF_ELASTIC_PARAMS,
    .params = tf_elastic_params,
    .moduli = tf_elastic_moduli,
    .check = tf_elastic_check,
    .eval = eval,
};
