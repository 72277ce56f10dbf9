/*
 * test_scene.c — scene files: block48 as GUIDE §5 defines it, the node
 * numbering, --set overrides, and one clear message (file, line, field) for
 * each kind of bad scene.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "scene/scene.h"
#include "scene_refused.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"

static const double *node_xyz(const tf_scene *s, uint32_t number)
{
    return s->problem.cloud.xyz + 3 * (size_t)(number - 1);
}

static void block48_as_the_guide_defines_it(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, BLOCK48, NULL, 0);
    assert_non_null(s);
    assert_string_equal(s->problem.name, "block48");
    assert_int_equal(s->problem.cloud.n, 363);
    const tf_material *m = &s->problem.material;
    assert_string_equal(tf_material_name(m), "linear");
    assert_true(tf_material_get(m, "E") == 0.32 && tf_material_get(m, "nu") == 0.49);
    /* node 61 is the top centre; N = i + 11 j + 1 on the top layer */
    const double *c = node_xyz(s, 61);
    assert_true(c[0] == 24 && c[1] == 24 && c[2] == 6);
    for (unsigned j = 0; j < 11; ++j) {
        for (unsigned i = 0; i < 11; ++i) {
            const double *x = node_xyz(s, i + 11 * j + 1);
            assert_true(fabs(x[0] - 4.8 * i) < 1e-12 && fabs(x[1] - 4.8 * j) < 1e-12);
            assert_true(x[2] == 6);
        }
    }
    /* the layers below follow: 122 .. 242 at z = 3, 243 .. 363 at z = 0 */
    assert_true(node_xyz(s, 122)[2] == 3 && node_xyz(s, 363)[2] == 0);
    assert_int_equal(s->problem.n_fixed, 4);
    for (size_t k = 0; k < 4; ++k) {
        assert_int_equal(s->problem.fixed[k].n_nodes, 33); /* 11 x 3 nodes per lateral face */
        assert_int_equal(s->problem.fixed[k].components, TF_COMP_ALL);
    }
    assert_int_equal(s->problem.n_contacts, 1);
    assert_int_equal(s->problem.contacts[0].node, 60);
    assert_int_equal(s->problem.contacts[0].patch.shape, TF_PATCH_RECT);
    assert_int_equal(s->problem.contacts[0].patch.face, TF_FACE_ZMAX);
    const tf_patch *patch = &s->problem.contacts[0].patch;
    assert_true(patch->centre[0] == 24 && patch->size[1] == 4.8);
    assert_true(s->problem.envelope.radius == 1.0);
    assert_string_equal(s->problem.solver.method, "rpim-galerkin");
    assert_int_equal(s->fit.contact, 0);
    assert_int_equal(s->fit.n_train, 100);
    assert_int_equal(s->problem.outputs.n_nodes, 121);
    for (size_t k = 0; k < 121; ++k) {
        assert_int_equal(s->problem.outputs.nodes[k], k); /* the top layer, in node order */
    }
    assert_int_equal(s->problem.solver.polynomial, 1);
    assert_int_equal(s->problem.solver.volumetric, TF_VOLUMETRIC_CELL);
    assert_int_equal(s->problem.solver.centre, TF_SUPPORT_CELL);
    const tf_solver_opts *o = &s->problem.solver;
    assert_true(o->alpha_c == 1.0 && o->d_c == 2.0 && o->q == 1.03);
    tf_scene_free(s);
}

