/*
 * kelvin.c — seed 001's nonlinear Kelvin viscoelastic law (§2, eqs 9-13),
 * small strain as published.  The seed's text is garbled here; the forms
 * below are the standard ones (Fung, Biomechanics, ch. 2, the "Kelvin model";
 * Simo & Hughes, Computational Inelasticity, ch. 10), derived again in
 * docs/solver.md.
 *
 * Fig. 2: a spring k1 in parallel with a Maxwell arm (spring k2 in series
 * with a dashpot eta).  Held at a unit strain step the Maxwell arm's force
 * decays as k2 exp(-t k2/eta), so the relaxation modulus is
 *
 *   E(t) = k1 + k2 exp(-t/tau),  tau = eta/k2,  E_0 = k1 + k2,  E_inf = k1.
 *
 * Eq 10 acts on the adjusted strain N(eps) = eps + k eps^2:
 * sigma(t) = int_0^t E(t - s) dN/ds ds.  In 3-D (our choice) the
 * relaxation multiplies the whole isotropic stress at constant nu and N is
 * the tensor function eps + k eps.eps (isotropic; in uniaxial stress the
 * axial response is exactly the 1-D law):
 *
 *   sigma(t) = D_inf N(eps(t)) + D_2 h(t),  h(t) = int_0^t exp(-(t-s)/tau) dN/ds ds,
 *
 * with D_inf = D(k1, nu), D_2 = D(k2, nu).  Eqs 11-12 split the integral at
 * t_n; for strain linear in time inside the step, eps(s) = eps_n + (s -
 * t_n) de/dt, dN/ds = (de + k(eps_n de + de eps_n))/dt + 2k de.de (s -
 * t_n)/dt^2 and the step's part of the integral is exact:
 *
 *   h_n+1 = exp(-x) h_n + phi1(x) (de + k (eps_n de + de eps_n))
 *                       + 2 k phi2(x) de.de,            x = dt/tau,
 *
 * phi1, phi2 as tf_relax_factors.  That is eq 13's incremental form,
 * d sigma_n = E_k d eps_n + sigma_0,n: E_k is the tangent below and
 * sigma_0,n = D_2 (exp(-x) - 1) h_n the relaxation of the history.
 *
 * Tangent dsigma/deps = D_inf M(1, eps) + D_2 M(phi1, phi1 eps_n + 2 phi2 de)
 * with M(a, Y): X -> a X + k (Y X + X Y).  It is not symmetric for k != 0:
 * lambda I x (I + 2k eps) is not the transpose of itself (sigma = D N(eps)
 * has no potential).  For k = 0 it is (k1 + k2 phi1) D(1, nu).
 */
#include <math.h>
#include <stdio.h>

#include "materials/elasticity.h"
#include "materials/kinematics.h"
#include "materials/laws.h"

void tf_relax_factors(double x, double *decay, double *phi1, double *phi2)
{
    *decay = exp(-x);
    if (x < 0.1) {
        /* phi1 = sum (-x)^j/(j+1)!, phi2 = sum (-x)^j/(j+2)!: the closed
         * forms lose digits to cancellation for small x; 14 terms leave
         * < 1e-20 at x = 0.1. */
        double t1 = 1, t2 = 0.5, s1 = 0, s2 = 0;
        for (int j = 0; j < 14; ++j) {
            s1 += t1;
            s2 += t2;
            t1 *= -x / (j + 2);
            t2 *= -x / (j + 3);
        }
        *phi1 = s1;
        *phi2 = s2;
        return;
    }
    double em1 = -expm1(-x); /* 1 - exp(-x) */
    *phi1 = em1 / x;
    *phi2 = (x - em1) / (x * x);
}

/* Tensor-component Voigt (history storage) -> symmetric tensor. */
static void sym_from_voigt(const double v[6], double t[9])
{
    for (int k = 0; k < 6; ++k) {
        t[3 * tf_voigt_i[k] + tf_voigt_j[k]] = t[3 * tf_voigt_j[k] + tf_voigt_i[k]] = v[k];
    }
}

