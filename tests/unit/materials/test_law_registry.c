/*
 * test_law_registry.c — the law registry (materials/registry.c) and what
 * every registered law declares about itself (materials/material.h):
 *
 *   names       every name finds its law again, names are distinct, an
 *               unknown one finds nothing, the default is linear;
 *   keys        every parameter key of every law is in the registry's key
 *               list exactly once, and a law's keys are distinct;
 *   parameters  set and get by key, fallbacks, unknown keys refused;
 *   capabilities what a law declares holds: HOOKE is lambda tr(E) I +
 *               2 mu E with a constant tangent, ENERGY gives a finite W,
 *               HISTORY has a history and a relaxation function, a
 *               GREEN_TRACE volume is the measure of the law's volumetric
 *               energy, the moduli are the law's response at small strain.
 *
 * A law added to the registry is tested by these without a change here,
 * given sample values for its parameters' keys (SAMPLES).
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
#include "materials/kinematics.h"
#include "materials/material.h"

/* A valid value for every parameter key (those with a fallback keep it). */
static const struct {
    const char *key;
    double v;
} SAMPLES[] = {{"E", 2.0}, {"nu", 0.3}, {"k1", 1.0}, {"k2", 2.0}, {"eta", 3.0}};

static tf_material sample(const tf_law_ops *law)
{
    tf_material m = tf_material_of(law);
    for (size_t i = 0; i < law->n_params; ++i) {
        for (size_t s = 0; s < sizeof SAMPLES / sizeof SAMPLES[0]; ++s) {
            if (isnan(m.p[i]) && strcmp(law->params[i].key, SAMPLES[s].key) == 0) {
                m.p[i] = SAMPLES[s].v;
            }
        }
        if (isnan(m.p[i])) {
            fail_msg("law %s: no sample value for its parameter '%s'", law->name,
                     law->params[i].key);
        }
    }
    return m;
}

static void names_round_trip(void **state)
{
    (void)state;
    char names[512];
    tf_law_names(names, sizeof names);
    assert_true(tf_law_count() > 0);
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        assert_non_null(l->name);
        assert_ptr_equal(tf_law_find(l->name), l);
        assert_non_null(strstr(names, l->name));
        assert_non_null(l->summary);
        for (size_t j = 0; j < i; ++j) {
            assert_string_not_equal(tf_law_at(j)->name, l->name);
        }
    }
    assert_null(tf_law_at(tf_law_count()));
    assert_null(tf_law_find("rubber"));
    assert_null(tf_law_find(""));
    assert_string_equal(tf_law_default()->name, "linear");
    print_message("%zu laws: %s\n", tf_law_count(), names);
}

static void every_key_is_listed_once(void **state)
{
    (void)state;
    size_t nkeys = tf_law_key_count();
    for (size_t k = 0; k < nkeys; ++k) {
        assert_non_null(tf_law_key_at(k));
        for (size_t j = 0; j < k; ++j) {
            assert_string_not_equal(tf_law_key_at(j), tf_law_key_at(k));
        }
    }
    assert_null(tf_law_key_at(nkeys));
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        assert_true(l->n_params <= TF_MATERIAL_MAX_PARAMS);
        for (size_t p = 0; p < l->n_params; ++p) {
            int listed = 0;
            for (size_t k = 0; k < nkeys; ++k) {
                listed += strcmp(tf_law_key_at(k), l->params[p].key) == 0;
            }
            assert_int_equal(listed, 1);
            assert_int_equal(tf_law_param_index(l, l->params[p].key), (int)p);
            assert_non_null(l->params[p].what);
        }
    }
}

static void parameters_by_key(void **state)
{
    (void)state;
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        tf_material m = tf_material_of(l);
        assert_ptr_equal(m.law, l);
        for (size_t p = 0; p < l->n_params; ++p) {
            double fb = l->params[p].fallback;
            assert_true(isnan(fb) ? isnan(m.p[p]) : m.p[p] == fb);
            assert_int_equal(tf_material_set(&m, l->params[p].key, 1.0 + (double)p), 0);
            assert_true(tf_material_get(&m, l->params[p].key) == 1.0 + (double)p);
        }
        assert_int_equal(tf_material_set(&m, "colour", 1), -1);
        assert_true(isnan(tf_material_get(&m, "colour")));
        char list[256];
        tf_law_param_list(l, 0, list, sizeof list);
        for (size_t p = 0; p < l->n_params; ++p) {
            assert_non_null(strstr(list, l->params[p].key));
        }
    }
}

/* F = I + a U(-1, 1), det F > 0.3. */
static void random_f(tf_rng *r, double a, double F[9])
{
    do {
        for (int k = 0; k < 9; ++k) {
            F[k] = (k % 4 == 0) + a * tf_rng_range(r, -1, 1);
        }
    } while (tf_det3(F) < 0.3);
}

/* The law's strain measure (tensor) at F. */
static void strain_of(const tf_material *m, const double F[9], double E[9])
{
    if (tf_material_caps(m) & TF_MATERIAL_FINITE) {
        tf_green_lagrange(F, E);
    } else {
        tf_small_strain(F, E);
    }
}

/* HOOKE: S = lambda tr(E) I + 2 mu E and C = lambda I x I + 2 mu I_sym,
 * with the Lame constants of the law's moduli. */
