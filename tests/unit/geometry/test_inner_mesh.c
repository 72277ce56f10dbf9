/*
 * test_inner_mesh.c — material regions in the finite-element reference's
 * mesh: an ellipsoid's triangulated surface (geometry/ellipsoid_surface.h)
 * is closed, wound outward, on the ellipsoid and as fine as asked; a
 * second-order mesh of a sphere that conforms to it
 * (geometry/volume_mesh_tet10.h, an inner surface) gives every
 * tetrahedron the region it lies in, and the region's volume is the inner
 * surface's.
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
#include "geometry/ellipsoid_surface.h"
#include "geometry/surface_prepare.h"
#include "geometry/volume_mesh_tet10.h"
#include "geometry/winding.h"

/* gmsh's pools, as test_mesh.c says (only a failed mesh leaks them). */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:meshGRegionBoundaryRecovery\n"
           "leak:tetgenBR::tetgenmesh::recoverboundary\n"
           "leak:delaunayTriangulation\n";
}

static const double centre[3] = {1, -2, 3}, radii[3] = {6, 4, 3};

static double longest_edge(const tf_surface *s)
{
    double l = 0;
    for (size_t t = 0; t < s->nt; ++t) {
        for (int k = 0; k < 3; ++k) {
            const double *a = s->xyz + 3 * s->tri[3 * t + (size_t)k];
            const double *b = s->xyz + 3 * s->tri[3 * t + (size_t)(k + 1) % 3];
            l = fmax(l, sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                             (a[2] - b[2]) * (a[2] - b[2])));
        }
    }
    return l;
}

static void an_ellipsoid_surface_is_closed_outward_and_on_the_ellipsoid(void **state)
{
    (void)state;
    double exact = 4.0 / 3 * M_PI * radii[0] * radii[1] * radii[2], before = 0;
    for (double edge = 4; edge >= 0.5; edge /= 2) {
        tf_surface s;
        tf_geom_msg m = {0};
        assert_int_equal(tf_surface_ellipsoid(&s, centre, radii, edge), 0);
        assert_true(longest_edge(&s) <= edge);
        for (size_t v = 0; v < s.nv; ++v) {
            double q = 0;
            for (int a = 0; a < 3; ++a) {
                double t = (s.xyz[3 * v + (size_t)a] - centre[a]) / radii[a];
                q += t * t;
            }
            assert_close(q, 1, 1e-12);
        }
        assert_int_equal(tf_surface_clean(&s, &m), TF_GEOM_OK);
        assert_string_equal(m.notes, ""); /* closed, manifold and wound outward as made */
        /* a polyhedron inscribed in a convex body: below its volume, and
         * closer to it as the edges shrink */
        double v = tf_surface_volume(&s);
        assert_true(v > before && v < exact);
        assert_true(exact - v < 0.25 * edge * edge / radii[2] * exact);
        before = v;
        tf_surface_free(&s);
    }
}

static void an_ellipsoid_out_of_range_is_refused(void **state)
{
    (void)state;
    tf_surface s;
    const double flat[3] = {6, 0, 3}, huge[3] = {6, INFINITY, 3};
    assert_int_equal(tf_surface_ellipsoid(&s, centre, flat, 1), -1);
    assert_int_equal(tf_surface_ellipsoid(&s, centre, huge, 1), -1);
    assert_int_equal(tf_surface_ellipsoid(&s, centre, radii, 0), -1);
    assert_int_equal(tf_surface_ellipsoid(&s, centre, radii, 1e-3), -1); /* too many halvings */
    assert_null(s.xyz);
}

static double tet_volume(const tf_tet10_mesh *q, size_t e)
{
    const double *p[4];
    for (int k = 0; k < 4; ++k) {
        p[k] = q->xyz + 3 * q->tet[10 * e + (size_t)k];
    }
    double a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) {
        a[i] = p[1][i] - p[0][i];
        b[i] = p[2][i] - p[0][i];
        c[i] = p[3][i] - p[0][i];
    }
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
            a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
}

static void a_mesh_conforms_to_an_inner_surface(void **state)
{
    (void)state;
    tf_surface body, skin;
    tf_geom_msg m = {0};
    const double at[3] = {0, 0, 0};
    assert_int_equal(shape_sphere(&body, at, 15, 12, 24), 0);
    assert_int_equal(tf_surface_clean(&body, &m), TF_GEOM_OK);
    assert_int_equal(tf_surface_ellipsoid(&skin, centre, radii, 1.5), 0);
    tf_mesh_options o = {.spacing = 5};
    tf_mesh_inner in = {.surface = &skin, .centre = {1, -2, 3}, .radius = 6, .spacing = 1.5};
    tf_tet10_mesh q;
    int rc = tf_volume_mesh_tet10(&body, &o, &in, 1, 0, &q, &m);
    if (rc != TF_GEOM_OK) {
        print_error("%s\n", m.error);
    }
    assert_int_equal(rc, TF_GEOM_OK);
    double volume[2] = {0, 0};
    size_t count[2] = {0, 0};
    for (size_t e = 0; e < q.ntet; ++e) {
        assert_true(q.region[e] == 0 || q.region[e] == 1);
        double v = tet_volume(&q, e), g[3] = {0, 0, 0};
        assert_true(v > 0);
        volume[q.region[e]] += v;
        count[q.region[e]]++;
        for (int k = 0; k < 4; ++k) {
            for (int a = 0; a < 3; ++a) {
                g[a] += 0.25 * q.xyz[3 * q.tet[10 * e + (size_t)k] + (size_t)a];
            }
        }
        /* each tetrahedron lies on its region's side of the inner surface */
        assert_close(tf_winding_number(&skin, g), q.region[e], 1e-9);
    }
    assert_true(count[0] > 0 && count[1] > 0);
    assert_close(volume[1], tf_surface_volume(&skin), 1e-9 * tf_surface_volume(&skin));
    assert_close(volume[0] + volume[1], tf_surface_volume(&body), 1e-9 * tf_surface_volume(&body));
    /* the inner surface's vertices are mesh nodes: it is not remeshed */
    for (size_t v = 0; v < skin.nv; ++v) {
        int found = 0;
        for (size_t i = 0; i < q.nn && !found; ++i) {
            found = memcmp(q.xyz + 3 * i, skin.xyz + 3 * v, 3 * sizeof(double)) == 0;
        }
        assert_true(found);
    }
    tf_tet10_mesh_free(&q);
    tf_surface_free(&skin);
    tf_surface_free(&body);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(an_ellipsoid_surface_is_closed_outward_and_on_the_ellipsoid),
        cmocka_unit_test(an_ellipsoid_out_of_range_is_refused),
        cmocka_unit_test(a_mesh_conforms_to_an_inner_surface),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
