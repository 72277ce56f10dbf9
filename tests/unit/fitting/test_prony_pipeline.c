/*
 * test_prony_pipeline.c — the fitting pipeline with a time-dependent
 * solver: it solves force histories (tf_solver_history) at the plan's tick,
 * the prony family applies and finds the solver's creep, and its held-out
 * errors are those of the histories; with the same solver declared static
 * the family does not apply and no history is solved.
 *
 * The solver is a test variant of rpim-galerkin (tf_solver_create_as):
 * the same static solves, declared TIME_DEPENDENT, whose history is block48
 * as a linear viscoelastic body (seed 001's Kelvin solid, k = 0): the unit
 * responses times the force filtered by the creep function, the force
 * linear between steps.  This is what issue 13's solver provides for a
 * Kelvin scene; the test checks the plumbing, not that solver.
 *
 * A solver step every m ticks (fit.solve_every): the ticks' forces are
 * linear between the solver's steps, the displacements at the solver's
 * steps are those of a solve at every tick of the same forces (this
 * solver is exact for force linear in a step), and between them within
 * the interpolation's error.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "fitting/cases.h"
#include "fitting/histories.h"
#include "fitting/pipeline.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define W 0.375   /* k2 / (k1 + k2) */
#define TAU_C 1.6 /* s */

static const tf_solver_ops *rpim;
static tf_solver_ops creeping;

static unsigned creeping_caps(const tf_solver *s)
{
    return rpim->caps(s) | TF_SOLVER_TIME_DEPENDENT;
}

/* u_n = u(0) + sum_k unit_k y_k[n], y = f - W e, e the exact update of
 * tau_c e' = -e + tau_c f' for f linear between steps. */
static int creeping_history(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                            double dt, double *u)
{
    const size_t dofs = 3 * tf_solver_node_count(s);
    const double unit[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double *base = malloc(4 * dofs * sizeof *base);
    if (base == NULL || rpim->solve(s, contact, unit, 4, NULL, base) != 0) {
        free(base);
        return -1;
    }
    const double r = dt / TAU_C, a = exp(-r), gain = -expm1(-r) / r;
    double e[3] = {0, 0, 0}, prev[3] = {0, 0, 0};
    for (size_t k = 0; k < n; ++k) {
        double y[3];
        for (int c = 0; c < 3; ++c) {
            e[c] = a * e[c] + gain * (forces[k][c] - prev[c]);
            prev[c] = forces[k][c];
            y[c] = forces[k][c] - W * e[c];
        }
        for (size_t i = 0; i < dofs; ++i) {
            u[k * dofs + i] = base[i] + y[0] * (base[dofs + i] - base[i]) +
                              y[1] * (base[2 * dofs + i] - base[i]) +
                              y[2] * (base[3 * dofs + i] - base[i]);
        }
    }
    free(base);
    return 0;
}

typedef struct fixture {
    tf_ctx ctx;
    tf_scene *scene;
} fixture;

static int setup(void **state)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    fixture *x = calloc(1, sizeof *x);
    tf_ctx_init(&x->ctx);
    x->ctx.level = TF_LOG_ERROR;
    x->scene = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", NULL, 0);
    if (x->scene == NULL) {
        print_error("%s\n", ctx.err);
        return -1;
    }
    rpim = tf_solver_type_find("rpim-galerkin");
    creeping = *rpim;
    creeping.caps = creeping_caps;
    creeping.history = creeping_history;
    *state = x;
    return 0;
}

static int teardown(void **state)
{
    fixture *x = *state;
    tf_scene_free(x->scene);
    free(x);
    return 0;
}

static const tf_family_result *prony_of(const tf_fit_outcome *o)
{
    return tf_fit_result_of(o, tf_family_find("prony"));
}

