/*
 * test_material_uniaxial.c — homogeneous responses at one material point
 * against closed forms: uniaxial stress of St. Venant-Kirchhoff and
 * neo-Hookean from 50% compression to 100% stretch, and seed 001's Kelvin
 * law under a step strain (relaxation), a step stress (creep, with the
 * observed order in dt) and a strain ramp (exact for piecewise-linear
 * strain), with k = 0 and k > 0.
 *
 * The point is driven like a test machine: F stays diagonal, some of its
 * entries are prescribed and the others are found by Newton's method with
 * the law's own tangent so that the matching stresses take their targets.
 * The closed forms are written in principal stretches, independently of
 * the tensor code in host/materials.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "materials/elasticity.h"
#include "materials/material.h"
#include "material_of.h"

/* A material's parameter by its key. */
#define PARAM(m, key) tf_material_get(m, key)

/* Newton on the free diagonal entries f[a] (fixed[a] == 0) of F = diag(f)
 * until S[a] = target[a] there, in a step of dt from history h (NULL for
 * elastic laws), which is then advanced.  Writes S. */
static void drive(const tf_material *m, double f[3], const int fixed[3], const double target[3],
                  double dt, double *h, double S[6])
{
    double hold[12] = {0}, hnew[12];
    size_t nh = tf_material_history_size(m);
    if (nh) {
        memcpy(hold, h, nh * sizeof *h);
    }
    int finite = tf_material_kinematics(m) == TF_KIN_FINITE, free_[3], nf = 0;
    for (int a = 0; a < 3; ++a) {
        if (!fixed[a]) {
            free_[nf++] = a;
        }
    }
    for (int it = 0; it < 60; ++it) {
        double F[9] = {f[0], 0, 0, 0, f[1], 0, 0, 0, f[2]}, C[36], J[9], r[3], step = 0;
        assert_int_equal(tf_material_eval(m, F, dt, hold, hnew, S, C, NULL), TF_MAT_OK);
        if (nf == 0) {
            break;
        }
        for (int p = 0; p < nf; ++p) {
            r[p] = S[free_[p]] - target[free_[p]];
            for (int q = 0; q < nf; ++q) { /* dE_bb/dF_bb = F_bb (finite), 1 (small) */
                J[3 * p + q] = C[6 * free_[p] + free_[q]] * (finite ? f[free_[q]] : 1);
            }
        }
        /* Gaussian elimination without pivoting: J is a principal block of
         * a positive definite tangent here. */
        for (int p = 0; p < nf; ++p) {
            for (int q = p + 1; q < nf; ++q) {
                double l = J[3 * q + p] / J[3 * p + p];
                for (int c = p; c < nf; ++c) {
                    J[3 * q + c] -= l * J[3 * p + c];
                }
                r[q] -= l * r[p];
            }
        }
        for (int p = nf - 1; p >= 0; --p) {
            for (int c = p + 1; c < nf; ++c) {
                r[p] -= J[3 * p + c] * r[c];
            }
            r[p] /= J[3 * p + p];
            f[free_[p]] -= r[p];
            step = fmax(step, fabs(r[p]));
        }
        if (step < 1e-15) {
            double F2[9] = {f[0], 0, 0, 0, f[1], 0, 0, 0, f[2]};
            assert_int_equal(tf_material_eval(m, F2, dt, hold, hnew, S, NULL, NULL), TF_MAT_OK);
            nf = 0;
            break;
        }
    }
    if (nf != 0) {
        fail_msg("material point Newton did not converge");
    }
    if (nh) {
        memcpy(h, hnew, nh * sizeof *h);
    }
}

/* --- hyperelastic uniaxial stress ----------------------------------------- */

/* Neo-Hookean, stretch lam along x, lateral stretch l: with J = lam l^2,
 * l^2 S_22 = mu/3 J^(-2/3) (l^2 - lam^2) + K J (J - 1) (material.h's W).
 * Scalar Newton from the incompressible guess l = lam^(-1/2). */
