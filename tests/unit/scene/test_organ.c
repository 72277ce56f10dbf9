/*
 * test_organ.c — organ scenes (geometry.surface) on generated surfaces: the
 * scene builds the mesh, regions, contact site and outputs it says; each bad
 * organ scene gets one message naming file, line and field; the Galerkin
 * solver on tetrahedral cells passes the patch test; a contact site's
 * nodal forces add up to the force.
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

#include "tests/geometry/shapes.h"
#include "materials/material.h"
#include "meshfree/shape.h"
#include "problem/mesh_geometry.h"
#include "scene/scene.h"
#include "solvers/load_vector.h"
#include "solvers/solver.h"

static char dir[64], sphere_obj[128], open_obj[128], scene_path[128];

/* A sphere of radius 10 about the origin and a sphere with a hole. */
static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/tf_organ_XXXXXX");
    if (mkdtemp(dir) == NULL) {
        return -1;
    }
    snprintf(sphere_obj, sizeof sphere_obj, "%s/sphere.obj", dir);
    snprintf(open_obj, sizeof open_obj, "%s/open.obj", dir);
    snprintf(scene_path, sizeof scene_path, "%s/t.yaml", dir);
    tf_surface s;
    const double c[3] = {0, 0, 0};
    if (shape_sphere(&s, c, 10, 10, 16) != 0 || shape_write_obj(&s, sphere_obj) != 0) {
        return -1;
    }
    s.nt -= 1; /* drop the last triangle: an open surface */
    int rc = shape_write_obj(&s, open_obj);
    tf_surface_free(&s);
    return rc;
}

static int teardown(void **state)
{
    (void)state;
    unlink(sphere_obj);
    unlink(open_obj);
    unlink(scene_path);
    return rmdir(dir);
}

/* The base organ scene; the file is `sphere.obj` beside the scene. */
static const char *base =
    "name: t\n"
    "geometry:\n"
    "  surface: {file: sphere.obj}\n"
    "  spacing: 4\n"
    "material: {E: 0.01, nu: 0.3}\n"
    "fixed:\n"
    "  - sphere: {centre: [0, 0, -10], radius: 6}\n"
    "contact:\n"
    "  - name: top\n"
    "    site: {point: [0, 0, 11], radius: 3}\n"
    "outputs: {select: near-contact, radius: 8}\n";

static tf_scene *load(tf_ctx *ctx, const char *text, const char *const *sets, size_t n_sets)
{
    return tf_scene_load_text(ctx, text, strlen(text), scene_path, sets, n_sets);
}

static void the_organ_scene_is_built_as_written(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = load(&ctx, base, NULL, 0);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_problem *p = &s->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    assert_non_null(m);
    assert_int_equal(p->cloud.n_surface, 2 + 9 * 16);
    assert_true(p->cloud.n > p->cloud.n_surface); /* interior nodes at 4 mm */
    assert_true(fabs(m->tm.cells_volume - m->tm.enclosed_volume) <= 1e-12 * m->tm.enclosed_volume);
    assert_true(m->min_winding > 0.5);
    /* the contact node is the north pole (vertex 0), nearest (0, 0, 11) */
    assert_int_equal(p->contacts[0].node, 0);
    const tf_patch *pt = &p->contacts[0].patch;
    assert_int_equal(pt->shape, TF_PATCH_SURFACE);
    /* the pole's fan of 16 triangles has its centroids 2.1 mm from the pole,
     * the next ring's 4.0 mm and more: radius 3 takes the fan only */
    assert_int_equal(pt->n_tri, 16);
    double area = 0;
    for (size_t t = 0; t < pt->n_tri; ++t) {
        const double *a = p->cloud.xyz + 3 * (size_t)pt->tri[3 * t];
        const double *b = p->cloud.xyz + 3 * (size_t)pt->tri[3 * t + 1];
        const double *c = p->cloud.xyz + 3 * (size_t)pt->tri[3 * t + 2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(n[2] > 0); /* outward */
    }
    assert_true(fabs(area - pt->area) <= 1e-12 * area);
    /* outputs: surface vertices within 8 mm of the pole, ascending */
    assert_true(p->outputs.n_nodes > 16);
    for (size_t k = 0; k < p->outputs.n_nodes; ++k) {
        const double *x = p->cloud.xyz + 3 * (size_t)p->outputs.nodes[k];
        assert_true(p->outputs.nodes[k] < p->cloud.n_surface);
        assert_true(x[0] * x[0] + x[1] * x[1] + (x[2] - 10) * (x[2] - 10) <= 64 + 1e-9);
        assert_true(k == 0 || p->outputs.nodes[k] > p->outputs.nodes[k - 1]);
    }
    /* fixed: every node (surface and interior) within 6 mm of the south pole */
    assert_true(p->fixed[0].n_nodes > 0);
    for (size_t k = 0; k < p->fixed[0].n_nodes; ++k) {
        const double *x = p->cloud.xyz + 3 * (size_t)p->fixed[0].nodes[k];
        assert_true(x[0] * x[0] + x[1] * x[1] + (x[2] + 10) * (x[2] + 10) <= 36 + 1e-9);
    }
    tf_scene_free(s);
}

/* The scene (with overrides) must be refused with a message holding parts. */
static void expect_refusal(const char *text, const char *const *sets, size_t n,
                           const char *const *parts)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = load(&ctx, text, sets, n);
    if (s != NULL) {
        tf_scene_free(s);
        fail_msg("accepted: %s", n > 0 ? sets[0] : text);
    }
    for (const char *const *p = parts; *p != NULL; ++p) {
        if (strstr(ctx.err, *p) == NULL) {
            fail_msg("message '%s' lacks '%s'", ctx.err, *p);
        }
    }
}

