/*
 * test_regions.c — contact regions in scenes: a region on a box face and on
 * an organ is read into its chart and probe (the frame, the domain, the
 * patch at the centre, friction and spacing, --set), and each bad region
 * gets one message naming file, line and field.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "problem/region_chart.h"
#include "scene/scene.h"
#include "scene_refused.h"
#include "tests/geometry/shapes.h"

/* tf_test_scene (a 10 x 10 x 2 box, 5 x 5 x 2 nodes) with line 11, its
 * contact, replaced. */
static tf_scene *box_with(const char *contact, const char *const *sets, size_t n)
{
    char text[4096];
    tf_ctx ec;
    tf_ctx_init(&ec);
    const char *line11 = strstr(tf_test_scene, "  - node: 13\n");
    int len = snprintf(text, sizeof text, "%.*s%s%s", (int)(line11 - tf_test_scene),
                       tf_test_scene, contact, line11 + strlen("  - node: 13\n"));
    tf_scene *s = tf_scene_load_text(&ec, text, (size_t)len, "t.yaml", sets, n);
    if (s == NULL) {
        fail_msg("%s", ec.err);
    }
    return s;
}

static double points_area(const tf_patch *p)
{
    double a = 0;
    for (size_t k = 0; k < p->n_pts; ++k) {
        a += p->pts[4 * k + 3];
    }
    return a;
}

static void a_face_region_is_read_into_its_chart(void **state)
{
    (void)state;
    tf_scene *s = box_with("  - name: top\n    region: {face: z+, rect: [2, 8, 3, 7]}\n"
                           "    tip: {radius: 1}\n",
                           NULL, 0);
    const tf_contact *c = &s->problem.contacts[0];
    const tf_contact_region *r = &c->region;
    assert_int_equal(r->kind, TF_CONTACT_REGION_FACE);
    assert_int_equal(r->tip, TF_TIP_DISC);
    assert_true(r->tip_radius == 1 && r->friction == 0.3 && r->spacing == 0);
    const tf_region_chart *ch = &r->chart;
    const double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, o[3] = {2, 3, 2};
    for (int k = 0; k < 9; ++k) {
        assert_true(ch->R[k] == R[k]);
    }
    for (int k = 0; k < 3; ++k) {
        assert_true(ch->o[k] == o[k]);
    }
    assert_true(ch->len[0] == 6 && ch->len[1] == 4 && ch->flat);
    /* the probe at the domain's centre: the contact point and its patch, a
     * 128-gon inscribed in the tip's disc (area (128/2) sin(2 pi/128) r^2) */
    assert_true(fabs(c->at[0] - 5) < 1e-12 && fabs(c->at[1] - 5) < 1e-12 && c->at[2] == 2);
    assert_int_equal(c->patch.shape, TF_PATCH_POINTS);
    double gon = 64 * sin(2 * M_PI / 128);
    assert_true(fabs(points_area(&c->patch) - gon) < 1e-12 * gon);
    assert_true(fabs(c->patch.area - gon) < 1e-12 * gon);
    for (size_t k = 0; k < c->patch.n_pts; ++k) { /* every point on the face, in the disc */
        const double *x = c->patch.pts + 4 * k;
        assert_true(x[2] == 2);
        assert_true((x[0] - 5) * (x[0] - 5) + (x[1] - 5) * (x[1] - 5) <= 1 + 1e-12);
        assert_true(x[3] > 0);
    }
    tf_scene_free(s);
}

/* On z- the chart's n is -z, e1 = +x and e2 = n x e1 = -y: b runs down y
 * from the rectangle's far edge. */
static void a_lower_face_turns_the_chart(void **state)
{
    (void)state;
    tf_scene *s = box_with("  - region: {face: z-, rect: [2, 8, 3, 7]}\n"
                           "    tip: {shape: rect, size: [2, 1]}\n"
                           "    friction: 0\n    spacing: 1\n",
                           NULL, 0);
    const tf_contact_region *r = &s->problem.contacts[0].region;
    const double R[9] = {1, 0, 0, 0, -1, 0, 0, 0, -1}, o[3] = {2, 7, 0};
    for (int k = 0; k < 9; ++k) {
        assert_true(r->chart.R[k] == R[k]);
    }
    for (int k = 0; k < 3; ++k) {
        assert_true(r->chart.o[k] == o[k]);
    }
    assert_true(r->friction == 0 && r->spacing == 1 && r->tip == TF_TIP_RECT);
    double q[3] = {1, 1, 0}, x[3], back[3];
    tf_region_chart_point(&r->chart, q, x);
    assert_true(x[0] == 3 && x[1] == 6 && x[2] == 0);
    tf_region_chart_coords(&r->chart, x, back);
    assert_true(back[0] == 1 && back[1] == 1 && back[2] == 0);
    /* a rectangle tip: area 2 exactly, split at the grid lines (x = 2.5, 5, ...) */
    tf_patch p;
    tf_ctx ec;
    tf_ctx_init(&ec);
    assert_int_equal(tf_region_site_patch(&ec, &s->problem, r, 1, 1, &p, x), 0);
    assert_true(fabs(p.area - 2) < 1e-12);
    for (size_t k = 0; k < p.n_pts; ++k) {
        const double *y = p.pts + 4 * k;
        assert_true(y[0] >= 2 && y[0] <= 4 && y[1] >= 5.5 && y[1] <= 6.5 && y[2] == 0);
    }
    tf_patch_release(&p);
    tf_scene_free(s);
}

