/*
 * test_region.c — the region models' contract (docs/header-format.md
 * §5.10-§5.12, tfit.h): the host builder's refusals, tfit_model_check()'s
 * rejections, the entry points' arguments, families, NaN and no-contact
 * outputs and state, the surface's state sanitising and superposition, and
 * the two-instrument forces against the linear system they solve (every
 * single-bit flip of their tables and descriptors: test_bitflip.c, which
 * runs every form).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "assert_close.h"
#include "model/golden.h"
#include "model/region_model.h"
#include "model/target_view.h"
#include "random_region.h"
#include "tfit.h"

static uint32_t bits(float x)
{
    uint32_t u;
    memcpy(&u, &x, 4);
    return u;
}

static tf_ctx ctx;

/* A block-like region (flat z+ face, 6 x 5 sites 2 mm apart), P = 2. */
static tf_random_region block(double mu)
{
    tf_random_region g;
    tf_random_region_block(&g, 6, 2.0, 0.5, 1.2, 0.3, 0, 2, mu);
    g.chart.ny = 5;
    return g;
}

static void view(const tf_model *m, tfit_model *t)
{
    tf_target_view(m, t);
    assert_int_equal(tfit_model_check(t), TFIT_OK);
}

static void builder_refusals(void **state)
{
    (void)state;
    tf_random_region g = block(0.3);
    const size_t points = (6 + 2) * (5 + 2);
    double *ctrl = calloc(points * 7, sizeof *ctrl);
    for (size_t j = 0; j < points; ++j) { /* K = diag(1, 1, 2) / s_u^2 ... */
        ctrl[7 * j + 1] = 0.5 * 4;
        ctrl[7 * j + 4] = 0.5 * 4;
        ctrl[7 * j + 6] = 1.0 * 4;
    }
    tf_model *m = tf_region_law_new(&ctx, "ok", &g.chart, 2, 0.5, 0.3, ctrl, 3);
    assert_non_null(m);
    assert_int_equal(m->node_ids[0], 3);
    tf_model_free(m);

    ctrl[7 * 11 + 6] = -1.0; /* ... but one control point not convex */
    assert_null(tf_region_law_new(&ctx, "bad", &g.chart, 2, 0.5, 0.3, ctrl, 0));
    assert_non_null(strstr(ctx.err, "control point 11"));
    ctrl[7 * 11 + 6] = 4.0;

    tf_region_grid c = g.chart;
    c.rot[1] = 0.1; /* not orthonormal */
    assert_null(tf_region_law_new(&ctx, "bad", &c, 2, 0.5, 0.3, ctrl, 0));
    assert_non_null(strstr(ctx.err, "orthonormal"));
    c = g.chart;
    c.nx = 1; /* a grid needs two sites a side */
    assert_null(tf_region_law_new(&ctx, "bad", &c, 2, 0.5, 0.3, ctrl, 0));
    assert_null(tf_region_law_new(&ctx, "bad", &g.chart, 5, 0.5, 0.3, ctrl, 0)); /* P > 4 */
    assert_null(tf_region_law_new(&ctx, "bad", &g.chart, 2, 0.5, -0.1, ctrl, 0)); /* mu < 0 */
    assert_non_null(strstr(ctx.err, "friction"));
    ctrl[7 * 5] = 1e12; /* a height beyond the overflow bound */
    assert_null(tf_region_law_new(&ctx, "bad", &g.chart, 2, 0.5, 0.3, ctrl, 0));
    assert_non_null(strstr(ctx.err, "max |h|"));
    free(ctrl);
}

static void agreement(void **state)
{
    (void)state;
    tf_rng r = {4};
    tf_random_region g = block(0.3), other = block(0.3);
    other.chart.ha = 2.5;
    tf_model *law = tf_random_region_law(&ctx, &g, "law");
    tf_model *surf = tf_random_region_surface(&ctx, &r, &g, "surface", 4, 1, 1, 7);
    tf_model *far = tf_random_region_surface(&ctx, &r, &other, "other", 4, 1, 1, 7);
    assert_int_equal(tf_region_agree(&ctx, law, surf), 0);
    assert_int_equal(tf_region_agree(&ctx, law, far), -1);
    assert_int_equal(tf_region_agree(&ctx, surf, law), -1);
    tf_model_free(law);
    tf_model_free(surf);
    tf_model_free(far);
}