static void overrides_change_every_kind_of_value(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[] = {"geometry.grid=21,21,5", "contact.0.node=221", "solver.rbf.q=0.5",
                          "fixed.0.components=x,z", "solver.bc=penalty", "name=b21",
                          "fixed.4.face=z-", "outputs={select: contact}",
                          "solver.volumetric=full", "fit.tick_us=20000", "fit.histories=8",
                          "fit.heldout_histories=3", "fit.history_ticks=250"};
    tf_scene *s = tf_scene_load(&ctx, BLOCK48, sets, sizeof sets / sizeof sets[0]);
    assert_non_null(s);
    assert_int_equal(s->fit.tick_ns, 20000000);
    assert_int_equal(s->fit.hist_train, 8);
    assert_int_equal(s->fit.hist_heldout, 3);
    assert_int_equal(s->fit.hist_ticks, 250);
    assert_int_equal(s->problem.cloud.n, 21 * 21 * 5);
    const double *c = node_xyz(s, 221);
    assert_true(c[0] == 24 && c[1] == 24 && c[2] == 6);
    assert_true(s->problem.solver.q == 0.5);
    assert_int_equal(s->problem.fixed[0].components, TF_COMP_X | TF_COMP_Z);
    assert_int_equal(s->problem.solver.bc, TF_BC_PENALTY);
    assert_int_equal(s->problem.solver.volumetric, TF_VOLUMETRIC_FULL);
    assert_string_equal(s->problem.name, "b21");
    assert_int_equal(s->problem.n_fixed, 5); /* appended */
    assert_int_equal(s->problem.fixed[4].n_nodes, 21 * 21);
    assert_int_equal(s->problem.outputs.n_nodes, 1);
    assert_int_equal(s->problem.outputs.nodes[0], 220);
    assert_int_equal(s->problem.solver.cells[0], 20); /* default cells follow the grid */
    tf_scene_free(s);
}

static void expect_span(int line, int span, const char *replacement,
                        const char *const *fragments)
{
    tf_test_refused(line, span, replacement, fragments);
}

static void expect_error(int line, const char *replacement, const char *const *fragments)
{
    tf_test_refused(line, 1, replacement, fragments);
}

static void the_base_scene_is_good(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load_text(&ctx, tf_test_scene, strlen(tf_test_scene), "t.yaml", NULL, 0);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    tf_scene_free(s);
}

/* Every law's parameters reach the problem; a Kelvin solid's small-strain
 * modulus is its instantaneous one. */
static void material_laws_and_their_parameters(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *nh[] = {"material.law=neo-hookean"};
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", nh, 1);
    assert_non_null(s);
    assert_string_equal(tf_material_name(&s->problem.material), "neo-hookean");
    assert_true(tf_material_get(&s->problem.material, "E") == 0.32);
    tf_scene_free(s);
    const char *kv[] = {"material={law: kelvin, nu: 0.45, k1: 0.2, k2: 0.1, eta: 0.5, k: 3}"};
    s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", kv, 1);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_material *m = &s->problem.material;
    assert_string_equal(tf_material_name(m), "kelvin");
    assert_true(tf_material_get(m, "k1") == 0.2 && tf_material_get(m, "k2") == 0.1 &&
                tf_material_get(m, "eta") == 0.5 && tf_material_get(m, "k") == 3);
    double young, nu;
    tf_material_moduli(m, &young, &nu);
    assert_true(young == 0.2 + 0.1 && nu == 0.45);
    tf_scene_free(s);
}

/* The material section comes from the law registry: every registered name
 * is accepted, an unknown one is refused at its line naming them all, and
 * an unknown key names every law's keys; each law's parameters reach the
 * material by their keys, in a file and through --set. */
