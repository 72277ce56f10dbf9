/*
 * test_discretisation_self.c — the discretisation the tool measures itself
 * (fitting/discretisation_self.h) when the coarser cloud fails: the
 * scene's cloud, h/r and h/r^2 take the place of h r, h and h/r, the
 * header's fields say so, and the figure is the scene's cloud's error (its
 * difference from the extrapolated solution), not the finer cloud's.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "base/context.h"
#include "fitting/discretisation_self.h"
#include "scene/scene_levels.h"

#define SCENE "tests/solver/block48_seed.yaml" /* 11 x 11 x 3, linear, node 61 */

/* The scene at spacing factor f; a coarser one refused when `refuse` is
 * set, as a coarse cloud whose solve fails would be. */
typedef struct rescale {
    int refuse;
    tf_scene *made;
} rescale;

static const tf_problem *make(void *user, tf_ctx *ctx, double f)
{
    rescale *r = user;
    if (r->refuse && f > 1) {
        tf_fail(ctx, "refused for the test");
        return NULL;
    }
    r->made = tf_scene_scaled(ctx, SCENE, NULL, 0, f);
    return r->made != NULL ? &r->made->problem : NULL;
}

static void release(void *user, const tf_problem *p)
{
    rescale *r = user;
    (void)p;
    tf_scene_free(r->made);
    r->made = NULL;
}

/* Measures SCENE's error with the coarser cloud refused or not. */
static int measure(tf_ctx *ctx, int refuse, tf_discretisation *out)
{
    rescale r = {.refuse = refuse};
    const tf_rescale re = {.make = make, .release = release, .user = &r};
    tf_scene *scene = tf_scene_load(ctx, SCENE, NULL, 0);
    assert_non_null(scene);
    tf_solver *s = tf_solver_create(&scene->problem, NULL, ctx);
    assert_non_null(s);
    int rc = tf_discretisation_self(ctx, &re, s, &scene->problem, 0, out);
    tf_solver_destroy(s);
    tf_scene_free(scene);
    return rc;
}

static void coarser_refused_finer_clouds_measure(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_discretisation own, shifted;
    assert_int_equal(measure(&ctx, 0, &own), 0);
    int rc = measure(&ctx, 1, &shifted);
    if (rc != 0) {
        fail_msg("%s", ctx.err);
    }
    assert_false(own.self_shifted);
    assert_true(shifted.self_shifted);
    assert_string_equal(shifted.self_shifted_why, "it could not be built");
    /* the scene's cloud first, then h/r and h/r^2 */
    assert_true(shifted.self_h[0] == own.self_h[1]);
    assert_true(shifted.self_nodes[0] == 363 && own.self_nodes[1] == 363);
    assert_true(shifted.self_h[1] == own.self_h[2]); /* both h/r */
    assert_true(shifted.self_h[2] < shifted.self_h[1]);
    assert_true(shifted.self_nodes[2] > shifted.self_nodes[1]);
    /* the same cloud's error measured around it (h r, h, h/r) and from it
     * and two finer clouds (h, h/r, h/r^2): of the same size (0.238 and
     * 0.159 mm), and the change from the scene's cloud to h/r is the same
     * two solves' in both */
    assert_true(isfinite(shifted.max_mm) && shifted.max_mm > 0);
    const double ratio = shifted.max_mm / own.max_mm;
    printf("three clouds around the scene's: %.4g mm (order %.3g); the scene's and two finer: "
           "%.4g mm (order %.3g; ratio %.3g)\n",
           own.max_mm, own.self_order, shifted.max_mm, shifted.self_order, ratio);
    assert_true(ratio >= 0.5 && ratio <= 2);
    assert_true(shifted.self_diff[0] == own.self_diff[1]); /* h -> h/r, solved twice */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(coarser_refused_finer_clouds_measure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
