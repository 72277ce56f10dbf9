/*
 * test_region_spline.c — the numerics of the region models: the uniform
 * cubic B-spline weights, not-a-knot interpolation (exact for bicubics,
 * fourth order for smooth data, derivatives of the blend), the potential's
 * terms and their order, the quadratic potential's round trip, the 3 x 3
 * helpers.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "fitting/region_law.h"
#include "numerics/grid_spline.h"

static void weights_are_a_partition_of_unity(void **state)
{
    (void)state;
    for (double t = 0; t <= 1; t += 0.125) {
        double w[4], dw[4], sum = 0, dsum = 0;
        tf_bspline_weights(t, w, dw);
        for (int k = 0; k < 4; ++k) {
            assert_true(w[k] >= 0);
            sum += w[k];
            dsum += dw[k];
        }
        assert_true(fabs(sum - 1) < 1e-15 && fabs(dsum) < 1e-15);
    }
    unsigned i;
    double t;
    assert_int_equal(tf_bspline_cell(2.25, 5, &i, &t), 0);
    assert_true(i == 2 && t == 0.25);
    assert_int_equal(tf_bspline_cell(4, 5, &i, &t), 0); /* the last site: the last cell's end */
    assert_true(i == 3 && t == 1);
    assert_int_equal(tf_bspline_cell(-1, 5, &i, &t), 1);
    assert_true(i == 0 && t == 0);
    assert_int_equal(tf_bspline_cell(NAN, 5, &i, &t), 1);
    assert_true(i == 0 && t == 0);
}

static double bicubic(double x, double y)
{
    return 1 + 2 * x - y + 0.5 * x * x * y + 0.1 * x * x * x - 0.2 * y * y * y +
           0.01 * x * x * x * y * y * y;
}

/* Not-a-knot ends reproduce every bicubic exactly (natural ends would not:
 * they force Q'' = 0 at the edges). */
static void interpolation_is_exact_for_bicubics(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    unsigned nx = 6, ny = 4;
    double site[24 * 2], ctrl[8 * 6 * 2];
    for (unsigned j = 0; j < ny; ++j) {
        for (unsigned i = 0; i < nx; ++i) {
            site[2 * (j * nx + i)] = bicubic(i, j);
            site[2 * (j * nx + i) + 1] = -3 * bicubic(j, i); /* a second quantity */
        }
    }
    assert_int_equal(tf_spline_interpolate(&ctx, nx, ny, 2, site, ctrl), 0);
    for (double y = 0; y <= ny - 1; y += 0.21) {
        for (double x = 0; x <= nx - 1; x += 0.17) {
            double q[2], da[2], db[2], h = 1e-6;
            tf_spline_eval(nx, ny, 2, ctrl, x, y, q, da, db);
            assert_true(fabs(q[0] - bicubic(x, y)) < 1e-12);
            assert_true(fabs(q[1] + 3 * bicubic(y, x)) < 1e-11);
            double fa = (bicubic(x + h, y) - bicubic(x - h, y)) / (2 * h);
            double fb = (bicubic(x, y + h) - bicubic(x, y - h)) / (2 * h);
            assert_true(fabs(da[0] - fa) < 1e-7 && fabs(db[0] - fb) < 1e-7);
        }
    }
    /* fewer than 4 sites on an axis: refused */
    assert_int_equal(tf_spline_interpolate(&ctx, 3, 5, 1, site, ctrl), -1);
}

/* A smooth function's interpolation error falls at least 12-fold when the
 * spacing halves (fourth order, up to the edges). */
static void interpolation_is_fourth_order(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double err[2];
    for (int level = 0; level < 2; ++level) {
        unsigned n = level == 0 ? 9 : 17;
        double h = 1.0 / (n - 1);
        double *site = malloc(n * n * sizeof *site), *ctrl = malloc((n + 2) * (n + 2) * sizeof *ctrl);
        for (unsigned j = 0; j < n; ++j) {
            for (unsigned i = 0; i < n; ++i) {
                site[j * n + i] = sin(3 * i * h) * exp(j * h);
            }
        }
        assert_int_equal(tf_spline_interpolate(&ctx, n, n, 1, site, ctrl), 0);
        err[level] = 0;
        for (double y = 0; y <= 1; y += 0.01) {
            for (double x = 0; x <= 1; x += 0.01) {
                double q;
                tf_spline_eval(n, n, 1, ctrl, x / h, y / h, &q, NULL, NULL);
                err[level] = fmax(err[level], fabs(q - sin(3 * x) * exp(y)));
            }
        }
        free(site);
        free(ctrl);
    }
    /* (measured 24.7: 7.6e-4 to 3.1e-5; natural ends would give about 4, their
     * O(h^2) error at the edges dominating) */
    assert_true(err[0] / err[1] > 12);
}

