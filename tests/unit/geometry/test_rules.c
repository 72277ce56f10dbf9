/*
 * test_rules.c — Gauss rules on tetrahedra and triangles
 * (geometry/simplex_rules.h): each integrates every monomial of its degree
 * exactly on a skewed simplex, and some monomial of the next degree not.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "assert_close.h"
#include "geometry/simplex_rules.h"

static double factorial(unsigned n)
{
    double f = 1;
    for (unsigned k = 2; k <= n; ++k) {
        f *= k;
    }
    return f;
}

/* A skewed tetrahedron: the reference one (0, e1, e2, e3) under x = A xi + b. */
static const double A[3][3] = {{2.0, 0.3, -0.4}, {0.5, 1.5, 0.2}, {-0.1, 0.6, 1.2}};
static const double b[3] = {1.0, -2.0, 0.5};

static void map(const double xi[3], double x[3])
{
    for (int i = 0; i < 3; ++i) {
        x[i] = b[i] + A[i][0] * xi[0] + A[i][1] * xi[1] + A[i][2] * xi[2];
    }
}

static double det_a(void)
{
    return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
           A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

/* Largest relative error of the rule over the monomials xi^p eta^q zeta^r
 * of total degree d, integrated on the mapped tetrahedron (pulled back to
 * the reference one, where the integral is p! q! r! / (d + 3)!). */
static double tet_error(const tf_simplex_rule *r, unsigned d)
{
    double c[4][3], ref[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 4; ++k) {
        map(ref[k], c[k]);
    }
    double x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS], worst = 0;
    tf_tet_points(r, c, x, w);
    for (unsigned p = 0; p <= d; ++p) {
        for (unsigned q = 0; p + q <= d; ++q) {
            unsigned s = d - p - q;
            double sum = 0;
            for (unsigned k = 0; k < r->n; ++k) {
                /* the reference coordinates of point k are its barycentrics 1..3 */
                const double *xi = r->bary[k] + 1;
                sum += w[k] * pow(xi[0], p) * pow(xi[1], q) * pow(xi[2], s);
            }
            double exact = fabs(det_a()) * factorial(p) * factorial(q) * factorial(s) /
                           factorial(d + 3);
            worst = fmax(worst, fabs(sum - exact) / exact);
        }
    }
    return worst;
}

static double tri_error(const tf_simplex_rule *r, unsigned d)
{
    /* reference triangle (0, e1, e2) mapped into 3-D */
    double c[3][3], ref[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int k = 0; k < 3; ++k) {
        map(ref[k], c[k]);
    }
    double u[3] = {A[0][0], A[1][0], A[2][0]}, v[3] = {A[0][1], A[1][1], A[2][1]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                   u[0] * v[1] - u[1] * v[0]};
    double jac = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS], worst = 0;
    tf_tri_points(r, c, x, w);
    for (unsigned p = 0; p <= d; ++p) {
        unsigned q = d - p;
        double sum = 0;
        for (unsigned k = 0; k < r->n; ++k) {
            sum += w[k] * pow(r->bary[k][1], p) * pow(r->bary[k][2], q);
        }
        double exact = jac * factorial(p) * factorial(q) / factorial(d + 2);
        worst = fmax(worst, fabs(sum - exact) / exact);
    }
    return worst;
}

static void check_rule(const tf_simplex_rule *r, int corners)
{
    double sum = 0;
    for (unsigned k = 0; k < r->n; ++k) {
        double bsum = 0;
        assert_true(r->w[k] > 0);
        for (int c = 0; c < corners; ++c) {
            assert_true(r->bary[k][c] > 0 && r->bary[k][c] < 1); /* strictly inside */
            bsum += r->bary[k][c];
        }
        assert_close(bsum, 1, 1e-15);
        sum += r->w[k];
    }
    assert_close(sum, 1, 1e-15);
}

typedef int (*rule_fn)(unsigned, tf_simplex_rule *);
typedef double (*error_fn)(const tf_simplex_rule *, unsigned);

/* Every degree 1 .. max gives a rule of the expected size and degree,
 * exact to that degree and not the next; other degrees are refused. */
static void check_family(rule_fn rule, error_fn error, int corners, const unsigned points[6])
{
    static const unsigned degree[6] = {0, 1, 2, 5, 5, 5};
    for (unsigned d = 1; d <= TF_SIMPLEX_MAX_DEGREE; ++d) {
        tf_simplex_rule r;
        assert_int_equal(rule(d, &r), 0);
        assert_int_equal(r.n, points[d]);
        assert_int_equal(r.degree, degree[d]);
        check_rule(&r, corners);
        for (unsigned e = 0; e <= r.degree; ++e) {
            assert_true(error(&r, e) < 1e-14);
        }
        assert_true(error(&r, r.degree + 1) > 1e-3); /* and no further */
    }
    tf_simplex_rule r;
    assert_int_equal(rule(0, &r), -1);
    assert_int_equal(rule(TF_SIMPLEX_MAX_DEGREE + 1, &r), -1);
}

static void tet_rules_are_exact_to_their_degree(void **state)
{
    (void)state;
    static const unsigned points[6] = {0, 1, 4, 15, 15, 15};
    check_family(tf_tet_rule, tet_error, 4, points);
}

static void triangle_rules_are_exact_to_their_degree(void **state)
{
    (void)state;
    static const unsigned points[6] = {0, 1, 3, 7, 7, 7};
    check_family(tf_tri_rule, tri_error, 3, points);
}

/* The mapped points are where the barycentric coordinates say. */
static void points_map_affinely(void **state)
{
    (void)state;
    tf_simplex_rule r;
    tf_tet_rule(5, &r);
    double c[4][3], ref[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 4; ++k) {
        map(ref[k], c[k]);
    }
    double x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS];
    tf_tet_points(&r, c, x, w);
    for (unsigned k = 0; k < r.n; ++k) {
        double y[3];
        map(r.bary[k] + 1, y);
        for (int a = 0; a < 3; ++a) {
            assert_close(x[k][a], y[a], 1e-14);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tet_rules_are_exact_to_their_degree),
        cmocka_unit_test(triangle_rules_are_exact_to_their_degree),
        cmocka_unit_test(points_map_affinely),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
