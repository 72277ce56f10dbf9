/*
 * test_indefinite.c — what the Newton solver does with a tangent that is
 * not positive definite (solver.newton.indefinite, nl_linear.c).  On a
 * small block48, 3 times the 1.5 N neo-Hookean equilibrium's displacements
 * is a state past stability (test_stability.c: mu_1 < 0 already at 2.5
 * times).  A solve of the same load started there must come back to the
 * equilibrium reached from rest (a stable one, mu_1 > 0): through LDL^T
 * factorisations of the indefinite tangents (ldl), or through Cholesky
 * factorisations of shifted ones and no LDL^T (shift), for full Newton and
 * Krylov; BFGS starts from the rest tangent's factor and needs neither.  A
 * scene naming another strategy is refused.
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

#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#include "scene_refused.h"
#include "scene_run.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
#define PAST 3.0 /* times the equilibrium: past stability */

typedef struct outcome {
    tf_nonlinear_info in; /* of the second solve */
    double diff;          /* max |u - u_rest| / max |u_rest| */
    double mu;            /* mu_1 at its answer */
} outcome;

/* Solves 1.5 N from rest, then again from PAST times that answer. */
static outcome from_past_stability(const char *tangent, const char *indefinite)
{
    const char *sets[] = {"geometry.grid=7,7,3", "contact.0.node=25",
                          "material.law=neo-hookean", tangent, indefinite};
    const double f[1][3] = {{0, 0, -1.5}};
    tf_scene_run *r = tf_scene_run_solve(BLOCK48, NULL, sets, 5, 1, f, 1);
    double *u0 = malloc(r->n3 * sizeof *u0), *u = malloc(r->n3 * sizeof *u);
    assert_non_null(u0);
    assert_non_null(u);
    for (size_t i = 0; i < r->n3; ++i) {
        u0[i] = PAST * r->u[i];
    }
    tf_nonlinear_info a;
    outcome o;
    assert_int_equal(tf_nonlinear_info_of(r->solver, &a), 0);
    assert_int_equal(tf_solver_solve(r->solver, 0, f, 1, u0, u), 0);
    assert_int_equal(tf_nonlinear_info_of(r->solver, &o.in), 0);
    o.in.steps -= a.steps;
    o.in.cuts -= a.cuts;
    o.in.indefinite -= a.indefinite;
    o.in.shifted -= a.shifted;
    double d = 0, m = 0;
    for (size_t i = 0; i < r->n3; ++i) {
        d = fmax(d, fabs(u[i] - r->u[i]));
        m = fmax(m, fabs(r->u[i]));
    }
    o.diff = d / m;
    tf_nonlinear_stability st;
    assert_int_equal(tf_nonlinear_stability_of(r->solver, 1.0 / 64, &st), 0);
    o.mu = st.mu;
    free(u0);
    free(u);
    tf_scene_run_free(r);
    return o;
}

/* Both strategies, one tangent kind: back to the stable equilibrium in
 * one load step without a cut (the start was continued from, not dropped
 * for a solve from rest: that one meets no indefinite tangent). */
static void both_come_back(const char *tangent)
{
    outcome l = from_past_stability(tangent, "solver.newton.indefinite=ldl");
    outcome s = from_past_stability(tangent, "solver.newton.indefinite=shift");
    assert_true(l.in.indefinite >= 1);
    assert_int_equal(l.in.shifted, 0);
    assert_int_equal(s.in.indefinite, 0);
    assert_true(s.in.shifted >= 1);
    assert_true(s.in.shift > 0);
    const outcome *both[] = {&l, &s};
    for (int k = 0; k < 2; ++k) {
        assert_int_equal(both[k]->in.steps, 1);
        assert_int_equal(both[k]->in.cuts, 0);
        assert_true(both[k]->diff < 1e-9);
        assert_true(both[k]->mu > 0.05); /* 0.0928 (test_stability.c) */
    }
}

static void full_newton_comes_back(void **state)
{
    (void)state;
    both_come_back("solver.newton.tangent=full");
}

/* BFGS from a guess starts from the rest tangent's factor
 * (nl_factor_for_rest), positive definite, and its pairs learn the way
 * back: no indefinite tangent is factorised on the way, with either
 * strategy. */
static void bfgs_comes_back(void **state)
{
    (void)state;
    static const char *how[] = {"solver.newton.indefinite=ldl", "solver.newton.indefinite=shift"};
    for (int k = 0; k < 2; ++k) {
        outcome o = from_past_stability("solver.newton.tangent=bfgs", how[k]);
        assert_int_equal(o.in.indefinite, 0);
        assert_int_equal(o.in.shifted, 0);
        assert_int_equal(o.in.steps, 1);
        assert_int_equal(o.in.cuts, 0);
        assert_true(o.diff < 1e-9); /* 7.8e-12 */
        assert_true(o.mu > 0.05);
    }
}

/* Krylov used to keep an LDL^T factor as its preconditioner: from this
 * start the body inverted (nl_linear.c, nl_linear_solve). */
static void krylov_comes_back(void **state)
{
    (void)state;
    both_come_back("solver.newton.tangent=krylov");
}

static void another_strategy_is_refused(void **state)
{
    (void)state;
    tf_test_refused(14, 1, "  face: z+\nsolver:\n  newton: {indefinite: lu}\n",
                    (const char *[]){"t.yaml:16:", "solver.newton.indefinite", "ldl", "shift",
                                     NULL});
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(full_newton_comes_back),
        cmocka_unit_test(bfgs_comes_back),
        cmocka_unit_test(krylov_comes_back),
        cmocka_unit_test(another_strategy_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