/* Terms of degree 2 .. P, graded, then decreasing i, then decreasing j. */
static void the_potential_terms_in_order(void **state)
{
    (void)state;
    assert_int_equal(tf_region_terms(2), 6);
    assert_int_equal(tf_region_terms(3), 16);
    assert_int_equal(tf_region_terms(4), 31);
    unsigned ex[31][3];
    tf_region_exponents(2, ex);
    const unsigned want[6][3] = {{2, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 2, 0}, {0, 1, 1}, {0, 0, 2}};
    for (int t = 0; t < 6; ++t) {
        for (int k = 0; k < 3; ++k) {
            assert_int_equal(ex[t][k], want[t][k]);
        }
    }
    tf_region_exponents(4, ex);
    assert_true(ex[6][0] == 3 && ex[15][2] == 3 && ex[16][0] == 4 && ex[30][2] == 4);
    /* gradients against differences */
    double v[3] = {0.3, -0.2, 0.5}, m[31], dm[31][3], mp[31], mm[31];
    tf_region_monomials(4, v, m, dm);
    for (int a = 0; a < 3; ++a) {
        double vp[3] = {v[0], v[1], v[2]}, vm[3] = {v[0], v[1], v[2]};
        vp[a] += 1e-6;
        vm[a] -= 1e-6;
        tf_region_monomials(4, vp, mp, NULL);
        tf_region_monomials(4, vm, mm, NULL);
        for (int t = 0; t < 31; ++t) {
            assert_true(fabs((mp[t] - mm[t]) / 2e-6 - dm[t][a]) < 1e-8);
        }
    }
}

/* P = 2: the force of E = u^T K u / 2 is K u, through the coefficients in
 * v = s_u u and the spline of a constant field. */
static void the_quadratic_law_is_linear_elasticity(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const double K[9] = {2, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 4};
    double e[6], back[9], s_u = 0.25;
    tf_region_quadratic_coefs(K, s_u, e);
    tf_region_quadratic_stiffness(e, s_u, back);
    for (int k = 0; k < 9; ++k) {
        assert_true(fabs(back[k] - K[k]) < 1e-15);
    }
    tf_region_law law = {.nx = 4, .ny = 5, .h = {2, 3}, .P = 2, .T = 6, .s_u = s_u, .mu = 0.3};
    double site[20 * 7];
    for (int s = 0; s < 20; ++s) {
        site[7 * s] = 0.5;
        for (int t = 0; t < 6; ++t) {
            site[7 * s + 1 + t] = e[t];
        }
    }
    law.ctrl = malloc(6 * 7 * 7 * sizeof *law.ctrl);
    assert_int_equal(tf_spline_interpolate(&ctx, 4, 5, 7, site, law.ctrl), 0);
    const double u[3] = {0.4, -0.7, 1.1};
    double F[3], h, Kg[9];
    tf_region_law_force(&law, 3.3, 7.9, u, F, &h);
    for (int i = 0; i < 3; ++i) {
        double want = K[3 * i] * u[0] + K[3 * i + 1] * u[1] + K[3 * i + 2] * u[2];
        assert_true(fabs(F[i] - want) < 1e-12);
    }
    assert_true(fabs(h - 0.5) < 1e-14);
    tf_region_law_stiffness(&law, 1, 1, Kg);
    assert_true(fabs(Kg[5] - 0.2) < 1e-14);
    double lam[3];
    tf_sym3_eigenvalues(K, lam);
    assert_true(fabs(tf_region_law_min_stiffness(&law) - lam[0]) < 1e-12);
    assert_true(fabs(tf_region_law_min_stiffness_sampled(&law, 4) - lam[0]) < 1e-12);
    assert_int_equal(tf_region_law_floats(&law), 12 + 4 + 6 * 7 * 7);
    tf_region_law_free(&law);
}

static void three_by_three_helpers(void **state)
{
    (void)state;
    /* eigenvalues of a rotated diag(1, 2, 5) */
    double c = cos(0.7), s = sin(0.7), Q[9] = {c, -s, 0, s * c, c * c, -s, s * s, s * c, c};
    const double d[3] = {5, 1, 2};
    double A[9] = {0}, lam[3], inv[9];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k) {
                A[3 * i + j] += Q[3 * i + k] * d[k] * Q[3 * j + k];
            }
        }
    }
    tf_sym3_eigenvalues(A, lam);
    assert_true(fabs(lam[0] - 1) < 1e-13 && fabs(lam[1] - 2) < 1e-13 && fabs(lam[2] - 5) < 1e-13);
    assert_int_equal(tf_mat3_inverse(A, inv), 0);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double p = A[3 * i] * inv[j] + A[3 * i + 1] * inv[3 + j] + A[3 * i + 2] * inv[6 + j];
            assert_true(fabs(p - (i == j)) < 1e-14);
        }
    }
    const double singular[9] = {1, 2, 3, 2, 4, 6, 0, 1, 1};
    assert_int_equal(tf_mat3_inverse(singular, inv), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(weights_are_a_partition_of_unity),
        cmocka_unit_test(interpolation_is_exact_for_bicubics),
        cmocka_unit_test(interpolation_is_fourth_order),
        cmocka_unit_test(the_potential_terms_in_order),
        cmocka_unit_test(the_quadratic_law_is_linear_elasticity),
        cmocka_unit_test(three_by_three_helpers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
