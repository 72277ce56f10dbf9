/*
 * test_mls_shape.c — EFG through the solver's shape-function code path
 * (shape.c after tf_shape_use_efg) on the jittered patch-test cloud:
 * partition of unity and linear reproduction at every Gauss point, with
 * supports centred on cells and on points; both give the same shape
 * functions (MLS does not depend on the support choice, only on the nodes
 * that reach the point); a support too small for a moment matrix is
 * refused with the place.
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

typedef struct efg {
    tf_scene *scene;
    tf_shape sh;
    tf_shape_work w;
} efg;

/* The shape object of a problem's cloud, bounds and solver options. */
static int shape_of(tf_shape *sh, const tf_problem *p)
{
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    return tf_shape_init(sh, &p->cloud, lo, hi, &p->solver);
}

static void efg_open(efg *e, const char *centre)
{
    char set[64];
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    snprintf(set, sizeof set, "solver.centre=%s", centre);
    const char *sets[] = {set};
    e->scene = tf_scene_load(&ctx, PATCH, sets, 1);
    if (e->scene == NULL) {
        fail_msg("%s", ctx.err);
    }
    assert_int_equal(shape_of(&e->sh, &e->scene->problem), 0);
    if (tf_shape_use_efg(&ctx, &e->sh) != 0) {
        fail_msg("%s", ctx.err);
    }
    tf_shape_work_init(&e->w);
}

static void efg_close(efg *e)
{
    tf_shape_work_free(&e->w);
    tf_shape_free(&e->sh);
    tf_scene_free(e->scene);
}

/* Largest violation of sum phi (1, x_i) = (1, x) and
 * sum d_a phi (1, x_i) = (0, e_a) at point p of the work's output. */
static double reproduction_error(const efg *e, size_t p, const double x[3])
{
    size_t n = e->w.n;
    return tf_test_reproduction_error(e->sh.cloud->xyz, e->w.idx, n, e->w.phi + p * n,
                                      e->w.dphi + 3 * p * n, x, 10); /* the patch cloud's box edge, mm */
}

static void reproduces_linear_fields_through_shape_c(void **state)
{
    (void)state;
    const char *modes[2] = {"cell", "point"};
    for (int m = 0; m < 2; ++m) {
        efg e;
        efg_open(&e, modes[m]);
        size_t np = tf_cells_points(&e.sh.cells), npoints = 0;
        double worst = 0, x[3 * 64], w;
        assert_true(np <= 64);
        for (size_t c = 0; c < tf_cells_count(&e.sh.cells); ++c) {
            for (size_t p = 0; p < np; ++p) {
                tf_cells_point(&e.sh.cells, c, p, x + 3 * p, &w);
            }
            if (m == 0) {
                assert_int_equal(tf_shape_cell_points(&e.sh, &e.w, c, x, np, 1), 0);
                for (size_t p = 0; p < np; ++p) {
                    worst = fmax(worst, reproduction_error(&e, p, x + 3 * p));
                }
            } else {
                for (size_t p = 0; p < np; ++p) {
                    assert_int_equal(tf_shape_at(&e.sh, &e.w, x + 3 * p, c, 1), 0);
                    worst = fmax(worst, reproduction_error(&e, 0, x + 3 * p));
                }
            }
            npoints += np;
        }
        printf("  EFG through shape.c, centre %s: %zu Gauss points, reproduction error %.1e, "
               "min rcond %.1e, nodes per support %zu..%zu\n",
               modes[m], npoints, worst, e.w.st.min_rcond, e.w.st.min_nodes, e.w.st.max_nodes);
        assert_true(worst < 1e-12);
        assert_int_equal(e.w.st.systems, npoints);
        assert_true(e.w.st.min_rcond > 1e-6);
        efg_close(&e);
    }
}

static void cell_and_point_supports_give_the_same_shape_functions(void **state)
{
    (void)state;
    efg ec, ep;
    efg_open(&ec, "cell");
    efg_open(&ep, "point");
    size_t nn = ec.scene->problem.cloud.n, np = tf_cells_points(&ec.sh.cells);
    double *dense = calloc(nn, sizeof *dense), x[3 * 64], w, worst = 0;
    for (size_t c = 0; c < tf_cells_count(&ec.sh.cells); c += 7) {
        for (size_t p = 0; p < np; ++p) {
            tf_cells_point(&ec.sh.cells, c, p, x + 3 * p, &w);
        }
        assert_int_equal(tf_shape_cell_points(&ec.sh, &ec.w, c, x, np, 1), 0);
        for (size_t p = 0; p < np; ++p) {
            assert_int_equal(tf_shape_at(&ep.sh, &ep.w, x + 3 * p, c, 1), 0);
            /* the point's support is the part of the cell's with weight */
            assert_true(ep.w.n <= ec.w.n);
            for (size_t i = 0; i < ec.w.n; ++i) {
                dense[ec.w.idx[i]] = ec.w.phi[p * ec.w.n + i];
            }
            for (size_t i = 0; i < ep.w.n; ++i) {
                worst = fmax(worst, fabs(dense[ep.w.idx[i]] - ep.w.phi[i]));
                dense[ep.w.idx[i]] = 0;
            }
            for (size_t k = 0; k < nn; ++k) { /* nodes only the cell lists: phi = 0 */
                assert_true(dense[k] == 0);
            }
        }
    }
    printf("  EFG cell- vs point-centred supports: max |phi difference| %.1e\n", worst);
    assert_true(worst < 1e-13);
    free(dense);
    efg_close(&ec);
    efg_close(&ep);
}

static void a_support_too_small_is_refused_with_the_place(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[] = {"solver.support=0.3", "solver.centre=point"};
    tf_scene *s = tf_scene_load(&ctx, PATCH, sets, 2);
    assert_non_null(s);
    tf_shape sh;
    tf_shape_work w;
    assert_int_equal(shape_of(&sh, &s->problem), 0);
    assert_int_equal(tf_shape_use_efg(&ctx, &sh), 0);
    tf_shape_work_init(&w);
    /* at a node only that node's domain (0.3 spacings; jitter keeps nodes
     * 0.4 spacings apart) reaches: A has rank 1 */
    const double *x = s->problem.cloud.xyz + 3 * 100;
    assert_int_equal(tf_shape_at(&sh, &w, x, tf_shape_cell(&sh, x), 1), -1);
    char where[128];
    snprintf(where, sizeof where, "(%g, %g, %g) mm", x[0], x[1], x[2]);
    assert_non_null(strstr(w.err, "MLS moment matrix"));
    assert_non_null(strstr(w.err, where));
    assert_non_null(strstr(w.err, "solver.support"));
    tf_shape_work_free(&w);
    tf_shape_free(&sh);
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reproduces_linear_fields_through_shape_c),
        cmocka_unit_test(cell_and_point_supports_give_the_same_shape_functions),
        cmocka_unit_test(a_support_too_small_is_refused_with_the_place),
    };
    return cmocka_run_group_tests_name("mls_shape", tests, NULL, NULL);
}
