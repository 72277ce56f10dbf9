/*
 * test_material.c — the material laws behind material.h at one point:
 * tangent against central differences of S, S against differences of W,
 * objectivity, the small-strain limit of every law against the linear law,
 * history aliasing, inverted points and the parameter checks.  The
 * homogeneous closed-form responses are in test_material_uniaxial.c.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "assert_close.h"
#include "base/rng.h"
#include "materials/elasticity.h"
#include "materials/kinematics.h"
#include "materials/laws.h"
#include "materials/material.h"
#include "material_of.h"

#define NLAWS 5
#define NF 40 /* random deformation gradients per law */

/* One material of every registered law (the first test checks that none
 * is left out). */
static tf_material laws[NLAWS];

static int setup(void **state)
{
    (void)state;
    laws[0] = tf_test_material("linear", "E=2 nu=0.3");
    laws[1] = tf_test_material("svk", "E=2 nu=0.3");
    laws[2] = tf_test_material("neo-hookean", "E=2 nu=0.45");
    laws[3] = tf_test_material("kelvin", "nu=0.3 k1=1 k2=2 eta=3 k=0.8");
    laws[4] = tf_test_material("kelvin-neo-hookean", "nu=0.45 k1=1 k2=2 eta=3");
    return 0;
}

static void every_registered_law_is_tested_here(void **state)
{
    (void)state;
    assert_int_equal(tf_law_count(), NLAWS);
    for (size_t i = 0; i < tf_law_count(); ++i) {
        int found = 0;
        for (int l = 0; l < NLAWS; ++l) {
            found += laws[l].law == tf_law_at(i);
        }
        assert_int_equal(found, 1);
    }
}

/* F = I + a U(-1, 1), det F > 0.2. */
static void random_f(tf_rng *r, double a, double F[9])
{
    do {
        for (int k = 0; k < 9; ++k) {
            F[k] = (k % 4 == 0) + a * tf_rng_range(r, -1, 1);
        }
    } while (tf_det3(F) < 0.2);
}

/* The change of the law's strain measure (engineering Voigt) along dF. */
static void dstrain(const tf_material *m, const double F[9], const double dF[9], double de[6])
{
    double t[9];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (tf_material_kinematics(m) == TF_KIN_SMALL) {
                t[3 * i + j] = 0.5 * (dF[3 * i + j] + dF[3 * j + i]);
            } else { /* sym(F^T dF) */
                double a = 0, b = 0;
                for (int k = 0; k < 3; ++k) {
                    a += F[3 * k + i] * dF[3 * k + j];
                    b += F[3 * k + j] * dF[3 * k + i];
                }
                t[3 * i + j] = 0.5 * (a + b);
            }
        }
    }
    tf_voigt_strain(t, de);
}

/* A history after one earlier step to Fp (zero for elastic laws). */
static void history_after(const tf_material *m, const double Fp[9], double *h)
{
    double S[6], h0[12];
    tf_material_history_init(m, h0);
    tf_material_history_init(m, h);
    if (tf_material_history_size(m)) {
        assert_int_equal(tf_material_eval(m, Fp, 0.4, h0, h, S, NULL, NULL), TF_MAT_OK);
    }
}

static void eval(const tf_material *m, const double F[9], const double *hold, double S[6],
                 double C[36], double *W)
{
    double hnew[12];
    assert_int_equal(tf_material_eval(m, F, 0.7, hold, hnew, S, C, W), TF_MAT_OK);
}

/* max |C dE - dS_fd| / max |C dE| over the nine directions dF = e_ij. */
static double tangent_error(const tf_material *m, const double F[9], const double *hold)
{
    const double h = 1e-6; /* truncation ~h^2, rounding ~1e-16/h: both < 1e-9 */
    double S[6], C[36], err = 0, scale = 0;
    eval(m, F, hold, S, C, NULL);
    for (int d = 0; d < 9; ++d) {
        double Fp[9], Fm[9], dF[9] = {0}, Sp[6], Sm[6], de[6];
        dF[d] = 1;
        for (int k = 0; k < 9; ++k) {
            Fp[k] = F[k] + h * dF[k];
            Fm[k] = F[k] - h * dF[k];
        }
        eval(m, Fp, hold, Sp, NULL, NULL);
        eval(m, Fm, hold, Sm, NULL, NULL);
        dstrain(m, F, dF, de);
        for (int r = 0; r < 6; ++r) {
            double cde = 0;
            for (int c = 0; c < 6; ++c) {
                cde += C[6 * r + c] * de[c];
            }
            err = fmax(err, fabs(cde - (Sp[r] - Sm[r]) / (2 * h)));
            scale = fmax(scale, fabs(cde));
        }
    }
    return err / scale;
}

