/*
 * test_cut.c — cut geometry (meshfree/cut.h) on hand-checked cases: a slit
 * along x = 0 from (0, -5) to (0, 5) on the top z = 10, 4 mm deep.  Its
 * tangent is +y, so its normal t x e_z is +x: side s = x.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "meshfree/cut.h"

static tf_cut_set slit(void)
{
    tf_cut c = {.n = 2, .xy = {{0, -5}, {0, 5}}, .top = 10, .depth = 4};
    tf_cut_set s;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_cut_set_build(&ctx, &s, &c, 1), 0);
    assert_int_equal(s.n, 1);
    return s;
}

static void side_and_distance(void **state)
{
    (void)state;
    tf_cut_set s = slit();
    const tf_cut_panel *p = &s.panel[0];
    double a[3] = {2, 1, 9}, b[3] = {-3, 0, 8}, ahead[3] = {1, 8, 9}, below[3] = {0, 0, 3};
    assert_true(fabs(tf_cut_side(p, a) - 2) < 1e-15);
    assert_true(fabs(tf_cut_side(p, b) + 3) < 1e-15);
    assert_true(fabs(tf_cut_distance(p, a) - 2) < 1e-15);     /* inside the span */
    assert_true(fabs(tf_cut_distance(p, ahead) - hypot(1, 3)) < 1e-14); /* past the end */
    assert_true(fabs(tf_cut_distance(p, below) - 3) < 1e-15); /* below the front */
    /* eq 32: 1 on the + side, 0 on the - side inside the span, 1/2 ahead */
    assert_true(tf_cut_h(p, a, NULL) == 1);
    assert_true(tf_cut_h(p, b, NULL) == 0);
    double on_line[3] = {0, 7, 9};
    assert_true(fabs(tf_cut_h(p, on_line, NULL) - 0.5) < 1e-15);
    /* on the panel: within tol of its plane and in its span (edges included) */
    const double on[3] = {1e-13, 4.9, 6}, edge[3] = {0, 5, 10}, off[3] = {1e-11, 0, 8},
                 past[3] = {0, 5.1, 8}, under[3] = {0, 0, 5.9};
    assert_true(tf_cut_on_panel(&s, on, 1e-12));
    assert_true(tf_cut_on_panel(&s, edge, 1e-12));
    assert_false(tf_cut_on_panel(&s, off, 1e-12));
    assert_false(tf_cut_on_panel(&s, past, 1e-12));
    assert_false(tf_cut_on_panel(&s, under, 1e-12));
    tf_cut_set_free(&s);
}

static void h_gradient_matches_differences(void **state)
{
    (void)state;
    tf_cut_set s = slit();
    const double pts[][3] = {{0.7, 6.2, 9.1}, {-0.4, -5.9, 5.2}, {0.3, 2, 4.5}, {-1, 6, 4}};
    for (size_t k = 0; k < 4; ++k) {
        double g[3], xi[3] = {0.5, 5.5, 6}, ge[3];
        tf_cut_h(&s.panel[0], pts[k], g);
        tf_cut_enrich(&s, xi, pts[k], ge);
        for (int a = 0; a < 3; ++a) {
            double xp[3] = {pts[k][0], pts[k][1], pts[k][2]}, xm[3] = {xp[0], xp[1], xp[2]};
            xp[a] += 1e-6;
            xm[a] -= 1e-6;
            double fd = (tf_cut_h(&s.panel[0], xp, NULL) - tf_cut_h(&s.panel[0], xm, NULL)) / 2e-6;
            double fe = (tf_cut_enrich(&s, xi, xp, NULL) - tf_cut_enrich(&s, xi, xm, NULL)) / 2e-6;
            assert_true(fabs(g[a] - fd) < 1e-7);
            assert_true(fabs(ge[a] - fe) < 1e-7);
        }
    }
    tf_cut_set_free(&s);
}

static void visibility(void **state)
{
    (void)state;
    tf_cut_set s = slit();
    double l[3] = {-1, 0, 9}, r[3] = {1, 0, 9}, r2[3] = {1, 4, 7};
    double deep[3] = {1, 0, 5}, deepl[3] = {-1, 0, 5}, past[3] = {1, 6, 9}, pastl[3] = {-1, 6, 9};
    assert_false(tf_cut_visible(&s, l, r));      /* straight through */
    assert_false(tf_cut_visible(&s, r2, l));     /* obliquely through */
    assert_true(tf_cut_visible(&s, r, r2));      /* same side */
    assert_true(tf_cut_visible(&s, deep, deepl)); /* below the front at z = 6 */
    assert_false(tf_cut_visible(&s, deep, l));   /* crosses at z = 7 */
    assert_true(tf_cut_visible(&s, past, pastl)); /* past the end y = 5 */
    /* the enrichment: 1 on the same side, 0 across */
    double l2[3] = {-2, 3, 8};
    assert_true(tf_cut_enrich(&s, l, l2, NULL) == 1);
    assert_true(tf_cut_enrich(&s, l, r, NULL) == 0);
    /* below the front: h(deepl) = (1 - 1/sqrt 2)/2, so e = 1 - h there */
    assert_true(fabs(tf_cut_enrich(&s, l, deepl, NULL) - (1 - 0.5 * (1 - sqrt(0.5)))) < 1e-15);
    tf_cut_set_free(&s);
}

static void box_and_refusals(void **state)
{
    (void)state;
    tf_cut_set s = slit();
    double lo[3] = {-1, 4, 5}, hi[3] = {1, 6, 7}, lo2[3] = {0.5, -1, 0}, hi2[3] = {2, 1, 10};
    double lo3[3] = {-1, -1, 0}, hi3[3] = {1, 1, 5.9};
    assert_true(tf_cut_meets_box(&s, lo, hi));
    assert_false(tf_cut_meets_box(&s, lo2, hi2)); /* beside the plane */
    assert_false(tf_cut_meets_box(&s, lo3, hi3)); /* below the front */
    tf_cut_set_free(&s);
    tf_cut zero = {.n = 2, .xy = {{1, 1}, {1, 1}}, .top = 10, .depth = 4};
    tf_cut flat = {.n = 2, .xy = {{0, 0}, {1, 1}}, .top = 10, .depth = 0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_cut_set_build(&ctx, &s, &zero, 1), -1);
    assert_non_null(strstr(ctx.err, "zero length"));
    assert_int_equal(tf_cut_set_build(&ctx, &s, &flat, 1), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(side_and_distance),
        cmocka_unit_test(h_gradient_matches_differences),
        cmocka_unit_test(visibility),
        cmocka_unit_test(box_and_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
