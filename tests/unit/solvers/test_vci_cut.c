/*
 * test_vci_cut.c — VCI's face integrals on a cut along the cells' faces
 * (solvers/cell_gradients.c): the jittered patch-test cloud (10 mm cube,
 * 11^3 nodes, 10^3 unit cells, RPIM on cell-centred supports) with a slit
 * on the cell faces x = 5, from y = -1 to 6, from the top z = 10 down to
 * z = 4.  For the cell [4, 5] x [1, 2] x [7, 8] on the slit's - side, every
 * node across the slit (x > 5) is hidden from every point of the cell, so
 * its corrected gradients must be exactly zero there: the cell's x+ face
 * lies on the slit and its integral takes the cell's own side's trace, not
 * the + side's (on the panel, the + side by convention) nor a mean with the
 * cell across the slit.  The corrected gradients still reproduce linear
 * fields.  Shown to fail: with the face points left on the panel (and the
 * face averaged with the cell across), nodes across the slit get corrected
 * gradients up to 1.25 per mm in this cell: VCI coupled the two lips.
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
#include "scene/scene.h"
#include "solvers/cell_gradients.h"

#define PATCH "tests/solver/patch.yaml"

static const tf_cut SLIT = {.n = 2, .xy = {{5, -1}, {5, 6}}, .top = 10, .depth = 6};

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

static void vci_across_the_slit(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    const char *sets[] = {"geometry.grid=11,11,11"};
    tf_scene *s = tf_scene_load(&ctx, PATCH, sets, 1);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_problem *p = &s->problem;
    tf_shape sh;
    double lo[3], hi[3];
    tf_problem_bounds(p, lo, hi);
    assert_int_equal(tf_shape_init(&sh, &p->cloud, lo, hi, &p->solver), 0);
    assert_int_equal(sh.centre, TF_SUPPORT_CELL);
    assert_int_equal(tf_shape_set_cuts(&ctx, &sh, &SLIT, 1), 0);
    const double at[3] = {4.5, 1.5, 7.5};
    size_t cell = tf_shape_cell(&sh, at), n = p->cloud.n, m = 0;
    double centre[3], half[3];
    tf_cells_box(&sh.cells, cell, centre, half);
    assert_true(fabs(centre[0] + half[0] - 5) < 1e-12); /* its x+ face on the slit */

    /* The cell's node set: its support and VCI's face supports. */
    tf_shape_work sw;
    tf_grad_work gw;
    tf_shape_work_init(&sw);
    assert_int_equal(tf_grad_work_init(&gw, &sh, n), 0);
    uint32_t *mark = calloc(n, sizeof *mark), *set = malloc(n * sizeof *set);
    assert_non_null(mark);
    assert_non_null(set);
    assert_int_equal(tf_shape_support(&sh, &sw, at, cell), 0);
    for (size_t k = 0; k < sw.n; ++k) {
        mark[sw.idx[k]] = 1;
        set[m++] = sw.idx[k];
    }
    assert_int_equal(tf_vci_cell_nodes(&sh, &gw, cell, mark, 1, set, &m), 0);
    qsort(set, m, sizeof *set, cmp_u32);

    size_t np = tf_cells_points(&sh.cells);
    double *g = malloc(3 * np * m * sizeof *g), across = 0, repro = 0;
    assert_non_null(g);
    assert_int_equal(tf_cell_gradients(&sh, 1, &gw, cell, set, m, g), 0);
    size_t n_across = 0;
    for (size_t i = 0; i < m; ++i) {
        const double *x = p->cloud.xyz + 3 * (size_t)set[i];
        n_across += x[0] > 5;
        for (size_t q = 0; x[0] > 5 && q < 3 * np; ++q) {
            across = fmax(across, fabs(g[q * m + i]));
        }
    }
    for (size_t pt = 0; pt < np; ++pt) { /* sum_i grad phi_i x_i^b = delta_ab */
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                double sum = 0;
                for (size_t i = 0; i < m; ++i) {
                    sum += g[(3 * pt + (size_t)a) * m + i] * p->cloud.xyz[3 * (size_t)set[i] + b];
                }
                repro = fmax(repro, fabs(sum - (a == b)));
            }
        }
    }
    printf("vci on a cut face: %zu of %zu nodes across the slit, largest corrected gradient "
           "there %.3g /mm (0 expected), linear reproduction %.3g\n",
           n_across, m, across, repro);
    assert_true(n_across > 0);
    assert_true(across == 0);
    assert_true(repro < 1e-9);
    free(g);
    free(mark);
    free(set);
    tf_grad_work_free(&gw);
    tf_shape_work_free(&sw);
    tf_shape_free(&sh);
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(vci_across_the_slit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