static void tangent_matches_finite_differences(void **state)
{
    (void)state;
    tf_rng r = {20240613};
    for (int l = 0; l < NLAWS; ++l) {
        double worst = 0;
        for (int t = 0; t < NF; ++t) {
            double F[9], Fp[9], hold[12];
            random_f(&r, 0.3, Fp);
            random_f(&r, 0.3, F);
            history_after(&laws[l], Fp, hold);
            worst = fmax(worst, tangent_error(&laws[l], F, hold));
        }
        printf("  %-18s tangent vs central differences: max relative error %.1e\n",
               tf_material_name(&laws[l]), worst);
        assert_true(worst < 1e-6);
    }
}

/* The materials that claim a symmetric tangent have one; the one that
 * declares UNSYMMETRIC (Kelvin with k != 0) has not, which the check would
 * notice if it had. */
static void tangent_symmetry_as_documented(void **state)
{
    (void)state;
    tf_rng r = {5};
    for (int l = 0; l < NLAWS; ++l) {
        double F[9], Fp[9], hold[12], S[6], C[36], asym = 0, scale = 0;
        random_f(&r, 0.3, Fp);
        random_f(&r, 0.3, F);
        history_after(&laws[l], Fp, hold);
        eval(&laws[l], F, hold, S, C, NULL);
        for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
                asym = fmax(asym, fabs(C[6 * i + j] - C[6 * j + i]));
                scale = fmax(scale, fabs(C[6 * i + j]));
            }
        }
        if (tf_material_caps(&laws[l]) & TF_MATERIAL_UNSYMMETRIC) {
            assert_true(asym > 1e-3 * scale);
        } else {
            assert_true(asym <= 1e-14 * scale);
        }
    }
}

static void stress_is_the_derivative_of_the_energy(void **state)
{
    (void)state;
    tf_rng r = {77};
    for (int l = 0; l < NLAWS; ++l) {
        const tf_material *m = &laws[l];
        if (!(tf_material_caps(m) & TF_MATERIAL_ENERGY)) {
            double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, S[6], W, h[12];
            tf_material_history_init(m, h);
            eval(m, F, h, S, NULL, &W);
            assert_true(isnan(W));
            continue;
        }
        double worst = 0;
        for (int t = 0; t < NF; ++t) {
            const double h = 1e-6;
            double F[9], S[6], W, err = 0, scale = 0;
            random_f(&r, 0.3, F);
            eval(m, F, NULL, S, NULL, &W);
            for (int d = 0; d < 9; ++d) {
                double Fp[9], Fm[9], dF[9] = {0}, Wp, Wm, de[6], sde = 0, dummy[6];
                dF[d] = 1;
                for (int k = 0; k < 9; ++k) {
                    Fp[k] = F[k] + h * dF[k];
                    Fm[k] = F[k] - h * dF[k];
                }
                eval(m, Fp, NULL, dummy, NULL, &Wp);
                eval(m, Fm, NULL, dummy, NULL, &Wm);
                dstrain(m, F, dF, de);
                for (int c = 0; c < 6; ++c) {
                    sde += S[c] * de[c];
                }
                err = fmax(err, fabs(sde - (Wp - Wm) / (2 * h)));
                scale = fmax(scale, fabs(sde));
            }
            worst = fmax(worst, err / scale);
        }
        printf("  %-18s S vs differences of W: max relative error %.1e\n", tf_material_name(m),
               worst);
        assert_true(worst < 1e-6);
    }
}

/* Rodrigues: rotation by angle |w| about w. */
static void rotation(const double w[3], double Q[9])
{
    double a = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]), c = cos(a), s = sin(a);
    double n[3] = {w[0] / a, w[1] / a, w[2] / a};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            Q[3 * i + j] = c * (i == j) + (1 - c) * n[i] * n[j];
        }
    }
    Q[1] -= s * n[2];
    Q[2] += s * n[1];
    Q[3] += s * n[2];
    Q[5] -= s * n[0];
    Q[6] -= s * n[1];
    Q[7] += s * n[0];
}

