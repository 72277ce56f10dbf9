/*
 * test_rpim.c — RPIM shape functions (seed eqs 11-17): interpolation at the
 * nodes, linear reproduction with the polynomial (and its absence without),
 * derivatives against finite differences, and the condition estimate.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "base/rng.h"
#include "meshfree/rpim.h"

#define N 30

typedef struct fixture {
    double xyz[3 * N];
    uint32_t idx[N];
    tf_rpim_work w;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    tf_rng r = {7};
    for (int i = 0; i < N; ++i) {
        for (int a = 0; a < 3; ++a) {
            f->xyz[3 * i + a] = tf_rng_range(&r, -3, 3);
        }
        f->idx[i] = (uint32_t)i;
    }
    tf_rpim_work_init(&f->w, N);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    tf_rpim_work_free(&f->w);
    free(f);
    return 0;
}

static const double centre[3] = {0.1, -0.2, 0.3};

static void interpolates_at_the_nodes(void **state)
{
    fixture *f = *state;
    for (int poly = 0; poly < 2; ++poly) {
        tf_rpim p = {.shape = 2.0, .q = 1.03, .poly = poly};
        double rcond, phi[N];
        assert_int_equal(tf_rpim_factor(&p, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond), 0);
        for (int k = 0; k < N; ++k) {
            assert_int_equal(tf_rpim_eval(&f->w, f->xyz + 3 * k, 1, phi, NULL), 0);
            for (int i = 0; i < N; ++i) {
                assert_true(fabs(phi[i] - (i == k)) < 1e-9); /* Kronecker delta */
            }
        }
    }
}

/* Sum of phi_i f(x_i) for f = a + b.x at x, against f(x). */
static double reproduction_error(fixture *f, const double x[3])
{
    const double a = 0.7, b[3] = {1.5, -2.0, 0.25};
    double phi[N], dphi[3 * N], v = 0, g[3] = {0, 0, 0};
    tf_rpim_eval(&f->w, x, 1, phi, dphi);
    for (int i = 0; i < N; ++i) {
        const double *xi = f->xyz + 3 * i;
        double fi = a + b[0] * xi[0] + b[1] * xi[1] + b[2] * xi[2];
        v += phi[i] * fi;
        for (int c = 0; c < 3; ++c) {
            g[c] += dphi[c * N + i] * fi;
        }
    }
    double e = fabs(v - (a + b[0] * x[0] + b[1] * x[1] + b[2] * x[2]));
    for (int c = 0; c < 3; ++c) {
        e = fmax(e, fabs(g[c] - b[c]));
    }
    return e;
}

static void the_polynomial_reproduces_linear_fields(void **state)
{
    fixture *f = *state;
    const double x[3] = {0.4, 0.9, -1.1};
    double rcond;
    tf_rpim with = {.shape = 2.0, .q = 1.03, .poly = 1}, without = with;
    without.poly = 0;
    tf_rpim_factor(&with, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond);
    assert_true(reproduction_error(f, x) < 1e-9);
    /* The seed's eq 12 (no polynomial) only approximates them: the check
     * above would notice a missing polynomial. */
    tf_rpim_factor(&without, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond);
    assert_true(reproduction_error(f, x) > 1e-4);
}

static void derivatives_match_finite_differences(void **state)
{
    fixture *f = *state;
    tf_rpim p = {.shape = 2.0, .q = 1.03, .poly = 1};
    double rcond, phi[N], dphi[3 * N], pp[N], pm[N];
    tf_rpim_factor(&p, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond);
    double x[3] = {0.3, -0.5, 0.8};
    tf_rpim_eval(&f->w, x, 1, phi, dphi);
    const double h = 1e-4; /* truncation ~h^2, rounding ~eps cond / h: both below 1e-7 */
    for (int a = 0; a < 3; ++a) {
        double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
        xp[a] += h;
        xm[a] -= h;
        tf_rpim_eval(&f->w, xp, 1, pp, NULL);
        tf_rpim_eval(&f->w, xm, 1, pm, NULL);
        for (int i = 0; i < N; ++i) {
            assert_true(fabs((pp[i] - pm[i]) / (2 * h) - dphi[a * N + i]) < 1e-6);
        }
    }
}

