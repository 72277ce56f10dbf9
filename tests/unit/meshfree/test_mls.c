/*
 * test_mls.c — MLS shape functions (seed 001 eqs 1-8) on a jittered cloud:
 * partition of unity and linear reproduction of values and derivatives,
 * derivatives against central differences, the cubic spline and the
 * behaviour at the edge of a node's domain of influence, the radii of
 * influence, and the singular-support error.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "base/rng.h"
#include "meshfree/mls.h"
#include "problem/nodes.h"

#define L 10.0 /* box edge, mm */

typedef struct fixture {
    tf_cloud cloud;
    double *radius;
    uint32_t *idx;
    double *phi, *dphi, *pp, *pm;
    tf_mls_work w;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    const double lo[3] = {0, 0, 0}, hi[3] = {L, L, L};
    const unsigned grid[3] = {7, 7, 7};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    if (tf_cloud_box(&f->cloud, lo, hi, grid, 0.3, 20170912) != 0) {
        return -1;
    }
    size_t n = f->cloud.n;
    f->radius = malloc(3 * n * sizeof *f->radius);
    f->idx = malloc(n * sizeof *f->idx);
    f->phi = malloc(n * sizeof *f->phi);
    f->dphi = malloc(3 * n * sizeof *f->dphi);
    f->pp = malloc(n * sizeof *f->pp);
    f->pm = malloc(n * sizeof *f->pm);
    if (tf_mls_radii(&ctx, f->cloud.xyz, n, f->cloud.spacing, 2.0, f->radius) != 0 ||
        tf_mls_work_init(&f->w, n) != 0) {
        return -1;
    }
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    tf_mls_work_free(&f->w);
    tf_cloud_free(&f->cloud);
    free(f->radius);
    free(f->idx);
    free(f->phi);
    free(f->dphi);
    free(f->pp);
    free(f->pm);
    free(f);
    return 0;
}

/* The nodes reaching the box [x - h, x + h]. */
static size_t support(fixture *f, const double x[3], double h)
{
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = x[a] - h;
        hi[a] = x[a] + h;
    }
    for (size_t i = 0; i < f->cloud.n; ++i) {
        f->idx[i] = (uint32_t)i;
    }
    return tf_mls_reach(f->cloud.xyz, f->radius, f->idx, f->cloud.n, lo, hi);
}

static size_t eval_at(fixture *f, const double x[3], double h, double *phi, double *dphi)
{
    double rcond;
    size_t bad, n = support(f, x, h);
    assert_int_equal(tf_mls_eval(&f->w, f->cloud.xyz, f->radius, f->idx, n, 4.0, x, 1, phi, dphi,
                                 &rcond, &bad),
                     0);
    return n;
}

static void partition_of_unity_and_linear_reproduction(void **state)
{
    fixture *f = *state;
    tf_rng r = {11};
    double worst = 0;
    for (int t = 0; t < 300; ++t) {
        double x[3];
        for (int a = 0; a < 3; ++a) {
            x[a] = tf_rng_range(&r, 0, L); /* boundary regions included */
        }
        size_t n = eval_at(f, x, 0, f->phi, f->dphi);
        /* sum phi_i (1, x_i) = (1, x); sum d_a phi_i (1, x_i) = (0, e_a) */
        double s = -1, sx[3] = {-x[0], -x[1], -x[2]}, ds[3] = {0}, dsx[9];
        for (int k = 0; k < 9; ++k) {
            dsx[k] = -(k % 4 == 0);
        }
        for (size_t i = 0; i < n; ++i) {
            const double *xi = f->cloud.xyz + 3 * (size_t)f->idx[i];
            s += f->phi[i];
            for (int a = 0; a < 3; ++a) {
                sx[a] += f->phi[i] * xi[a];
                ds[a] += f->dphi[a * n + i];
                for (int b = 0; b < 3; ++b) {
                    dsx[3 * a + b] += f->dphi[a * n + i] * xi[b];
                }
            }
        }
        /* values relative to 1 and to the box edge, derivatives per unit
         * gradient (dimensionless) and per 1/L */
        double e = fabs(s);
        for (int a = 0; a < 3; ++a) {
            e = fmax(e, fmax(fabs(sx[a]) / L, fabs(ds[a]) * L));
        }
        for (int k = 0; k < 9; ++k) {
            e = fmax(e, fabs(dsx[k]));
        }
        worst = fmax(worst, e);
    }
    printf("  partition of unity and linear reproduction, 300 points: max error %.1e\n", worst);
    assert_true(worst < 1e-12);
}

