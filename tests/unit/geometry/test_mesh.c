/*
 * test_mesh.c — a generated sphere filled with tetrahedra by gmsh
 * (geometry/volume_mesh.h): the cells' volume is the enclosed volume, no
 * node is outside (winding numbers), the surface vertices are the first
 * nodes unchanged, the same input gives the same bits, grading adds nodes
 * near its point, and the checks that guard all this do fail on a broken
 * mesh.
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
#include "assert_close.h"
#include "geometry/simplex_rules.h"
#include "geometry/surface_prepare.h"
#include "geometry/tetmesh_check.h"
#include "geometry/volume_mesh.h"
#include "geometry/winding.h"

/* gmsh 4.8 leaks tetgen's memory pools and the Delaunay mesh when boundary
 * recovery fails (its exception skips their release; a successful mesh
 * leaks nothing); a_mesher_failure_says_what_gmsh_said takes that path on
 * purpose.  LeakSanitizer reads this hook; any other leak is still
 * reported.  (gmsh's frames have no frame pointers, so a stack shows one
 * gmsh function: each is named.) */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:meshGRegionBoundaryRecovery\n"
           "leak:tetgenBR::tetgenmesh::recoverboundary\n"
           "leak:delaunayTriangulation\n";
}

static const double centre[3] = {5, -3, 2};
#define RADIUS 20.0

static void sphere(tf_surface *s)
{
    tf_geom_msg m = {0};
    assert_int_equal(shape_sphere(s, centre, RADIUS, 12, 24), 0);
    assert_int_equal(tf_surface_clean(s, &m), TF_GEOM_OK);
    assert_string_equal(m.notes, ""); /* generated outward and closed */
    assert_int_equal(tf_surface_check_placed(s, &m), TF_GEOM_OK);
}

static tf_mesh_options spacing(double h)
{
    tf_mesh_options o = {.spacing = h};
    return o;
}

static void mesh(const tf_surface *s, const tf_mesh_options *o, tf_tetmesh *t)
{
    tf_geom_msg m = {0};
    int rc = tf_volume_mesh(s, o, t, &m);
    if (rc != TF_GEOM_OK) {
        print_error("%s\n", m.error);
    }
    assert_int_equal(rc, TF_GEOM_OK);
}

/* The test sphere and its mesh at spacing h. */
static void sphere_mesh(double h, tf_surface *s, tf_tetmesh *t)
{
    sphere(s);
    tf_mesh_options o = spacing(h);
    mesh(s, &o, t);
}

static void cells_fill_the_sphere_and_every_node_is_inside(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh t;
    sphere_mesh(5, &s, &t);
    assert_int_equal(t.nsurf, s.nv);
    assert_true(t.nn > t.nsurf + 50); /* there are interior nodes */
    assert_close(t.enclosed_volume, tf_surface_volume(&s), 0);
    /* acceptance: within 1 %; in fact to rounding, since the boundary is the surface */
    assert_close(t.cells_volume, t.enclosed_volume, 1e-12 * t.enclosed_volume);
    double sum = 0;
    for (size_t e = 0; e < t.ntet; ++e) {
        assert_true(t.tet_volume[e] > 0);
        sum += t.tet_volume[e];
    }
    assert_close(sum, t.cells_volume, 0);
    tf_inside_report in;
    tf_tetmesh_inside(&t, &s, &in);
    assert_int_equal(in.tested, t.nn - t.nsurf);
    assert_int_equal(in.outside, 0);
    assert_true(in.min_winding > 0.5);
    for (size_t i = 0; i < t.nn; ++i) {
        const double *x = t.xyz + 3 * i;
        double r = sqrt(pow(x[0] - centre[0], 2) + pow(x[1] - centre[1], 2) +
                        pow(x[2] - centre[2], 2));
        assert_true(r <= RADIUS * (1 + 1e-12));
        if (i < t.nsurf) { /* the renderer's vertices, bit for bit */
            assert_int_equal(t.source[i], s.source[i]);
            assert_true(memcmp(x, s.xyz + 3 * i, 3 * sizeof *x) == 0);
        } else {
            assert_int_equal(t.source[i], -1);
        }
    }
    assert_int_equal(t.ntri, s.nt);
    assert_true(memcmp(t.tri, s.tri, 3 * s.nt * sizeof *t.tri) == 0);
    tf_tetmesh_free(&t);
    tf_surface_free(&s);
}

/* div F = x^2 + y z for F = (x^3 / 3, 0, y z^2 / 2): the volume integral
 * by the degree-2 tetrahedron rule over the cells equals the flux of F
 * through the surface by the degree-5 triangle rule (exact for F, cubic). */
