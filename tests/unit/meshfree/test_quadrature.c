/*
 * test_quadrature.c — Gauss-Legendre rules, background cells and load
 * patch points.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "meshfree/quadrature.h"

static void gauss_legendre_is_exact_to_degree_2n_minus_1(void **state)
{
    (void)state;
    for (unsigned n = 1; n <= TF_GAUSS_MAX; ++n) {
        double x[TF_GAUSS_MAX], w[TF_GAUSS_MAX];
        assert_int_equal(tf_gauss_legendre(n, x, w), 0);
        for (unsigned d = 0; d <= 2 * n; ++d) {
            double sum = 0, exact = d % 2 ? 0 : 2.0 / (d + 1);
            for (unsigned k = 0; k < n; ++k) {
                sum += w[k] * pow(x[k], d);
            }
            if (d < 2 * n) {
                assert_true(fabs(sum - exact) < 1e-14);
            } else if (n <= 5) {
                assert_true(fabs(sum - exact) > 1e-6); /* degree 2n is not exact */
            }
        }
        for (unsigned k = 0; k < n; ++k) {
            assert_true(x[k] == -x[n - 1 - k] && w[k] == w[n - 1 - k]); /* mirror-exact */
            assert_true(k == 0 || x[k] > x[k - 1]);
        }
    }
    double x[1], w[1];
    assert_int_equal(tf_gauss_legendre(0, x, w), -1);
    assert_int_equal(tf_gauss_legendre(TF_GAUSS_MAX + 1, x, w), -1);
}

static void cells_cover_the_box(void **state)
{
    (void)state;
    tf_cells c;
    const double lo[3] = {0, -6, 0}, hi[3] = {48, 6, 3};
    const unsigned n[3] = {8, 2, 1};
    assert_int_equal(tf_cells_init(&c, lo, hi, n, 3), 0);
    double vol = 0, mx = 0;
    for (size_t cell = 0; cell < tf_cells_count(&c); ++cell) {
        for (size_t p = 0; p < tf_cells_points(&c); ++p) {
            double x[3], w;
            tf_cells_point(&c, cell, p, x, &w);
            vol += w;
            mx += w * x[0] * x[0] * x[1] * x[1]; /* integral of x^2 y^2 */
            for (int a = 0; a < 3; ++a) {
                assert_true(x[a] > lo[a] && x[a] < hi[a]);
            }
        }
    }
    assert_true(fabs(vol - 48 * 12 * 3) < 1e-9);
    assert_true(fabs(mx - (48.0 * 48 * 48 / 3) * (2 * 216.0 / 3) * 3) < 1e-6 * mx);
}

static tf_cloud box_cloud(void)
{
    tf_cloud c;
    const double lo[3] = {0, 0, 0}, hi[3] = {48, 48, 6};
    const unsigned g[3] = {11, 11, 3};
    tf_cloud_box(&c, lo, hi, g, 0, 1);
    return c;
}

static void patches_integrate_their_area_and_moments(void **state)
{
    (void)state;
    tf_cloud cloud = box_cloud();
    tf_cells cells;
    const unsigned n[3] = {10, 10, 2};
    tf_cells_init(&cells, cloud.lo, cloud.hi, n, 3);
    const tf_patch patches[] = {
        {.shape = TF_PATCH_RECT, .face = TF_FACE_ZMAX, .centre = {24, 24}, .size = {4.8, 4.8}},
        {.shape = TF_PATCH_CIRCLE, .face = TF_FACE_ZMAX, .centre = {20, 30}, .radius = 3.0},
        {.shape = TF_PATCH_FACE, .face = TF_FACE_XMAX},
    };
    for (size_t k = 0; k < 3; ++k) {
        size_t nq;
        tf_qpoint *q = tf_patch_points(&patches[k], &cloud, &cells, &nq);
        assert_non_null(q);
        double area = 0, mu = 0;
        int u, v, axis = tf_face_axis(patches[k].face);
        tf_face_axes(patches[k].face, &u, &v);
        for (size_t i = 0; i < nq; ++i) {
            area += q[i].w;
            mu += q[i].w * q[i].x[u];
            assert_true(q[i].x[axis] == tf_cloud_face_coord(&cloud, patches[k].face));
        }
        double a = tf_patch_area(&patches[k], &cloud);
        assert_true(fabs(area - a) < 1e-9 * a);
        double centroid = patches[k].shape == TF_PATCH_FACE ? 24 : patches[k].centre[0];
        assert_true(fabs(mu / area - centroid) < 1e-9);
        free(q);
    }
    tf_cloud_free(&cloud);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gauss_legendre_is_exact_to_degree_2n_minus_1),
        cmocka_unit_test(cells_cover_the_box),
        cmocka_unit_test(patches_integrate_their_area_and_moments),
    };
    return cmocka_run_group_tests_name("quadrature", tests, NULL, NULL);
}