/* Without a tip the region takes the patch of the scene's point contact;
 * --set reaches every region key. */
static void defaults_and_overrides(void **state)
{
    (void)state;
    const char *two = "  - patch: {face: z+, centre: [5, 5], size: [2, 3]}\n"
                      "  - name: palpate\n    region: {face: z+, rect: [2, 8, 3, 7]}\n";
    tf_scene *s = box_with(two, NULL, 0);
    const tf_contact_region *r = &s->problem.contacts[1].region;
    assert_int_equal(r->tip, TF_TIP_RECT);
    assert_true(r->tip_size[0] == 2 && r->tip_size[1] == 3);
    tf_scene_free(s);
    const char *sets[] = {"contact.1.friction=0.7", "contact.1.spacing=1.5",
                          "contact.1.region.rect=1.5,8.5,2,8", "contact.1.tip={radius: 0.5}"};
    s = box_with(two, sets, 4);
    r = &s->problem.contacts[1].region;
    assert_true(r->friction == 0.7 && r->spacing == 1.5);
    assert_true(r->tip == TF_TIP_DISC && r->tip_radius == 0.5);
    assert_true(r->chart.len[0] == 7 && r->chart.len[1] == 6 && r->chart.o[0] == 1.5);
    tf_scene_free(s);
}

static void expect(const char *contact, const char *const *fragments)
{
    char text[4096];
    const char *line11 = strstr(tf_test_scene, "  - node: 13\n");
    int len = snprintf(text, sizeof text, "%.*s%s%s", (int)(line11 - tf_test_scene),
                       tf_test_scene, contact, line11 + strlen("  - node: 13\n"));
    tf_test_refused_text(text, (size_t)len, fragments);
}

static void each_bad_region_has_its_own_message(void **state)
{
    (void)state;
    expect("  - node: 13\n    region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0", "replaces node", NULL});
    expect("  - node: 13\n    friction: 0.2\n",
           (const char *[]){"t.yaml:11:", "contact.0", "belong to a region", NULL});
    expect("  - region: {face: z+, rect: [2, 11, 2, 8]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region", "inside the face", NULL});
    expect("  - region: {face: z+, rect: [8, 2, 2, 8]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region", "a0 < a1", NULL});
    expect("  - region: {face: z+, rect: [0.5, 8, 2, 8]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region", "tip reaches", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {radius: 1}\n"
           "    friction: -0.1\n",
           (const char *[]){"t.yaml:13:", "contact.0.friction", ">= 0", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {radius: 1}\n"
           "    spacing: 2.5\n",
           (const char *[]){"t.yaml:11:", "contact.0.spacing", "third", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {radius: 0}\n",
           (const char *[]){"t.yaml:12:", "contact.0.tip.radius", "positive", NULL});
    expect("  - region: {centre: [5, 5, 2], radius: 3}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region", "on a box", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {shape: rect, radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.tip", "rect tip takes size", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n    tip: {shape: oval, radius: 1}\n",
           (const char *[]){"t.yaml:12:", "contact.0.tip.shape", "disc", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2, 8]}\n",
           (const char *[]){"t.yaml:11:", "contact.0", "tip", NULL});
    expect("  - region: {face: q+, rect: [2, 8, 2, 8]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region.face", NULL});
    expect("  - region: {face: z+, rect: [2, 8, 2]}\n    tip: {radius: 1}\n",
           (const char *[]){"t.yaml:11:", "contact.0.region.rect", NULL});
}

/* ---- organs: a sphere of radius 10 ----------------------------------------
 * (20 rings of 32 vertices: on 24 x 32, gmsh's tetgen leaks 640 bytes in
 * tetgenmesh::reconstructmesh, which check-sanitize's LeakSanitizer finds) */

static char dir[64], sphere_obj[128], scene_path[128];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/tf_region_XXXXXX");
    if (mkdtemp(dir) == NULL) {
        return -1;
    }
    snprintf(sphere_obj, sizeof sphere_obj, "%s/sphere.obj", dir);
    snprintf(scene_path, sizeof scene_path, "%s/t.yaml", dir);
    tf_surface s;
    const double c[3] = {0, 0, 0};
    if (shape_sphere(&s, c, 10, 20, 32) != 0 || shape_write_obj(&s, sphere_obj) != 0) {
        return -1;
    }
    tf_surface_free(&s);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    unlink(sphere_obj);
    unlink(scene_path);
    return rmdir(dir);
}

