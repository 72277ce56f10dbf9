/*
 * test_cut_shape.c — shape functions with a cut (shape.c + cut.h) on the
 * jittered patch-test cloud (10 mm cube, refined to 11^3 nodes), RPIM and EFG, supports
 * centred on cells: a slit x = 5.3 from y = -1 to the front y = 6, from the
 * top z = 10 down to z = 4.
 *   - partition of unity and linear reproduction (values and gradients)
 *     still hold at every Gauss point, cut or not (RPIM with its linear
 *     polynomial on the visible nodes; MLS reproduces its basis whatever
 *     the weights);
 *   - the jump: at a point in the span of the slit, phi_J = 0 exactly for
 *     every node J across it (also in the span);
 *   - at every point whose support does not meet the cut the shape
 *     functions are those of the uncut cloud, bit for bit;
 *   - only a part of the points is recomputed (counted).
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

#include "meshfree/shape.h"
#include "reproduction.h"
#include "scene/scene.h"

#define PATCH "tests/solver/patch.yaml"

static const tf_cut SLIT = {.n = 2, .xy = {{5.3, -1}, {5.3, 6}}, .top = 10, .depth = 6};

typedef struct pair {
    tf_scene *scene;
    tf_shape cut, plain;
    tf_shape_work wc, wp;
} pair;

static void shape_of(tf_shape *sh, const tf_problem *p, int efg)
{
    double lo[3], hi[3];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_problem_bounds(p, lo, hi);
    assert_int_equal(tf_shape_init(sh, &p->cloud, lo, hi, &p->solver), 0);
    if (efg && tf_shape_use_efg(&ctx, sh) != 0) {
        fail_msg("%s", ctx.err);
    }
}

static void pair_open(pair *q, int efg)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[] = {"geometry.grid=11,11,11"};
    q->scene = tf_scene_load(&ctx, PATCH, sets, 1);
    if (q->scene == NULL) {
        fail_msg("%s", ctx.err);
    }
    shape_of(&q->cut, &q->scene->problem, efg);
    shape_of(&q->plain, &q->scene->problem, efg);
    assert_int_equal(tf_shape_set_cuts(&ctx, &q->cut, &SLIT, 1), 0);
    tf_shape_work_init(&q->wc);
    tf_shape_work_init(&q->wp);
}

static void pair_close(pair *q)
{
    tf_shape_work_free(&q->wc);
    tf_shape_work_free(&q->wp);
    tf_shape_free(&q->cut);
    tf_shape_free(&q->plain);
    tf_scene_free(q->scene);
}

/* Largest violation of linear reproduction at point p (values, gradients). */
static double reproduction_error(const tf_shape *sh, const tf_shape_work *w, size_t p,
                                 const double x[3])
{
    size_t n = w->n;
    return tf_test_reproduction_error(sh->cloud->xyz, w->idx, n, w->phi + p * n, w->dphi + 3 * p * n, x, 10);
}

static int in_span(const double x[3])
{
    return x[1] > -1 && x[1] < 6 && x[2] > 4 && x[2] < 10;
}

/* Nodes across the slit from x, both in its span, that have phi != 0. */
static size_t jump_violations(const tf_shape *sh, const tf_shape_work *w, size_t p,
                              const double x[3])
{
    size_t bad = 0;
    for (size_t i = 0; in_span(x) && i < w->n; ++i) {
        const double *xi = sh->cloud->xyz + 3 * (size_t)w->idx[i];
        if (in_span(xi) && (xi[0] - 5.3) * (x[0] - 5.3) < 0 && w->phi[p * w->n + i] != 0) {
            bad++;
        }
    }
    return bad;
}

static int same_bits(const tf_shape_work *a, const tf_shape_work *b, size_t np)
{
    return a->n == b->n && memcmp(a->idx, b->idx, a->n * sizeof *a->idx) == 0 &&
           memcmp(a->phi, b->phi, np * a->n * sizeof *a->phi) == 0 &&
           memcmp(a->dphi, b->dphi, 3 * np * a->n * sizeof *a->dphi) == 0;
}

static void check(int efg)
{
    pair q;
    pair_open(&q, efg);
    size_t np = tf_cells_points(&q.cut.cells), jumps = 0, spanned = 0, differ = 0;
    double x[3 * 64], w, worst = 0;
    assert_true(np <= 64);
    for (size_t c = 0; c < tf_cells_count(&q.cut.cells); ++c) {
        for (size_t p = 0; p < np; ++p) {
            tf_cells_point(&q.cut.cells, c, p, x + 3 * p, &w);
        }
        assert_int_equal(tf_shape_cell_points(&q.cut, &q.wc, c, x, np, 1), 0);
        assert_int_equal(tf_shape_cell_points(&q.plain, &q.wp, c, x, np, 1), 0);
        for (size_t p = 0; p < np; ++p) {
            worst = fmax(worst, reproduction_error(&q.cut, &q.wc, p, x + 3 * p));
            jumps += jump_violations(&q.cut, &q.wc, p, x + 3 * p);
            spanned += in_span(x + 3 * p);
        }
        if (!q.wc.cut) {
            differ += !same_bits(&q.wc, &q.wp, np);
        }
    }
    printf("  %s: %zu of %zu Gauss points recomputed for the cut (%zu enriched nodes), "
           "%zu in the slit's span; reproduction error %.1e; phi != 0 across the slit: %zu; "
           "uncut cells not bitwise equal: %zu\n",
           efg ? "EFG" : "RPIM", q.wc.st.cut_points, q.wc.st.points, tf_shape_cut_nodes(&q.cut),
           spanned, worst, jumps, differ);
    assert_true(q.wc.st.cut_points > 0 && q.wc.st.cut_points < q.wc.st.points);
    assert_true(spanned > 0);
    assert_true(worst < 1e-10);
    assert_int_equal(jumps, 0);
    assert_int_equal(differ, 0);
    pair_close(&q);
}

static void rpim_with_a_cut(void **state)
{
    (void)state;
    check(0);
}

static void efg_with_a_cut(void **state)
{
    (void)state;
    check(1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rpim_with_a_cut),
        cmocka_unit_test(efg_with_a_cut),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