static void expect_error(const char *const *sets, size_t n, const char *const *parts)
{
    expect_refusal(base, sets, n, parts);
}

static void expect_text_error(const char *text, const char *const *parts)
{
    expect_refusal(text, NULL, 0, parts);
}

#define SETS(...) (const char *[]){__VA_ARGS__}, sizeof((const char *[]){__VA_ARGS__}) / sizeof(char *)
#define PARTS(...) (const char *[]){__VA_ARGS__, NULL}

static void each_bad_organ_scene_has_its_own_message(void **state)
{
    (void)state;
    expect_error(SETS("geometry.surface.file=nowhere.obj"),
                 PARTS("--set", "geometry.surface.file", "nowhere.obj"));
    expect_error(SETS("geometry.surface.file=open.obj"),
                 PARTS("geometry.surface.file", "open surface"));
    expect_error(SETS("geometry.surface.scale=0.01"),
                 PARTS("geometry.surface.scale", "absurd size"));
    expect_error(SETS("geometry.spacing=-1"), PARTS("geometry.spacing", "positive"));
    expect_error(SETS("geometry.surface.rotate={axis: [0, 0, 0], angle: 90}"),
                 PARTS("geometry.surface.rotate.axis", "non-zero axis"));
    expect_error(SETS("contact.0.site.radius=0.5"),
                 PARTS("contact.0.site", "no surface triangle", "raise the radius"));
    expect_error(SETS("fixed.0.sphere.centre=[0, 0, 50]"), PARTS("fixed.0", "holds no node"));
    expect_error(SETS("fixed.1.face=z-"), PARTS("fixed.1.face", "no box faces"));
    expect_error(SETS("fixed.1.vertices=[100000]"), PARTS("fixed.1.vertices", "vertex 100000"));
    expect_error(SETS("outputs={select: face, face: z+}"), PARTS("outputs", "no box faces"));
    /* the last node is an interior one (they follow the 146 surface vertices) */
    char interior[64];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = load(&ctx, base, NULL, 0);
    assert_non_null(s);
    assert_true(s->problem.cloud.n > s->problem.cloud.n_surface);
    snprintf(interior, sizeof interior, "outputs={select: nodes, nodes: [%zu]}", s->problem.cloud.n);
    tf_scene_free(s);
    expect_error(SETS(interior), PARTS("outputs", "not a vertex of the mesh file"));
    expect_error(SETS("outputs={select: near-contact}"), PARTS("outputs", "radius"));
    expect_error(SETS("geometry.grid=2,2,2"), PARTS("geometry", "belong to a box"));
    expect_error(SETS("contact.0.node=1"), PARTS("contact.0", "site on an organ"));
    expect_error(SETS("cuts=[{path: [[0, 0], [1, 1]], depth: 1}]"), PARTS("cuts", "organ"));
    /* the line of the offending key: geometry.surface.file is on line 3 */
    expect_text_error("name: t\ngeometry:\n  surface: {file: open.obj}\n  spacing: 4\n"
                      "material: {E: 0.01, nu: 0.3}\nfixed:\n  - sphere: {centre: [0, 0, -10], "
                      "radius: 6}\noutputs: {select: surface}\n",
                      PARTS("t.yaml:3:", "geometry.surface.file", "open surface"));
    /* a box has no near region */
    expect_text_error("name: b\ngeometry: {box: {min: [0, 0, 0], max: [1, 1, 1]}, grid: [2, 2, 2]}\n"
                      "material: {E: 1, nu: 0.3}\nfixed:\n  - near: {point: [0, 0, 0], distance: 1}\n"
                      "outputs: {select: all}\n",
                      PARTS("t.yaml:5:", "fixed.0.near", "organ"));
}

