/*
 * test_history.c — load histories (problem/history.h): samples at the time
 * step and at every jump (an instantaneous jump is two samples at one
 * time), each segment's shape, a table of forces interpolated linearly;
 * and the scene's history: section with its checks.
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

#include "problem/history.h"
#include "scene/scene.h"

static void segments_are_sampled_at_steps_and_jumps(void **state)
{
    (void)state;
    tf_segment seg[] = {{.kind = TF_SEG_STEP, .to = 1},
                        {.kind = TF_SEG_HOLD, .time = 1},
                        {.kind = TF_SEG_RAMP, .to = 0.5, .time = 1},
                        {.kind = TF_SEG_RELEASE},
                        {.kind = TF_SEG_SINUSOID, .amplitude = 0.2, .time = 1, .period = 1}};
    tf_history h = {.present = 1, .dt = 0.5, .duration = 4, .force = {0, 0, -2}, .contact = 0,
                    .seg = seg, .n_seg = 5};
    tf_samples s;
    assert_int_equal(tf_history_sample(&h, &s), 0);
    /* 0 (the step), 0.5, 1, 1.5, 2 (ramp end: 0.5, then the release to 0),
     * 2.5, 3, 3.5, 4 */
    const double t[] = {0, 0.5, 1, 1.5, 2, 2, 2.5, 3, 3.5, 4};
    const double a[] = {1, 1, 1, 0.75, 0.5, 0, 0.2 * sin(M_PI), 0.2 * sin(2 * M_PI), 0.2 * sin(2 * M_PI), 0.2 * sin(2 * M_PI)};
    assert_int_equal(s.n, 10);
    for (size_t k = 0; k < s.n; ++k) {
        assert_true(fabs(s.t[k] - t[k]) < 1e-15);
        assert_true(fabs(s.scale[k] - a[k]) < 1e-15);
        assert_true(fabs(s.force[k][2] + 2 * a[k]) < 1e-15);
    }
    assert_true(fabs(tf_history_factor(&h, 2.75) - 0.2 * sin(1.5 * M_PI)) < 1e-15);
    tf_samples_free(&s);
}

static void a_table_is_the_force_itself(void **state)
{
    (void)state;
    double rows[] = {0, 0, 0, -1, 1, 0.5, 0, -3};
    tf_history h = {.present = 1, .dt = 0.25, .duration = 1.5, .contact = 0, .table = rows,
                    .n_rows = 2};
    tf_samples s;
    assert_int_equal(tf_history_sample(&h, &s), 0);
    assert_int_equal(s.n, 7); /* the jump to the first row at 0, then every 0.25 s */
    assert_true(s.t[0] == 0 && s.force[0][2] == -1 && s.scale[0] == 1);
    assert_true(fabs(s.force[2][2] + 2) < 1e-15 && fabs(s.force[2][0] - 0.25) < 1e-15);
    assert_true(s.force[6][2] == -3); /* held after the last row */
    tf_samples_free(&s);
}

static const char *scene =
    "name: t\n"
    "geometry: {box: {min: [0, 0, 0], max: [10, 10, 2]}, grid: [5, 5, 2]}\n"
    "material: {law: kelvin, nu: 0.3, k1: 1, k2: 0.5, eta: 1}\n"
    "fixed: [{face: z-}]\n"
    "contact: [{node: 13}]\n"
    "outputs: {select: all}\n"
    "history:\n"                                   /* 7 */
    "  dt: 0.1\n"                                  /* 8 */
    "  duration: 2\n"                              /* 9 */
    "  force: [0, 0, -1]\n"                        /* 10 */
    "  segments:\n"                                /* 11 */
    "    - {kind: step, to: 1}\n"                  /* 12 */
    "    - {kind: hold, time: 1}\n";               /* 13 */

static void scene_history_and_its_checks(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load_text(&ctx, scene, strlen(scene), "t.yaml", NULL, 0);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    const tf_history *h = &s->problem.history;
    assert_true(h->present && h->dt == 0.1 && h->duration == 2 && h->n_seg == 2);
    assert_true(h->contact == 0 && h->force[2] == -1 && h->seg[1].kind == TF_SEG_HOLD);
    tf_scene_free(s);
    const struct {
        const char *set, *fragment;
    } bad[] = {
        {"history.dt=0", "history.dt"},
        {"history.duration=-1", "history.duration"},
        {"history.segments.1={kind: hold}", "history.segments.1.time"},
        {"history.segments.0={kind: ramp, to: 1, time: 0}", "must be positive"},
        {"history.segments.1={kind: release, to: 1}", "takes no to"},
        {"history.contact=elsewhere", "history.contact"},
        {"history.table=nowhere.csv", "history"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        const char *sets[] = {bad[k].set};
        s = tf_scene_load_text(&ctx, scene, strlen(scene), "t.yaml", sets, 1);
        if (s != NULL) {
            tf_scene_free(s);
            fail_msg("accepted %s", bad[k].set);
        }
        if (strstr(ctx.err, bad[k].fragment) == NULL) {
            fail_msg("%s: message '%s' lacks '%s'", bad[k].set, ctx.err, bad[k].fragment);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(segments_are_sampled_at_steps_and_jumps),
        cmocka_unit_test(a_table_is_the_force_itself),
        cmocka_unit_test(scene_history_and_its_checks),
    };
    return cmocka_run_group_tests_name("history", tests, NULL, NULL);
}
