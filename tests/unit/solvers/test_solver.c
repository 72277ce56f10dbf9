/*
 * test_solver.c — the RPIM Galerkin solver on block48 (GUIDE §5), beyond
 * what test_conformance.c asks of every solver: reactions under a point
 * force, elimination against the seed's penalty, many load cases through
 * one factorisation, OpenMP's default thread count, B-bar against locking,
 * node numbering, and the capabilities it declares for each problem.
 */
#include <math.h>
#include <omp.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "base/context.h"
#include "scene/scene.h"
#include "scene_run.h"
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"

static const double unit_forces[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}; /* fx, fy, fz */

typedef tf_scene_run run;

/* block48 with overrides, the scene's own solver. */
static run *solve(const char *const *sets, size_t n_sets, const double (*forces)[3],
                  size_t ncases)
{
    return tf_scene_run_solve(BLOCK48, NULL, sets, n_sets, 0, forces, ncases);
}

static run *solve_on(const char *scene, const char *const *sets, size_t n_sets, int threads,
                     const double (*forces)[3], size_t ncases)
{
    return tf_scene_run_solve(scene, NULL, sets, n_sets, threads, forces, ncases);
}

/* A point force instead of the patch (test_conformance.c has the patch). */
static void reactions_balance_a_point_force(void **state)
{
    (void)state;
    const char *point[] = {"contact.0={node: 61}"};
    run *r = solve(point, 1, unit_forces, 3);
    for (int c = 0; c < 3; ++c) {
        double sum[3], resid;
        assert_int_equal(tf_scene_run_balance(r, unit_forces[c], r->u + c * r->n3, sum, &resid),
                         0);
        for (int a = 0; a < 3; ++a) {
            assert_true(fabs(sum[a] + unit_forces[c][a]) < 1e-6);
        }
        assert_true(resid < 1e-10);
    }
    tf_scene_run_free(r);
}

static double relative_difference(const double *a, const double *b, size_t n)
{
    double worst = 0;
    for (size_t d = 0; d < n; ++d) {
        worst = fmax(worst, fabs(a[d] - b[d]));
    }
    return worst / tf_max_abs(b, n);
}

static void penalty_agrees_with_elimination(void **state)
{
    (void)state;
    run *elim = solve(NULL, 0, unit_forces, 3);
    size_t n = 9 * elim->p->cloud.n;
    const char *seed[] = {"solver.bc=penalty"};
    run *pen = solve(seed, 1, unit_forces, 3);
    assert_true(relative_difference(pen->u, elim->u, n) < 1e-6); /* lambda = 1e7 */
    tf_scene_run_free(pen);
    /* a small lambda does not hold the faces (error about 0.1 / lambda):
     * the check above can fail */
    const char *weak[] = {"solver.bc=penalty", "solver.penalty=10"};
    run *loose = solve(weak, 2, unit_forces, 3);
    assert_true(relative_difference(loose->u, elim->u, n) > 1e-3);
    tf_scene_run_free(loose);
    tf_scene_run_free(elim);
}

static void many_cases_through_one_factorisation(void **state)
{
    (void)state;
    double forces[6][3];
    for (int k = 0; k < 18; ++k) {
        forces[k / 3][k % 3] = sin(1.7 * k + 0.3); /* six arbitrary forces */
    }
    run *units = solve(NULL, 0, unit_forces, 3);
    run *many = solve(NULL, 0, (const double(*)[3])forces, 6);
    size_t n3 = 3 * units->p->cloud.n;
    double *one = malloc(n3 * sizeof *one);
    for (int k = 0; k < 6; ++k) {
        const double *f = forces[k], *u = many->u + k * n3;
        assert_int_equal(tf_solver_solve(many->solver, 0, &forces[k], 1, NULL, one), 0);
        for (size_t d = 0; d < n3; ++d) {
            /* linear: the superposition of the unit cases (fz case is -z) */
            double sup = f[0] * units->u[d] + f[1] * units->u[n3 + d] - f[2] * units->u[2 * n3 + d];
            assert_true(fabs(u[d] - sup) < 1e-12 * tf_max_abs(units->u, 3 * n3));
            assert_true(fabs(u[d] - one[d]) < 1e-13 * tf_max_abs(units->u, 3 * n3));
        }
    }
    assert_int_equal(tf_solver_info_of(many->solver)->solves, 12);
    free(one);
    tf_scene_run_free(many);
    tf_scene_run_free(units);
}

/* The context left at 0 threads takes OpenMP's default: the same bits as
 * one thread (test_conformance.c compares one and two). */
static void same_bits_with_openmps_default(void **state)
{
    (void)state;
    int saved = omp_get_max_threads();
    const char *finer[] = {"geometry.grid=15,15,4", "contact.0.node=113"};
    run *one = solve_on(BLOCK48, finer, 2, 1, unit_forces, 3);
    omp_set_num_threads(2);
    run *dflt = solve_on(BLOCK48, finer, 2, 0, unit_forces, 3);
    omp_set_num_threads(saved);
    size_t n = 9 * one->p->cloud.n;
    assert_memory_equal(one->u, dflt->u, n * sizeof *one->u);
    tf_scene_run_free(one);
    tf_scene_run_free(dflt);
}

