/*
 * test_cases.c — the load cases of a fit follow what the solver declares:
 * an affine solver's training cases are superposed from four unit solves,
 * any other solver's are all solved, and the two agree to rounding.  The
 * "other" solver is the RPIM Galerkin solver with its capabilities hidden
 * (same operations, caps 0), so the only difference is the pipeline's path.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "base/context.h"
#include "fitting/cases.h"
#include "fitting/families/family.h"
#include "scene/scene.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define N_TRAIN 30
#define N_HELD 10

static int id_is_node; /* contact_id_of: the id was the nearest node's number */

static unsigned no_caps(const tf_solver *s)
{
    (void)s;
    return 0;
}

static double max_abs(const double *v, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        m = fmax(m, fabs(v[i]));
    }
    return m;
}

static double max_diff(const double *a, const double *b, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        m = fmax(m, fabs(a[i] - b[i]));
    }
    return m;
}

/* block48 (linear), and block48 with a load that always acts (affine: the
 * superposition's constant term is not zero). */
static void check_paths(const char *const *sets, size_t n_sets)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, n_sets);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_problem *p = &s->problem;
    tf_solver_ops plain = tf_galerkin_ops;
    plain.name = "galerkin-without-caps";
    plain.caps = no_caps;
    tf_solver *affine = tf_solver_create(p, NULL, &ctx);
    tf_solver *other = tf_solver_create_as(&plain, p, NULL, &ctx);
    assert_non_null(affine);
    assert_non_null(other);
    assert_true(tf_solver_caps_of(affine) & TF_SOLVER_AFFINE);
    assert_int_equal(!!(tf_solver_caps_of(affine) & TF_SOLVER_LINEAR), n_sets == 0);
    assert_int_equal(tf_solver_caps_of(other), 0);

    tf_cases a, o;
    tf_fit_plan plan;
    tf_fit_plan_defaults(&plan);
    plan.n_train = N_TRAIN;
    plan.n_heldout = N_HELD;
    plan.seed = 7;
    assert_int_equal(tf_cases_build(p, affine, &plan, &a), 0);
    assert_int_equal(tf_cases_build(p, other, &plan, &o), 0);
    assert_true(a.superposed && !o.superposed);
    assert_int_equal(a.solves, 4 + N_HELD); /* unit responses + held-out */
    /* training, 3 axes, held-out, the seed-table levels */
    assert_int_equal(o.solves, 4 * N_TRAIN + N_HELD + 3 * TF_FAMILY_LEVELS);

    /* superposition against direct solves: rounding only */
    const size_t rows = 3 * p->outputs.n_nodes;
    double scale = max_abs(o.train.u, N_TRAIN * rows);
    assert_true(scale > 1);
    assert_true(max_diff(a.train.u, o.train.u, N_TRAIN * rows) < 1e-13 * scale);
    assert_true(max_diff(&a.train.contact[0][0], &o.train.contact[0][0], 3 * N_TRAIN) <
                1e-13 * scale);
    for (int k = 0; k < 3; ++k) {
        assert_true(max_diff(a.axis[k].u, o.axis[k].u, N_TRAIN * rows) < 1e-13 * scale);
    }
    /* the held-out cases are solved on both paths, in one batch or one by
     * one (CHOLMOD's bits depend on the batch): the same to rounding */
    assert_true(max_diff(a.heldout.u, o.heldout.u, N_HELD * rows) < 1e-13 * scale);

    /* the seed-table levels: superposed, or solved with the other cases */
    double *la = malloc(rows * sizeof *la), *lo = malloc(rows * sizeof *lo);
    for (int ax = 0; ax < 3; ++ax) {
        for (int level = 1; level <= TF_FAMILY_LEVELS; ++level) {
            tf_cases_level_response(&a, ax, level, la);
            tf_cases_level_response(&o, ax, level, lo);
            assert_true(max_abs(lo, rows) > 0.1 * level * scale / TF_FAMILY_LEVELS);
            assert_true(max_diff(la, lo, rows) < 1e-13 * scale);
        }
    }
    free(la);
    free(lo);

    /* a response at a new force: superposed, or one more solve */
    const double f[3] = {0.3, -0.2, -0.6};
    double *ua = malloc(rows * sizeof *ua), *uo = malloc(rows * sizeof *uo), ca[3], co[3];
    size_t before = o.solves;
    assert_int_equal(tf_cases_response(&a, f, ua, ca), 0);
    assert_int_equal(tf_cases_response(&o, f, uo, co), 0);
    assert_int_equal(o.solves, before + 1);
    assert_true(max_diff(ua, uo, rows) < 1e-13 * scale);
    assert_true(max_diff(ca, co, 3) < 1e-13 * scale);

    /* --direct on the affine solver: every case solved, as the other one */
    tf_cases d;
    plan.direct = 1;
    assert_int_equal(tf_cases_build(p, affine, &plan, &d), 0);
    assert_false(d.superposed);
    assert_true(max_diff(d.train.u, o.train.u, N_TRAIN * rows) < 1e-13 * scale);

    free(ua);
    free(uo);
    tf_cases_free(&a);
    tf_cases_free(&o);
    tf_cases_free(&d);
    tf_solver_destroy(affine);
    tf_solver_destroy(other);
    tf_scene_free(s);
}

