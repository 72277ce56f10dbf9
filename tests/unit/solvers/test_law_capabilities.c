/*
 * test_law_capabilities.c — a solver's behaviour for a material depends
 * only on what the material declares (materials/material.h), never on
 * which law it is.
 *
 * Each case solves block48 (7 x 7 x 3) with a registered law and again
 * with its twin: a law defined here, outside the registry, whose table is
 * a copy of the registered law's under another name and whose evaluation
 * is another function calling the original.  A solver that recognised a
 * law by its name, its table or its evaluation function would take another
 * path for the twin; every registered solver type gives the twin's answer
 * bit for bit, and names the same solver.  The controls show the
 * comparison would notice: the same twin declaring one capability or
 * quantity less (HOOKE, or the tr E volume measure) is solved otherwise.
 */
#include <math.h>
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
#include "solvers/solver.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
#define SMALL_GRID "geometry.grid=7,7,3"
#define SMALL_NODE "contact.0.node=25" /* the top centre of the 7 x 7 x 3 grid */

static const double force[1][3] = {{0.02, -0.01, -0.06}};

/* The twins' evaluations: the registered law's, through another function. */
#define TWIN_EVAL(fn, law)                                                                      \
    static int fn(const double *p, const double F[9], double dt, const double *hold,           \
                  double *hnew, double S[6], double C[36], double *W)                          \
    {                                                                                           \
        return tf_law_find(law)->eval(p, F, dt, hold, hnew, S, C, W);                           \
    }
TWIN_EVAL(linear_eval, "linear")
TWIN_EVAL(svk_eval, "svk")
TWIN_EVAL(kelvin_eval, "kelvin")
TWIN_EVAL(kelvin_nh_eval, "kelvin-neo-hookean")

static tf_law_ops twin_of(const char *law, int (*eval)(const double *, const double *, double,
                                                        const double *, double *, double *,
                                                        double *, double *))
{
    tf_law_ops t = *tf_law_find(law);
    t.name = "twin";
    t.eval = eval;
    return t;
}

typedef struct solved {
    char name[64];
    unsigned caps;
    size_t n3;
    double *u; /* 3N x steps */
} solved;

/* block48 (small) with sets, its material's law replaced by law (NULL:
 * kept), solved by its solver.method: one static case, or a history of
 * steps when steps > 1. */