static void cell_quadrature_matches_the_divergence_theorem(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh t;
    sphere_mesh(6, &s, &t);
    tf_simplex_rule tet, tri;
    tf_tet_rule(2, &tet);
    tf_tri_rule(3, &tri);
    double volume = 0, flux = 0, x[TF_SIMPLEX_MAX_POINTS][3], w[TF_SIMPLEX_MAX_POINTS];
    for (size_t e = 0; e < t.ntet; ++e) {
        double c[4][3];
        for (int k = 0; k < 4; ++k) {
            memcpy(c[k], t.xyz + 3 * t.tet[4 * e + k], sizeof c[k]);
        }
        tf_tet_points(&tet, c, x, w);
        for (unsigned q = 0; q < tet.n; ++q) {
            volume += w[q] * (x[q][0] * x[q][0] + x[q][1] * x[q][2]);
        }
    }
    for (size_t f = 0; f < t.ntri; ++f) {
        double c[3][3], u[3], v[3], n[3];
        for (int k = 0; k < 3; ++k) {
            memcpy(c[k], t.xyz + 3 * t.tri[3 * f + k], sizeof c[k]);
        }
        for (int a = 0; a < 3; ++a) {
            u[a] = c[1][a] - c[0][a];
            v[a] = c[2][a] - c[0][a];
        }
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        tf_tri_points(&tri, c, x, w);
        for (unsigned q = 0; q < tri.n; ++q) {
            double fx = x[q][0] * x[q][0] * x[q][0] / 3, fz = x[q][1] * x[q][2] * x[q][2] / 2;
            flux += w[q] * (fx * n[0] + fz * n[2]) / len;
        }
    }
    assert_true(fabs(volume) > 1e5);
    assert_close(volume, flux, 1e-10 * fabs(volume));
    tf_tetmesh_free(&t);
    tf_surface_free(&s);
}

static void the_same_input_gives_the_same_bits(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh a, b;
    sphere(&s);
    tf_mesh_options o = spacing(4);
    mesh(&s, &o, &a);
    mesh(&s, &o, &b);
    assert_int_equal(a.nn, b.nn);
    assert_int_equal(a.ntet, b.ntet);
    assert_true(memcmp(a.xyz, b.xyz, 3 * a.nn * sizeof *a.xyz) == 0);
    assert_true(memcmp(a.tet, b.tet, 4 * a.ntet * sizeof *a.tet) == 0);
    tf_tetmesh_free(&a);
    tf_tetmesh_free(&b);
    tf_surface_free(&s);
}

static size_t interior_within(const tf_tetmesh *t, const double p[3], double r)
{
    size_t n = 0;
    for (size_t i = t->nsurf; i < t->nn; ++i) {
        const double *x = t->xyz + 3 * i;
        n += pow(x[0] - p[0], 2) + pow(x[1] - p[1], 2) + pow(x[2] - p[2], 2) < r * r;
    }
    return n;
}

static void grading_adds_nodes_near_its_point_only(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh u, g;
    sphere(&s);
    tf_mesh_options o = spacing(6);
    mesh(&s, &o, &u);
    const double far[3] = {centre[0], centre[1], centre[2] + RADIUS};
    o.graded = 1;
    o.grade_at[0] = centre[0];
    o.grade_at[1] = centre[1];
    o.grade_at[2] = centre[2] - RADIUS; /* the south pole */
    o.grade_spacing = 1.5;
    o.grade_radius = 4;
    o.grade_ramp = 12;
    mesh(&s, &o, &g);
    size_t near_u = interior_within(&u, o.grade_at, 8), near_g = interior_within(&g, o.grade_at, 8);
    assert_true(near_g > 4 * near_u + 20);
    size_t far_u = interior_within(&u, far, 8), far_g = interior_within(&g, far, 8);
    assert_true(far_g <= far_u + far_u / 2 + 2);
    assert_close(g.cells_volume, g.enclosed_volume, 1e-12 * g.enclosed_volume);
    tf_tetmesh_free(&u);
    tf_tetmesh_free(&g);
    tf_surface_free(&s);
}

