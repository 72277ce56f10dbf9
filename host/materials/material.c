/*
 * material.c — one interface over the material laws (material.h): the
 * linear law itself, dispatch to the others, history sizes and parameter
 * checks.
 */
#include "materials/material.h"

#include <math.h>
#include <stdio.h>

#include "materials/elasticity.h"
#include "materials/kinematics.h"
#include "materials/laws.h"

const char *tf_law_name(tf_law law)
{
    switch (law) {
    case TF_LAW_LINEAR: return "linear";
    case TF_LAW_SVK: return "svk";
    case TF_LAW_NEOHOOKE: return "neohooke";
    case TF_LAW_KELVIN: return "kelvin";
    case TF_LAW_KELVIN_NH: return "kelvin-neohooke";
    }
    return "?";
}

tf_kinematics tf_material_kinematics(const tf_material *m)
{
    return m->law == TF_LAW_LINEAR || m->law == TF_LAW_KELVIN ? TF_KIN_SMALL : TF_KIN_FINITE;
}

size_t tf_material_history_size(const tf_material *m)
{
    return m->law == TF_LAW_KELVIN || m->law == TF_LAW_KELVIN_NH ? 12 : 0;
}

void tf_material_history_init(const tf_material *m, double *h)
{
    for (size_t k = 0; k < tf_material_history_size(m); ++k) {
        h[k] = 0;
    }
}

int tf_material_has_energy(const tf_material *m)
{
    return m->law == TF_LAW_LINEAR || m->law == TF_LAW_SVK || m->law == TF_LAW_NEOHOOKE;
}

void tf_neohooke_constants(double young, double poisson, double *c10, double *d1)
{
    tf_lame l = tf_lame_from(young, poisson);
    *c10 = l.mu / 2;
    *d1 = 2 / (l.lambda + 2 * l.mu / 3);
}

void tf_kelvin_moduli(const tf_material *m, double *e0, double *einf, double *tau)
{
    *e0 = m->k1 + m->k2;
    *einf = m->k1;
    *tau = m->k2 > 0 ? m->eta / m->k2 : INFINITY;
}

/* LINEAR: S = D eps, eps = sym(F - I); W = S.eps / 2. */
static void linear_eval(const tf_material *m, const double F[9], double S[6], double C[36],
                        double *W)
{
    double d[36], eps[9], e[6];
    tf_dmatrix(m->young, m->poisson, d);
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
}

int tf_material_eval(const tf_material *m, const double F[9], double dt, const double *hold,
                     double *hnew, double S[6], double C[36], double *W)
{
    tf_lame l = tf_lame_from(m->young, m->poisson);
    if (W) {
        *W = NAN;
    }
    switch (m->law) {
    case TF_LAW_LINEAR:
        linear_eval(m, F, S, C, W);
        return TF_MAT_OK;
    case TF_LAW_SVK:
        return tf_svk_eval(l.lambda, l.mu, F, S, C, W);
    case TF_LAW_NEOHOOKE:
        return tf_neohooke_eval(l.mu, l.lambda + 2 * l.mu / 3, F, S, C, W);
    case TF_LAW_KELVIN:
        tf_kelvin_eval(m, F, dt, hold, hnew, S, C);
        return TF_MAT_OK;
    case TF_LAW_KELVIN_NH:
        return tf_kelvin_nh_eval(m, F, dt, hold, hnew, S, C);
    }
    return TF_MAT_INVERTED; /* not reached: every law is handled */
}

/* A sentence for field `name` = v, and the name. */
static const char *bad(char *msg, size_t len, const char *name, double v, const char *why)
{
    snprintf(msg, len, "%s = %g: %s", name, v, why);
    return name;
}

static const char *check_kelvin(const tf_material *m, char *msg, size_t len)
{
    if (!isfinite(m->k1) || !(m->k1 > 0)) {
        return bad(msg, len, "k1", m->k1, "the relaxed modulus k1 must be a finite number > 0 MPa");
    }
    if (!isfinite(m->k2) || !(m->k2 >= 0)) {
        char why[160];
        snprintf(why, sizeof why,
                 "the relaxed modulus k1 = %g MPa must not be above the instantaneous one "
                 "k1 + k2 (k2 a finite number >= 0 MPa)",
                 m->k1);
        return bad(msg, len, "k2", m->k2, why);
    }
    if (m->k2 > 0 && (!isfinite(m->eta) || !(m->eta > 0) || !isfinite(m->eta / m->k2))) {
        return bad(msg, len, "eta", m->eta,
                   "the dashpot eta must be a finite number > 0 MPa s (tau = eta/k2 > 0)");
    }
    if (!isfinite(m->k) || !(m->k >= 0)) {
        return bad(msg, len, "k", m->k, "the adjustment k of N = eps + k eps^2 must be >= 0");
    }
    if (m->law == TF_LAW_KELVIN_NH && m->k != 0) {
        return bad(msg, len, "k", m->k,
                   "the neo-Hookean Kelvin law takes its nonlinearity from the energy: k must "
                   "be 0");
    }
    return NULL;
}

const char *tf_material_check(const tf_material *m, char *msg, size_t len)
{
    msg[0] = '\0';
    if (!isfinite(m->poisson) || !(m->poisson > -1 && m->poisson < 0.5)) {
        return bad(msg, len, "poisson", m->poisson, "Poisson's ratio must lie in (-1, 0.5)");
    }
    if (m->law == TF_LAW_KELVIN || m->law == TF_LAW_KELVIN_NH) {
        return check_kelvin(m, msg, len);
    }
    if (!isfinite(m->young) || !(m->young > 0)) {
        return bad(msg, len, "young", m->young, "Young's modulus must be a finite number > 0 MPa");
    }
    return NULL;
}
