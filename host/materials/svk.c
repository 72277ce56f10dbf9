/*
 * svk.c — St. Venant-Kirchhoff: Hooke's law between the Green-St. Venant
 * strain and the second Piola-Kirchhoff stress (seed 004 eqs 4-5, 10):
 *
 *   W = lambda/2 tr(E)^2 + mu E:E,   S = lambda tr(E) I + 2 mu E,
 *   C = dS/dE = lambda I x I + 2 mu I_sym  (the linear D matrix).
 *
 * Objective (E depends on F^T F only) but not stable in compression: the
 * stress returns to zero as a line element shrinks to nothing, so the
 * uniaxial force has a maximum in compression at stretch 1/sqrt(3)
 * (docs/solver.md).
 */
#include "materials/kinematics.h"
#include "materials/laws.h"

int tf_svk_eval(double lambda, double mu, const double F[9], double S[6], double C[36],
                double *W)
{
    if (!(tf_det3(F) > 0)) {
        return TF_MAT_INVERTED;
    }
    double E[9], s[9];
    tf_green_lagrange(F, E);
    double tr = E[0] + E[4] + E[8], ee = 0;
    for (int k = 0; k < 9; ++k) {
        s[k] = 2 * mu * E[k] + (k % 4 == 0 ? lambda * tr : 0);
        ee += E[k] * E[k];
    }
    tf_voigt_stress(s, S);
    if (C) {
        /* D(E, nu) with E = mu (3 lambda + 2 mu)/(lambda + mu) and
         * nu = lambda / (2 (lambda + mu)) is lambda I x I + 2 mu I_sym. */
        for (int k = 0; k < 36; ++k) {
            C[k] = 0;
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                C[6 * i + j] = lambda + (i == j ? 2 * mu : 0);
            }
            C[6 * (i + 3) + i + 3] = mu;
        }
    }
    if (W) {
        *W = 0.5 * lambda * tr * tr + mu * ee;
    }
    return TF_MAT_OK;
}

static int eval(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W)
{
    (void)dt;
    (void)hold;
    (void)hnew;
    tf_lame l = tf_lame_from(p[TF_ELASTIC_E], p[TF_ELASTIC_NU]);
    return tf_svk_eval(l.lambda, l.mu, F, S, C, W);
}

/* Its volumetric energy is lambda (tr E)^2 / 2: a volumetric correction
 * averages tr E (docs/solver.md, "Nonlinear laws"). */
const tf_law_ops tf_law_svk = {
    .name = "svk",
    .summary = "St. Venant-Kirchhoff: S = lambda tr(E) I + 2 mu E in the Green strain "
               "([Aras-MLS] eqs 4-5)",
    .caps = TF_MATERIAL_FINITE | TF_MATERIAL_ENERGY | TF_MATERIAL_HOOKE,
    .volume = TF_VOLUME_GREEN_TRACE,
    .n_params = TF_ELASTIC_PARAMS,
    .params = tf_elastic_params,
    .moduli = tf_elastic_moduli,
    .check = tf_elastic_check,
    .eval = eval,
};
