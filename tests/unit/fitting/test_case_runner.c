/*
 * test_case_runner.c — case lists (fitting/case_runner.h) and their
 * continuation graph (fitting/case_graph.h), on a model solver whose answer
 * depends on where it starts, as a nonlinear solver's last bits do:
 *
 *   graph      the first ceil(sqrt(n)) cases start from rest, every other
 *              one from its nearest anchor (or from rest when the zero
 *              force is nearer), computed here by brute force;
 *   serial     each kept value is the model's answer from the start the
 *              graph names, recomputed here case by case; the fields of the
 *              starts are kept until their last use;
 *   refusals   a start that is not an earlier case, a kept DOF beyond the
 *              solution; a failing case is named with its segment, index,
 *              force and the solver's message.
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
#include "fitting/case_graph.h"
#include "fitting/case_runner.h"
#include "solvers/solver.h"

#define NODES 4
#define N 30

/* The model: u = g(f) + u0 / 3 on every DOF, failing at |f_z| > 2. */
typedef struct model {
    struct tf_solver base;
} model;

static void answer(const double f[3], const double *u0, double *u)
{
    for (size_t d = 0; d < 3 * NODES; ++d) {
        u[d] = sin((double)(d + 1) * f[0]) + f[1] * f[1] * (double)d - f[2] +
               (u0 != NULL ? u0[d] / 3 : 0);
    }
}

static tf_solver *create(const tf_problem *p, const tf_solver_opts *o, tf_ctx *ctx)
{
    (void)p;
    (void)o;
    (void)ctx;
    return calloc(1, sizeof(model));
}

static unsigned caps(const tf_solver *s)
{
    (void)s;
    return 0;
}

static int solve(tf_solver *s, int contact, const double (*forces)[3], size_t n, const double *u0,
                 double *u)
{
    (void)contact;
    for (size_t k = 0; k < n; ++k) {
        if (fabs(forces[k][2]) > 2) {
            return tf_fail(s->ctx, "Newton did not converge at step 3");
        }
        answer(forces[k], u0 ? u0 + k * 3 * NODES : NULL, u + k * 3 * NODES);
    }
    return 0;
}

static size_t node_count(const tf_solver *s)
{
    (void)s;
    return NODES;
}

static void destroy(tf_solver *s) { free(s); }

static const tf_solver_ops model_ops = {
    .name = "start-dependent", .create = create, .caps = caps, .solve = solve, .node_count = node_count,
    .destroy = destroy};

typedef struct fixture {
    tf_ctx ctx;
    tf_problem p;
    tf_solver *s;
    double f[N][3];
    long from[N];
    size_t keep[5];
} fixture;

static int setup(void **state)
{
    fixture *x = calloc(1, sizeof *x);
    tf_ctx_init(&x->ctx);
    x->ctx.level = TF_LOG_ERROR;
    snprintf(x->p.name, sizeof x->p.name, "model");
    x->p.n_contacts = 1;
    x->s = tf_solver_create_as(&model_ops, &x->p, NULL, &x->ctx);
    for (size_t i = 0; i < N; ++i) { /* a scatter of forces, no two alike */
        x->f[i][0] = cos(1.7 * (double)i);
        x->f[i][1] = sin(2.3 * (double)i + 0.4);
        x->f[i][2] = 0.9 * sin(0.9 * (double)i);
    }
    static const size_t keep[5] = {0, 4, 5, 9, 11};
    memcpy(x->keep, keep, sizeof keep);
    *state = x;
    return x->s == NULL ? -1 : 0;
}

static int teardown(void **state)
{
    fixture *x = *state;
    tf_solver_destroy(x->s);
    free(x);
    return 0;
}

static double d2(const double a[3], const double b[3])
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

static void graph_is_two_levels_to_the_nearest_anchor(void **state)
{
    fixture *x = *state;
    assert_int_equal(tf_case_graph_anchors(1), 1);
    assert_int_equal(tf_case_graph_anchors(30), 6);
    assert_int_equal(tf_case_graph_anchors(36), 6);
    assert_int_equal(tf_case_graph_anchors(37), 7);
    const size_t a = tf_case_graph_anchors(N);
    x->f[N - 1][0] = x->f[N - 1][1] = x->f[N - 1][2] = 1e-3; /* nearer rest than any anchor */
    tf_case_graph_anchored((const double(*)[3])x->f, N, a, x->from);
    const double zero[3] = {0, 0, 0};
    size_t from_anchor = 0;
    for (size_t i = 0; i < N; ++i) {
        if (i < a) {
            assert_int_equal(x->from[i], -1);
            continue;
        }
        long best = -1;
        double dbest = d2(x->f[i], zero);
        for (size_t k = 0; k < a; ++k) {
            if (d2(x->f[i], x->f[k]) < dbest) {
                dbest = d2(x->f[i], x->f[k]);
                best = (long)k;
            }
        }
        assert_int_equal(x->from[i], best);
        from_anchor += best >= 0;
    }
    assert_int_equal(x->from[N - 1], -1);
    assert_true(from_anchor > N / 2); /* the graph is used */
}