/* Every law of the registry loads on an organ: the Newton solvers
 * integrate over its tetrahedra as the linear Galerkin solver does. */
static void an_organ_takes_every_law(void **state)
{
    (void)state;
    static const char *laws[] = {"material.law=neo-hookean", "material.law=svk",
                                 "material={law: kelvin, k1: 0.01, k2: 0.01, eta: 1, nu: 0.3}"};
    for (size_t k = 0; k < sizeof laws / sizeof laws[0]; ++k) {
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        tf_scene *s = load(&ctx, base, &laws[k], 1);
        if (s == NULL) {
            fail_msg("%s: %s", laws[k], ctx.err);
        }
        assert_true(tf_material_caps(&s->problem.material) & TF_MATERIAL_FINITE ||
                    tf_material_caps(&s->problem.material) & TF_MATERIAL_HISTORY);
        tf_scene_free(s);
    }
}

/* Legal but implausible values are said, not refused: a contact point far
 * off the organ, a modulus in Pa, an organ in other units than its scale. */
static void implausible_values_are_warned(void **state)
{
    (void)state;
    static const struct {
        const char *set, *says;
    } cases[] = {
        {"contact.0.site.point=[0, 0, 400]", "contact.0.site.point: 390 mm from the organ's surface"},
        {"material.E=5000", "Young's modulus 5000 MPa, stiffer than 1 GPa"},
        {"geometry.surface.scale=0.1", "the organ is 3.464 mm across (its box's diagonal), smaller than any organ"},
    };
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = load(&ctx, base, NULL, 0);
    assert_non_null(s);
    assert_string_equal(s->warnings, ""); /* the plausible base says nothing */
    tf_scene_free(s);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        /* the small organ (scale 0.1): everything at a tenth of the size */
        const char *sets[] = {cases[k].set, "geometry.spacing=0.4",
                              "fixed.0.sphere={centre: [0, 0, -1], radius: 0.6}",
                              "contact.0.site={point: [0, 0, 1.1], radius: 0.3}",
                              "outputs.radius=0.8"};
        size_t n = strstr(cases[k].set, "scale") ? 5 : 1;
        s = load(&ctx, base, sets, n);
        if (s == NULL) {
            fail_msg("%s: %s", cases[k].set, ctx.err);
        }
        if (strstr(s->warnings, cases[k].says) == NULL) {
            fail_msg("--set %s: warnings '%s' lack '%s'", cases[k].set, s->warnings, cases[k].says);
        }
        tf_scene_free(s);
    }
}

/* The patch test on tetrahedral cells: every surface vertex held at a
 * linear field u = a + G x; the interior nodes must follow it.  RPIM with
 * the linear polynomial reproduces a linear field exactly; what remains is
 * the Gauss rules' error on non-polynomial shape-function products. */
static void tetrahedral_cells_pass_the_patch_test(void **state)
{
    (void)state;
    const char *sets[] = {
        "reference={kind: linear, offset: [0.1, -0.2, 0.05], gradient: [0.01, 0.002, -0.003, "
        "0.004, -0.02, 0.001, 0.003, 0.002, 0.015]}",
        "fixed=[{near: {point: [0, 0, 0], distance: 20}, exact: true}]"};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = load(&ctx, base, sets, 2);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_problem *p = &s->problem;
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    assert_non_null(sv);
    double *u = malloc(3 * p->cloud.n * sizeof *u);
    assert_int_equal(tf_solver_solve(sv, -1, NULL, 1, NULL, u), 0);
    double worst = 0, top = 0;
    for (size_t i = p->cloud.n_surface; i < p->cloud.n; ++i) {
        const double *x = p->cloud.xyz + 3 * i;
        for (int a = 0; a < 3; ++a) {
            double exact = p->analytic.offset[a];
            for (int b = 0; b < 3; ++b) {
                exact += p->analytic.gradient[3 * a + b] * x[b];
            }
            worst = fmax(worst, fabs(u[3 * i + (size_t)a] - exact));
            top = fmax(top, fabs(exact));
        }
    }
    print_message("patch test on %zu tetrahedra: interior error %.3g of %.3g mm\n",
                  tf_problem_mesh(p)->tm.ntet, worst, top);
    /* Not to quadrature accuracy: RPIM shape functions jump between cells
     * (docs/validation.md §2 and §14); 2.5 % measured. */
    assert_true(worst <= 0.03 * top);
    free(u);
    tf_solver_destroy(sv);
    tf_scene_free(s);
}

