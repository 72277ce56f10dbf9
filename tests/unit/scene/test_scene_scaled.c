/*
 * test_scene_scaled.c — the clouds the self-measured discretisation solves
 * (tf_scene_scaled, scene_levels.h): a box's grid rounded to whole
 * intervals on every axis of more than two nodes, its background cells
 * with it; an organ's interior spacing scaled and its surface vertices
 * kept; a contact node kept at its point; an absolute d_c scaled, a
 * relative one left alone; the user's overrides applied first.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "base/context.h"
#include "scene/scene_levels.h"

static tf_scene *scaled(const char *path, const char *const *sets, size_t n, double f)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_scaled(&ctx, path, sets, n, f);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    return s;
}

static void box_grid_and_cells(void **state)
{
    (void)state;
    /* coeffs/block48.yaml: 26 x 26 x 6 nodes, 25 x 25 x 5 cells */
    tf_scene *fine = scaled("coeffs/block48.yaml", NULL, 0, 0.75);
    const tf_box_geometry *b = &fine->problem.geometry.as.box;
    assert_int_equal(b->grid[0], 34); /* 25 / 0.75 = 33.3 intervals -> 33 */
    assert_int_equal(b->grid[1], 34);
    assert_int_equal(b->grid[2], 8);  /* 5 / 0.75 = 6.67 -> 7 */
    assert_int_equal(fine->problem.solver.cells[0], 33);
    assert_int_equal(fine->problem.solver.cells[2], 7);
    assert_true(b->max[2] == 6.0); /* the body stays */
    tf_scene_free(fine);
    tf_scene *coarse = scaled("coeffs/block48.yaml", NULL, 0, 4.0 / 3.0);
    assert_int_equal(coarse->problem.geometry.as.box.grid[0], 20); /* 18.75 -> 19 */
    assert_int_equal(coarse->problem.geometry.as.box.grid[2], 5);  /* 3.75 -> 4 */
    tf_scene_free(coarse);
}

static void user_sets_first(void **state)
{
    (void)state;
    const char *sets[] = {"geometry.grid=11,11,3"};
    tf_scene *s = scaled("coeffs/block48.yaml", sets, 1, 0.5);
    assert_int_equal(s->problem.geometry.as.box.grid[0], 21);
    assert_int_equal(s->problem.geometry.as.box.grid[2], 5);
    tf_scene_free(s);
}

static void absolute_d_c_scales(void **state)
{
    (void)state;
    const char *sets[] = {"solver.rbf.d_c=3"};
    tf_scene *s = scaled("coeffs/block48.yaml", sets, 1, 0.75);
    assert_true(s->problem.solver.d_c_spacings == 0);
    assert_true(fabs(s->problem.solver.d_c - 2.25) < 1e-12);
    tf_scene_free(s);
}

/* A contact site by node number: renumbered to the node at the same point
 * of the new grid, whose axes are rounded to keep that point a node. */
