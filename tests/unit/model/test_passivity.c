/*
 * test_passivity.c — the contact law's passivity check (model/passivity.h):
 * exact stiffness of linear laws, refusal of a law that creates energy in
 * all or part of its envelope, the symmetric part (not J) decides, and the
 * basis gradient the check differentiates with.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "model/basis.h"
#include "model/passivity.h"

/* A contact model of degree p with ball map (centre 0, radius r) whose
 * force is f_i = sum_v k[i][v] r g_v + (quadratic term q on f_x in g_x),
 * i.e. stiffness k at the centre in N/mm. */
static tf_model *contact(uint32_t p, double r, const double k[9], double q)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_model *m = tf_model_new(&ctx, "test_contact", TFIT_FAMILY_CONTACT, 1, &p, 1);
    assert_non_null(m);
    const double centre[3] = {0, 0, 0};
    tf_model_set_ball(m, centre, r);
    float *c = tf_model_tables(m);
    const uint32_t t = tf_terms(p);
    for (int i = 0; i < 3; ++i) {
        for (int v = 0; v < 3; ++v) {
            c[(uint32_t)i * t + 1 + (uint32_t)v] = (float)(k[3 * i + v] * r); /* T_1(g_v) terms */
        }
    }
    if (p >= 2) {
        c[4] = (float)q; /* T_2(g_x) in f_x: d/dg_x = 4 q g_x */
    }
    return m;
}

static void linear_law_exact_stiffness(void **state)
{
    (void)state;
    const double k[9] = {6, 1, 0, 1, 4, 0, 0, 0, 2};
    tf_model *m = contact(1, 2.0, k, 0);
    tf_passivity p;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_passivity_measure(&ctx, m, &p), 0);
    assert_true(p.samples > 4000);
    assert_true(fabs(p.min_eig - 2) < 1e-9);
    assert_true(fabs(p.max_stiffness - (5 + sqrt(2))) < 1e-9);
    assert_int_equal(tf_passivity_require(&ctx, m), 0);
    assert_true(fabs(m->stiffness_max - (5 + sqrt(2))) < 1e-9);
    assert_int_equal(m->passivity_samples, p.samples);
    tf_model_free(m);
}

static void negative_stiffness_refused(void **state)
{
    (void)state;
    const double k[9] = {6, 1, 0, 1, 4, 0, 0, 0, -2};
    tf_model *m = contact(1, 2.0, k, 0);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_passivity_require(&ctx, m), 1);
    assert_non_null(strstr(ctx.err, "test_contact is not passive"));
    assert_non_null(strstr(ctx.err, "eigenvalue -2 N/mm"));
    tf_model_free(m);
}

/* f_x = 2 r g_x - 0.75 T_2(g_x): dF/dg_x = 2 r - 3 g_x, negative beyond
 * g_x = 2r/3 only: passive at the centre, not at the edge. */
static void stiffness_lost_at_the_edge_refused(void **state)
{
    (void)state;
    const double k[9] = {2, 0, 0, 0, 2, 0, 0, 0, 2};
    tf_model *m = contact(2, 1.0, k, -0.75);
    tf_passivity p;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_passivity_measure(&ctx, m, &p), 0);
    assert_true(fabs(p.min_eig - (2 - 3)) < 1e-9); /* at g = (1, 0, 0) */
    assert_true(fabs(p.worst_g[0] - 1) < 1e-12);
    assert_true(fabs(p.worst_delta[0] - 1) < 1e-6); /* r = 1, centre 0 */
    assert_int_equal(tf_passivity_require(&ctx, m), 1);
    tf_model_free(m);
    /* the same law on a smaller envelope (|g_x| <= 0.6 in these units) is passive */
    m = contact(2, 1.0, k, -0.75 * 0.36);
    float *c = tf_model_tables(m);
    for (int i = 0; i < 3; ++i) {
        for (int v = 0; v < 3; ++v) {
            c[i * 10 + 1 + v] *= 0.6f;
        }
    }
    tf_model_set_ball(m, (const double[3]){0, 0, 0}, 0.6);
    assert_int_equal(tf_passivity_require(&ctx, m), 0);
    tf_model_free(m);
}

/* A gyroscopic part (skew J) neither creates nor stores energy: the
 * symmetric part decides passivity, the full J the stiffness to render. */
static void skew_part_does_not_decide(void **state)
{
    (void)state;
    const double k[9] = {2, 5, 0, -5, 2, 0, 0, 0, 2};
    tf_model *m = contact(1, 1.0, k, 0);
    tf_passivity p;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_passivity_measure(&ctx, m, &p), 0);
    assert_true(fabs(p.min_eig - 2) < 1e-9);
    assert_true(fabs(p.max_stiffness - sqrt(29)) < 1e-9);
    tf_model_free(m);
}

static void basis_gradient_matches_differences(void **state)
{
    (void)state;
    const uint32_t p = 6, t = tf_terms(p);
    const double g[3] = {0.31, -0.77, 0.52}, h = 1e-6;
    double phi[100], dphi[100][3], plus[100], minus[100];
    tf_basis_grad(p, g, phi, dphi);
    tf_basis(p, g, plus);
    assert_memory_equal(phi, plus, t * sizeof *phi); /* same bits as tf_basis */
    for (int v = 0; v < 3; ++v) {
        double gp[3] = {g[0], g[1], g[2]}, gm[3] = {g[0], g[1], g[2]};
        gp[v] += h;
        gm[v] -= h;
        tf_basis(p, gp, plus);
        tf_basis(p, gm, minus);
        for (uint32_t k = 0; k < t; ++k) {
            assert_true(fabs(dphi[k][v] - (plus[k] - minus[k]) / (2 * h)) < 1e-6);
        }
    }
}

static void not_a_contact_model(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const uint32_t p = 1;
    tf_model *m = tf_model_new(&ctx, "fwd", TFIT_FAMILY_NODAL, 2, &p, 1);
    tf_passivity out;
    assert_int_equal(tf_passivity_measure(&ctx, m, &out), -1);
    assert_non_null(strstr(ctx.err, "not a contact model"));
    tf_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_law_exact_stiffness),
        cmocka_unit_test(negative_stiffness_refused),
        cmocka_unit_test(stiffness_lost_at_the_edge_refused),
        cmocka_unit_test(skew_part_does_not_decide),
        cmocka_unit_test(basis_gradient_matches_differences),
        cmocka_unit_test(not_a_contact_model),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