static void laws_and_keys_come_from_the_registry(void **state)
{
    (void)state;
    const char *unknown[16] = {"t.yaml:6:", "material.law", "'rubber'"};
    size_t n = 3;
    for (size_t i = 0; i < tf_law_count() && n + 1 < 16; ++i) {
        unknown[n++] = tf_law_at(i)->name;
    }
    unknown[n] = NULL;
    expect_error(6, "  law: rubber\n  E: 1\n", unknown);
    const char *keys[24] = {"t.yaml:7:", "material.colour", "unknown key", "law"};
    n = 4;
    for (size_t k = 0; k < tf_law_key_count() && n + 1 < 24; ++k) {
        keys[n++] = tf_law_key_at(k);
    }
    keys[n] = NULL;
    expect_error(6, "  E: 1\n  colour: red\n", keys);
    char params[256];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    for (size_t i = 0; i < tf_law_count(); ++i) {
        const tf_law_ops *l = tf_law_at(i);
        /* a valid value of every parameter: the registry test's samples */
        size_t used = (size_t)snprintf(params, sizeof params, "material={law: %s", l->name);
        for (size_t p = 0; p < l->n_params; ++p) {
            const char *key = l->params[p].key;
            double v = !strcmp(key, "nu") ? 0.45 : !strcmp(key, "k") ? 0 : 0.5 + (double)p / 8;
            used += (size_t)snprintf(params + used, sizeof params - used, ", %s: %.17g", key, v);
        }
        snprintf(params + used, sizeof params - used, "}");
        const char *sets[] = {params};
        tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, 1);
        if (s == NULL) {
            fail_msg("%s: %s", l->name, ctx.err);
        }
        assert_ptr_equal(s->problem.material.law, l);
        for (size_t p = 0; p < l->n_params; ++p) {
            const char *key = l->params[p].key;
            double v = !strcmp(key, "nu") ? 0.45 : !strcmp(key, "k") ? 0 : 0.5 + (double)p / 8;
            assert_true(tf_material_get(&s->problem.material, key) == v);
        }
        tf_scene_free(s);
    }
}

