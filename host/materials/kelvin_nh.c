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
 * (tf_material_check refuses k != 0 for this law).  S depends on C = F^T F
 * only (objective), and the tangent (g_inf + (1 - g_inf) phi1) C0 is
 * symmetric.  At small strain it is the KELVIN law with k = 0.
 */
#include "materials/elasticity.h"
#include "materials/laws.h"
#include "materials/material.h"

int tf_kelvin_nh_eval(const tf_material *m, const double F[9], double dt, const double *hold,
                      double *hnew, double S[6], double C[36])
{
    double e0 = m->k1 + m->k2, ginf = m->k1 / e0, s0[6];
    tf_lame l = tf_lame_from(e0, m->poisson);
    int rc = tf_neohooke_eval(l.mu, l.lambda + 2 * l.mu / 3, F, s0, C, NULL);
    if (rc != TF_MAT_OK) {
        return rc;
    }
    double decay, phi1, phi2, x = m->k2 > 0 ? dt * m->k2 / m->eta : 0;
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