static double neohooke_lateral(double mu, double kappa, double lam)
{
    double l = 1 / sqrt(lam);
    int extra = -1; /* two more steps once converged to 1e-12: quadratic */
    for (int it = 0; it < 100 && extra != 0; ++it) {
        double J = lam * l * l, j23 = pow(J, -2.0 / 3), dJ = 2 * lam * l;
        double g = mu / 3 * j23 * (l * l - lam * lam) + kappa * J * (J - 1);
        double dg = mu / 3 * (j23 * 2 * l - 2.0 / 3 * j23 / J * dJ * (l * l - lam * lam)) +
                    kappa * (2 * J - 1) * dJ;
        double d = g / dg;
        l -= d;
        if (extra < 0 && fabs(d) < 1e-12 * l) {
            extra = 2;
        }
        extra -= extra > 0;
    }
    if (extra != 0) {
        fail_msg("scalar Newton did not converge");
    }
    return l;
}

/* Nominal stress (force per reference area) P = lam S_11. */
static double neohooke_force(double mu, double kappa, double lam, double l)
{
    double J = lam * l * l;
    return (2 * mu / 3 * pow(J, -2.0 / 3) * (lam * lam - l * l) + kappa * J * (J - 1)) / lam;
}

/* Force-stretch curve from stretch 0.5 to 2.0 in steps of 0.1 (not 1.0):
 * the largest relative error of P and of the lateral stretch. */
static double uniaxial_curve_error(const tf_material *m)
{
    tf_lame lm = tf_lame_from(PARAM(m, "E"), PARAM(m, "nu"));
    double kappa = lm.lambda + 2 * lm.mu / 3, err = 0, f[3] = {1, 1, 1};
    for (int j = 0; j <= 15; ++j) {
        double lam = (5 + j) / 10.0, S[6], P, l;
        if (j == 5) {
            continue; /* lam = 1: zero force */
        }
        f[0] = lam;
        drive(m, f, (const int[3]){1, 0, 0}, (const double[3]){0, 0, 0}, 0, NULL, S);
        if (tf_material_caps(m) & TF_MATERIAL_HOOKE) {
            /* S_11 = E E_11, E_22 = -nu E_11: P = E lam (lam^2 - 1)/2 */
            P = PARAM(m, "E") * lam * (lam * lam - 1) / 2;
            l = sqrt(1 - PARAM(m, "nu") * (lam * lam - 1));
        } else {
            l = neohooke_lateral(lm.mu, kappa, lam);
            P = neohooke_force(lm.mu, kappa, lam, l);
        }
        err = fmax(err, fabs(lam * S[0] - P) / fabs(P));
        err = fmax(err, fabs(f[1] - l) / l);
        assert_true(fabs(f[1] - f[2]) <= 1e-14);
    }
    return err;
}

static void hyperelastic_uniaxial_stress_to_half_and_double_length(void **state)
{
    (void)state;
    /* SVK needs nu < 1/3 to reach stretch 2: its lateral stretch is
     * sqrt(1 - nu (lam^2 - 1)). */
    const tf_material cases[] = {
        tf_test_material("svk", "E=1 nu=0.3"),
        tf_test_material("svk", "E=0.32 nu=0"),
        tf_test_material("neo-hookean", "E=1 nu=0.3"),
        tf_test_material("neo-hookean", "E=0.32 nu=0.45"),
        tf_test_material("neo-hookean", "E=0.32 nu=0.49"),
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        double err = uniaxial_curve_error(&cases[c]);
        printf("  %-8s nu = %.2f: force-stretch 0.5..2.0 vs closed form: max relative error "
               "%.1e\n",
               tf_material_name(&cases[c]), PARAM(&cases[c], "nu"), err);
        assert_true(err < 1e-6);
    }
}

/* --- Kelvin -------------------------------------------------------------- */

#define KELVIN "nu=0.3 k1=1 k2=2 eta=3 k=0"

static double adjusted(double k, double e) { return e + k * e * e; }

/* Inverse of N on the branch through 0. */
static double unadjusted(double k, double n)
{
    return k == 0 ? n : 2 * n / (1 + sqrt(1 + 4 * k * n));
}

/* Relaxation modulus E(t) = k1 + k2 exp(-t/tau). */
static double relaxation(const tf_material *m, double t)
{
    return PARAM(m, "k1") + PARAM(m, "k2") * exp(-t * PARAM(m, "k2") / PARAM(m, "eta"));
}

/* Creep compliance of the same solid: N(eps(t)) = sigma0 J(t) under a
 * stress step, J(t) = 1/k1 - k2/(k1 (k1 + k2)) exp(-t/tau_c),
 * tau_c = eta (k1 + k2)/(k1 k2) (Fung, Biomechanics, ch. 2). */