/* The strain energy of a linear field is exact: RPIM with the linear
 * polynomial reproduces its gradient G at every Gauss point, so
 * u^T K u = sum_g w_g G:D:G = V G:D:G when the tetrahedra's weights add up
 * to the organ's volume (B-bar too: div u is constant). */
static void a_linear_field_has_the_exact_energy(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    tf_scene *s = load(&ctx, base, NULL, 0);
    assert_non_null(s);
    const tf_problem *p = &s->problem;
    tf_solver *sv = tf_solver_create(p, NULL, &ctx);
    assert_non_null(sv);
    const double g[9] = {0.01, 0.002, -0.003, 0.004, -0.02, 0.001, 0.003, 0.002, 0.015};
    size_t n3 = 3 * p->cloud.n;
    double *u = malloc(n3 * sizeof *u), *r = malloc(n3 * sizeof *r), zero[3] = {0, 0, 0};
    for (size_t i = 0; i < p->cloud.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            u[3 * i + (size_t)a] = 0;
            for (int b = 0; b < 3; ++b) {
                u[3 * i + (size_t)a] += g[3 * a + b] * p->cloud.xyz[3 * i + (size_t)b];
            }
        }
    }
    assert_int_equal(tf_solver_reactions(sv, -1, zero, u, r), 0);
    double energy = 0;
    for (size_t d = 0; d < n3; ++d) {
        energy += u[d] * r[d];
    }
    double E, nu;
    tf_material_moduli(&p->material, &E, &nu);
    double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    double tr = g[0] + g[4] + g[8], eps2 = 0;
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
            double e = 0.5 * (g[3 * a + b] + g[3 * b + a]);
            eps2 += e * e;
        }
    }
    double exact = tf_problem_mesh(p)->tm.enclosed_volume * (lambda * tr * tr + 2 * mu * eps2);
    print_message("strain energy of a linear field: %.12g, exact %.12g\n", energy, exact);
    assert_true(fabs(energy - exact) <= 1e-9 * exact);
    free(u);
    free(r);
    tf_solver_destroy(sv);
    tf_scene_free(s);
}

/* A site's nodal forces add up to the force (the shape functions are a
 * partition of unity, the triangle weights sum to the patch's area). */
static void a_contact_site_applies_the_whole_force(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = load(&ctx, base, NULL, 0);
    assert_non_null(s);
    const tf_problem *p = &s->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(p);
    tf_shape sh;
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    assert_int_equal(tf_shape_init(&sh, &p->cloud, lo, hi, &p->solver), 0);
    assert_int_equal(tf_shape_use_tets(&ctx, &sh, m->tm.tet, m->tm.ntet, 2), 0);
    size_t n3 = 3 * p->cloud.n;
    double *f = calloc(n3, sizeof *f);
    const double force[3] = {0.3, -0.2, 0.7};
    assert_int_equal(tf_load_patch(&ctx, &sh, &p->contacts[0].patch, force, f), 0);
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < p->cloud.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            sum[a] += f[3 * i + (size_t)a];
        }
    }
    for (int a = 0; a < 3; ++a) {
        assert_true(fabs(sum[a] - force[a]) <= 1e-12);
    }
    free(f);
    tf_shape_free(&sh);
    tf_scene_free(s);
}

/* geometry.refine_skin: the sphere's skin (edges of 3.1-3.9 mm) split to a
 * 2 mm spacing on its own triangles.  The file's vertices stay the first
 * nodes bit for bit; the contact vertex, the outputs and the loaded area
 * are those of the file's skin (a site is the same union of the file's
 * triangles, in smaller pieces); the hold takes the new vertices inside
 * its ball; a midpoint is not an output, and a list of the file's
 * vertices cannot hold a refined skin. */
