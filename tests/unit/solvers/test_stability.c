/*
 * test_stability.c — tf_nonlinear_stability_of (nl_stability.c) against
 * LAPACK's dense generalized eigensolver on a small block48: the bracket
 * holds the least eigenvalue of K_t v = mu K_0 v, the Rayleigh quotient is
 * that eigenvalue, "definite" is its sign, the node is where the dense
 * mode is largest, and the probe leaves the solver's state alone.
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
#include <lapacke.h>

#include "base/context.h"
#include "scene/scene.h"
#include "solvers/nonlinear/nl_internal.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#include "scene_run.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
#define TOL (1.0 / 256)

/* The eliminated tangent at d as a dense n x n matrix (both triangles). */
static double *dense_tangent(nl_solver *s, const double *d)
{
    size_t n = s->k.n;
    nl_fault f = {0};
    assert_int_equal(nl_assemble(s, d, &s->at, 0, 1, s->r, NULL, &f), 0);
    nl_eliminate(s);
    double *a = calloc(n * n, sizeof *a);
    for (size_t j = 0; j < n; ++j) {
        for (int q = s->k.p[j]; q < s->k.p[j + 1]; ++q) {
            size_t i = (size_t)s->k.i[q];
            a[i + n * j] = a[j + n * i] = s->k.x[q];
        }
    }
    return a;
}

/* The least eigenvalue of K_t v = mu K_0 v at the solver's state, dense,
 * and the node where its mode is largest. */
static double dense_least(nl_solver *s, size_t *node)
{
    size_t n = s->k.n;
    double *zero = calloc(n, sizeof *zero), *w = malloc(n * sizeof *w);
    double *kt = dense_tangent(s, s->d), *k0 = dense_tangent(s, zero);
    assert_int_equal(LAPACKE_dsygv(LAPACK_COL_MAJOR, 1, 'V', 'L', (lapack_int)n, kt,
                                   (lapack_int)n, k0, (lapack_int)n, w), 0);
    double most = -1;
    for (size_t i = 0; i < n / 3; ++i) { /* the first column: the least eigenvalue's mode */
        double m = kt[3 * i] * kt[3 * i] + kt[3 * i + 1] * kt[3 * i + 1] + kt[3 * i + 2] * kt[3 * i + 2];
        if (m > most) {
            most = m;
            *node = i;
        }
    }
    double mu = w[0];
    free(zero);
    free(w);
    free(kt);
    free(k0);
    return mu;
}

/* block48 on a 7 x 7 x 3 grid (node 25: the top centre) with a law,
 * solved under force at the contact site. */
static tf_scene_run *solved(const char *law, double fz)
{
    const char *sets[] = {"geometry.grid=7,7,3", "contact.0.node=25", law};
    const double f[1][3] = {{0, 0, fz}};
    return tf_scene_run_solve(BLOCK48, NULL, sets, 3, 0, f, 1);
}

/* The probe against the dense answer at the solver's state. */
static void agrees_with_dense(tf_scene_run *r, double *least)
{
    nl_solver *s = (nl_solver *)r->solver;
    size_t node = 0;
    double mu = dense_least(s, &node);
    size_t n3 = s->k.n;
    double *d = malloc(n3 * sizeof *d), *k = malloc(s->k.nnz * sizeof *k);
    memcpy(d, s->d, n3 * sizeof *d);
    memcpy(k, s->k.x, s->k.nnz * sizeof *k);
    nl_stats before = s->st;
    tf_nonlinear_stability st;
    assert_int_equal(tf_nonlinear_stability_of(r->solver, TOL, &st), 0);
    /* the state, the matrix and the Newton solver's counters as they were */
    assert_memory_equal(d, s->d, n3 * sizeof *d);
    assert_memory_equal(k, s->k.x, s->k.nnz * sizeof *k);
    assert_int_equal(s->st.factorisations, before.factorisations);
    assert_int_equal(s->st.tangents, before.tangents);
    free(d);
    free(k);
    assert_true(st.hi - st.lo <= TOL);
    assert_true(st.lo < mu && mu <= st.hi + 1e-12);
    assert_true(fabs(st.mu - mu) <= 1e-6 * fmax(1, fabs(mu)));
    assert_int_equal(st.definite, mu > 0);
    if (mu < 1 - TOL) { /* at rest every mu is 1: no single mode to locate */
        assert_int_equal(st.node, node);
    }
    *least = mu;
}

static void the_bracket_holds_the_least_eigenvalue(void **state)
{
    (void)state;
    tf_scene_run *r = solved("material.law=neo-hookean", -1.5);
    nl_solver *s = (nl_solver *)r->solver;
    double mu;
    agrees_with_dense(r, &mu); /* a stable equilibrium that has softened */
    assert_true(mu > 0 && mu < 1 - TOL);
    /* a state past stability: the equilibrium's displacements times 2.5
     * (not an equilibrium: the probe needs none) */
    for (size_t i = 0; i < r->n3; ++i) {
        s->d[i] *= 2.5;
    }
    agrees_with_dense(r, &mu);
    assert_true(mu < 0);
    assert_int_equal(tf_nonlinear_reset(r->solver), 0);
    agrees_with_dense(r, &mu); /* at rest K_t = K_0 */
    assert_true(fabs(mu - 1) < 1e-9);
    tf_scene_run_free(r);
}

static void only_elastic_laws(void **state)
{
    (void)state;
    tf_scene_run *r = solved("material={law: kelvin, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3}", -0.1);
    tf_nonlinear_stability st;
    assert_int_equal(tf_nonlinear_stability_of(r->solver, TOL, &st), -1);
    assert_non_null(strstr(r->ctx.err, "elastic laws"));
    assert_int_equal(tf_nonlinear_stability_of(r->solver, 0, &st), -1);
    tf_scene_run_free(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_bracket_holds_the_least_eigenvalue),
        cmocka_unit_test(only_elastic_laws),
    };
    return cmocka_run_group_tests_name("stability", tests, NULL, NULL);
}