static void superposed_only_when_the_solver_is_affine(void **state)
{
    (void)state;
    const char *loaded[] = {"loads.0.node=50", "loads.0.force=0.2,0,-0.4"};
    check_paths(NULL, 0);
    check_paths(loaded, 2);
}

/* Sites between nodes: the affine path evaluates the field there; the
 * case list of a solver that is not affine keeps every DOF and reads the
 * same field, so the two agree to rounding at every point; a solver with no
 * field between nodes must refuse them, naming the point, rather than read
 * the nearest node. */
static void sites_between_nodes_read_from_the_field(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    const char *grid[] = {"geometry.grid=10,10,3"}; /* no node at the seed's points */
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_at.yaml", grid, 1);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    tf_solver_ops plain = tf_galerkin_ops, blind;
    plain.name = "galerkin-without-caps";
    plain.caps = no_caps;
    blind = plain;
    blind.name = "galerkin-without-field";
    blind.field = NULL;
    tf_solver *affine = tf_solver_create(&s->problem, NULL, &ctx);
    tf_solver *other = tf_solver_create_as(&plain, &s->problem, NULL, &ctx);
    tf_solver *nofield = tf_solver_create_as(&blind, &s->problem, NULL, &ctx);
    assert_non_null(affine);
    assert_non_null(other);
    assert_non_null(nofield);
    tf_fit_plan plan;
    tf_fit_plan_defaults(&plan);
    plan.n_train = N_TRAIN;
    plan.n_heldout = N_HELD;
    tf_cases a, o, b;
    assert_int_equal(tf_cases_build(&s->problem, affine, &plan, &a), 0);
    assert_int_equal(tf_cases_build(&s->problem, other, &plan, &o), 0);
    const size_t rows = 3 * s->problem.outputs.n_nodes;
    const double scale = max_abs(a.train.u, N_TRAIN * rows);
    assert_true(scale > 0);
    assert_true(max_diff(a.train.u, o.train.u, N_TRAIN * rows) < 1e-13 * scale);
    assert_true(max_diff(a.heldout.u, o.heldout.u, N_HELD * rows) < 1e-13 * scale);
    assert_true(max_diff(&a.train.contact[0][0], &o.train.contact[0][0], 3 * N_TRAIN) <
                1e-13 * scale);
    assert_int_equal(tf_cases_build(&s->problem, nofield, &plan, &b), -1);
    assert_non_null(strstr(ctx.err, "lies between nodes"));
    tf_cases_free(&a);
    tf_cases_free(&o);
    tf_solver_destroy(affine);
    tf_solver_destroy(other);
    tf_solver_destroy(nofield);
    tf_scene_free(s);
}

/* The contact model's id for a site given by position: the number of the
 * output point there (firmware finds the contact among the outputs by it),
 * or, at no output point, the nearest node's number. */
static uint32_t contact_id_of(const char *centre)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    const char *sets[] = {"geometry.grid=10,10,3", centre}; /* no node at the seed's points */
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_at.yaml", sets, 2);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    tf_solver *solver = tf_solver_create(&s->problem, NULL, &ctx);
    assert_non_null(solver);
    tf_fit_plan plan;
    tf_fit_plan_defaults(&plan);
    plan.n_train = N_TRAIN;
    plan.n_heldout = N_HELD;
    tf_cases c;
    assert_int_equal(tf_cases_build(&s->problem, solver, &plan, &c), 0);
    const uint32_t id = c.contact_id;
    assert_int_equal(c.contact_node, s->problem.contacts[0].node);
    if (id == s->problem.contacts[0].node + 1) { /* the nearest node: then no output is there */
        id_is_node = 1;
    }
    tf_cases_free(&c);
    tf_solver_destroy(solver);
    tf_scene_free(s);
    return id;
}

static void contact_by_position_is_named_by_its_output(void **state)
{
    (void)state;
    /* output j + 1 sits at (4.8 (j mod 11), 4.8 floor(j / 11), 6) */
    id_is_node = 0;
    assert_int_equal(contact_id_of("contact.0.patch.centre=[24, 24]"), 61);
    assert_false(id_is_node);
    assert_int_equal(contact_id_of("contact.0.patch.centre=[19.2, 24]"), 60);
    assert_int_equal(contact_id_of("contact.0.patch.centre=[24, 28.8]"), 72);
    /* between the output points: the nearest node's number */
    id_is_node = 0;
    contact_id_of("contact.0.patch.centre=[22, 24]");
    assert_true(id_is_node);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(superposed_only_when_the_solver_is_affine),
        cmocka_unit_test(sites_between_nodes_read_from_the_field),
        cmocka_unit_test(contact_by_position_is_named_by_its_output),
    };
    return cmocka_run_group_tests_name("cases", tests, NULL, NULL);
}