static void derivatives_match_finite_differences(void **state)
{
    fixture *f = *state;
    tf_rng r = {12};
    const double h = 1e-5; /* mm: truncation ~h^2 |phi'''|, rounding ~1e-16/h */
    double worst = 0;
    for (int t = 0; t < 50; ++t) {
        double x[3];
        for (int a = 0; a < 3; ++a) {
            x[a] = tf_rng_range(&r, 0.5, L - 0.5);
        }
        size_t n = eval_at(f, x, h, f->phi, f->dphi);
        double scale = 0, err = 0;
        for (int a = 0; a < 3; ++a) {
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]}, rc;
            size_t bad;
            xp[a] += h;
            xm[a] -= h;
            /* the same node list: nodes reaching the box around x */
            assert_int_equal(tf_mls_eval(&f->w, f->cloud.xyz, f->radius, f->idx, n, 4.0, xp, 1,
                                         f->pp, NULL, &rc, &bad),
                             0);
            assert_int_equal(tf_mls_eval(&f->w, f->cloud.xyz, f->radius, f->idx, n, 4.0, xm, 1,
                                         f->pm, NULL, &rc, &bad),
                             0);
            for (size_t i = 0; i < n; ++i) {
                err = fmax(err, fabs((f->pp[i] - f->pm[i]) / (2 * h) - f->dphi[a * n + i]));
                scale = fmax(scale, fabs(f->dphi[a * n + i]));
            }
        }
        worst = fmax(worst, err / scale);
    }
    printf("  derivatives vs central differences: max relative error %.1e\n", worst);
    assert_true(worst < 1e-6);
}

static void cubic_spline_is_eq_8(void **state)
{
    (void)state;
    double d;
    assert_true(fabs(tf_mls_weight(0, &d) - 2.0 / 3) < 1e-15 && d == -8);
    /* both branches give 1/6 and the same slope -1 at r = 1/2 */
    double wl = tf_mls_weight(0.5, &d), sl = d * 0.5;
    double wr = tf_mls_weight(nextafter(0.5, 1), &d), sr = d * 0.5;
    assert_true(fabs(wl - 1.0 / 6) < 1e-15 && fabs(wr - 1.0 / 6) < 1e-15);
    assert_true(fabs(sl + 1) < 1e-14 && fabs(sr + 1) < 1e-14);
    /* 4/3 - 4r + 4r^2 - 4/3 r^3 at r = 0.8 */
    assert_true(fabs(tf_mls_weight(0.8, &d) - (4.0 / 3 - 3.2 + 2.56 - 4.0 / 3 * 0.512)) < 1e-15);
    assert_true(tf_mls_weight(1, &d) == 0 && d == 0);
    assert_true(tf_mls_weight(1.2, &d) == 0 && d == 0);
    for (double r = 0.05; r < 1; r += 0.1) { /* dw/dr against differences */
        double wp = tf_mls_weight(r + 1e-6, &d), wm = tf_mls_weight(r - 1e-6, &d);
        tf_mls_weight(r, &d);
        assert_true(fabs((wp - wm) / 2e-6 - d * r) < 1e-8);
    }
}

/* Along a ray leaving node j's domain: phi_j and its gradient fall to zero
 * as the third and second power of the distance to the edge (the spline is
 * C2 there) and are exactly 0 beyond. */
static void shape_functions_vanish_smoothly_at_the_domain_edge(void **state)
{
    fixture *f = *state;
    size_t j = tf_cloud_index(&f->cloud, 3, 3, 3);
    const double *xj = f->cloud.xyz + 3 * j, *d = f->radius + 3 * j;
    const double dir[3] = {0.48, 0.6, 0.64}; /* unit */
    double rr = 0;
    for (int a = 0; a < 3; ++a) {
        rr += (dir[a] / d[a]) * (dir[a] / d[a]);
    }
    rr = 1 / sqrt(rr); /* distance to the edge along dir */
    double v[3], g[3];
    const double delta[3] = {2e-3, 1e-3, -1e-9};
    for (int k = 0; k < 3; ++k) {
        double x[3];
        for (int a = 0; a < 3; ++a) {
            x[a] = xj[a] + (1 - delta[k]) * rr * dir[a];
        }
        size_t n = eval_at(f, x, 3 * L, f->phi, f->dphi), at = n; /* all nodes */
        for (size_t i = 0; i < n; ++i) {
            if (f->idx[i] == j) {
                at = i;
            }
        }
        assert_true(at < n);
        v[k] = f->phi[at];
        g[k] = fabs(f->dphi[at]) + fabs(f->dphi[n + at]) + fabs(f->dphi[2 * n + at]);
    }
    printf("  at the domain edge: phi ratio %.4f (1/8), gradient ratio %.4f (1/4)\n",
           v[1] / v[0], g[1] / g[0]);
    assert_true(v[0] != 0 && fabs(v[1] / v[0] - 0.125) < 0.01);
    assert_true(fabs(g[1] / g[0] - 0.25) < 0.01);
    assert_true(v[2] == 0 && g[2] == 0);
}