static void a_refined_skin_keeps_the_file_and_its_sites(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_WARN;
    const char *plain_sets[] = {"geometry.spacing=2"};
    const char *fine_sets[] = {"geometry.spacing=2", "geometry.refine_skin=true"};
    tf_scene *plain = load(&ctx, base, plain_sets, 1), *fine = load(&ctx, base, fine_sets, 2);
    if (plain == NULL || fine == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_problem *p = &plain->problem, *q = &fine->problem;
    const tf_mesh_geometry *m = tf_problem_mesh(q);
    size_t nv = 2 + 9 * 16;
    assert_int_equal(tf_problem_mesh(p)->file_nv, nv);
    assert_int_equal(m->file_nv, nv);
    assert_int_equal(p->cloud.n_surface, nv);
    assert_true(q->cloud.n_surface > 3 * nv);
    assert_memory_equal(q->cloud.xyz, p->cloud.xyz, 3 * nv * sizeof *q->cloud.xyz);
    for (size_t i = nv; i < q->cloud.n_surface; ++i) {
        assert_int_equal(m->tm.source[i], -1);
    }
    assert_true(fabs(m->tm.cells_volume - m->tm.enclosed_volume) <= 1e-12 * m->tm.enclosed_volume);
    assert_true(fabs(m->tm.enclosed_volume - tf_problem_mesh(p)->tm.enclosed_volume) <=
                1e-12 * m->tm.enclosed_volume);
    const tf_patch *a = &p->contacts[0].patch, *b = &q->contacts[0].patch;
    assert_int_equal(q->contacts[0].node, p->contacts[0].node);
    assert_int_equal(a->n_tri, 16);
    assert_true(b->n_tri > 2 * a->n_tri);
    assert_true(fabs(a->area - b->area) <= 1e-12 * a->area);
    assert_int_equal(q->outputs.n_nodes, p->outputs.n_nodes);
    assert_memory_equal(q->outputs.nodes, p->outputs.nodes,
                        p->outputs.n_nodes * sizeof *p->outputs.nodes);
    size_t held_midpoints = 0;
    for (size_t k = 0; k < q->fixed[0].n_nodes; ++k) {
        uint32_t i = q->fixed[0].nodes[k];
        held_midpoints += i >= nv && i < q->cloud.n_surface;
    }
    assert_true(held_midpoints > 0);
    tf_scene_free(plain);
    tf_scene_free(fine);
    char midpoint[80];
    snprintf(midpoint, sizeof midpoint, "outputs={select: nodes, nodes: [%zu]}", nv + 1);
    expect_error(SETS("geometry.spacing=2", "geometry.refine_skin=true", midpoint),
                 PARTS("outputs", "not a vertex of the mesh file"));
    expect_error(SETS("geometry.refine_skin=true", "fixed.1.vertices=[3, 4]"),
                 PARTS("fixed.1.vertices", "refined skin"));
    expect_error(SETS("geometry.spacing=0.001", "geometry.refine_skin=true"),
                 PARTS("geometry", "tetrahedra"));
    expect_text_error("name: b\ngeometry: {box: {min: [0, 0, 0], max: [1, 1, 1]}, grid: [2, 2, 2], "
                      "refine_skin: true}\nmaterial: {E: 1, nu: 0.3}\nfixed:\n  - face: z-\n"
                      "outputs: {select: all}\n",
                      PARTS("geometry", "refine_skin"));
}

/* An organ's multiquadric: the seed's absolute d_c = 2 mm by default (the
 * boxes' relative 8 h is singular on its supports of up to 60 nodes), and
 * a relative d_c when the scene asks for one, through the tetrahedra's
 * local spacing: 8 h is refused naming the key to lower, 1 h solves. */
static void an_organ_takes_an_absolute_d_c_by_default(void **state)
{
    (void)state;
    const char *const sets[][1] = {{"solver.rbf.spacings=8"}, {"solver.rbf.spacings=1"}};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_scene *s = load(&ctx, base, NULL, 0);
    assert_non_null(s);
    assert_true(s->problem.solver.d_c_spacings == 0 && s->problem.solver.d_c == 2.0);
    tf_scene_free(s);
    for (int k = 0; k < 2; ++k) {
        s = load(&ctx, base, sets[k], 1);
        assert_non_null(s);
        assert_true(s->problem.solver.d_c_spacings == (k == 0 ? 8.0 : 1.0));
        tf_solver *sv = tf_solver_create(&s->problem, NULL, &ctx);
        if (k == 0) {
            assert_null(sv);
            assert_non_null(strstr(ctx.err, "lower solver.rbf.spacings"));
        } else {
            assert_non_null(sv);
            tf_solver_destroy(sv);
        }
        tf_scene_free(s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_organ_scene_is_built_as_written),
        cmocka_unit_test(each_bad_organ_scene_has_its_own_message),
        cmocka_unit_test(an_organ_takes_every_law),
        cmocka_unit_test(implausible_values_are_warned),
        cmocka_unit_test(tetrahedral_cells_pass_the_patch_test),
        cmocka_unit_test(a_linear_field_has_the_exact_energy),
        cmocka_unit_test(a_contact_site_applies_the_whole_force),
        cmocka_unit_test(an_organ_takes_an_absolute_d_c_by_default),
        cmocka_unit_test(a_refined_skin_keeps_the_file_and_its_sites),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