static void finite_strain_laws_are_objective(void **state)
{
    (void)state;
    tf_rng r = {99};
    for (int l = 0; l < NLAWS; ++l) {
        const tf_material *m = &laws[l];
        if (tf_material_kinematics(m) != TF_KIN_FINITE) {
            continue;
        }
        for (int t = 0; t < 10; ++t) {
            double F[9], Fp[9], Q[9], QF[9], w[3], hold[12], S[6], C[36], S2[6], C2[36];
            random_f(&r, 0.4, F);
            random_f(&r, 0.4, Fp);
            for (int a = 0; a < 3; ++a) {
                w[a] = tf_rng_range(&r, -2, 2);
            }
            rotation(w, Q);
            tf_matmul3(Q, F, QF);
            history_after(m, Fp, hold);
            eval(m, F, hold, S, C, NULL);
            eval(m, QF, hold, S2, C2, NULL);
            double sc = 0, cc = 0;
            for (int k = 0; k < 6; ++k) {
                sc = fmax(sc, fabs(S[k]));
            }
            for (int k = 0; k < 36; ++k) {
                cc = fmax(cc, fabs(C[k]));
            }
            for (int k = 0; k < 6; ++k) {
                assert_close(S2[k], S[k], 1e-12 * sc);
            }
            for (int k = 0; k < 36; ++k) {
                assert_close(C2[k], C[k], 1e-12 * cc);
            }
        }
    }
}

/* S(I + delta G) / delta and C against the linear law of modulus e. */
static double small_strain_error(const tf_material *m, double e, double dt, int steps)
{
    const double delta = 1e-7, G[9] = {0.3, -0.8, 0.5, 0.1, 1.0, -0.4, 0.7, 0.2, -0.6};
    double e_m, nu;
    tf_material_moduli(m, &e_m, &nu);
    tf_material lin = tf_test_material("linear", "");
    tf_material_set(&lin, "E", e);
    tf_material_set(&lin, "nu", nu);
    double F[9], h[12], S[6], C[36], Sl[6], Cl[36], Gd[9], err = 0, sc = 0, cc = 0;
    for (int k = 0; k < 9; ++k) {
        F[k] = (k % 4 == 0) + delta * G[k];
        Gd[k] = (k % 4 == 0) + G[k];
    }
    tf_material_history_init(m, h);
    assert_int_equal(tf_material_eval(m, F, 0, h, h, S, C, NULL), TF_MAT_OK);
    for (int s = 0; s < steps; ++s) { /* held: relaxes */
        assert_int_equal(tf_material_eval(m, F, dt, h, h, S, C, NULL), TF_MAT_OK);
    }
    tf_material_eval(&lin, Gd, 0, NULL, NULL, Sl, Cl, NULL);
    for (int k = 0; k < 6; ++k) {
        err = fmax(err, fabs(S[k] / delta - Sl[k]));
        sc = fmax(sc, fabs(Sl[k]));
    }
    err /= sc;
    for (int k = 0; k < 36; ++k) {
        cc = fmax(cc, fabs(Cl[k]));
    }
    for (int k = 0; k < 36; ++k) {
        err = fmax(err, fabs(C[k] - Cl[k]) / cc);
    }
    return err;
}

static void small_strain_limit_is_the_linear_law(void **state)
{
    (void)state;
    for (int l = 0; l < NLAWS; ++l) {
        const tf_material *m = &laws[l];
        double e0, nu, g_inf, tau, err;
        tf_material_moduli(m, &e0, &nu);
        if (tf_material_history_size(m) == 0) {
            err = small_strain_error(m, e0, 0, 0);
        } else {
            /* instantaneous: E_0; held for 1e8 tau: g_inf E_0 (the step's
             * tangent keeps phi1 = 1e-8 of the rest) */
            tf_material_relaxation(m, &g_inf, &tau);
            err = fmax(small_strain_error(m, e0, 0, 0),
                       small_strain_error(m, g_inf * e0, 1e8 * tau, 1));
        }
        printf("  %-18s small-strain limit vs linear: max relative error %.1e\n",
               tf_material_name(m), err);
        assert_true(err < 1e-6);
    }
}

static void history_may_be_updated_in_place(void **state)
{
    (void)state;
    tf_rng r = {3};
    for (int l = 0; l < NLAWS; ++l) {
        double F[9], Fp[9], h[12], h2[12], hn[12], S[6], S2[6], C[36], C2[36];
        if (tf_material_history_size(&laws[l]) == 0) {
            continue;
        }
        random_f(&r, 0.3, Fp);
        random_f(&r, 0.3, F);
        history_after(&laws[l], Fp, h);
        memcpy(h2, h, sizeof h);
        tf_material_eval(&laws[l], F, 0.3, h, hn, S, C, NULL);
        tf_material_eval(&laws[l], F, 0.3, h2, h2, S2, C2, NULL);
        assert_memory_equal(S, S2, sizeof S);
        assert_memory_equal(C, C2, sizeof C);
        assert_memory_equal(hn, h2, sizeof hn);
        assert_memory_not_equal(h, hn, sizeof h); /* the step did change it */
    }
}