static void many_points_equal_one_at_a_time(void **state)
{
    fixture *f = *state;
    tf_rpim p = {.shape = 2.0, .q = 1.03, .poly = 1};
    double rcond, x[9] = {0.1, 0.2, 0.3, -1, 1, 0.5, 2, -2, 0}, phi[3 * N], dphi[9 * N];
    double one[N], done[3 * N];
    tf_rpim_factor(&p, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond);
    tf_rpim_eval(&f->w, x, 3, phi, dphi);
    for (int k = 0; k < 3; ++k) {
        tf_rpim_eval(&f->w, x + 3 * k, 1, one, done);
        /* equal to rounding: the triangular solves block the columns
         * differently */
        for (int i = 0; i < N; ++i) {
            assert_true(fabs(one[i] - phi[k * N + i]) < 1e-12);
            for (int a = 0; a < 3; ++a) {
                assert_true(fabs(done[a * N + i] - dphi[(3 * k + a) * N + i]) < 1e-12);
            }
        }
    }
}

/* Largest |phi_i(x_k) - delta_ik| over the nodes. */
static double interpolation_error(fixture *f)
{
    double e = 0, phi[N];
    for (int k = 0; k < N; ++k) {
        tf_rpim_eval(&f->w, f->xyz + 3 * k, 1, phi, NULL);
        for (int i = 0; i < N; ++i) {
            e = fmax(e, fabs(phi[i] - (i == k)));
        }
    }
    return e;
}

static void flatter_basis_worse_condition(void **state)
{
    fixture *f = *state;
    double prev = 1;
    for (double shape = 0.5; shape < 600; shape *= 4) {
        tf_rpim p = {.shape = shape, .q = 1.03, .poly = 1};
        double rcond;
        assert_int_equal(tf_rpim_factor(&p, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond), 0);
        assert_true(rcond > 0 && rcond < prev);
        /* the estimate tracks the digits the shape functions lose */
        assert_true(interpolation_error(f) < 100 * DBL_EPSILON / rcond);
        prev = rcond;
    }
    assert_true(prev < 1e-10);
}

/* A flat multiquadric (alpha_c d_c = 32 mm over nodes 3 mm apart on
 * average, 11 times the support's scale) keeps its digits: the constant
 * and r^2 terms that dominate it are removed before the solve in the null
 * space of P^T.  Solving the full saddle-point system by LU instead lost
 * all but 2 digits here (5.6e-3), the null-space solve with the whole
 * kernel all but 4 (5.4e-4); measured when writing this. */
static void flat_basis_keeps_its_digits(void **state)
{
    fixture *f = *state;
    tf_rpim p = {.shape = 32.0, .q = 1.03, .poly = 1};
    double rcond;
    assert_int_equal(tf_rpim_factor(&p, &f->w, f->xyz, f->idx, N, centre, 3.0, &rcond), 0);
    double e = interpolation_error(f);
    print_message("flat multiquadric: reciprocal condition %.1e, interpolation error %.1e\n",
                  rcond, e);
    assert_true(e < 1e-6);
}

static void coplanar_nodes_are_singular_with_the_polynomial(void **state)
{
    fixture *f = *state;
    for (int i = 0; i < 4; ++i) {
        f->xyz[3 * i + 2] = 0; /* four nodes in z = 0 */
    }
    tf_rpim p = {.shape = 2.0, .q = 1.03, .poly = 1};
    double rcond;
    /* P has rank 3 for coplanar nodes: the augmented system is singular */
    assert_int_not_equal(tf_rpim_factor(&p, &f->w, f->xyz, f->idx, 4, centre, 3.0, &rcond), 0);
    p.poly = 0;
    assert_int_equal(tf_rpim_factor(&p, &f->w, f->xyz, f->idx, 4, centre, 3.0, &rcond), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(interpolates_at_the_nodes, setup, teardown),
        cmocka_unit_test_setup_teardown(the_polynomial_reproduces_linear_fields, setup, teardown),
        cmocka_unit_test_setup_teardown(derivatives_match_finite_differences, setup, teardown),
        cmocka_unit_test_setup_teardown(many_points_equal_one_at_a_time, setup, teardown),
        cmocka_unit_test_setup_teardown(flatter_basis_worse_condition, setup, teardown),
        cmocka_unit_test_setup_teardown(flat_basis_keeps_its_digits, setup, teardown),
        cmocka_unit_test_setup_teardown(coplanar_nodes_are_singular_with_the_polynomial, setup,
                                        teardown),
    };
    return cmocka_run_group_tests_name("rpim", tests, NULL, NULL);
}
