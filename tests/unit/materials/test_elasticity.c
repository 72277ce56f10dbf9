/*
 * test_elasticity.c — the D matrix (textbook form of seed eq 7) and the
 * Lame-form stiffness block against B^T D B.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "materials/elasticity.h"

/* B of one node (6 x 3, seed eq 4 ordering xx, yy, zz, yz, xz, xy). */
static void bmatrix(const double g[3], double b[18])
{
    const double rows[6][3] = {{g[0], 0, 0}, {0, g[1], 0}, {0, 0, g[2]},
                               {0, g[2], g[1]}, {g[2], 0, g[0]}, {g[1], g[0], 0}};
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 3; ++c) {
            b[3 * r + c] = rows[r][c];
        }
    }
}

static void stiffness_block_is_bt_d_b(void **state)
{
    (void)state;
    const double e = 0.32, nu = 0.49, w = 0.7;
    const double ga[3] = {0.3, -1.2, 0.5}, gb[3] = {-0.4, 0.25, 2.0};
    double d[36], ba[18], bb[18], k[9] = {0};
    tf_dmatrix(e, nu, d);
    bmatrix(ga, ba);
    bmatrix(gb, bb);
    tf_lame l = tf_lame_from(e, nu);
    tf_stiffness_block(&l, w, ga, gb, k);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double ref = 0;
            for (int r = 0; r < 6; ++r) {
                for (int s = 0; s < 6; ++s) {
                    ref += ba[3 * r + i] * d[6 * r + s] * bb[3 * s + j];
                }
            }
            assert_true(fabs(w * ref - k[3 * i + j]) < 1e-12 * (1 + fabs(ref)));
        }
    }
}

static void dmatrix_is_the_textbook_one(void **state)
{
    (void)state;
    double d[36];
    tf_dmatrix(200.0, 0.25, d);
    /* E (1-nu) / ((1+nu)(1-2nu)) = 240, E nu / (...) = 80, G = 80 */
    assert_true(fabs(d[0] - 240) < 1e-12 && fabs(d[7] - 240) < 1e-12 && fabs(d[14] - 240) < 1e-12);
    assert_true(fabs(d[1] - 80) < 1e-12 && fabs(d[2] - 80) < 1e-12 && fabs(d[8] - 80) < 1e-12);
    for (int i = 3; i < 6; ++i) {
        assert_true(fabs(d[7 * i] - 80) < 1e-12);
        for (int j = 0; j < 6; ++j) {
            assert_true(i == j || d[6 * i + j] == 0); /* no coupling into shear */
        }
    }
}

static void uniaxial_stress_gives_e_and_nu(void **state)
{
    (void)state;
    /* u = (eps x, -nu eps y, -nu eps z) is uniaxial stress E eps along x */
    const double e = 3.0e7, nu = 0.3, eps = 1e-4;
    const double g[9] = {eps, 0, 0, 0, -nu * eps, 0, 0, 0, -nu * eps};
    double s[9];
    tf_lame l = tf_lame_from(e, nu);
    tf_stress(&l, g, s);
    assert_true(fabs(s[0] - e * eps) < 1e-9 * e * eps);
    for (int k = 1; k < 9; ++k) {
        assert_true(fabs(s[k]) < 1e-9 * e * eps);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stiffness_block_is_bt_d_b),
        cmocka_unit_test(dmatrix_is_the_textbook_one),
        cmocka_unit_test(uniaxial_stress_gives_e_and_nu),
    };
    return cmocka_run_group_tests_name("elasticity", tests, NULL, NULL);
}