static double creep(const tf_material *m, double t)
{
    double tc = PARAM(m, "eta") * (PARAM(m, "k1") + PARAM(m, "k2")) / (PARAM(m, "k1") * PARAM(m, "k2"));
    return 1 / PARAM(m, "k1") - PARAM(m, "k2") / (PARAM(m, "k1") * (PARAM(m, "k1") + PARAM(m, "k2"))) * exp(-t / tc);
}

static void kelvin_relaxation_under_a_step_strain(void **state)
{
    (void)state;
    const double eps0 = 0.05, dt = 0.3;
    for (int kk = 0; kk < 2; ++kk) {
        tf_material m = tf_test_material("kelvin", KELVIN);
        tf_material_set(&m, "k", kk ? 5.0 : 0.0);
        double h[12], f[3] = {1 + eps0, 1, 1}, S[6], err = 0;
        tf_material_history_init(&m, h);
        const int fixed[3] = {1, 0, 0};
        const double zero[3] = {0, 0, 0};
        drive(&m, f, fixed, zero, 0, h, S); /* the step, at t = 0 */
        for (int n = 0; n <= 20; ++n) {
            if (n > 0) {
                drive(&m, f, fixed, zero, dt, h, S);
            }
            double want = relaxation(&m, n * dt) * adjusted(PARAM(&m, "k"), eps0);
            /* lateral: N(eps_l) = -nu N(eps0), constant in time */
            double lat = unadjusted(PARAM(&m, "k"), -PARAM(&m, "nu") * adjusted(PARAM(&m, "k"), eps0));
            err = fmax(err, fabs(S[0] - want) / want);
            err = fmax(err, fabs(f[1] - 1 - lat) / fabs(lat));
        }
        printf("  kelvin k = %g: relaxation after a strain step: max relative error %.1e\n", PARAM(&m, "k"),
               err);
        assert_true(err < 1e-10); /* the update is exact for piecewise-constant strain */
    }
}

/* Axial strain at time T after a stress step sigma0, n equal steps. */
static double creep_strain(const tf_material *m, double sigma0, double T, int n)
{
    double h[12], f[3] = {1, 1, 1}, S[6];
    const int fixed[3] = {0, 0, 0};
    const double target[3] = {sigma0, 0, 0};
    tf_material_history_init(m, h);
    drive(m, f, fixed, target, 0, h, S);
    for (int s = 0; s < n; ++s) {
        drive(m, f, fixed, target, T / n, h, S);
    }
    return f[0] - 1;
}

static void kelvin_creep_under_a_step_stress_converges_in_dt(void **state)
{
    (void)state;
    const double sigma0 = 0.05, T = 5.0;
    for (int kk = 0; kk < 2; ++kk) {
        tf_material m = tf_test_material("kelvin", KELVIN);
        tf_material_set(&m, "k", kk ? 5.0 : 0.0);
        double want = unadjusted(PARAM(&m, "k"), sigma0 * creep(&m, T)), prev = 0, order = 0;
        double at0 = creep_strain(&m, sigma0, T, 0), want0 = unadjusted(PARAM(&m, "k"), sigma0 * creep(&m, 0));
        assert_true(fabs(at0 - want0) <= 1e-13 * want0); /* the instantaneous response */
        printf("  kelvin k = %g: creep strain at t = %g s vs closed form %.6f:\n", PARAM(&m, "k"), T, want);
        for (int n = 5; n <= 1280; n *= 2) {
            double err = fabs(creep_strain(&m, sigma0, T, n) - want) / want;
            if (prev > 0) {
                order = log2(prev / err);
                assert_true(order > 1.0); /* first order or better */
            }
            printf("    dt = %-9.5g relative error %.2e   observed order %.2f\n", T / n, err,
                   prev > 0 ? order : NAN);
            prev = err;
        }
        assert_true(prev < 1e-6);
    }
}

/* Uniaxial strain eps(t) = r t up to t_r, then held: with N = eps + k eps^2
 * linear plus quadratic in t,
 *   int_0^t E(t-s) dN/ds ds = k1 N(t) + k2 H(t),
 *   H(t) = r tau (1 - e^(-t/tau)) + 2 k r^2 (tau t - tau^2 (1 - e^(-t/tau)))  (t <= t_r),
 *   H(t) = H(t_r) e^(-(t - t_r)/tau)                                           (t > t_r),
 * and sigma_11 = (1 - nu)/((1 + nu)(1 - 2 nu)) times that, sigma_22 = nu/(1 - nu) sigma_11. */
