/*
 * test_resonant_fit.c — the resonant family's fit (fitting/resonant_modes.c,
 * fitting/families/resonant.c): frequencies, damping ratios and weights
 * recovered from exact data, the number of modes by cross-validation, and
 * the whole pipeline with a ringing solver: dynamic histories designed and
 * solved, the family fitted and judged on held-out histories, and not
 * fitted unless asked for.
 *
 * The solver is a test variant of rpim-galerkin (tf_solver_create_as): the
 * same static solves, declared TIME_DEPENDENT, whose history is block48 as
 * a linear body with one damped mode per force axis (the unit responses
 * times the force carried through the mode, the force held over each
 * step, as mls-collocation applies it).  It checks the plumbing and the
 * fit, not a physical solver (docs/fitting.md §8 has the collocation runs).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "base/rng.h"
#include "fitting/families/resonant_family.h"
#include "fitting/pipeline.h"
#include "fitting/resonant_modes.h"
#include "model/forms/resonant.h"
#include "scene/scene.h"
#include "solvers/solver.h"

#define TICKS 1500
#define HIST 8
#define TICK 1e-3
#define TWO_PI 6.283185307179586

/* Histories of g (strikes of 2..8 ticks and presses along random
 * directions, then ringing) and the target h of modes t, by the
 * zero-order-hold recursion in double. */
static void make_data(const tf_resonant_modes *t, double *g, double *h, uint64_t seed)
{
    tf_rng r = {seed};
    for (int k = 0; k < HIST; ++k) {
        double to[3], s[TFIT_RESONANT_MAX_MODES][3] = {{0}}, v[TFIT_RESONANT_MAX_MODES][3] = {{0}};
        double prev[3] = {0, 0, 0}, F[TFIT_RESONANT_MAX_MODES][4];
        for (int j = 0; j < t->n; ++j) {
            tf_resonant_transition(t->omega[j] * TICK, t->zeta[j], F[j]);
        }
        for (int c = 0; c < 3; ++c) {
            to[c] = tf_rng_range(&r, -0.4, 0.4);
        }
        const long on = 20 + (long)tf_rng_below(&r, 100), len = k % 2 ? 2 + (long)tf_rng_below(&r, 7)
                                                                       : 200 + (long)tf_rng_below(&r, 400);
        for (long n = 0; n < TICKS; ++n) {
            const double lev = n >= on && n < on + len ? 1.0 : 0.0;
            double *gn = g + 3 * ((size_t)k * TICKS + (size_t)n), *hn = h + (gn - g);
            for (int c = 0; c < 3; ++c) {
                gn[c] = lev * to[c];
                hn[c] = gn[c];
                for (int j = 0; j < t->n; ++j) {
                    const double e1 = s[j][c] - (gn[c] - prev[c]), e2 = v[j][c];
                    s[j][c] = F[j][0] * e1 + F[j][1] * e2;
                    v[j][c] = F[j][2] * e1 + F[j][3] * e2;
                    hn[c] += t->w[j][c] * s[j][c];
                }
                prev[c] = gn[c];
            }
        }
    }
}

static tf_prony_data data_of(const double *g, const double *h)
{
    return (tf_prony_data){.n_hist = HIST, .n_ticks = TICKS, .g = g, .target = h,
                           .g_rest = {0, 0, 0}, .tick = TICK};
}

static const tf_resonant_bounds bounds = {2 * TWO_PI, 1.5 / TICK, 1e-3, 1.0};