static void inverted_points_are_reported(void **state)
{
    (void)state;
    const double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, -0.5};
    for (int l = 0; l < NLAWS; ++l) {
        double h[12], S[6], C[36];
        tf_material_history_init(&laws[l], h);
        int rc = tf_material_eval(&laws[l], F, 0.1, h, h, S, C, NULL);
        assert_int_equal(rc, tf_material_kinematics(&laws[l]) == TF_KIN_FINITE
                                 ? TF_MAT_INVERTED
                                 : TF_MAT_OK);
    }
}

typedef struct bad_case {
    const char *law, *params, *field, *words;
} bad_case;

static void parameter_checks_name_the_field(void **state)
{
    (void)state;
    const tf_material kel = tf_test_material("kelvin", "nu=0.45 k1=1 k2=2 eta=3 k=0.5");
    const bad_case cases[] = {
        {"neo-hookean", "E=0 nu=0.3", "E", "Young"},
        {"svk", "E=inf nu=0.3", "E", "finite"},
        {"linear", "E=1 nu=0.5", "nu", "(-1, 0.5)"},
        {"linear", "E=1 nu=-1", "nu", "(-1, 0.5)"},
        {"kelvin", "nu=0.3 k1=nan k2=1 eta=1", "k1", "relaxed"},
        {"kelvin", "nu=0.3 k1=2 k2=-1 eta=1", "k2", "not be above the instantaneous"},
        {"kelvin", "nu=0.3 k1=2 k2=1 eta=0", "eta", "tau"},
        {"kelvin", "nu=0.3 k1=2 k2=1e-300 eta=1e300", "eta", "tau"},
        {"kelvin", "nu=0.3 k1=2 k2=1 eta=1 k=-0.1", "k", "N = eps + k eps^2"},
        {"kelvin-neo-hookean", "nu=0.3 k1=2 k2=1 eta=1 k=0.1", "k", "must be 0"},
        {"kelvin", "nu=0.5 k1=2 k2=1 eta=1", "nu", "(-1, 0.5)"},
    };
    char msg[256];
    assert_null(tf_material_check(&kel, msg, sizeof msg));
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        tf_material m = tf_test_material(cases[c].law, cases[c].params);
        const char *field = tf_material_check(&m, msg, sizeof msg);
        assert_non_null(field);
        assert_string_equal(field, cases[c].field);
        assert_non_null(strstr(msg, cases[c].words));
    }
    /* a parameter left at NaN (never given) is refused too */
    tf_material unset = tf_test_material("svk", "nu=0.3");
    assert_string_equal(tf_material_check(&unset, msg, sizeof msg), "E");
    /* no relaxation (k2 = 0) is a valid, purely elastic Kelvin solid */
    tf_material elastic = kel;
    tf_material_set(&elastic, "k2", 0);
    tf_material_set(&elastic, "eta", 0);
    assert_null(tf_material_check(&elastic, msg, sizeof msg));
}

static void neohooke_constants_are_calculix_ones(void **state)
{
    (void)state;
    double c10, d1;
    tf_neohooke_constants(0.32, 0.49, &c10, &d1);
    /* mu = E / (2 (1 + nu)), K = E / (3 (1 - 2 nu)) */
    assert_close(c10, 0.32 / (4 * 1.49), 1e-15);
    assert_close(d1, 2 / (0.32 / (3 * 0.02)), 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_registered_law_is_tested_here),
        cmocka_unit_test(tangent_matches_finite_differences),
        cmocka_unit_test(tangent_symmetry_as_documented),
        cmocka_unit_test(stress_is_the_derivative_of_the_energy),
        cmocka_unit_test(finite_strain_laws_are_objective),
        cmocka_unit_test(small_strain_limit_is_the_linear_law),
        cmocka_unit_test(history_may_be_updated_in_place),
        cmocka_unit_test(inverted_points_are_reported),
        cmocka_unit_test(parameter_checks_name_the_field),
        cmocka_unit_test(neohooke_constants_are_calculix_ones),
    };
    return cmocka_run_group_tests_name("material", tests, setup, NULL);
}