/* Compliance at node 61 under 1 N along -z. */
static double uz61(const char *nu, const char *volumetric, const char *centre)
{
    char a[64], b[64], c[64];
    snprintf(a, sizeof a, "material.nu=%s", nu);
    snprintf(b, sizeof b, "solver.volumetric=%s", volumetric);
    snprintf(c, sizeof c, "solver.centre=%s", centre);
    const char *sets[] = {a, b, c};
    run *r = solve(sets, 3, unit_forces + 2, 1);
    double uz = -r->u[3 * 60 + 2];
    tf_scene_run_free(r);
    return uz;
}

static void cell_averaged_volume_strain_relieves_locking(void **state)
{
    (void)state;
    /* From nu = 0.49 to 0.499 the compliance barely changes in the
     * continuum; full integration locks (loses 29 %), B-bar does not. */
    assert_true(uz61("0.499", "full", "cell") < 0.8 * uz61("0.49", "full", "cell"));
    assert_true(uz61("0.499", "cell", "cell") > 0.95 * uz61("0.49", "cell", "cell"));
    assert_true(uz61("0.499", "cell", "point") > 0.95 * uz61("0.49", "cell", "point"));
    assert_true(uz61("0.49", "cell", "cell") > 1.1 * uz61("0.49", "full", "cell"));
}

static void nodes_are_exposed_in_scene_numbering(void **state)
{
    (void)state;
    run *r = solve(NULL, 0, unit_forces, 1);
    assert_int_equal(tf_solver_node_count(r->solver), 363);
    assert_int_equal(tf_problem_node_number(r->p, 60), 61);
    const double *x = tf_solver_coords(r->solver) + 3 * 60;
    assert_true(x[0] == 24 && x[1] == 24 && x[2] == 6);
    tf_scene_run_free(r);
}

/* block48 has no loads and clamped faces: linear.  The cantilever carries
 * a traction and prescribed values: affine only.  Both name the solver
 * they asked for, and an unknown one is refused with the list. */
static void capabilities_follow_the_problem(void **state)
{
    (void)state;
    run *b = solve(NULL, 0, unit_forces, 1);
    assert_int_equal(tf_solver_caps_of(b->solver),
                     TF_SOLVER_AFFINE | TF_SOLVER_LINEAR | TF_SOLVER_CUTS);
    assert_string_equal(tf_solver_name(b->solver), "rpim-galerkin");
    assert_non_null(tf_galerkin_info_of(b->solver));
    assert_true(tf_galerkin_info_of(b->solver)->nnz_k > 0);
    tf_solver_opts o = b->p->solver;
    snprintf(o.method, sizeof o.method, "fem");
    assert_null(tf_solver_create(b->p, &o, &b->ctx));
    assert_non_null(strstr(b->ctx.err, "no solver 'fem'"));
    assert_non_null(strstr(b->ctx.err, "rpim-galerkin"));
    tf_scene_run_free(b);
    run *c = solve_on("coeffs/cantilever.yaml", NULL, 0, 0, NULL, 1);
    assert_int_equal(tf_solver_caps_of(c->solver), TF_SOLVER_AFFINE | TF_SOLVER_CUTS);
    tf_scene_run_free(c);
}

static unsigned no_cuts(const tf_solver *s)
{
    return tf_galerkin_ops.caps(s) & ~(unsigned)TF_SOLVER_CUTS;
}

/* A problem with a cut is refused by a solver without the CUTS capability
 * (here rpim-galerkin with that bit taken away, and rpim-galerkin handing a
 * nonlinear law to the Newton solver, which has no cuts), with the solver
 * named. */
static void cuts_need_the_capability(void **state)
{
    (void)state;
    run *b = solve(NULL, 0, unit_forces, 1);
    tf_cut cut = {.n = 2, .xy = {{10, 20}, {30, 20}}, .top = 6, .depth = 3};
    tf_problem p = *b->p;
    p.cuts = &cut;
    p.n_cuts = 1;
    tf_solver_ops variant = tf_galerkin_ops;
    variant.caps = no_cuts;
    assert_null(tf_solver_create_as(&variant, &p, NULL, &b->ctx));
    assert_non_null(strstr(b->ctx.err, "does not support cuts"));
    tf_solver *s = tf_solver_create_as(&tf_galerkin_ops, &p, NULL, &b->ctx);
    assert_non_null(s);
    tf_solver_destroy(s);
    p.material.law = tf_law_find("neo-hookean"); /* (its parameters are linear's: E, nu) */
    assert_null(tf_solver_create_as(&tf_galerkin_ops, &p, NULL, &b->ctx));
    assert_non_null(strstr(b->ctx.err, "does not support cuts"));
    assert_non_null(strstr(b->ctx.err, "Newton"));
    tf_scene_run_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reactions_balance_a_point_force),
        cmocka_unit_test(cuts_need_the_capability),
        cmocka_unit_test(penalty_agrees_with_elimination),
        cmocka_unit_test(many_cases_through_one_factorisation),
        cmocka_unit_test(same_bits_with_openmps_default),
        cmocka_unit_test(cell_averaged_volume_strain_relieves_locking),
        cmocka_unit_test(nodes_are_exposed_in_scene_numbering),
        cmocka_unit_test(capabilities_follow_the_problem),
    };
    return cmocka_run_group_tests_name("solver", tests, NULL, NULL);
}