static void contact_node_stays(void **state)
{
    (void)state;
    /* tests/solver/block48_seed.yaml: 11 x 11 x 3, node 61 the top centre */
    tf_scene *fine = scaled("tests/solver/block48_seed.yaml", NULL, 0, 0.75);
    const tf_box_geometry *b = &fine->problem.geometry.as.box;
    assert_int_equal(b->grid[0], 15); /* 10 / 0.75 = 13.3 -> 14 intervals, even: 5 / 10 stays */
    assert_int_equal(b->grid[2], 4);
    /* the cells follow the rounded intervals, one per interval as in the
     * scene (13.3 cells would have been 13: a softer cloud) */
    assert_int_equal(fine->problem.solver.cells[0], 14);
    assert_int_equal(fine->problem.solver.cells[2], 3);
    assert_true(fine->problem.contacts[0].by_node);
    assert_int_equal(fine->problem.contacts[0].node, 7 + 15 * 7); /* (7, 7) on the top layer */
    const double *x = fine->problem.cloud.xyz + 3 * (size_t)fine->problem.contacts[0].node;
    assert_true(fabs(x[0] - 24) < 1e-12 && fabs(x[1] - 24) < 1e-12 && fabs(x[2] - 6) < 1e-12);
    tf_scene_free(fine);
    tf_scene *coarse = scaled("tests/solver/block48_seed.yaml", NULL, 0, 4.0 / 3.0);
    assert_int_equal(coarse->problem.geometry.as.box.grid[0], 9); /* 7.5 -> 8, even */
    assert_int_equal(coarse->problem.contacts[0].node, 4 + 9 * 4);
    tf_scene_free(coarse);
    /* node (3, 5) on top: 3 / 10 stays a node only on multiples of 10
     * intervals in x; y still refines */
    const char *sets[] = {"contact.0.node=59"};
    fine = scaled("tests/solver/block48_seed.yaml", sets, 1, 0.75);
    assert_int_equal(fine->problem.geometry.as.box.grid[0], 11);
    assert_int_equal(fine->problem.geometry.as.box.grid[1], 15);
    assert_int_equal(fine->problem.solver.cells[0], 10);
    assert_int_equal(fine->problem.solver.cells[1], 14);
    assert_int_equal(fine->problem.contacts[0].node, 3 + 11 * 7);
    x = fine->problem.cloud.xyz + 3 * (size_t)fine->problem.contacts[0].node;
    assert_true(fabs(x[0] - 14.4) < 1e-12 && fabs(x[1] - 24) < 1e-12 && fabs(x[2] - 6) < 1e-12);
    tf_scene_free(fine);
}

static void organ_interior_spacing(void **state)
{
    (void)state;
    /* the shipped stomach (its skin refined to the spacing) at 12 mm rather
     * than its 6: the same rules on an eighth of the nodes (meshing the
     * shipped cloud four times took 26 s, 59 s under the sanitizers) */
    const char *coarse[] = {"geometry.spacing=12"};
    tf_scene *base = scaled("coeffs/stomach.yaml", coarse, 1, 1.0);
    tf_scene *s = scaled("coeffs/stomach.yaml", coarse, 1, 0.75);
    const tf_mesh_geometry *mb = tf_problem_mesh(&base->problem), *ms = tf_problem_mesh(&s->problem);
    assert_true(mb->mesh.spacing == 12.0);
    assert_true(ms->mesh.spacing == 9.0);
    assert_true(ms->mesh.refine_skin && mb->mesh.refine_skin);
    assert_true(fabs(s->problem.solver.d_c - 1.5) < 1e-12); /* the scene's absolute 2 mm */
    /* the skin refines with the interior; the file's vertices stay the first nodes */
    assert_int_equal(ms->file_nv, mb->file_nv);
    assert_true(ms->tm.nsurf > mb->tm.nsurf);
    assert_true(ms->tm.nn > mb->tm.nn);
    tf_scene_free(s);
    tf_scene_free(base);
    /* with the file's skin the surface is the file's on both */
    const char *sets[] = {"geometry.spacing=12", "geometry.refine_skin=false"};
    base = scaled("coeffs/stomach.yaml", sets, 2, 1.0);
    s = scaled("coeffs/stomach.yaml", sets, 2, 0.75);
    mb = tf_problem_mesh(&base->problem);
    ms = tf_problem_mesh(&s->problem);
    assert_int_equal(ms->tm.nsurf, mb->tm.nsurf);
    assert_int_equal(mb->tm.nsurf, mb->file_nv);
    assert_true(ms->tm.nn > mb->tm.nn);
    tf_scene_free(s);
    tf_scene_free(base);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_grid_and_cells),
        cmocka_unit_test(user_sets_first),
        cmocka_unit_test(absolute_d_c_scales),
        cmocka_unit_test(contact_node_stays),
        cmocka_unit_test(organ_interior_spacing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