static tf_case_list list_of(fixture *x, size_t n)
{
    return (tf_case_list){.contact = 0, .n = n, .force = (const double(*)[3])x->f,
                          .from = x->from, .n_keep = 5, .keep = x->keep};
}

static void serial_runner_starts_each_case_where_the_graph_says(void **state)
{
    fixture *x = *state;
    tf_case_graph_anchored((const double(*)[3])x->f, N, tf_case_graph_anchors(N), x->from);
    const tf_case_list l = list_of(x, N);
    double kept[N * 5], full[N][3 * NODES];
    assert_int_equal(tf_case_run(NULL, x->s, &l, kept), 0);
    unsigned char is_start[N];
    tf_case_starts(&l, is_start);
    size_t starts = 0, continued = 0;
    for (size_t i = 0; i < N; ++i) {
        answer(x->f[i], x->from[i] >= 0 ? full[x->from[i]] : NULL, full[i]);
        for (size_t k = 0; k < 5; ++k) {
            assert_true(kept[5 * i + k] == full[i][x->keep[k]]);
        }
        starts += is_start[i];
        continued += x->from[i] >= 0;
        assert_int_equal(is_start[i] != 0, i < tf_case_graph_anchors(N) && is_start[i]);
    }
    assert_true(starts >= 2 && continued > N / 2);
    assert_int_equal(tf_solver_info_of(x->s)->solves, N);
    /* without the graph every case starts from rest */
    tf_case_list rest = l;
    rest.from = NULL;
    assert_int_equal(tf_case_run(NULL, x->s, &rest, kept), 0);
    for (size_t i = 0; i < N; ++i) {
        answer(x->f[i], NULL, full[i]);
        assert_true(kept[5 * i + 1] == full[i][4]);
    }
}

static void bad_lists_and_failing_cases_are_named(void **state)
{
    fixture *x = *state;
    double kept[N * 5];
    for (size_t i = 0; i < N; ++i) {
        x->from[i] = -1;
    }
    x->from[7] = 7;
    tf_case_list l = list_of(x, N);
    assert_int_equal(tf_case_run(NULL, x->s, &l, kept), -1);
    assert_non_null(strstr(x->ctx.err, "case 7 starts from case 7, which is not an earlier case"));
    x->from[7] = -1;
    x->keep[2] = 3 * NODES;
    assert_int_equal(tf_case_run(NULL, x->s, &l, kept), -1);
    assert_non_null(strstr(x->ctx.err, "kept DOF 12 is not one of the solver's 12"));
    x->keep[2] = 5;

    x->f[12][2] = 2.5; /* the model fails there */
    const tf_case_segment seg[2] = {{"training", 0}, {"held-out", 10}};
    l.n_seg = 2;
    l.seg = seg;
    assert_int_equal(tf_case_run(NULL, x->s, &l, kept), -1);
    assert_non_null(strstr(x->ctx.err, "held-out case 2 (case 12 of 30, force ("));
    assert_non_null(strstr(x->ctx.err, ", 2.5) N): Newton did not converge at step 3"));
    l.n_seg = 0;
    assert_int_equal(tf_case_run(NULL, x->s, &l, kept), -1);
    assert_non_null(strstr(x->ctx.err, "case 12 of 30 (force ("));
    assert_int_equal(tf_case_failed(&x->ctx, &l, 3, 2), -1);
    assert_non_null(strstr(x->ctx.err, ") N) on rank 2: case 12 of 30"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(graph_is_two_levels_to_the_nearest_anchor),
        cmocka_unit_test(serial_runner_starts_each_case_where_the_graph_says),
        cmocka_unit_test(bad_lists_and_failing_cases_are_named),
    };
    return cmocka_run_group_tests_name("case_runner", tests, setup, teardown);
}