static const char *organ =
    "name: t\n"                                           /* 1 */
    "geometry:\n"                                         /* 2 */
    "  surface: {file: sphere.obj}\n"                     /* 3 */
    "  spacing: 4\n"                                      /* 4 */
    "material: {E: 0.01, nu: 0.3}\n"                      /* 5 */
    "fixed:\n"                                            /* 6 */
    "  - sphere: {centre: [0, 0, -10], radius: 6}\n"      /* 7 */
    "contact:\n"                                          /* 8 */
    "  - name: cap\n"                                     /* 9 */
    "    region: {centre: [0, 0, 12], radius: 3}\n"       /* 10 */
    "    tip: {radius: 1}\n"                              /* 11 */
    "outputs: {select: near-contact, radius: 8}\n";       /* 12 */

static tf_scene *load_organ(tf_ctx *ctx, const char *const *sets, size_t n)
{
    return tf_scene_load_text(ctx, organ, strlen(organ), scene_path, sets, n);
}

/* The cap's chart: n = +z by symmetry, e1 = x, o on the fitted plane, the
 * height field the sphere's, every line meeting it. */
static void an_organ_region_is_a_height_field(void **state)
{
    (void)state;
    tf_ctx ec;
    tf_ctx_init(&ec);
    tf_scene *s = load_organ(&ec, NULL, 0);
    if (s == NULL) {
        fail_msg("%s", ec.err);
    }
    const tf_contact *c = &s->problem.contacts[0];
    const tf_region_chart *ch = &c->region.chart;
    assert_int_equal(c->region.kind, TF_CONTACT_REGION_ORGAN);
    assert_true(ch->len[0] == 6 && ch->len[1] == 6 && !ch->flat);
    /* (the fitted plane settles to an angle below 1e-6) */
    assert_true(fabs(ch->R[8] - 1) < 1e-12 && fabs(ch->R[0] - 1) < 1e-12);
    assert_true(fabs(ch->o[0] + 3) < 1e-5 && fabs(ch->o[1] + 3) < 1e-5);
    /* h over the domain: within the facets' sag (r (1 - cos(pi / 32)), 0.05 mm)
     * of the sphere's, and the highest at the centre */
    double hc;
    assert_int_equal(tf_region_chart_height(ch, 3, 3, &hc), 0);
    for (int i = 0; i <= 6; ++i) {
        for (int j = 0; j <= 6; ++j) {
            double h, q[3] = {i, j, 0}, x[3];
            assert_int_equal(tf_region_chart_height(ch, i, j, &h), 0);
            q[2] = h;
            tf_region_chart_point(ch, q, x);
            double rho = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
            assert_true(rho <= 10 + 1e-9 && rho >= 10 - 0.1);
            assert_true(h <= hc + 1e-12);
        }
    }
    /* the probe's patch: the surface under the tip's disc; its area is the
     * sphere's over the projected disc (2 pi r (r - sqrt(r^2 - a^2)) for a
     * 1 mm disc at the pole: 3.1495) within the facets' and the 128-gon's */
    assert_int_equal(c->patch.shape, TF_PATCH_POINTS);
    assert_true(fabs(c->patch.area - 3.1495) < 0.01);
    tf_scene_free(s);
}

static void expect_organ(const char *const *sets, size_t n, const char *const *parts)
{
    tf_ctx ec;
    tf_ctx_init(&ec);
    tf_scene *s = load_organ(&ec, sets, n);
    if (s != NULL) {
        tf_scene_free(s);
        fail_msg("accepted: %s", sets[0]);
    }
    for (const char *const *f = parts; *f; ++f) {
        if (strstr(ec.err, *f) == NULL) {
            fail_msg("message '%s' lacks '%s'", ec.err, *f);
        }
    }
}

static void a_region_that_is_no_graph_is_refused(void **state)
{
    (void)state;
    /* wider than the sphere: lines beyond it meet nothing */
    expect_organ((const char *[]){"contact.0.region.radius=10"}, 1,
                 (const char *[]){"contact.0.region", "not a graph", "meets no surface", NULL});
    /* a strip out to 9.7 mm from the axis: there the surface leans 77 to 79
     * degrees from +z (the facets') */
    expect_organ((const char *[]){"contact.0.region={centre: [0, 0, 12], size: [19, 1.6]}",
                                  "contact.0.tip.radius=0.2"},
                 2,
                 (const char *[]){"contact.0.region", "not a graph", "more than 75", NULL});
    expect_organ((const char *[]){"contact.0.region={face: z+, rect: [0, 1, 0, 1]}"}, 1,
                 (const char *[]){"contact.0.region", "on an organ", NULL});
    expect_organ((const char *[]){"contact.0.tip={shape: rect, size: [1, 1]}"}, 1,
                 (const char *[]){"contact.0.tip", "on an organ the tip is a disc", NULL});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_face_region_is_read_into_its_chart),
        cmocka_unit_test(a_lower_face_turns_the_chart),
        cmocka_unit_test(defaults_and_overrides),
        cmocka_unit_test(each_bad_region_has_its_own_message),
        cmocka_unit_test_setup_teardown(an_organ_region_is_a_height_field, setup, teardown),
        cmocka_unit_test_setup_teardown(a_region_that_is_no_graph_is_refused, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