static void modes_are_recovered_from_exact_data(void **state)
{
    (void)state;
    const tf_resonant_modes truth = {2, {TWO_PI * 12, TWO_PI * 95}, {0.04, 0.15},
                                     {{0.7, 0.5, 0.9}, {0.2, 0.35, -0.1}}, 0};
    double *g = malloc(3 * HIST * TICKS * sizeof *g), *h = malloc(3 * HIST * TICKS * sizeof *h);
    make_data(&truth, g, h, 1);
    const tf_prony_data d = data_of(g, h);
    tf_resonant_modes t;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_resonant_fit_modes(&ctx, &d, NULL, 0, 2, &bounds, &t), 0);
    for (int j = 0; j < 2; ++j) {
        print_message("mode %d: %.9g Hz (truth %g), zeta %.9g (truth %g), w %.6g %.6g %.6g\n", j,
                      t.omega[j] / TWO_PI, truth.omega[j] / TWO_PI, t.zeta[j], truth.zeta[j],
                      t.w[j][0], t.w[j][1], t.w[j][2]);
        assert_true(fabs(t.omega[j] / truth.omega[j] - 1) < 1e-6);
        assert_true(fabs(t.zeta[j] / truth.zeta[j] - 1) < 1e-5);
        for (int c = 0; c < 3; ++c) {
            assert_true(fabs(t.w[j][c] - truth.w[j][c]) < 1e-6);
        }
    }
    assert_true(t.rms < 1e-9);
    free(g);
    free(h);
}

static void cross_validation_finds_the_number_of_modes(void **state)
{
    (void)state;
    const tf_resonant_modes cases[3] = {
        {0, {0}, {0}, {{0}}, 0},
        {1, {TWO_PI * 30}, {0.05}, {{0.8, 0.8, 0.6}}, 0},
        {2, {TWO_PI * 8, TWO_PI * 140}, {0.1, 0.03}, {{0.6, 0.7, 0.5}, {0.3, 0.2, 0.4}}, 0}};
    double *g = malloc(3 * HIST * TICKS * sizeof *g), *h = malloc(3 * HIST * TICKS * sizeof *h);
    tf_fit_plan plan;
    tf_fit_plan_defaults(&plan);
    tf_histories hist = {.tick = TICK, .tick_ns = 1000000};
    hist.train.n_ticks = TICKS;
    for (int c = 0; c < 3; ++c) {
        make_data(&cases[c], g, h, 10 + (uint64_t)c);
        const tf_prony_data d = data_of(g, h);
        double cv[TF_RESONANT_SEARCH_MODES + 1];
        int k;
        tf_resonant_modes t;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        assert_int_equal(tf_resonant_select_modes(&ctx, &d, &hist, &plan, cv, &k, &t), 0);
        print_message("truth K = %d: CV RMS by K %.3g %.3g %.3g %.3g: K = %d\n", cases[c].n, cv[0],
                      cv[1], cv[2], cv[3], k);
        assert_int_equal(k, cases[c].n);
    }
    free(g);
    free(h);
}

/* ---- the pipeline with a ringing solver ---------------------------------- */

#define OMEGA (TWO_PI * 25)
#define ZETA 0.04
static const double WEIGHT[3] = {0.9, 0.8, 0.95};

static const tf_solver_ops *rpim;
static tf_solver_ops ringing;

static unsigned ringing_caps(const tf_solver *s)
{
    return rpim->caps(s) | TF_SOLVER_TIME_DEPENDENT;
}

/* u_n = u(0) + sum_a unit_a y_a[n], y_a = f_a + W_a (x_a - f_a), x the
 * unit-gain oscillator under the force held over each step. */
