/*
 * test_colloc_solver.c — the MLS collocation solver behind the solver
 * interface ("mls-collocation", solvers/collocation/colloc_solver.h) on
 * block48: equilibrium of reactions and load, a suddenly applied force's
 * overshoot and its damped end at the static answer, the same bits on 1
 * and 2 threads, the field between particles, the scene's collocation keys.
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

#include "assert_close.h"
#include "base/context.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
#define NODE61 60 /* index of the top centre */

static const double down[1][3] = {{0, 0, -0.01}}; /* small: the linear limit */

typedef struct run {
    tf_ctx ctx;
    tf_scene *scene;
    tf_solver *solver;
    size_t n3;
} run;

static run *open_block48(int threads, const char *extra)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    run *r = calloc(1, sizeof *r);
    tf_ctx_init(&r->ctx);
    r->ctx.level = TF_LOG_ERROR;
    r->ctx.threads = threads;
    const char *sets[2] = {"solver.method=mls-collocation", extra};
    r->scene = tf_scene_load(&ctx, BLOCK48, sets, extra ? 2 : 1);
    if (r->scene == NULL) {
        fail_msg("%s", ctx.err);
    }
    r->solver = tf_solver_create(&r->scene->problem, NULL, &r->ctx);
    if (r->solver == NULL) {
        fail_msg("%s", r->ctx.err);
    }
    r->n3 = 3 * r->scene->problem.cloud.n;
    return r;
}

static void done(run *r)
{
    tf_solver_destroy(r->solver);
    tf_scene_free(r->scene);
    free(r);
}

/* A static case is in equilibrium: the supports take the load, and the
 * residual at free components is below the relaxation's tolerance. */
static void static_case_balances(void **state)
{
    (void)state;
    run *r = open_block48(0, NULL);
    assert_int_equal(tf_solver_caps_of(r->solver), TF_SOLVER_TIME_DEPENDENT);
    assert_string_equal(tf_solver_name(r->solver), "mls-collocation");
    double *u = malloc(r->n3 * sizeof *u), *re = malloc(r->n3 * sizeof *re);
    assert_int_equal(tf_solver_solve(r->solver, 0, down, 1, NULL, u), 0);
    assert_true(u[3 * NODE61 + 2] < -1e-3); /* about -0.02 mm */
    assert_int_equal(tf_solver_reactions(r->solver, 0, down[0], u, re), 0);
    unsigned char *fixed = calloc(r->n3, 1);
    tf_problem_fixed_dofs(&r->scene->problem, fixed);
    double support = 0, worst = 0;
    for (size_t d = 2; d < r->n3; d += 3) {
        if (fixed[d]) {
            support += re[d];
        } else {
            worst = fmax(worst, fabs(re[d]));
        }
    }
    assert_close(support, 0.01, 1e-6); /* K u - f at the supports: their reaction, up */
    assert_true(worst < 1e-6 * 0.01);
    free(fixed);
    free(u);
    free(re);
    done(r);
}

/* A force applied suddenly and held: without damping the top centre
 * overshoots its static displacement (up to twice it, for one mode); with
 * damping the history ends at the static answer. */
static void history_overshoots_then_settles(void **state)
{
    (void)state;
    enum { steps = 80 };
    double (*f)[3] = malloc(steps * sizeof *f);
    for (int k = 0; k < steps; ++k) {
        f[k][0] = f[k][1] = 0;
        f[k][2] = -0.01;
    }
    run *r = open_block48(0, NULL);
    double *us = malloc(r->n3 * sizeof *us), *uh = malloc(r->n3 * steps * sizeof *uh);
    assert_int_equal(tf_solver_solve(r->solver, 0, down, 1, NULL, us), 0);
    assert_int_equal(tf_solver_history(r->solver, 0, (const double(*)[3])f, steps, 5e-4, uh), 0);
    double peak = 0, stat = us[3 * NODE61 + 2];
    for (int k = 0; k < steps; ++k) {
        peak = fmin(peak, uh[k * r->n3 + 3 * NODE61 + 2]);
    }
    assert_true(peak / stat > 1.5 && peak / stat < 2.05);
    done(r);
    r = open_block48(0, "solver.collocation.damping=2000");
    assert_int_equal(tf_solver_history(r->solver, 0, (const double(*)[3])f, steps, 5e-4, uh), 0);
    assert_close(uh[(steps - 1) * r->n3 + 3 * NODE61 + 2], stat, 0.01 * fabs(stat));
    done(r);
    free(f);
    free(us);
    free(uh);
}