static void check_rejections(void **state)
{
    (void)state;
    tf_rng r = {5};
    tf_random_region g = block(0.3);
    tf_model *law = tf_random_region_law(&ctx, &g, "law");
    tf_model *surf = tf_random_region_surface(&ctx, &r, &g, "surface", 3, 2, 1, 4);
    tfit_model t;
    for (int k = 0; k < 2; ++k) {
        tf_model *m = k ? surf : law;
        view(m, &t);
        t.family = TFIT_FAMILY_REGION_SURFACE + 1;
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_FAMILY);
        view(m, &t);
        t.family = k ? TFIT_FAMILY_REGION : TFIT_FAMILY_REGION_SURFACE; /* dims count differs */
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
        view(m, &t);
        const uint32_t one_site[5] = {1, m->dims[1], m->dims[2], m->dims[3], m->dims[4]};
        t.dims = one_site;
        t.dims_end = one_site + m->n_dims;
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_SIZE);
        view(m, &t);
        float *c = m->coef + m->n_coef - 1; /* one bit of the last coefficient */
        const float keep = *c;
        *c = nextafterf(*c, INFINITY);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_CORRUPT);
        *c = keep;
        /* a chart scalar out of range, the CRC made to match */
        const float sc = m->coef[12 + 2];
        m->coef[12 + 2] = 0x1p30f;
        t.crc32 = tf_model_crc32_checked(m, t.check);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_RANGE);
        m->coef[12 + 2] = sc;
        /* the self-test's CRC of another build's bits */
        view(m, &t);
        t.check[3 * TFIT_CHECK_INPUTS] ^= 1u;
        t.crc32 = tf_model_crc32_checked(m, t.check);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_ARITH);
        view(m, &t);
        t.check[3 * TFIT_CHECK_INPUTS + 1] ^= 1u; /* the far part */
        t.crc32 = tf_model_crc32_checked(m, t.check);
        assert_int_equal(tfit_model_check(&t), TFIT_ERR_ARITH);
    }
    tf_model_free(law);
    tf_model_free(surf);
}