static void bad_options_are_refused(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh t;
    tf_geom_msg m;
    sphere(&s);
    tf_mesh_options o = spacing(0);
    assert_int_equal(tf_volume_mesh(&s, &o, &t, &m), TF_GEOM_BAD_INPUT);
    assert_string_equal(m.error, "spacing 0: must be a positive number of mm");
    o = spacing(0.05);
    assert_int_equal(tf_volume_mesh(&s, &o, &t, &m), TF_GEOM_BAD_INPUT);
    assert_non_null(strstr(m.error, "tetrahedra (at most 2e+07): use a larger spacing"));
    o = spacing(5);
    o.graded = 1;
    o.grade_spacing = 6; /* coarser than the spacing */
    o.grade_ramp = 10;
    assert_int_equal(tf_volume_mesh(&s, &o, &t, &m), TF_GEOM_BAD_INPUT);
    assert_non_null(strstr(m.error, "grading: need"));
    tf_surface_free(&s);
}

/* A surface that crosses itself, given to the mesher without the checks:
 * gmsh refuses and its reason comes through. */
static void a_mesher_failure_says_what_gmsh_said(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh t;
    tf_geom_msg m;
    shape_cube(&s, 10, 20);
    s.xyz[3 * 6] = 22, s.xyz[3 * 6 + 1] = 22, s.xyz[3 * 6 + 2] = 5;
    tf_mesh_options o = spacing(5);
    assert_int_equal(tf_volume_mesh(&s, &o, &t, &m), TF_GEOM_FAILED);
    assert_non_null(strstr(m.error, "gmsh could not mesh the volume: "));
    assert_null(strstr(m.error, "without a message"));
    assert_null(t.xyz);
    tf_surface_free(&s);
}

/* The topology check and the inside test do fail: a missing cell, a
 * flipped cell, a moved surface vertex, a node pushed outside. */
static void the_checks_catch_a_broken_mesh(void **state)
{
    (void)state;
    tf_surface s;
    tf_tetmesh t;
    tf_tetmesh_faults f;
    tf_geom_msg m;
    sphere_mesh(6, &s, &t);
    assert_int_equal(tf_tetmesh_topology(&t, &s, &f), 0);
    assert_int_equal(f.nonpositive + f.moved + f.unused + f.extra + f.missing + f.bad_faces, 0);

    t.ntet--; /* a hole: faces of its neighbours become boundary faces */
    assert_int_equal(tf_tetmesh_check_topology(&t, &s, &m), TF_GEOM_FAILED);
    tf_tetmesh_topology(&t, &s, &f);
    assert_true(f.extra + f.missing >= 4);
    t.ntet++;

    size_t v = t.tet[1];
    t.tet[1] = t.tet[2], t.tet[2] = v;
    tf_tetmesh_volumes(&t);
    tf_tetmesh_topology(&t, &s, &f);
    assert_int_equal(f.nonpositive, 1);
    assert_true(f.bad_faces >= 3);
    t.tet[2] = t.tet[1], t.tet[1] = v;
    tf_tetmesh_volumes(&t);

    t.xyz[0] += 1e-9;
    tf_tetmesh_topology(&t, &s, &f);
    assert_int_equal(f.moved, 1);
    t.xyz[0] -= 1e-9;

    double *x = t.xyz + 3 * (t.nn - 1);
    x[0] = centre[0] + 2 * RADIUS;
    tf_inside_report in;
    tf_tetmesh_inside(&t, &s, &in);
    assert_int_equal(in.outside, 1);
    assert_int_equal(in.worst, t.nn - 1);
    assert_true(fabs(in.min_winding) < 1e-9);
    tf_tetmesh_free(&t);
    tf_surface_free(&s);
}

static void winding_numbers_of_a_cube(void **state)
{
    (void)state;
    tf_surface s;
    shape_cube(&s, 10, 20);
    const double in[3] = {12, 29, 20}, out[3] = {31, 20, 20}, far[3] = {-100, 5, 300};
    const double face[3] = {20, 20, 10};
    assert_close(tf_winding_number(&s, in), 1, 1e-12);
    assert_close(tf_winding_number(&s, out), 0, 1e-12);
    assert_close(tf_winding_number(&s, far), 0, 1e-12);
    assert_close(tf_winding_number(&s, face), 0.5, 1e-12);
    tf_surface_reverse(&s);
    assert_close(tf_winding_number(&s, in), -1, 1e-12);
    tf_surface_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cells_fill_the_sphere_and_every_node_is_inside),
        cmocka_unit_test(cell_quadrature_matches_the_divergence_theorem),
        cmocka_unit_test(the_same_input_gives_the_same_bits),
        cmocka_unit_test(grading_adds_nodes_near_its_point_only),
        cmocka_unit_test(bad_options_are_refused),
        cmocka_unit_test(a_mesher_failure_says_what_gmsh_said),
        cmocka_unit_test(the_checks_catch_a_broken_mesh),
        cmocka_unit_test(winding_numbers_of_a_cube),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