/* The interface's thread count reaches the solver: 1 and 2 threads give
 * the same bits. */
static void same_bits_on_one_and_two_threads(void **state)
{
    (void)state;
    double *u[2];
    for (int t = 0; t < 2; ++t) {
        run *r = open_block48(t + 1, NULL);
        u[t] = malloc(r->n3 * sizeof *u[t]);
        assert_int_equal(tf_solver_solve(r->solver, 0, down, 1, NULL, u[t]), 0);
        if (t) {
            assert_memory_equal(u[0], u[1], r->n3 * sizeof *u[0]);
        }
        done(r);
    }
    free(u[0]);
    free(u[1]);
}

/* solver.collocation keys: a bad one is refused, naming it. */
/* The field between particles (the self-measured discretisation compares
 * clouds through it): the particle's own value at a particle, and a linear
 * displacement reproduced anywhere, gradient included (the MLS gradient's
 * first-order consistency, seed 004 eq 9). */
static void field_between_particles(void **state)
{
    (void)state;
    run *r = open_block48(1, NULL);
    const tf_cloud *cl = &r->scene->problem.cloud;
    const double A[9] = {1e-3, -2e-3, 5e-4, 3e-3, 1e-3, -1e-3, -5e-4, 2e-3, 4e-3}, b[3] = {0.1, -0.2, 0.05};
    double *u = malloc(r->n3 * sizeof *u);
    for (size_t i = 0; i < cl->n; ++i) {
        for (int a = 0; a < 3; ++a) {
            const double *x = cl->xyz + 3 * i;
            u[3 * i + (size_t)a] = b[a] + A[3 * a] * x[0] + A[3 * a + 1] * x[1] + A[3 * a + 2] * x[2];
        }
    }
    /* two particles, then points between them (away from the clamped faces) */
    const double x[5][3] = {{24, 24, 6}, {4.8, 9.6, 0}, {21.7, 25.9, 4.4}, {30.1, 14.2, 1.3},
                            {9.9, 38.3, 5.2}};
    double uh[15], grad[45];
    assert_int_equal(tf_solver_field(&r->ctx, r->solver, u, &x[0][0], 5, uh, grad), 0);
    for (int a = 0; a < 3; ++a) {
        assert_true(uh[a] == u[3 * NODE61 + (size_t)a]); /* exactly the particle's */
    }
    for (size_t j = 0; j < 5; ++j) {
        for (int a = 0; a < 3; ++a) {
            const double want = b[a] + A[3 * a] * x[j][0] + A[3 * a + 1] * x[j][1] + A[3 * a + 2] * x[j][2];
            assert_close(uh[3 * j + (size_t)a], want, 1e-12);
            for (int c = 0; c < 3; ++c) {
                assert_close(grad[9 * j + 3 * (size_t)a + (size_t)c], A[3 * a + c], 1e-12);
            }
        }
    }
    free(u);
    done(r);
}

static void bad_keys_are_named(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *bad[][2] = {{"solver.collocation.density=0", "solver.collocation.density"},
                            {"solver.collocation.neighbours=2", "solver.collocation.neighbours"},
                            {"solver.collocation.support=0.5", "solver.collocation.support"},
                            {"solver.collocation.tolerance=2", "solver.collocation.tolerance"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        const char *sets[2] = {"solver.method=mls-collocation", bad[k][0]};
        tf_scene *s = tf_scene_load(&ctx, BLOCK48, sets, 2);
        assert_null(s);
        assert_non_null(strstr(ctx.err, bad[k][1]));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(static_case_balances),
        cmocka_unit_test(history_overshoots_then_settles),
        cmocka_unit_test(same_bits_on_one_and_two_threads),
        cmocka_unit_test(field_between_particles),
        cmocka_unit_test(bad_keys_are_named),
    };
    return cmocka_run_group_tests_name("colloc_solver", tests, NULL, NULL);
}