static void several_points_equal_one_at_a_time(void **state)
{
    fixture *f = *state;
    const double x[6] = {4.1, 5.2, 3.3, 4.6, 4.9, 5.5};
    double phi2[2 * 400], dphi2[6 * 400], rc;
    size_t bad, n = support(f, x, 2.0); /* reaches both points */
    assert_true(n <= 400);
    assert_int_equal(tf_mls_eval(&f->w, f->cloud.xyz, f->radius, f->idx, n, 4.0, x, 2, phi2,
                                 dphi2, &rc, &bad),
                     0);
    for (int p = 0; p < 2; ++p) {
        assert_int_equal(tf_mls_eval(&f->w, f->cloud.xyz, f->radius, f->idx, n, 4.0, x + 3 * p,
                                     1, f->phi, f->dphi, &rc, &bad),
                         0);
        assert_memory_equal(f->phi, phi2 + p * n, n * sizeof *f->phi);
        assert_memory_equal(f->dphi, dphi2 + 3 * p * n, 3 * n * sizeof *f->dphi);
    }
}

static void singular_supports_are_refused(void **state)
{
    fixture *f = *state;
    double rc;
    size_t bad;
    /* a point that only three nodes reach: A has rank 3 */
    const double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 0};
    const double rad[12] = {2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2};
    const uint32_t idx[4] = {0, 1, 2, 3};
    const double x[6] = {0.2, 0.2, 0.1, 0.2, 0.2, 5.0};
    assert_int_equal(
        tf_mls_eval(&f->w, xyz, rad, idx, 3, 1.0, x, 1, f->phi, f->dphi, &rc, &bad), -1);
    /* four nodes, all in the plane z = 0 */
    assert_int_equal(
        tf_mls_eval(&f->w, xyz, rad, idx, 4, 1.0, x, 1, f->phi, f->dphi, &rc, &bad), -1);
    assert_true(rc <= 1e-15);
    /* the second of two points lies outside every domain: reported as point 1 */
    double xyz5[15], rad5[15];
    uint32_t idx5[5] = {0, 1, 2, 3, 4};
    memcpy(xyz5, xyz, sizeof xyz);
    xyz5[12] = 0.1, xyz5[13] = 0.2, xyz5[14] = 0.9; /* off the plane */
    for (int k = 0; k < 15; ++k) {
        rad5[k] = 2;
    }
    assert_int_equal(
        tf_mls_eval(&f->w, xyz5, rad5, idx5, 5, 1.0, x, 2, f->phi, f->dphi, &rc, &bad), -1);
    assert_int_equal(bad, 1);
    assert_int_equal(
        tf_mls_eval(&f->w, xyz5, rad5, idx5, 5, 1.0, x, 1, f->phi, f->dphi, &rc, &bad), 0);
    assert_true(rc > 1e-6);
}

static void radii_follow_the_grid_spacing(void **state)
{
    (void)state;
    /* block48's grid: spacing 4.8 x 4.8 x 3 mm, every node (corners too) */
    tf_cloud c;
    const double lo[3] = {0, 0, 0}, hi[3] = {48, 48, 6};
    const unsigned grid[3] = {11, 11, 3};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_cloud_box(&c, lo, hi, grid, 0, 1), 0);
    double *rad = malloc(3 * c.n * sizeof *rad);
    assert_int_equal(tf_mls_radii(&ctx, c.xyz, c.n, c.spacing, 2.5, rad), 0);
    for (size_t i = 0; i < c.n; ++i) {
        assert_true(fabs(rad[3 * i] - 12) < 1e-12 && fabs(rad[3 * i + 1] - 12) < 1e-12 &&
                    fabs(rad[3 * i + 2] - 7.5) < 1e-12);
    }
    /* a single layer of nodes has no spacing across it */
    double plane[3 * 25];
    for (int k = 0; k < 25; ++k) {
        plane[3 * k] = 12.0 * (k % 5);
        plane[3 * k + 1] = 12.0 * (k / 5);
        plane[3 * k + 2] = 0;
    }
    const double sp[3] = {12, 12, 12};
    assert_int_equal(tf_mls_radii(&ctx, plane, 25, sp, 2.5, rad), -1);
    assert_non_null(strstr(ctx.err, "no spacing along z"));
    free(rad);
    tf_cloud_free(&c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(partition_of_unity_and_linear_reproduction, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(derivatives_match_finite_differences, setup, teardown),
        cmocka_unit_test(cubic_spline_is_eq_8),
        cmocka_unit_test_setup_teardown(shape_functions_vanish_smoothly_at_the_domain_edge,
                                        setup, teardown),
        cmocka_unit_test_setup_teardown(several_points_equal_one_at_a_time, setup, teardown),
        cmocka_unit_test_setup_teardown(singular_supports_are_refused, setup, teardown),
        cmocka_unit_test(radii_follow_the_grid_spacing),
    };
    return cmocka_run_group_tests_name("mls", tests, NULL, NULL);
}
