/*
 * test_surface_refine.c — a finer skin on the same polyhedron
 * (geometry/surface_refine.h): every edge at most the ratio times the size
 * asked for, the surface still closed and consistently wound, its volume
 * and area those of the file's, the file's vertices first and bit for bit,
 * every new vertex on its triangle's file triangle, and the smallest angle
 * at least half the file's (longest-edge bisection's bound).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "tests/geometry/shapes.h"
#include "geometry/surface_edges.h"
#include "geometry/surface_refine.h"

typedef struct graded {
    double at[3], near, far, ramp;
} graded;

/* near within 0 of `at`, rising linearly to far at ramp. */
static double size_graded(const double x[3], const void *arg)
{
    const graded *g = arg;
    double d = sqrt((x[0] - g->at[0]) * (x[0] - g->at[0]) + (x[1] - g->at[1]) * (x[1] - g->at[1]) +
                    (x[2] - g->at[2]) * (x[2] - g->at[2]));
    return d >= g->ramp ? g->far : g->near + d / g->ramp * (g->far - g->near);
}

static double size_constant(const double x[3], const void *arg)
{
    (void)x;
    return *(const double *)arg;
}

static double dist(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double smallest_angle(const tf_surface *s)
{
    double lo = M_PI;
    for (size_t t = 0; t < s->nt; ++t) {
        for (int k = 0; k < 3; ++k) {
            const double *p = s->xyz + 3 * s->tri[3 * t + (size_t)k];
            const double *q = s->xyz + 3 * s->tri[3 * t + (size_t)(k + 1) % 3];
            const double *r = s->xyz + 3 * s->tri[3 * t + (size_t)(k + 2) % 3];
            double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
            double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
            double c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (dist(q, p) * dist(r, p));
            lo = fmin(lo, acos(fmax(-1, fmin(1, c))));
        }
    }
    return lo;
}

/* The distance of x from the triangle abc's plane, and whether its
 * barycentric coordinates are all >= -tol. */
static int on_triangle(const double *a, const double *b, const double *c, const double *x,
                       double tol)
{
    double u[3], v[3], w[3], n[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = x[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    double off = fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / sqrt(nn);
    double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double wu = w[0] * u[0] + w[1] * u[1] + w[2] * u[2], wv = w[0] * v[0] + w[1] * v[1] + w[2] * v[2];
    double den = uu * vv - uv * uv, beta = (wu * vv - wv * uv) / den, gam = (wv * uu - wu * uv) / den;
    return off <= tol && beta >= -tol && gam >= -tol && beta + gam <= 1 + tol;
}

/* Everything the header promises, for a refinement of `file` into s. */
static void assert_same_polyhedron(const tf_surface *file, const tf_surface *s, tf_size_at size,
                                   const void *arg, double ratio)
{
    assert_true(s->nv > file->nv);
    assert_memory_equal(s->xyz, file->xyz, 3 * file->nv * sizeof *s->xyz);
    for (size_t i = 0; i < s->nv; ++i) {
        assert_int_equal(s->source[i], i < file->nv ? file->source[i] : -1);
    }
    tf_edge_report r;
    assert_int_equal(tf_surface_edges(s, &r), 0);
    assert_int_equal(r.open.count + r.nonmanifold.count + r.flipped.count, 0);
    assert_true(fabs(tf_surface_volume(s) - tf_surface_volume(file)) <=
                1e-12 * tf_surface_volume(file));
    assert_true(fabs(tf_surface_area(s) - tf_surface_area(file)) <= 1e-12 * tf_surface_area(file));
    assert_non_null(s->tri_parent);
    for (size_t t = 0; t < s->nt; ++t) {
        const size_t *f = file->tri + 3 * s->tri_parent[t];
        const double *a = file->xyz + 3 * f[0], *b = file->xyz + 3 * f[1], *c = file->xyz + 3 * f[2];
        for (int k = 0; k < 3; ++k) {
            const double *x = s->xyz + 3 * s->tri[3 * t + (size_t)k];
            double mid[3];
            const double *y = s->xyz + 3 * s->tri[3 * t + (size_t)(k + 1) % 3];
            assert_true(on_triangle(a, b, c, x, 1e-12));
            for (int q = 0; q < 3; ++q) {
                mid[q] = 0.5 * (x[q] + y[q]);
            }
            assert_true(dist(x, y) <= ratio * size(mid, arg) * (1 + 1e-12));
        }
    }
    assert_true(smallest_angle(s) >= 0.5 * smallest_angle(file) - 1e-12);
}

static void a_cube_refines_to_its_size(void **state)
{
    (void)state;
    tf_surface file, s;
    tf_geom_msg m = {{0}, {0}};
    double h = 2.5;
    assert_int_equal(shape_cube(&file, 10, 20), 0);
    assert_int_equal(shape_cube(&s, 10, 20), 0);
    assert_int_equal(tf_surface_refine(&s, size_constant, &h, sqrt(2), 100000, &m), TF_GEOM_OK);
    assert_same_polyhedron(&file, &s, size_constant, &h, sqrt(2));
    /* about 6 * 20^2 / (h^2 sqrt(3) / 4 ... 2 h^2 / 2) triangles: 2,400 +- a factor 2 */
    assert_in_range(s.nt, 600, 10000);
    tf_surface_free(&file);
    tf_surface_free(&s);
}

static void a_graded_size_refines_near_its_point_only(void **state)
{
    (void)state;
    double c[3] = {0, 0, 0};
    graded g = {{0, 0, 40}, 1.0, 20.0, 30.0};
    tf_surface file, s;
    tf_geom_msg m = {{0}, {0}};
    assert_int_equal(shape_sphere(&file, c, 40, 12, 24), 0);
    assert_int_equal(shape_sphere(&s, c, 40, 12, 24), 0);
    assert_int_equal(tf_surface_refine(&s, size_graded, &g, sqrt(2), 1000000, &m), TF_GEOM_OK);
    assert_same_polyhedron(&file, &s, size_graded, &g, sqrt(2));
    size_t near = 0, far = 0;
    for (size_t i = file.nv; i < s.nv; ++i) {
        double d = dist(s.xyz + 3 * i, g.at);
        near += d < 10;
        far += d > 60;
    }
    /* the file has 1 vertex within 10 mm of the pole (the next ring is at
     * 10.4 mm); the 314 mm^2 there at sizes of 1-7 mm take tens more (72) */
    assert_true(near > 40);
    assert_int_equal(far, 0); /* the sphere's own edges (about 10 mm) are short enough there */
    tf_surface_free(&file);
    tf_surface_free(&s);
}

static void a_refined_skin_refines_again_keeping_its_parents(void **state)
{
    (void)state;
    tf_surface file, s;
    tf_geom_msg m = {{0}, {0}};
    double h1 = 8, h2 = 3;
    assert_int_equal(shape_cube(&file, 0, 20), 0);
    assert_int_equal(shape_cube(&s, 0, 20), 0);
    assert_int_equal(tf_surface_refine(&s, size_constant, &h1, sqrt(2), 100000, &m), TF_GEOM_OK);
    assert_int_equal(tf_surface_refine(&s, size_constant, &h2, sqrt(2), 100000, &m), TF_GEOM_OK);
    assert_same_polyhedron(&file, &s, size_constant, &h2, sqrt(2));
    tf_surface_free(&file);
    tf_surface_free(&s);
}

static void too_many_vertices_are_refused_and_leave_the_surface(void **state)
{
    (void)state;
    tf_surface s;
    tf_geom_msg m = {{0}, {0}};
    double h = 0.01;
    assert_int_equal(shape_cube(&s, 0, 20), 0);
    assert_int_equal(tf_surface_refine(&s, size_constant, &h, sqrt(2), 5000, &m),
                     TF_GEOM_BAD_INPUT);
    assert_non_null(strstr(m.error, "more than 5000 vertices"));
    assert_int_equal(s.nv, 8);
    assert_int_equal(s.nt, 12);
    assert_null(s.tri_parent);
    tf_surface_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_cube_refines_to_its_size),
        cmocka_unit_test(a_graded_size_refines_near_its_point_only),
        cmocka_unit_test(a_refined_skin_refines_again_keeping_its_parents),
        cmocka_unit_test(too_many_vertices_are_refused_and_leave_the_surface),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