static solved solve(const char *const *sets, size_t n_sets, const tf_law_ops *law, int steps)
{
    const char *all[8] = {SMALL_GRID, SMALL_NODE};
    for (size_t k = 0; k < n_sets; ++k) {
        all[2 + k] = sets[k];
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_scene *sc = tf_scene_load(&ctx, BLOCK48, all, 2 + n_sets);
    if (sc == NULL) {
        fail_msg("%s", ctx.err);
    }
    if (law != NULL) {
        sc->problem.material.law = law; /* the same parameters, in the same order */
    }
    tf_solver *s = tf_solver_create(&sc->problem, NULL, &ctx);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    solved out = {.caps = tf_solver_caps_of(s), .n3 = 3 * sc->problem.cloud.n};
    snprintf(out.name, sizeof out.name, "%s", tf_solver_name(s));
    out.u = malloc((size_t)steps * out.n3 * sizeof *out.u);
    double f[4][3];
    for (int k = 0; k < steps; ++k) {
        for (int a = 0; a < 3; ++a) {
            f[k][a] = force[0][a] * (k + 1) / steps;
        }
    }
    int rc = steps > 1 ? tf_solver_history(s, 0, (const double(*)[3])f, (size_t)steps, 0.1, out.u)
                       : tf_solver_solve(s, 0, force, 1, NULL, out.u);
    if (rc != 0) {
        fail_msg("%s", ctx.err);
    }
    tf_solver_destroy(s);
    tf_scene_free(sc);
    return out;
}

/* The twin's run is the law's, bit for bit, by the same solver. */
static void same(const solved *a, const solved *b, int steps)
{
    assert_string_equal(a->name, b->name);
    assert_int_equal(a->caps, b->caps);
    assert_memory_equal(a->u, b->u, (size_t)steps * a->n3 * sizeof *a->u);
}

static void solved_free(solved *s) { free(s->u); }

/* rpim-galerkin: a linear elastic material (HOOKE at small strain) is
 * factorised once; its twin too.  Without HOOKE the twin goes to the
 * Newton solver. */
static void galerkin_asks_for_hooke(void **state)
{
    (void)state;
    tf_law_ops twin = twin_of("linear", linear_eval);
    solved law = solve(NULL, 0, NULL, 1), t = solve(NULL, 0, &twin, 1);
    same(&law, &t, 1);
    assert_string_equal(law.name, "rpim-galerkin");
    twin.caps &= ~(unsigned)TF_MATERIAL_HOOKE;
    solved newton = solve(NULL, 0, &twin, 1);
    assert_string_equal(newton.name, "rpim-newton");
    assert_memory_not_equal(newton.u, law.u, law.n3 * sizeof *law.u);
    double scale = 0, worst = 0;
    for (size_t d = 0; d < law.n3; ++d) { /* the same equilibrium, to Newton's tolerance */
        scale = fmax(scale, fabs(law.u[d]));
        worst = fmax(worst, fabs(newton.u[d] - law.u[d]));
    }
    assert_true(worst < 1e-6 * scale);
    solved_free(&law);
    solved_free(&t);
    solved_free(&newton);
}

/* The Newton solver's volumetric correction averages the volume measure
 * the material declares (St. Venant-Kirchhoff's tr E). */
static void newton_asks_for_the_volume_measure(void **state)
{
    (void)state;
    const char *sets[] = {"material.law=svk"};
    tf_law_ops twin = twin_of("svk", svk_eval);
    solved law = solve(sets, 1, NULL, 1), t = solve(sets, 1, &twin, 1);
    same(&law, &t, 1);
    assert_string_equal(law.name, "rpim-newton");
    twin.volume = TF_VOLUME_JACOBIAN;
    solved other = solve(sets, 1, &twin, 1);
    assert_memory_not_equal(other.u, law.u, law.n3 * sizeof *law.u);
    solved_free(&law);
    solved_free(&t);
    solved_free(&other);
}

/* An unsymmetric tangent (Kelvin with k != 0: GMRES) and a history
 * (TIME_DEPENDENT): a force history through rpim-newton directly. */
static void newton_asks_for_history_and_symmetry(void **state)
{
    (void)state;
    const char *sets[] = {"material={law: kelvin, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3, k: 0.8}",
                          "solver.method=rpim-newton"};
    tf_law_ops twin = twin_of("kelvin", kelvin_eval);
    solved law = solve(sets, 2, NULL, 3), t = solve(sets, 2, &twin, 3);
    same(&law, &t, 3);
    assert_true(law.caps & TF_SOLVER_TIME_DEPENDENT);
    solved_free(&law);
    solved_free(&t);
}

/* efg-galerkin hands a finite-strain material with history to efg-newton. */
static void efg_galerkin_hands_over_by_capability(void **state)
{
    (void)state;
    const char *sets[] = {
        "material={law: kelvin-neo-hookean, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3}",
        "solver.method=efg-galerkin"};
    tf_law_ops twin = twin_of("kelvin-neo-hookean", kelvin_nh_eval);
    solved law = solve(sets, 2, NULL, 1), t = solve(sets, 2, &twin, 1);
    same(&law, &t, 1);
    assert_string_equal(law.name, "efg-newton");
    solved_free(&law);
    solved_free(&t);
}

/* mls-collocation evaluates a HOOKE material at finite strain inline (its
 * own copy of St. Venant-Kirchhoff's operations): the twin takes that path,
 * and without HOOKE the law's own evaluation, with the same bits. */
static void collocation_asks_for_hooke(void **state)
{
    (void)state;
    const char *sets[] = {"material.law=svk", "solver.method=mls-collocation"};
    tf_law_ops twin = twin_of("svk", svk_eval);
    solved law = solve(sets, 2, NULL, 1), t = solve(sets, 2, &twin, 1);
    same(&law, &t, 1);
    twin.caps &= ~(unsigned)TF_MATERIAL_HOOKE;
    solved called = solve(sets, 2, &twin, 1);
    same(&law, &called, 1);
    solved_free(&law);
    solved_free(&t);
    solved_free(&called);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(galerkin_asks_for_hooke),
        cmocka_unit_test(newton_asks_for_the_volume_measure),
        cmocka_unit_test(newton_asks_for_history_and_symmetry),
        cmocka_unit_test(efg_galerkin_hands_over_by_capability),
        cmocka_unit_test(collocation_asks_for_hooke),
    };
    return cmocka_run_group_tests_name("law_capabilities", tests, NULL, NULL);
}
