/*
 * test_conformance.c — what every registered solver (solvers/registry.c)
 * must do on block48 (GUIDE §5), through the solver interface only:
 *
 *   equilibrium   reactions at the supports balance the applied force, the
 *                 residual elsewhere vanishes (when the solver has
 *                 reactions; one without must refuse the call);
 *   symmetry      the fx case mirrored about x = y is the fy case, the fz
 *                 case is symmetric about both centre lines;
 *   1/E scaling   u(k E, k f) = u(E, f) for any law whose stresses scale
 *                 with E, and u(k E, f) = u(E, f) / k for a linear solver;
 *   threads       the same bits with one thread and with two;
 *   small loads   the secant compliance u(s f) / s has a limit: s = 1e-3
 *                 and 1e-4 N agree to 1e-3 (a linear solver: to 1e-12);
 *   capabilities  what a solver declares holds: AFFINE superposes, LINEAR
 *                 gives u(0) = 0, a static solver's history is its batch
 *                 (bit for bit when affine, else to 1e-9);
 *   arguments     a contact site the problem lacks is refused.
 *
 * A new solver is tested by registering it: nothing here names one.  Each
 * solver solves block48 once, as one batch of every load case the
 * properties use (the group's setup): the properties read their cases from
 * it, and only the stiffer material and the finer grid are solved again.
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

#include "scene_run.h"
#include "solvers/solver.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
#define GRID 11 /* block48's default grid: 11 x 11 x 3 */

static const double unit_forces[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};

/* The batch every solver solves once: the unit forces (equilibrium,
 * symmetry, the 1/E reference), two small loads (their limit) and the
 * capabilities' four cases (zero, two loads and their sum less zero). */
enum { UNIT = 0, SMALL = 3, CAPS = 5, N_CASES = 9 };
static const double cases[N_CASES][3] = {
    {1, 0, 0},       {0, 1, 0},        {0, 0, -1},         /* UNIT */
    {1e-3, -2e-3, -3e-3}, {1e-4, -2e-4, -3e-4},             /* SMALL: s = 1e-3, 1e-4 */
    {0, 0, 0},       {0.3, -0.2, 0.1}, {-0.1, 0.4, -0.5}, {0.2, 0.2, -0.4}, /* CAPS */
};

typedef tf_scene_run run;

#define MAX_SOLVERS 16
static run *batch[MAX_SOLVERS]; /* solver t's solve of cases, from setup */

/* displacement of case c in solver t's batch */
static const double *u_of(size_t t, size_t c)
{
    return batch[t]->u + c * batch[t]->n3;
}

/* Solver type t on block48 with overrides, threads (0: OpenMP's), and
 * cases forces[n] at contact site 0. */
static run *solve_with(const tf_solver_ops *t, const char *const *sets, size_t n_sets, int threads,
                       const double (*forces)[3], size_t n)
{
    return tf_scene_run_solve(BLOCK48, t, sets, n_sets, threads, forces, n);
}

static run *solve(const tf_solver_ops *t, const double (*forces)[3], size_t n)
{
    return solve_with(t, NULL, 0, 0, forces, n);
}

/* max |a - s b| / max |s b| */
static double mismatch(const double *a, const double *b, double s, size_t n)
{
    double worst = 0;
    for (size_t i = 0; i < n; ++i) {
        worst = fmax(worst, fabs(a[i] - s * b[i]));
    }
    return worst / (fabs(s) * tf_max_abs(b, n));
}

static int linear(const tf_solver *s)
{
    return (tf_solver_caps_of(s) & TF_SOLVER_LINEAR) != 0;
}