/* out += D(lame) t in tensor form: lambda tr(t) I + 2 mu t. */
static void add_iso(const tf_lame *l, const double t[9], double out[9])
{
    double tr = t[0] + t[4] + t[8];
    for (int k = 0; k < 9; ++k) {
        out[k] += 2 * l->mu * t[k] + (k % 4 == 0 ? l->lambda * tr : 0);
    }
}

/* out = a x + k (y x + x y). */
static void adjust(double a, double k, const double y[9], const double x[9], double out[9])
{
    double yx[9], xy[9];
    tf_matmul3(y, x, yx);
    tf_matmul3(x, y, xy);
    for (int q = 0; q < 9; ++q) {
        out[q] = a * x[q] + k * (yx[q] + xy[q]);
    }
}

typedef struct kelvin_step {
    tf_lame inf, two;         /* D_inf = D(k1, nu), D_2 = D(k2, nu) */
    double phi1, phi2, decay; /* tf_relax_factors(dt / tau) */
    double eps[9], en[9], de[9];
} kelvin_step;

static void step_init(const double *p, const double F[9], double dt, const double *hold,
                      kelvin_step *st)
{
    double k2 = p[TF_KELVIN_K2];
    st->inf = tf_lame_from(p[TF_KELVIN_K1], p[TF_KELVIN_NU]);
    st->two = tf_lame_from(k2, p[TF_KELVIN_NU]);
    double x = k2 > 0 ? dt * k2 / p[TF_KELVIN_ETA] : 0;
    tf_relax_factors(x, &st->decay, &st->phi1, &st->phi2);
    tf_small_strain(F, st->eps);
    sym_from_voigt(hold + 6, st->en);
    for (int q = 0; q < 9; ++q) {
        st->de[q] = st->eps[q] - st->en[q];
    }
}

static void tangent(double k, const kelvin_step *st, double C[36])
{
    double y[9];
    for (int q = 0; q < 9; ++q) {
        y[q] = st->phi1 * st->en[q] + 2 * st->phi2 * st->de[q];
    }
    for (int c = 0; c < 6; ++c) {
        double unit[6] = {0, 0, 0, 0, 0, 0}, dx[9], dn[9], dh[9], ds[9] = {0};
        unit[c] = 1; /* engineering shear: the tensor gets 1/2 */
        tf_tensor_strain(unit, dx);
        adjust(1, k, st->eps, dx, dn);
        adjust(st->phi1, k, y, dx, dh);
        add_iso(&st->inf, dn, ds);
        add_iso(&st->two, dh, ds);
        for (int r = 0; r < 6; ++r) {
            C[6 * r + c] = ds[3 * tf_voigt_i[r] + tf_voigt_j[r]];
        }
    }
}

static int eval(const double *p, const double F[9], double dt, const double *hold, double *hnew,
                double S[6], double C[36], double *W)
{
    (void)W; /* none: the law has no stored energy */
    const double k = p[TF_KELVIN_K];
    kelvin_step st;
    step_init(p, F, dt, hold, &st);
    double h[9], n[9], inc[9], dd[9], s[9] = {0};
    sym_from_voigt(hold, h);
    tf_matmul3(st.eps, st.eps, n);
    adjust(1, k, st.en, st.de, inc);
    tf_matmul3(st.de, st.de, dd);
    for (int q = 0; q < 9; ++q) {
        n[q] = st.eps[q] + k * n[q]; /* N(eps), eq 10 */
        h[q] = st.decay * h[q] + st.phi1 * inc[q] + 2 * k * st.phi2 * dd[q];
    }
    if (C) {
        tangent(k, &st, C); /* before hnew is written: hold may be hnew */
    }
    add_iso(&st.inf, n, s);
    add_iso(&st.two, h, s);
    tf_voigt_stress(s, S);
    tf_voigt_stress(h, hnew);
    tf_voigt_stress(st.eps, hnew + 6);
    return TF_MAT_OK;
}