static void each_bad_scene_has_its_own_message(void **state)
{
    (void)state;
    expect_error(6, "  E: -1\n", (const char *[]){"t.yaml:6:", "material.E", "positive", NULL});
    expect_error(7, "  nu: 0.5\n", (const char *[]){"t.yaml:7:", "material.nu", "0.5", NULL});
    expect_error(7, "  nu: 0.7\n", (const char *[]){"t.yaml:7:", "material.nu", NULL});
    expect_error(6, "  E: soft\n", (const char *[]){"t.yaml:6:", "material.E", "not a number", NULL});
    expect_error(6, "\n", (const char *[]){"t.yaml:", "material", "'E' is missing", NULL});
    expect_error(6, "  E: 1\n  colour: red\n",
                 (const char *[]){"t.yaml:7:", "material.colour", "unknown key", "E, nu", NULL});
    /* material laws and their parameters (materials/material.h) */
    expect_error(6, "  law: rubber\n  E: 1\n",
                 (const char *[]){"t.yaml:6:", "material.law", "neo-hookean", "kelvin", NULL});
    expect_error(6, "  law: kelvin\n  k1: 1\n  k2: 0.5\n",
                 (const char *[]){"t.yaml:", "material.eta", "k1, k2 and eta", NULL});
    expect_error(6, "  law: kelvin\n  E: 1\n  k1: 1\n  k2: 0.5\n  eta: 1\n",
                 (const char *[]){"t.yaml:7:", "material.E", "not E", NULL});
    expect_error(6, "  law: svk\n  E: 1\n  k1: 1\n",
                 (const char *[]){"t.yaml:8:", "material.k1", "kelvin", NULL});
    expect_error(6, "  law: kelvin\n  k1: 1\n  k2: -0.5\n  eta: 1\n",
                 (const char *[]){"t.yaml:8:", "material.k2", "not be above", NULL});
    expect_error(6, "  law: kelvin\n  k1: 1\n  k2: 0.5\n  eta: 0\n",
                 (const char *[]){"t.yaml:9:", "material.eta", "tau", NULL});
    expect_error(6, "  law: kelvin\n  k1: 1\n  k2: 0.5\n  eta: 1\n  k: -2\n",
                 (const char *[]){"t.yaml:10:", "material.k", ">= 0", NULL});
    expect_error(6, "  law: kelvin-neo-hookean\n  k1: 1\n  k2: 0.5\n  eta: 1\n  k: 2\n",
                 (const char *[]){"t.yaml:10:", "material.k", "must be 0", NULL});
    expect_error(6, "  law: neo-hookean\n  E: 0\n",
                 (const char *[]){"t.yaml:7:", "material.E", "Young", NULL});
    expect_span(6, 2, "  law: svk\n  E: 1\n  nu: 0.5\n",
                (const char *[]){"t.yaml:8:", "material.nu", "(-1, 0.5)", NULL});
    expect_error(4, "  grid: [5, 5]\n", (const char *[]){"t.yaml:4:", "geometry.grid", "few", NULL});
    expect_error(4, "  grid: [5, 1, 2]\n", (const char *[]){"t.yaml:4:", "geometry.grid", "at least 2", NULL});
    expect_error(9, "  - face: w+\n", (const char *[]){"t.yaml:9:", "fixed.0.face", "x-, x+", NULL});
    expect_error(9, "  - {face: z-, plane: {axis: x, at: 0}}\n",
                 (const char *[]){"t.yaml:9:", "fixed.0", "exactly one of face, plane, box", NULL});
    expect_error(9, "  - plane: {axis: x, at: 3}\n",
                 (const char *[]){"t.yaml:9:", "fixed.0", "holds no node", NULL});
    expect_span(8, 2, "fixed: []\n", (const char *[]){"t.yaml:", "fixed", "few", NULL});
    expect_error(11, "  - node: 99\n", (const char *[]){"t.yaml:11:", "contact.0.node", "1 to 50", NULL});
    expect_error(14, "  face: q\n", (const char *[]){"t.yaml:14:", "outputs.face", NULL});
    expect_span(13, 2, "  select: box\n  box: {min: [20, 20, 20], max: [30, 30, 30]}\n",
                (const char *[]){"t.yaml:13:", "outputs", "holds no node", NULL});
    expect_span(13, 2, "  select: nodes\n  nodes: []\n",
                (const char *[]){"t.yaml:13:", "outputs", "non-empty", NULL});
    expect_error(13, "  select: all\n", (const char *[]){"t.yaml:", "outputs", "take nothing else", NULL});
    expect_error(1, "name: t\nsolver: {gauss: 40}\n", (const char *[]){"t.yaml:2:", "solver.gauss", NULL});
    expect_error(1, "name: t\nsolver: {method: fem}\n",
                 (const char *[]){"t.yaml:2:", "solver.method", "'fem'", "rpim-galerkin", NULL});
    expect_error(1, "name: t\nsolver: {rbf: {q: 1}}\n", (const char *[]){"t.yaml:2:", "solver.rbf.q", "whole", NULL});
    expect_error(1, "name: t\nfitting: {family: nodal}\n", (const char *[]){"t.yaml:2:", "fitting", "unknown key", NULL});
    expect_error(1, "name: t\nfit: {family: cubic}\n", (const char *[]){"t.yaml:2:", "fit.family", NULL});
    expect_error(1, "name: t\nfit: {folds: 1}\n", (const char *[]){"t.yaml:2:", "fit.folds", NULL});
    expect_error(1, "name: t\nfit: {contact: nowhere}\n", (const char *[]){"t.yaml:2:", "fit.contact", NULL});
    expect_error(1, "name: t\nfit: {tick_us: 0}\n", (const char *[]){"t.yaml:2:", "fit.tick_us", NULL});
    expect_error(1, "name: t\nfit: {tick_us: 1000001}\n", (const char *[]){"t.yaml:2:", "fit.tick_us", NULL});
    expect_error(1, "name: t\nfit: {histories: 1}\n", (const char *[]){"t.yaml:2:", "fit.histories", NULL});
    expect_error(1, "name: t\nfit: {heldout_histories: 0}\n",
                 (const char *[]){"t.yaml:2:", "fit.heldout_histories", NULL});
    expect_error(1, "name: t\nfit: {history_ticks: 9}\n", (const char *[]){"t.yaml:2:", "fit.history_ticks", NULL});
    expect_error(3, "  box: {min: [0, 0, 0], max: [10, 10, 2]\n", (const char *[]){"t.yaml:", NULL});
    /* cuts: a point off the top face, a zero-length segment, a bad depth */
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [12, 1]], depth: 1}\n",
                 (const char *[]){"t.yaml:3:", "cuts.0.path.1", "outside the top face", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4], [4, 4]], depth: 1}\n",
                 (const char *[]){"t.yaml:3:", "cuts.0.path.2", "zero length", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4]], depth: 3}\n",
                 (const char *[]){"t.yaml:3:", "cuts.0.depth", "(0, 2]", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1]], depth: 1}\n",
                 (const char *[]){"t.yaml:3:", "cuts.0.path", NULL});
    /* cut progress: a power of two on a scene with cuts; held-out values with it */
    expect_error(1, "name: t\nfit: {cut_intervals: 4}\n",
                 (const char *[]){"t.yaml:2:", "fit.cut_intervals", "no cuts", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4]], depth: 1}\nfit: {cut_intervals: 6}\n",
                 (const char *[]){"t.yaml:4:", "fit.cut_intervals", "power of two", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4]], depth: 1}\nfit: {cut_intervals: 128}\n",
                 (const char *[]){"t.yaml:4:", "fit.cut_intervals", "1 to 64", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4]], depth: 1}\nfit: {cut_heldout: 3}\n",
                 (const char *[]){"t.yaml:4:", "fit.cut_heldout", "needs fit.cut_intervals", NULL});
    expect_error(1, "name: t\ncuts:\n  - {path: [[1, 1], [4, 4]], depth: 1}\n"
                    "fit: {cut_intervals: 2, cut_heldout: 0}\n",
                 (const char *[]){"t.yaml:4:", "fit.cut_heldout", "1 to 100", NULL});
}