static double ramp_stress(const tf_material *m, double r, double tr, double t)
{
    double tau = PARAM(m, "eta") / PARAM(m, "k2"), te = fmin(t, tr), e1 = -expm1(-te / tau);
    double H = r * tau * e1 + 2 * PARAM(m, "k") * r * r * (tau * te - tau * tau * e1);
    if (t > tr) {
        H *= exp(-(t - tr) / tau);
    }
    double nu = PARAM(m, "nu"), c = (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    return c * (PARAM(m, "k1") * adjusted(PARAM(m, "k"), r * te) + PARAM(m, "k2") * H);
}

static void kelvin_strain_ramp_is_integrated_exactly(void **state)
{
    (void)state;
    const double r = 0.04, tr = 1.0, dt = 0.125;
    for (int kk = 0; kk < 2; ++kk) {
        tf_material m = tf_test_material("kelvin", KELVIN);
        tf_material_set(&m, "k", kk ? 5.0 : 0.0);
        double h[12], S[6], err = 0;
        tf_material_history_init(&m, h);
        for (int n = 1; n <= 40; ++n) {
            double t = n * dt, F[9] = {1 + r * fmin(t, tr), 0, 0, 0, 1, 0, 0, 0, 1};
            assert_int_equal(tf_material_eval(&m, F, dt, h, h, S, NULL, NULL), TF_MAT_OK);
            double want = ramp_stress(&m, r, tr, t);
            err = fmax(err, fabs(S[0] - want) / want);
            err = fmax(err, fabs(S[1] - PARAM(&m, "nu") / (1 - PARAM(&m, "nu")) * want) / want);
        }
        printf("  kelvin k = %g: ramp and hold in uniaxial strain: max relative error %.1e\n",
               PARAM(&m, "k"), err);
        assert_true(err < 1e-12);
    }
}

/* Ours: the neo-Hookean Kelvin law under a stretch step relaxes as
 * S_11(t) = g(t) S0_11 with the lateral stretch of the instantaneous
 * neo-Hookean solid, constant in time. */
static void kelvin_neohooke_relaxation_under_a_stretch_step(void **state)
{
    (void)state;
    const tf_material m = tf_test_material("kelvin-neo-hookean", "nu=0.45 k1=0.1 k2=0.22 eta=0.5");
    tf_lame l0 = tf_lame_from(PARAM(&m, "k1") + PARAM(&m, "k2"), PARAM(&m, "nu"));
    double kappa = l0.lambda + 2 * l0.mu / 3, err = 0;
    for (int c = 0; c < 2; ++c) {
        double lam = c ? 2.0 : 0.5, h[12], f[3] = {lam, 1, 1}, S[6];
        double l = neohooke_lateral(l0.mu, kappa, lam), s0 = neohooke_force(l0.mu, kappa, lam, l) / lam;
        const int fixed[3] = {1, 0, 0};
        const double zero[3] = {0, 0, 0};
        tf_material_history_init(&m, h);
        drive(&m, f, fixed, zero, 0, h, S);
        for (int n = 0; n <= 10; ++n) {
            if (n > 0) {
                drive(&m, f, fixed, zero, 0.4, h, S);
            }
            double g = relaxation(&m, 0.4 * n) / (PARAM(&m, "k1") + PARAM(&m, "k2"));
            err = fmax(err, fabs(S[0] - g * s0) / fabs(g * s0));
            err = fmax(err, fabs(f[1] - l) / l);
        }
    }
    printf("  kelvin-neohooke: relaxation after stretch steps to 0.5 and 2: max relative error "
           "%.1e\n",
           err);
    assert_true(err < 1e-10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hyperelastic_uniaxial_stress_to_half_and_double_length),
        cmocka_unit_test(kelvin_relaxation_under_a_step_strain),
        cmocka_unit_test(kelvin_creep_under_a_step_stress_converges_in_dt),
        cmocka_unit_test(kelvin_strain_ramp_is_integrated_exactly),
        cmocka_unit_test(kelvin_neohooke_relaxation_under_a_stretch_step),
    };
    return cmocka_run_group_tests_name("material_uniaxial", tests, NULL, NULL);
}