/* ---- the Kelvin solid's parameters, shared with kelvin_nh.c ---- */

const tf_law_param tf_kelvin_params[TF_KELVIN_PARAMS] = {
    [TF_KELVIN_NU] = {"nu", "Poisson's ratio", NAN},
    [TF_KELVIN_K1] = {"k1", "the relaxed modulus E_inf, MPa (Fig. 2's spring K1)", NAN},
    [TF_KELVIN_K2] = {"k2", "the Maxwell arm's spring, MPa: E_0 = k1 + k2 (K2)", NAN},
    [TF_KELVIN_ETA] = {"eta", "the dashpot, MPa s: tau = eta / k2", NAN},
    [TF_KELVIN_K] = {"k", "the adjustment N(eps) = eps + k eps^2 (eq 10)", 0},
};

void tf_kelvin_moduli(const double *p, double *young, double *poisson)
{
    *young = p[TF_KELVIN_K1] + p[TF_KELVIN_K2];
    *poisson = p[TF_KELVIN_NU];
}

void tf_kelvin_relaxation(const double *p, double *g_inf, double *tau)
{
    double k1 = p[TF_KELVIN_K1], k2 = p[TF_KELVIN_K2], e0 = k1 + k2;
    *g_inf = k1 / e0;
    *tau = k2 > 0 ? p[TF_KELVIN_ETA] / k2 : INFINITY;
}

const char *tf_kelvin_check(const double *p, char *msg, size_t len)
{
    double k1 = p[TF_KELVIN_K1], k2 = p[TF_KELVIN_K2], eta = p[TF_KELVIN_ETA];
    double k = p[TF_KELVIN_K];
    const char *bad = tf_poisson_check(p[TF_KELVIN_NU], msg, len);
    if (bad != NULL) {
        return bad;
    }
    if (!isfinite(k1) || !(k1 > 0)) {
        return tf_law_bad(msg, len, "k1", k1,
                          "the relaxed modulus k1 must be a finite number > 0 MPa");
    }
    if (!isfinite(k2) || !(k2 >= 0)) {
        char why[160];
        snprintf(why, sizeof why,
                 "the relaxed modulus k1 = %g MPa must not be above the instantaneous one "
                 "k1 + k2 (k2 a finite number >= 0 MPa)",
                 k1);
        return tf_law_bad(msg, len, "k2", k2, why);
    }
    if (k2 > 0 && (!isfinite(eta) || !(eta > 0) || !isfinite(eta / k2))) {
        return tf_law_bad(msg, len, "eta", eta,
                          "the dashpot eta must be a finite number > 0 MPa s (tau = eta/k2 > 0)");
    }
    if (!isfinite(k) || !(k >= 0)) {
        return tf_law_bad(msg, len, "k", k, "the adjustment k of N = eps + k eps^2 must be >= 0");
    }
    return NULL;
}

/* sigma = D N(eps) has no potential: with k != 0 its tangent is not
 * symmetric (above). */
static unsigned caps_at(const double *p)
{
    return p[TF_KELVIN_K] != 0 ? TF_MATERIAL_UNSYMMETRIC : 0u;
}

const tf_law_ops tf_law_kelvin = {
    .name = "kelvin",
    .summary = "[EFG-Kelvin]'s nonlinear Kelvin solid (eqs 9-13): relaxation modulus "
               "k1 + k2 exp(-t/tau) on N(eps) = eps + k eps^2, small strain",
    .caps = TF_MATERIAL_HISTORY,
    .caps_at = caps_at,
    .volume = TF_VOLUME_JACOBIAN,
    .n_params = TF_KELVIN_PARAMS,
    .params = tf_kelvin_params,
    .history = 12, /* [h(6), eps_n(6)] */
    .moduli = tf_kelvin_moduli,
    .relaxation = tf_kelvin_relaxation,
    .check = tf_kelvin_check,
    .eval = eval,
};
