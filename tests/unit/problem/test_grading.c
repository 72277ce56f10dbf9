/*
 * test_grading.c — graded box clouds (problem/grading.h, nodes.h) and what
 * the meshless layer does with them (supports in index space, cells along
 * the grid lines, d_c from the local spacing):
 *
 *   - grid lines: exact ends, increasing, densest on the attractors,
 *     largest / smallest spacing = the ratio asked (to the 256-sub-step
 *     integration), mirror-symmetric for mirror-symmetric attractors;
 *   - ratio 1 (or no attractor) is the uniform cloud, bit for bit;
 *   - the index map inverts the grid lines;
 *   - every background cell's support holds as many nodes on a graded cloud
 *     as on the uniform one (32 inside a regular grid, 2 spacings);
 *   - RPIM on a graded cloud reproduces a linear field (the patch test on a
 *     regular graded grid, as on a uniform one).
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
#include "meshfree/shape.h"
#include "problem/nodes.h"
#include "scene/scene.h"
#include "verify/verify.h"

/* block48's x axis: clamped at 0 and 48, the load patch over [21.6, 26.4]. */
static void lines_follow_the_attractors(void **state)
{
    (void)state;
    const double at[3][2] = {{0, 0}, {21.6, 26.4}, {48, 48}};
    const unsigned n = 41;
    double x[41];
    for (double ratio = 1.5; ratio <= 4; ratio += 1.25) {
        assert_int_equal(tf_cloud_grading_axis(0, 48, n, ratio, at, 3, x), 0);
        assert_true(x[0] == 0 && x[n - 1] == 48);
        double hmin = INFINITY, hmax = 0;
        unsigned imin = 0, imax = 0;
        for (unsigned i = 0; i + 1 < n; ++i) {
            double h = x[i + 1] - x[i];
            assert_true(h > 0);
            if (h < hmin) {
                hmin = h;
                imin = i;
            }
            if (h > hmax) {
                hmax = h;
                imax = i;
            }
            assert_true(fabs(x[i] + x[n - 1 - i] - 48) < 1e-9); /* mirror-symmetric */
        }
        /* smallest at a clamped face or inside the patch, largest midway
         * (10.8 mm from both), ratio as asked to a few per cent (the
         * spacing is sampled per interval, the ratio is of the density) */
        double mid = 0.5 * (x[imin] + x[imin + 1]), far = 0.5 * (x[imax] + x[imax + 1]);
        assert_true(mid < 2 || (mid > 21.6 && mid < 26.4) || mid > 46);
        assert_true(fabs(far - 10.8) < 2 || fabs(far - 37.2) < 2);
        assert_true(fabs(hmax / hmin / ratio - 1) < 0.1);
    }
    /* ratio 1 and no attractor are the uniform axis */
    double u[41], v[41];
    assert_int_equal(tf_cloud_grading_axis(0, 48, n, 1, at, 3, u), 0);
    assert_int_equal(tf_cloud_grading_axis(0, 48, n, 3, at, 0, v), 0);
    for (unsigned i = 0; i + 1 < n; ++i) {
        assert_true(u[i] == i * 1.2 && v[i] == u[i]);
    }
}