static void a_creeping_solver_gets_a_prony_model(void **state)
{
    fixture *x = *state;
    tf_fit_plan plan = x->scene->fit;
    plan.hist_train = 8;
    plan.hist_heldout = 4;
    plan.hist_ticks = 3000;
    tf_solver *s = tf_solver_create_as(&creeping, &x->scene->problem, NULL, &x->ctx);
    assert_non_null(s);
    tf_fit_outcome o;
    assert_int_equal(tf_fit_run(&x->ctx, &x->scene->problem, s, &plan, &o), 0);
    assert_true(o.has_hist && o.cases.hist == &o.hist);
    assert_int_equal(o.hist.train.n, 8);
    assert_int_equal(o.hist.heldout.n_ticks, 3000);
    const tf_family_result *r = prony_of(&o);
    assert_true(r->applicable);
    const tf_model *m = r->model;
    assert_int_equal(m->dims[2], 1);
    assert_int_equal(m->dims[3], plan.tick_ns);
    const float *pt = m->coef + TFIT_INPUT_MAP_FLOATS;
    print_message("prony: K = %u, a = %a (tau_c %g s asked), held-out max %.3g mm = %.3g %% of "
                  "the peak over %u histories\n",
                  m->dims[2], (double)pt[0], TAU_C, r->heldout_max, 100 * r->heldout_rel_max,
                  m->heldout_cases);
    assert_true(fabs((double)pt[0] - exp(-1e-3 / TAU_C)) < 1e-7);
    assert_true(r->heldout_rel_max < 1e-4);
    assert_int_equal(m->heldout_cases, 4);
    /* the emitted forward model is still the plan's family */
    assert_int_equal(tf_fit_emitted(&o, &plan, TF_FAMILY_FORWARD)->family, TFIT_FAMILY_NODAL);
    tf_fit_outcome_free(&o);
    tf_solver_destroy(s);
}

static void a_coarser_solver_step_is_interpolated(void **state)
{
    enum { M = 10, TICKS = 1001 };
    fixture *x = *state;
    tf_fit_plan plan = x->scene->fit;
    tf_solver *s = tf_solver_create_as(&creeping, &x->scene->problem, NULL, &x->ctx);
    tf_cases c;
    tf_histories h;
    assert_non_null(s);
    assert_int_equal(tf_cases_build(&x->scene->problem, s, &plan, &c), 0);
    assert_int_equal(tf_histories_solve(&c, TF_HIST_PRESS, 1000000, M, 2, 2, TICKS, 7, &h), 0);
    const tf_history_set *set = &h.heldout;
    const size_t dofs = 3 * tf_solver_node_count(s);
    const tf_outputs *o = &x->scene->problem.outputs;
    double *u = malloc(TICKS * dofs * sizeof *u), at_steps = 0, between = 0, peak = 0;
    assert_non_null(u);
    for (size_t i = 0; i < set->n; ++i) {
        const double(*f)[3] = (const double(*)[3])set->force + i * TICKS;
        for (size_t n = 0; n + M < TICKS; n += M) { /* linear between the steps */
            for (size_t q = 1; q < M; ++q) {
                for (int k = 0; k < 3; ++k) {
                    double lin = f[n][k] + (double)q / M * (f[n + M][k] - f[n][k]);
                    assert_true(fabs(f[n + q][k] - lin) <= 1e-6 * (1 + fabs(lin)));
                }
            }
        }
        assert_int_equal(creeping_history(s, c.contact, f, TICKS, 1e-3, u), 0);
        for (size_t n = 0; n < TICKS; ++n) {
            const double *fit = tf_history_u(set, i, n);
            for (size_t j = 0; j < o->n_nodes; ++j) {
                for (size_t k = 0; k < 3; ++k) {
                    double e = fabs(fit[3 * j + k] - u[n * dofs + 3 * (size_t)o->nodes[j] + k]);
                    peak = fmax(peak, fabs(fit[3 * j + k]));
                    if (n % M == 0) {
                        at_steps = fmax(at_steps, e);
                    } else {
                        between = fmax(between, e);
                    }
                }
            }
        }
    }
    print_message("solve_every %d: at the solver's steps %.3g mm, between them %.3g mm (peak "
                  "%.3g mm) against every tick solved\n", M, at_steps, between, peak);
    assert_true(peak > 0.1);
    assert_true(at_steps < 1e-9 * peak);
    assert_true(between < 1e-3 * peak);
    free(u);
    tf_histories_free(&h);
    tf_cases_free(&c);
    tf_solver_destroy(s);
}

static void a_static_solver_gets_none(void **state)
{
    fixture *x = *state;
    tf_fit_plan plan = x->scene->fit;
    tf_solver *s = tf_solver_create(&x->scene->problem, NULL, &x->ctx);
    tf_fit_outcome o;
    assert_int_equal(tf_fit_run(&x->ctx, &x->scene->problem, s, &plan, &o), 0);
    assert_false(o.has_hist);
    assert_null(o.cases.hist);
    const tf_family_result *r = prony_of(&o);
    assert_false(r->applicable);
    assert_non_null(strstr(r->why, "does not creep"));
    tf_fit_outcome_free(&o);
    tf_solver_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_creeping_solver_gets_a_prony_model),
        cmocka_unit_test(a_coarser_solver_step_is_interpolated),
        cmocka_unit_test(a_static_solver_gets_none),
    };
    return cmocka_run_group_tests_name("prony_pipeline", tests, setup, teardown);
}