static int ringing_history(tf_solver *s, int contact, const double (*forces)[3], size_t n,
                           double dt, double *u)
{
    const size_t dofs = 3 * tf_solver_node_count(s);
    const double unit[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double *base = malloc(4 * dofs * sizeof *base), F[4];
    if (base == NULL || rpim->solve(s, contact, unit, 4, NULL, base) != 0) {
        free(base);
        return -1;
    }
    tf_resonant_transition(OMEGA * dt, ZETA, F);
    double x[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    for (size_t k = 0; k < n; ++k) {
        double y[3];
        for (int c = 0; c < 3; ++c) {
            const double e1 = x[c] - forces[k][c], e2 = v[c];
            x[c] = forces[k][c] + F[0] * e1 + F[1] * e2;
            v[c] = F[2] * e1 + F[3] * e2;
            y[c] = forces[k][c] + WEIGHT[c] * (x[c] - forces[k][c]);
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
    ringing = *rpim;
    ringing.caps = ringing_caps;
    ringing.history = ringing_history;
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

static void a_ringing_solver_gets_a_resonant_model(void **state)
{
    fixture *x = *state;
    tf_fit_plan plan = x->scene->fit;
    plan.family = tf_family_find("resonant");
    plan.hist_train = 8;
    plan.hist_heldout = 4;
    plan.hist_ticks = 800;
    tf_solver *s = tf_solver_create_as(&ringing, &x->scene->problem, NULL, &x->ctx);
    assert_non_null(s);
    tf_fit_outcome o;
    assert_int_equal(tf_fit_run(&x->ctx, &x->scene->problem, s, &plan, &o), 0);
    assert_true(o.has_hist);
    /* the dynamic design: every history starts and ends at rest, and one
     * training history in four is a strike of at most 8 ticks */
    size_t loaded = 0;
    for (size_t n = 0; n < o.hist.train.n_ticks; ++n) {
        const double *f = tf_history_force(&o.hist.train, 0, n);
        loaded += f[0] != 0 || f[1] != 0 || f[2] != 0;
    }
    print_message("strike: the force acts on %zu ticks of %zu\n", loaded, o.hist.train.n_ticks);
    assert_true(loaded >= 1 && loaded <= 16);
    const tf_family_result *r = tf_fit_result_of(&o, tf_family_find("resonant"));
    assert_true(r->applicable);
    const tf_model *m = r->model;
    double omega, zeta, w[3];
    tf_resonant_get_mode(m, 0, &omega, &zeta, w);
    print_message("resonant: K = %u, %.6g Hz (asked %g), zeta %.6g (asked %g), w %.4g %.4g %.4g; "
                  "held-out max %.3g mm = %.3g %% of the peak over %u histories\n",
                  m->dims[2], omega / TWO_PI, OMEGA / TWO_PI, zeta, ZETA, w[0], w[1], w[2],
                  r->heldout_max, 100 * r->heldout_rel_max, m->heldout_cases);
    assert_int_equal(m->dims[2], 1);
    assert_true(fabs(omega / OMEGA - 1) < 1e-5);
    assert_true(fabs(zeta / ZETA - 1) < 1e-4);
    assert_true(r->heldout_rel_max < 1e-4);
    assert_int_equal(m->heldout_cases, 4);
    assert_int_equal(tf_fit_emitted(&o, &plan, TF_FAMILY_FORWARD)->family, TFIT_FAMILY_RESONANT);
    /* prony fits the same histories and cannot ring: far worse */
    const tf_family_result *p = tf_fit_result_of(&o, tf_family_find("prony"));
    print_message("prony on the same histories: held-out %.3g %% of the peak\n",
                  100 * p->heldout_rel_max);
    assert_true(p->heldout_rel_max > 100 * r->heldout_rel_max);
    tf_fit_outcome_free(&o);
    tf_solver_destroy(s);
}

static void not_fitted_unless_asked(void **state)
{
    fixture *x = *state;
    tf_fit_plan plan = x->scene->fit;
    plan.hist_train = 4;
    plan.hist_heldout = 2;
    plan.hist_ticks = 100;
    tf_solver *s = tf_solver_create_as(&ringing, &x->scene->problem, NULL, &x->ctx);
    tf_fit_outcome o;
    assert_int_equal(tf_fit_run(&x->ctx, &x->scene->problem, s, &plan, &o), 0);
    const tf_family_result *r = tf_fit_result_of(&o, tf_family_find("resonant"));
    assert_false(r->applicable);
    assert_non_null(strstr(r->why, "fit.family: resonant"));
    tf_fit_outcome_free(&o);
    tf_solver_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(modes_are_recovered_from_exact_data),
        cmocka_unit_test(cross_validation_finds_the_number_of_modes),
        cmocka_unit_test(a_ringing_solver_gets_a_resonant_model),
        cmocka_unit_test(not_fitted_unless_asked),
    };
    return cmocka_run_group_tests_name("resonant_fit", tests, setup, teardown);
}