static void ratio_one_is_the_uniform_cloud(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {48, 48, 6};
    const unsigned grid[3] = {11, 11, 3};
    tf_cloud_grading g = {.ratio = {1, 1, 1}, .n = {2, 2, 1}, .at = {{{0, 0}, {48, 48}},
                                                                {{0, 0}, {48, 48}},
                                                                {{6, 6}}}};
    tf_cloud a, b;
    assert_int_equal(tf_cloud_box(&a, lo, hi, grid, 0.2, 5), 0);
    assert_int_equal(tf_cloud_box_graded(&b, lo, hi, grid, 0.2, 5, &g), 0);
    assert_false(b.graded);
    assert_memory_equal(a.xyz, b.xyz, 3 * a.n * sizeof *a.xyz);
    tf_cloud_free(&b);
    g.ratio[0] = 3;
    assert_int_equal(tf_cloud_box_graded(&b, lo, hi, grid, 0, 5, &g), 0);
    assert_true(b.graded);
    /* the index map inverts the grid lines, and is linear between them */
    for (unsigned i = 0; i < 11; ++i) {
        assert_true(fabs(tf_cloud_to_index(&b, 0, b.axis[0][i]) - i) < 1e-12);
        assert_true(fabs(tf_cloud_from_index(&b, 0, i) - b.axis[0][i]) < 1e-12);
    }
    double xi = tf_cloud_to_index(&b, 0, 0.5 * (b.axis[0][3] + b.axis[0][4]));
    assert_true(fabs(xi - 3.5) < 1e-12);
    tf_cloud_free(&a);
    tf_cloud_free(&b);
}

static tf_scene *block48(const char *grading)
{
    char set[64];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    snprintf(set, sizeof set, "geometry.grading=%s", grading);
    const char *sets[] = {"geometry.grid=13,13,5", set};
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_at.yaml", sets, 2);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    return s;
}

static void supports_hold_the_same_nodes(void **state)
{
    (void)state;
    tf_scene *u = block48("1,1,1"), *g = block48("3,3,2");
    assert_false(u->problem.cloud.graded);
    assert_true(g->problem.cloud.graded);
    tf_shape su, sg;
    double lo[3], hi[3];
    tf_problem_bounds(&u->problem, lo, hi);
    assert_int_equal(tf_shape_init(&su, &u->problem.cloud, lo, hi, &u->problem.solver), 0);
    assert_int_equal(tf_shape_init(&sg, &g->problem.cloud, lo, hi, &g->problem.solver), 0);
    tf_shape_work wu, wg;
    tf_shape_work_init(&wu);
    tf_shape_work_init(&wg);
    size_t cells = tf_cells_count(&su.cells), inner = 0;
    assert_int_equal(tf_cells_count(&sg.cells), cells);
    for (size_t c = 0; c < cells; ++c) {
        double cu[3], cg[3], half[3];
        tf_cells_box(&su.cells, c, cu, half);
        tf_cells_box(&sg.cells, c, cg, half);
        /* graded cells follow the grid lines: the cell of the same index */
        assert_int_equal(tf_shape_cell(&sg, cg), c);
        assert_int_equal(tf_shape_support(&su, &wu, cu, c), 0);
        assert_int_equal(tf_shape_support(&sg, &wg, cg, c), 0);
        assert_int_equal(wu.n, wg.n);
        assert_memory_equal(wu.idx, wg.idx, wu.n * sizeof *wu.idx);
        inner += wu.n == 32;
    }
    assert_true(inner > 0);
    tf_shape_work_free(&wu);
    tf_shape_work_free(&wg);
    tf_shape_free(&su);
    tf_shape_free(&sg);
    tf_scene_free(u);
    tf_scene_free(g);
}

static void graded_patch_test(void **state)
{
    (void)state;
    const char *sets[] = {"geometry.jitter=0", "geometry.grading=3,3,3"};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/patch.yaml", sets, 2);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    assert_true(s->problem.cloud.graded);
    tf_verify_row row;
    assert_int_equal(tf_verify_problem(&s->problem, 0, &ctx, &row), 0);
    print_message("patch test on a graded regular grid (ratio 3): L2 %.2e, energy %.2e\n",
                  row.error_l2, row.error_energy);
    /* as on the uniform regular grid (docs/validation.md §2: 2.9e-4) */
    assert_true(row.error_l2 < 1e-3);
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lines_follow_the_attractors),
        cmocka_unit_test(ratio_one_is_the_uniform_cloud),
        cmocka_unit_test(supports_hold_the_same_nodes),
        cmocka_unit_test(graded_patch_test),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