static void equilibrium(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const tf_solver_ops *type = tf_solver_type_at(t);
        const run *r = batch[t];
        double sum[3], resid;
        if (type->reactions == NULL) {
            assert_int_equal(tf_scene_run_balance(r, cases[UNIT], u_of(t, UNIT), sum, &resid), -1);
            print_message("%s: no reactions (refused, as declared)\n", type->name);
        }
        for (int c = UNIT; type->reactions != NULL && c < UNIT + 3; ++c) {
            assert_int_equal(tf_scene_run_balance(r, cases[c], u_of(t, (size_t)c), sum, &resid), 0);
            for (int a = 0; a < 3; ++a) {
                assert_true(fabs(sum[a] + cases[c][a]) < 1e-6);
            }
            assert_true(resid < 1e-9);
        }
    }
}

static void symmetry(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const run *r = batch[t];
        const tf_cloud *c = &r->p->cloud;
        const double *ux = u_of(t, UNIT), *uy = u_of(t, UNIT + 1), *uz = u_of(t, UNIT + 2);
        double worst = 0;
        for (unsigned k = 0; k < 3; ++k) {
            for (unsigned j = 0; j < GRID; ++j) {
                for (unsigned i = 0; i < GRID; ++i) {
                    size_t a = tf_cloud_index(c, i, j, k), b = tf_cloud_index(c, j, i, k);
                    size_t m = tf_cloud_index(c, GRID - 1 - i, j, k);
                    worst = fmax(worst, fabs(ux[3 * a] - uy[3 * b + 1]));
                    worst = fmax(worst, fabs(ux[3 * a + 1] - uy[3 * b]));
                    worst = fmax(worst, fabs(ux[3 * a + 2] - uy[3 * b + 2]));
                    worst = fmax(worst, fabs(uz[3 * a + 2] - uz[3 * m + 2]));
                    worst = fmax(worst, fabs(uz[3 * a] + uz[3 * m]));
                }
            }
        }
        assert_true(worst < 1e-9 * tf_max_abs(ux, 3 * r->n3));
        assert_true(uz[3 * 60 + 2] < 0 && ux[3 * 60] > 0); /* node 61 moves with the force */
    }
}

static void scaling_with_young_modulus(void **state)
{
    (void)state;
    const double k = 1000;
    double stiff_cases[6][3]; /* k f (both scaled), then f (E only) */
    for (int c = 0; c < 9; ++c) {
        stiff_cases[c / 3][c % 3] = k * unit_forces[c / 3][c % 3];
        stiff_cases[3 + c / 3][c % 3] = unit_forces[c / 3][c % 3];
    }
    const char *stiff[] = {"material.E=320"}; /* block48's 0.32 MPa x 1000 */
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const double *ref = u_of(t, UNIT);
        run *r = solve_with(tf_solver_type_at(t), stiff, 1, 0,
                            (const double(*)[3])stiff_cases, 6);
        const size_t n = 3 * r->n3;
        assert_true(mismatch(r->u, ref, 1, n) < 1e-9);
        if (linear(r->solver)) {
            assert_true(mismatch(r->u + n, ref, 1 / k, n) < 1e-12);
        }
        tf_scene_run_free(r);
    }
}

static void same_bits_with_one_and_two_threads(void **state)
{
    (void)state;
    const char *finer[] = {"geometry.grid=15,15,4", "contact.0.node=113"};
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const tf_solver_ops *type = tf_solver_type_at(t);
        run *one = solve_with(type, finer, 2, 1, unit_forces, 3);
        run *two = solve_with(type, finer, 2, 2, unit_forces, 3);
        assert_memory_equal(one->u, two->u, 3 * one->n3 * sizeof *one->u);
        tf_scene_run_free(one);
        tf_scene_run_free(two);
    }
}

static void small_load_limit(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const run *r = batch[t];
        /* secant compliances u(s f) / s at s = 1e-3 and 1e-4 */
        const double d = mismatch(u_of(t, SMALL), u_of(t, SMALL + 1), 10, r->n3);
        assert_true(d < (linear(r->solver) ? 1e-12 : 1e-3));
    }
}

