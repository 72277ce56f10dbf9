/*
 * test_context.c — the run's context replaces global state: messages go to
 * the context's sink and stop at its level, failures leave their message in
 * its buffer (a caller may wrap a callee's message in it), and a solver
 * built with a context logs through it (two contexts, two different sinks,
 * no cross-talk).
 */
#include <omp.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "base/context.h"
#include "base/log.h"
#include "base/progress.h"
#include "scene/scene.h"
#include "solvers/solver.h"

typedef struct captured {
    char text[8192];
    int count[3]; /* per level */
} captured;

static void capture(void *user, tf_log_level level, const char *msg)
{
    captured *c = user;
    size_t len = strlen(c->text);
    snprintf(c->text + len, sizeof c->text - len, "%d:%s\n", (int)level, msg);
    c->count[level]++;
}

static void capturing(tf_ctx *ctx, captured *c, tf_log_level level)
{
    tf_ctx_init(ctx);
    memset(c, 0, sizeof *c);
    ctx->sink = capture;
    ctx->sink_user = c;
    ctx->level = level;
}

static void messages_stop_at_the_level(void **state)
{
    (void)state;
    tf_ctx ctx;
    captured c;
    capturing(&ctx, &c, TF_LOG_INFO);
    tf_info(&ctx, "progress %d", 1);
    tf_warn(&ctx, "careful");
    tf_error(&ctx, "broken %s", "badly");
    assert_int_equal(c.count[TF_LOG_INFO], 1);
    assert_int_equal(c.count[TF_LOG_WARN], 1);
    assert_int_equal(c.count[TF_LOG_ERROR], 1);
    assert_non_null(strstr(c.text, "2:progress 1\n"));
    assert_non_null(strstr(c.text, "0:broken badly\n"));
    capturing(&ctx, &c, TF_LOG_WARN); /* tissuefit -q */
    tf_info(&ctx, "progress");
    tf_warn(&ctx, "careful");
    assert_int_equal(c.count[TF_LOG_INFO], 0);
    assert_int_equal(c.count[TF_LOG_WARN], 1);
    capturing(&ctx, &c, TF_LOG_ERROR);
    tf_warn(&ctx, "careful");
    tf_error(&ctx, "broken");
    assert_int_equal(c.count[TF_LOG_WARN], 0);
    assert_int_equal(c.count[TF_LOG_ERROR], 1);
}

/* Progress lines (long nonlinear fits, base/progress.h): info level, so
 * -q drops them; at most one per interval, with the seconds so far. */
static void progress_lines_come_at_most_once_per_interval(void **state)
{
    (void)state;
    tf_ctx ctx;
    captured c;
    tf_progress p;
    capturing(&ctx, &c, TF_LOG_INFO);
    tf_progress_start(&p, &ctx, 0); /* every call is due */
    tf_progress_line(&p, "cases: %d of %d solved", 1, 3);
    tf_progress_line(&p, "cases: %d of %d solved", 2, 3);
    assert_int_equal(c.count[TF_LOG_INFO], 2);
    assert_non_null(strstr(c.text, "2:cases: 2 of 3 solved (0 s)\n"));
    capturing(&ctx, &c, TF_LOG_INFO);
    tf_progress_start(&p, &ctx, 3600); /* none due within the test */
    for (int k = 0; k < 1000; ++k) {
        tf_progress_line(&p, "cases: %d solved", k);
    }
    assert_int_equal(c.count[TF_LOG_INFO], 0);
    capturing(&ctx, &c, TF_LOG_WARN); /* tissuefit -q */
    tf_progress_start(&p, &ctx, 0);
    tf_progress_line(&p, "cases: 1 solved");
    assert_int_equal(c.count[TF_LOG_INFO], 0);
}

static void a_failure_leaves_its_message(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_string_equal(ctx.err, "");
    assert_int_equal(tf_fail(&ctx, "node %d of %s", 7, "block48"), -1);
    assert_string_equal(ctx.err, "node 7 of block48");
    assert_int_equal(tf_ctx_threads(&ctx), omp_get_max_threads());
    ctx.threads = 3;
    assert_int_equal(tf_ctx_threads(&ctx), 3);
}

/* A caller that says where a failure happened wraps the callee's message,
 * passing ctx->err back to tf_fail, which reads it before writing it; a
 * message longer than the buffer is cut, never overrun. */
static void a_caller_wraps_its_callees_message(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_null(tf_scene_load(&ctx, "no/such/scene.yaml", NULL, 0));
    char inner[sizeof ctx.err], want[sizeof ctx.err + 32];
    memcpy(inner, ctx.err, sizeof inner);
    assert_non_null(strstr(inner, "no/such/scene.yaml"));
    assert_int_equal(tf_fail(&ctx, "fit: %s: %s", "block48.yaml", ctx.err), -1);
    snprintf(want, sizeof want, "fit: block48.yaml: %s", inner);
    assert_string_equal(ctx.err, want);
    memset(inner, 'x', sizeof inner - 1);
    inner[sizeof inner - 1] = '\0';
    tf_fail(&ctx, "%s", inner);
    assert_int_equal(tf_fail(&ctx, "%s+%s", ctx.err, ctx.err), -1);
    assert_int_equal(strlen(ctx.err), sizeof ctx.err - 1);
    assert_int_equal(strspn(ctx.err, "x"), sizeof ctx.err - 1);
}

/* Two solvers, each with its own context: each context's sink hears its own
 * solver's progress, and a quiet context hears nothing. */
static void a_solver_logs_through_its_own_context(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", NULL, 0);
    assert_non_null(s);
    tf_ctx loud, quiet;
    captured heard_loud, heard_quiet;
    capturing(&loud, &heard_loud, TF_LOG_INFO);
    capturing(&quiet, &heard_quiet, TF_LOG_WARN);
    tf_solver *a = tf_solver_create(&s->problem, NULL, &loud);
    tf_solver *b = tf_solver_create(&s->problem, NULL, &quiet);
    assert_non_null(a);
    assert_non_null(b);
    tf_solver_report(a);
    tf_solver_report(b);
    assert_non_null(strstr(heard_loud.text, "solver: factorised"));
    assert_non_null(strstr(heard_loud.text, "solver: times (s)"));
    assert_int_equal(heard_quiet.count[TF_LOG_INFO], 0);
    assert_string_equal(heard_quiet.text, "");
    /* a failure lands in the context of the solver that failed */
    assert_int_equal(tf_solver_solve(b, 5, NULL, 1, NULL, NULL), -1);
    assert_non_null(strstr(quiet.err, "no contact site 5"));
    assert_null(strstr(loud.err, "no contact site"));
    tf_solver_destroy(a);
    tf_solver_destroy(b);
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(messages_stop_at_the_level),
        cmocka_unit_test(progress_lines_come_at_most_once_per_interval),
        cmocka_unit_test(a_failure_leaves_its_message),
        cmocka_unit_test(a_caller_wraps_its_callees_message),
        cmocka_unit_test(a_solver_logs_through_its_own_context),
    };
    return cmocka_run_group_tests_name("context", tests, NULL, NULL);
}