static void arguments_and_families(void **state)
{
    (void)state;
    tf_rng r = {6};
    tf_random_region g = block(0.3);
    tf_model *law = tf_random_region_law(&ctx, &g, "law");
    tf_model *surf = tf_random_region_surface(&ctx, &r, &g, "surface", 3, 1, 1, 4);
    tf_model *surf2 = tf_random_region_surface(&ctx, &r, &g, "surface2", 3, 2, 1, 4);
    g.degree = 3;
    g.cubic = 0.5;
    tf_model *law3 = tf_random_region_law(&ctx, &g, "law3");
    tfit_model tl, ts, ts2, tl3;
    view(law, &tl);
    view(surf, &ts);
    view(surf2, &ts2);
    view(law3, &tl3);
    float st[6] = {0}, tip[6] = {10, 5, 6, 10, 5, 6}, f[6], out[12];
    assert_int_equal(tfit_region_reset(NULL, st), TFIT_ERR_ARG);
    assert_int_equal(tfit_region_reset(&tl, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_region_reset(&ts, st), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_region_force(&tl, st, NULL, f), TFIT_ERR_ARG);
    assert_int_equal(tfit_region_force(&ts, st, tip, f), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_region_surface(&tl, st, tip, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_region_surface(&ts, NULL, tip, out), TFIT_ERR_ARG);
    assert_int_equal(tfit_region_pair(&tl, &ts, st, tip, NULL), TFIT_ERR_ARG);
    assert_int_equal(tfit_region_pair(&ts, &tl, st, tip, f), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_region_pair(&tl3, &ts, st, tip, f), TFIT_ERR_FAMILY); /* P = 3 */
    assert_int_equal(tfit_region_pair(&tl, &ts2, st, tip, f), TFIT_ERR_FAMILY); /* p = 2 */
    assert_int_equal(tfit_region_surface_pair(&ts2, st, tip, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_displacements(&ts, tip, out), TFIT_ERR_FAMILY);
    assert_int_equal(tfit_contact_force(&tl, tip, out), TFIT_ERR_FAMILY);
    tfit_model bare = tl;
    bare.coef = NULL;
    assert_int_equal(tfit_region_force(&bare, st, tip, f), TFIT_ERR_ARG);
    tf_model_free(law);
    tf_model_free(law3);
    tf_model_free(surf);
    tf_model_free(surf2);
}

/* Reset, contact, no contact, a NaN tip: outputs and state. */
static void ticks(void **state)
{
    (void)state;
    tf_random_region g = block(0.3);
    tf_model *law = tf_random_region_law(&ctx, &g, "law");
    tfit_model t;
    view(law, &t);
    float st[3] = {7, 7, 7}, f[3];
    assert_int_equal(tfit_region_reset(&t, st), TFIT_OK);
    assert_true(st[0] == 0.0f && st[1] == 0.0f && st[2] == 0.0f);
    const float above[3] = {5, 4, 6.5f}, below[3] = {5, 4, 5.5f};
    assert_int_equal(tfit_region_force(&t, st, above, f), TFIT_NO_CONTACT);
    for (int i = 0; i < 3; ++i) {
        assert_int_equal(bits(f[i]), 0u); /* +0.0f, not -0 */
    }
    assert_true(st[2] == 0.0f && st[0] == 2.5f && st[1] == 2.0f); /* the tip's site */
    assert_int_equal(tfit_region_force(&t, st, below, f), TFIT_OK);
    assert_true(f[2] < 0.0f); /* presses into the tissue, -z */
    assert_true(st[2] == 1.0f);
    float kept[3];
    memcpy(kept, st, sizeof kept);
    const float nan_tip[3] = {5, NAN, 5.5f};
    assert_int_equal(tfit_region_force(&t, st, nan_tip, f), TFIT_ERR_INPUT);
    assert_memory_equal(kept, st, sizeof kept);
    for (int i = 0; i < 3; ++i) {
        assert_int_equal(bits(f[i]), 0u);
    }
    const float off_edge[3] = {40, 4, 5.5f}; /* beyond the region's edge: clamped */
    assert_int_equal(tfit_region_force(&t, st, off_edge, f), TFIT_CLAMPED);
    tf_model_free(law);
}

/* The surface: a NaN proxy word is the edge at 0, the pair is the sum. */
static void surface(void **state)
{
    (void)state;
    tf_rng r = {7};
    tf_random_region g = block(0.3);
    tf_model *surf = tf_random_region_surface(&ctx, &r, &g, "surface", 5, 1, 1, 6);
    tfit_model t;
    view(surf, &t);
    float a[18], b[18], s[18];
    const float f1[3] = {0.3f, -0.2f, -1.0f}, f2[3] = {-0.1f, 0.4f, -2.0f};
    const float at_nan[3] = {NAN, 2.5f, 1}, at_zero[3] = {0, 2.5f, 1};
    assert_int_equal(tfit_region_surface(&t, at_nan, f1, a), TFIT_OK);
    assert_int_equal(tfit_region_surface(&t, at_zero, f1, b), TFIT_OK);
    assert_memory_equal(a, b, sizeof a);
    const float st2[6] = {1.5f, 2.5f, 1, 4.0f, 0.5f, 1};
    const float both[6] = {f1[0], f1[1], f1[2], f2[0], f2[1], f2[2]};
    assert_int_equal(tfit_region_surface(&t, st2, f1, a), TFIT_OK);
    assert_int_equal(tfit_region_surface(&t, st2 + 3, f2, b), TFIT_OK);
    assert_int_equal(tfit_region_surface_pair(&t, st2, both, s), TFIT_OK);
    for (int i = 0; i < 18; ++i) {
        assert_close(s[i], (double)a[i] + b[i], 1e-5 * (fabs(a[i]) + fabs(b[i]) + 1e-6));
    }
    const float huge[6] = {1e30f, 0, 0, 0, 0, 0};
    assert_int_equal(tfit_region_surface_pair(&t, st2, huge, s), TFIT_CLAMPED);
    const float bad[6] = {0, 0, 0, INFINITY, 0, 0};
    assert_int_equal(tfit_region_surface_pair(&t, st2, bad, s), TFIT_ERR_INPUT);
    for (int i = 0; i < 18; ++i) {
        assert_int_equal(bits(s[i]), 0u);
    }
    tf_model_free(surf);
}

/* A surface whose cross compliance is c I (A = a I, Phi_site = s I): two
 * pressed instruments; their forces must solve u1 = K1^-1 F1 + C F2,
 * u2 = C F1 + K2^-1 F2 (K_i from the law at each proxy, in double). */
static void pair_solves_the_coupling(void **state)
{
    (void)state;
    tf_random_region g = block(0.3);
    g.variation = 0; /* K = diag(0.5, 0.5, 1.2) everywhere */
    tf_model *law = tf_random_region_law(&ctx, &g, "law");
    const uint32_t r = 3, n_out = 2;
    const size_t points = (size_t)(g.chart.nx + 2) * (g.chart.ny + 2), stride = 6 * r;
    double *ctrl = calloc(points * stride, sizeof *ctrl);
    const double amp = 0.3, site = 0.5, rf = 5; /* C = amp site / rf = 0.03 mm/N */
    for (size_t j = 0; j < points; ++j) {
        for (uint32_t k = 0; k < 3; ++k) {
            ctrl[j * stride + 3 * k + k] = amp;       /* A[k][t] */
            ctrl[j * stride + 3 * r + k * r + k] = site; /* Phi_site[i][k] */
        }
    }
    const double modes[3 * 2 * 3] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};
    const uint32_t ids[2] = {1, 2};
    tf_model *surf = tf_region_surface_new(&ctx, "coupled", &g.chart, g.s_u, g.mu, rf, r, 1, 1,
                                           ctrl, NULL, modes, n_out, ids);
    assert_non_null(surf);
    tfit_model tl, ts;
    view(law, &tl);
    view(surf, &ts);
    float st[6], f[6];
    tfit_region_reset(&tl, st);
    tfit_region_reset(&tl, st + 3);
    const float tip[6] = {3, 3, 5.4f, 7, 5, 5.1f}; /* both pressed in */
    assert_int_equal(tfit_region_pair(&tl, &ts, st, tip, f), TFIT_OK);
    const double c = amp * site / rf, k[3] = {0.5, 0.5, 1.2};
    for (int i = 0; i < 2; ++i) {
        const double g2[2] = {st[3 * i], st[3 * i + 1]};
        double x[3];
        tf_region_rest_point(law, g2, x, NULL);
        for (int a = 0; a < 3; ++a) { /* u_i = K^-1 F_i + C F_other (chart = scene axes) */
            const double u = (double)tip[3 * i + a] - g.chart.origin[a] - x[a];
            const double rhs = f[3 * i + a] / k[a] + c * f[3 * (1 - i) + a];
            assert_close(rhs, u, 2e-5);
        }
    }
    /* the uncoupled forces differ by about K C K u: the coupling acts */
    float single[3], s1[3];
    tfit_region_reset(&tl, s1);
    tfit_region_force(&tl, s1, tip, single);
    assert_true(fabs(single[2] - f[2]) > 1e-3);
    /* one instrument in the air: no coupling, the law's own force */
    const float one[6] = {3, 3, 5.4f, 7, 5, 9};
    tfit_region_reset(&tl, st);
    tfit_region_reset(&tl, st + 3);
    assert_int_equal(tfit_region_pair(&tl, &ts, st, one, f), TFIT_OK);
    assert_memory_equal(f, single, sizeof single);
    assert_int_equal(bits(f[3]) | bits(f[4]) | bits(f[5]), 0u);
    free(ctrl);
    tf_model_free(law);
    tf_model_free(surf);
}

int main(void)
{
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(builder_refusals),
        cmocka_unit_test(agreement),
        cmocka_unit_test(check_rejections),
        cmocka_unit_test(arguments_and_families),
        cmocka_unit_test(ticks),
        cmocka_unit_test(surface),
        cmocka_unit_test(pair_solves_the_coupling),
    };
    return cmocka_run_group_tests_name("region", tests, NULL, NULL);
}