static void capabilities_hold(void **state)
{
    (void)state;
    const double(*f)[3] = cases + CAPS;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        const tf_solver_ops *type = tf_solver_type_at(t);
        const run *r = batch[t];
        const unsigned caps = tf_solver_caps_of(r->solver);
        const double *u0 = u_of(t, CAPS), *u1 = u_of(t, CAPS + 1), *u2 = u_of(t, CAPS + 2);
        const double *u12 = u_of(t, CAPS + 3), scale = tf_max_abs(u0, 4 * r->n3);
        assert_true(!(caps & TF_SOLVER_LINEAR) || (caps & TF_SOLVER_AFFINE));
        for (size_t d = 0; (caps & TF_SOLVER_AFFINE) && d < r->n3; ++d) {
            assert_true(fabs(u12[d] - (u1[d] + u2[d] - u0[d])) < 1e-12 * scale);
        }
        if (caps & TF_SOLVER_LINEAR) {
            assert_true(tf_max_abs(u0, r->n3) <= 1e-14 * scale);
        }
        if (!(caps & TF_SOLVER_TIME_DEPENDENT)) {
            /* a static solver's history is its batch: the same bits when
             * affine (one batch of the same four forces: an iterative
             * solver's stopping test sees the whole batch); else step by
             * step, each from the last step's displacement, to the solver's
             * tolerance */
            double *h = malloc(8 * r->n3 * sizeof *h), *four = h + 4 * r->n3;
            assert_non_null(h);
            assert_int_equal(tf_solver_history(r->solver, 0, f, 4, 1e-3, h), 0);
            if (caps & TF_SOLVER_AFFINE) {
                assert_int_equal(tf_solver_solve(r->solver, 0, f, 4, NULL, four), 0);
                assert_memory_equal(h, four, 4 * r->n3 * sizeof *h);
            } else {
                assert_true(mismatch(h, u0, 1, 4 * r->n3) < 1e-9);
            }
            free(h);
        }
        assert_string_equal(tf_solver_name(r->solver), type->name);
        assert_ptr_equal(tf_solver_type_find(type->name), type);
    }
}

static void bad_arguments_are_refused(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        run *r = batch[t];
        double *u = malloc(r->n3 * sizeof *u); /* the batch stays as solved */
        assert_non_null(u);
        r->ctx.err[0] = '\0';
        assert_int_equal(tf_solver_solve(r->solver, 1, unit_forces, 1, NULL, u), -1);
        assert_non_null(strstr(r->ctx.err, "no contact site 1"));
        assert_int_equal(tf_solver_solve(r->solver, 0, NULL, 1, NULL, u), -1);
        assert_int_equal(tf_solver_reactions(r->solver, 2, unit_forces[0], u, u), -1);
        assert_int_equal(tf_solver_history(r->solver, 0, unit_forces, 1, 0, u), -1);
        assert_non_null(strstr(r->ctx.err, "time step"));
        free(u);
    }
}

static int solve_batches(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        batch[t] = solve(tf_solver_type_at(t), cases, N_CASES);
    }
    return 0;
}

static int free_batches(void **state)
{
    (void)state;
    for (size_t t = 0; t < tf_solver_type_count(); ++t) {
        tf_scene_run_free(batch[t]);
        batch[t] = NULL;
    }
    return 0;
}

int main(void)
{
    char names[256];
    tf_solver_type_names(names, sizeof names);
    print_message("solver conformance: %zu registered solver(s): %s\n", tf_solver_type_count(),
                  names);
    if (tf_solver_type_count() == 0 || tf_solver_type_count() > MAX_SOLVERS) {
        print_error("%zu solvers registered: 1 to %d are tested\n", tf_solver_type_count(),
                    MAX_SOLVERS);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(equilibrium),
        cmocka_unit_test(symmetry),
        cmocka_unit_test(scaling_with_young_modulus),
        cmocka_unit_test(same_bits_with_one_and_two_threads),
        cmocka_unit_test(small_load_limit),
        cmocka_unit_test(capabilities_hold),
        cmocka_unit_test(bad_arguments_are_refused),
    };
    return cmocka_run_group_tests_name("solver_conformance", tests, solve_batches, free_batches);
}