static void override_errors_name_the_override(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *bad[][2] = {
        {"material.E=-3", "--set material.E=-3: material.E"},
        {"solver.gauss=x", "not a non-negative whole number"},
        {"solver.foo=1", "no key 'foo'"},
        {"geometry.grid=4,4", "few"},
        {"fixed.9.face=x-", "has 4 entries"},
        {"material", "key=value"},
        {"material.E.x=1", "holds a value"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        tf_scene *s = tf_scene_load(&ctx, BLOCK48, &bad[k][0], 1);
        assert_null(s);
        if (strstr(ctx.err, bad[k][1]) == NULL) {
            fail_msg("--set %s: message '%s' lacks '%s'", bad[k][0], ctx.err, bad[k][1]);
        }
    }
}

static void a_missing_file_is_named(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_null(tf_scene_load(&ctx, "no/such/scene.yaml", NULL, 0));
    assert_non_null(strstr(ctx.err, "no/such/scene.yaml"));
}

static void jitter_moves_only_interior_nodes(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/patch.yaml", NULL, 0);
    assert_non_null(s);
    size_t moved = 0;
    for (unsigned k = 0; k < 6; ++k) {
        for (unsigned j = 0; j < 6; ++j) {
            for (unsigned i = 0; i < 6; ++i) {
                const tf_cloud *cl = &s->problem.cloud;
                const double *x = cl->xyz + 3 * tf_cloud_index(cl, i, j, k);
                const unsigned ijk[3] = {i, j, k};
                int interior = i % 5 && j % 5 && k % 5;
                for (int a = 0; a < 3; ++a) {
                    double d = fabs(x[a] - 2.0 * ijk[a]);
                    assert_true(d <= 0.3 * 2.0 + 1e-12);
                    assert_true(interior || d == 0);
                    moved += d > 0;
                }
            }
        }
    }
    assert_true(moved > 3 * 64 / 2);
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(block48_as_the_guide_defines_it),
        cmocka_unit_test(overrides_change_every_kind_of_value),
        cmocka_unit_test(the_base_scene_is_good),
        cmocka_unit_test(each_bad_scene_has_its_own_message),
        cmocka_unit_test(material_laws_and_their_parameters),
        cmocka_unit_test(laws_and_keys_come_from_the_registry),
        cmocka_unit_test(override_errors_name_the_override),
        cmocka_unit_test(a_missing_file_is_named),
        cmocka_unit_test(jitter_moves_only_interior_nodes),
    };
    return cmocka_run_group_tests_name("scene", tests, NULL, NULL);
}
