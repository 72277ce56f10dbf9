/*
 * kelvin_nh.c — our large-strain variant of seed 001's Kelvin law (not in
 * the seed): the relaxation function of its three-parameter solid,
 * g(t) = E(t)/E_0 = g_inf + (1 - g_inf) exp(-t/tau), g_inf = k1/(k1 + k2),
 * acting on the neo-Hookean second Piola-Kirchhoff stress S0 of the
 * instantaneous moduli (E_0 = k1 + k2, nu) in the reference configuration
 * (a convolution model like those of Simo & Hughes, Computational
 * Inelasticity, ch. 10, with one relaxation term; unlike theirs it relaxes
 * the whole S, the volumetric part too, as the small-strain law does):
 *
 *   S(t) = g_inf S0(t) + (1 - g_inf) h(t),  h(t) = int_0^t exp(-(t-s)/tau) dS0/ds ds,
 *   h_n+1 = exp(-x) h_n + phi1(x) (S0_n+1 - S0_n),  x = dt/tau,
 *
 * exact when S0 is linear in time inside the step.  The neo-Hookean energy
 * supplies the strain stiffening, so seed 001's adjustment k is not used
 * (its check refuses k != 0).  S depends on C = F^T F
 * only (objective), and the tangent (g_inf + (1 - g_inf) phi1) C0 is
 * symmetric.  At small strain it is the KELVIN law with k = 0.
 */
#include "materials/elasticity.h"
#include "materials/laws.h"

static int eval(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W)
{
    (void)W; /* none: the law has no stored energy */
    double k1 = p[TF_KELVIN_K1], k2 = p[TF_KELVIN_K2];
    double e0 = k1 + k2, ginf = k1 / e0, s0[6];
    tf_lame l = tf_lame_from(e0, p[TF_KELVIN_NU]);
    int rc = tf_neohooke_eval(l.mu, l.lambda + 2 * l.mu / 3, F, s0, C, NULL);
    if (rc != TF_MAT_OK) {
        return rc;
    }
    double decay, phi1, phi2, x = k2 > 0 ? dt * k2 / p[TF_KELVIN_ETA] : 0;
    tf_relax_factors(x, &decay, &phi1, &phi2);
    for (int v = 0; v < 6; ++v) {
        double h = decay * hold[v] + phi1 * (s0[v] - hold[6 + v]);
        S[v] = ginf * s0[v] + (1 - ginf) * h;
        hnew[v] = h;
        hnew[6 + v] = s0[v];
    }
    if (C) {
        double f = ginf + (1 - ginf) * phi1;
        for (int k = 0; k < 36; ++k) {
            C[k] *= f;
        }
    }
    return TF_MAT_OK;
}

static const char *check(const double *p, char *msg, size_t len)
{
    const char *bad = tf_kelvin_check(p, msg, len);
    if (bad == NULL && p[TF_KELVIN_K] != 0) {
        bad = tf_law_bad(msg, len, "k", p[TF_KELVIN_K],
                         "the neo-Hookean Kelvin law takes its nonlinearity from the energy: k "
                         "must be 0");
    }
    return bad;
}

const tf_law_ops tf_law_kelvin_nh = {
    .name = "kelvin-neo-hookean",
    .summary = "ours: the kelvin law's relaxation g(t) on the neo-Hookean S of the "
               "instantaneous moduli, finite strain (k must be 0)",
    .caps = TF_MATERIAL_FINITE | TF_MATERIAL_HISTORY,
    .volume = TF_VOLUME_JACOBIAN,
    .n_params = TF_KELVIN_PARAMS,
    .params = tf_kelvin_params,
    .history = 12, /* [h(6), S0_n(6)] */
    .moduli = tf_kelvin_moduli,
    .relaxation = tf_kelvin_relaxation,
    .check = check,
    .eval = eval,
};