static void hooke_holds(const tf_material *m, const double F[9])
{
    tf_lame l = tf_material_lame(m);
    double E[9], S[6], C[36], h[12], hn[12];
    strain_of(m, F, E);
    tf_material_history_init(m, h);
    assert_int_equal(tf_material_eval(m, F, 0.1, h, hn, S, C, NULL), TF_MAT_OK);
    double tr = E[0] + E[4] + E[8], scale = (fabs(l.lambda) + 2 * l.mu);
    for (int v = 0; v < 6; ++v) {
        int i = tf_voigt_i[v], j = tf_voigt_j[v];
        assert_close(S[v], l.lambda * tr * (i == j) + 2 * l.mu * E[3 * i + j], 1e-12 * scale);
        for (int w = 0; w < 6; ++w) {
            double want = v < 3 && w < 3 ? l.lambda + 2 * l.mu * (v == w) : v == w ? l.mu : 0;
            assert_close(C[6 * v + w], want, 1e-12 * scale);
        }
    }
}

/* GREEN_TRACE: W - mu E:E = lambda/2 (tr E)^2. */
static void green_trace_holds(const tf_material *m, const double F[9])
{
    tf_lame l = tf_material_lame(m);
    double E[9], S[6], W, ee = 0;
    assert_true(tf_material_caps(m) & TF_MATERIAL_ENERGY);
    tf_green_lagrange(F, E);
    assert_int_equal(tf_material_eval(m, F, 0, NULL, NULL, S, NULL, &W), TF_MAT_OK);
    for (int k = 0; k < 9; ++k) {
        ee += E[k] * E[k];
    }
    double tr = E[0] + E[4] + E[8];
    assert_close(W - l.mu * ee, 0.5 * l.lambda * tr * tr, 1e-12 * (l.lambda + l.mu));
}

static void declared_capabilities_hold(void **state)
{
    (void)state;
    tf_rng r = {424242};
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        tf_material m = sample(l);
        char msg[256];
        const char *bad = tf_material_check(&m, msg, sizeof msg);
        if (bad != NULL) {
            fail_msg("law %s refuses its samples: %s: %s", l->name, bad, msg);
        }
        unsigned caps = tf_material_caps(&m);
        assert_int_equal(tf_material_kinematics(&m),
                         caps & TF_MATERIAL_FINITE ? TF_KIN_FINITE : TF_KIN_SMALL);
        /* history and relaxation go together */
        double g_inf, tau, young, nu;
        tf_material_relaxation(&m, &g_inf, &tau);
        tf_material_moduli(&m, &young, &nu);
        assert_true(young > 0 && nu > -1 && nu < 0.5);
        assert_true(tf_material_history_size(&m) <= 12);
        if (caps & TF_MATERIAL_HISTORY) {
            assert_true(tf_material_history_size(&m) > 0);
            assert_non_null(l->relaxation);
            assert_true(g_inf > 0 && g_inf <= 1 && tau > 0);
        } else {
            assert_int_equal(tf_material_history_size(&m), 0);
            assert_true(g_inf == 1 && isinf(tau));
        }
        /* HOOKE: no history, its formula; GREEN_TRACE: its volumetric energy */
        assert_true(!(caps & TF_MATERIAL_HOOKE) || !(caps & TF_MATERIAL_HISTORY));
        for (int t = 0; t < 10; ++t) {
            double F[9], S[6], W, h[12], hn[12];
            random_f(&r, 0.3, F);
            if (caps & TF_MATERIAL_HOOKE) {
                hooke_holds(&m, F);
            }
            if (tf_material_volume(&m) == TF_VOLUME_GREEN_TRACE) {
                green_trace_holds(&m, F);
            }
            tf_material_history_init(&m, h);
            assert_int_equal(tf_material_eval(&m, F, 0.1, h, hn, S, NULL, &W), TF_MAT_OK);
            assert_true((caps & TF_MATERIAL_ENERGY) ? isfinite(W) : isnan(W));
        }
        print_message("  %-18s caps %#x, %zu history doubles, volume %s\n", l->name, caps,
                      tf_material_history_size(&m),
                      tf_material_volume(&m) == TF_VOLUME_GREEN_TRACE ? "tr E" : "J - 1");
    }
}

/* A law defined here, not registered: a material of it answers every
 * question from its own operations (what a test law for a solver relies
 * on). */
static unsigned twin_caps_at(const double *p)
{
    return p[0] > 1 ? TF_MATERIAL_UNSYMMETRIC : 0u;
}

static void a_law_outside_the_registry_is_a_material_too(void **state)
{
    (void)state;
    tf_law_ops twin = *tf_law_find("svk");
    twin.name = "svk-twin";
    twin.caps_at = twin_caps_at;
    tf_material m = tf_material_of(&twin);
    assert_null(tf_law_find("svk-twin"));
    assert_int_equal(tf_material_set(&m, "E", 0.5), 0);
    assert_int_equal(tf_material_set(&m, "nu", 0.25), 0);
    assert_string_equal(tf_material_name(&m), "svk-twin");
    assert_int_equal(tf_material_caps(&m), tf_law_find("svk")->caps);
    tf_material_set(&m, "E", 2);
    assert_int_equal(tf_material_caps(&m), tf_law_find("svk")->caps | TF_MATERIAL_UNSYMMETRIC);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(names_round_trip),
        cmocka_unit_test(every_key_is_listed_once),
        cmocka_unit_test(parameters_by_key),
        cmocka_unit_test(declared_capabilities_hold),
        cmocka_unit_test(a_law_outside_the_registry_is_a_material_too),
    };
    return cmocka_run_group_tests_name("law_registry", tests, NULL, NULL);
}
