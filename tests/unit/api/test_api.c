/*
 * test_api.c — the flat API of the Python module (host/api/api.h): a
 * failure leaves the tool's message in the context (a scene's with file,
 * line and field); a solve gives the bits of the solver the tool drives; the
 * cut progress truncates the scene's cuts and puts them back whole; the
 * grid's cells; `fit`'s exit statuses.  The Python side's comparisons with
 * the tool itself are tests/python (check-python).
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

#include "api/api.h"
#include "scene/scene.h"
#include "solvers/probe.h"
#include "solvers/solver.h"

#define SEED "tests/solver/block48_seed.yaml" /* 11 x 11 x 3 nodes, top-centre, 121 outputs */
#define CUT "coeffs/block48_cut.yaml"          /* 11 x 11 x 3 with an incision */

static void errors_are_kept(void **state)
{
    (void)state;
    tf_ctx *ctx = tf_api_ctx_new(0);
    assert_non_null(ctx);
    assert_string_equal(tf_api_ctx_error(ctx), "");
    const char *sets[] = {"material.nu=0.7"};
    assert_null(tf_api_scene_load(ctx, SEED, sets, 1));
    assert_non_null(strstr(tf_api_ctx_error(ctx), "--set material.nu=0.7: material.nu: "));
    assert_null(tf_api_scene_load(ctx, "tests/unit/api/none.yaml", NULL, 0));
    assert_non_null(strstr(tf_api_ctx_error(ctx), "tests/unit/api/none.yaml"));
    tf_api_ctx_free(ctx);
}

/* The bits of tf_solver_solve on the scene the tool reads. */
static void solve_is_the_solvers(void **state)
{
    (void)state;
    tf_ctx *ctx = tf_api_ctx_new(0);
    tf_api_scene *s = tf_api_scene_load(ctx, SEED, NULL, 0);
    assert_non_null(s);
    const double *xyz;
    size_t n = tf_api_scene_nodes(s, &xyz), m = tf_api_scene_outputs(s, NULL, NULL);
    assert_int_equal(n, 363);
    assert_int_equal(m, 121);
    assert_int_equal(tf_api_scene_contacts(s), 1);
    assert_string_equal(tf_api_scene_contact_name(s, 0), "top-centre");
    assert_null(tf_api_scene_contact_name(s, 1));
    double *pos = malloc(3 * m * sizeof *pos), *u = malloc(3 * n * sizeof *u);
    double *v = malloc(3 * m * sizeof *v), *w = malloc(3 * n * sizeof *w);
    uint64_t *id = malloc(m * sizeof *id);
    tf_api_scene_outputs(s, pos, id);
    assert_int_equal(id[60], 61); /* the top centre, node 61 */
    assert_true(pos[3 * 60] == 24 && pos[3 * 60 + 1] == 24 && pos[3 * 60 + 2] == 6);
    const double f[3] = {0.9, -0.7, -0.22};
    assert_int_equal(tf_api_solve(ctx, s, NULL, f, NAN, u, v), 0);

    tf_ctx plain;
    tf_ctx_init(&plain);
    plain.level = TF_LOG_WARN;
    tf_scene *sc = tf_scene_load(&plain, SEED, NULL, 0);
    tf_solver *sv = tf_solver_create(&sc->problem, NULL, &plain);
    assert_non_null(sv);
    assert_int_equal(tf_solver_solve(sv, 0, (const double(*)[3])f, 1, NULL, w), 0);
    assert_memory_equal(u, w, 3 * n * sizeof *u);
    assert_int_equal(tf_solver_probe_outputs(&plain, sv, &sc->problem, w, pos), 0);
    assert_memory_equal(v, pos, 3 * m * sizeof *v);
    assert_true(u[3 * 60] > 0.5); /* node 61 follows the force */
    tf_solver_destroy(sv);
    tf_scene_free(sc);

    /* the field at a node of this interpolating (RPIM) cloud is its value */
    double at[3];
    assert_int_equal(tf_api_field(ctx, s, u, xyz + 3 * 60, 1, at), 0);
    for (int a = 0; a < 3; ++a) {
        assert_true(fabs(at[a] - u[3 * 60 + a]) < 1e-9);
    }
    /* what the tool refuses */
    assert_int_equal(tf_api_solve(ctx, s, "nowhere", f, NAN, u, v), -1);
    assert_string_equal(tf_api_ctx_error(ctx),
                        "solve: " SEED " has no contact site 'nowhere'");
    assert_int_equal(tf_api_solve(ctx, s, NULL, NULL, NAN, u, v), -1);
    assert_non_null(strstr(tf_api_ctx_error(ctx), "nothing loads the body"));
    assert_int_equal(tf_api_solve(ctx, s, NULL, f, 0.5, u, v), -1);
    assert_string_equal(tf_api_ctx_error(ctx), "solve: --cut-progress: " SEED " has no cuts");

    size_t count;
    unsigned corners;
    assert_int_equal(tf_api_cells(ctx, s, &count, &corners, NULL), 0);
    assert_int_equal(count, 10 * 10 * 2);
    assert_int_equal(corners, 8);
    free(pos);
    free(u);
    free(v);
    free(w);
    free(id);
    tf_api_scene_free(s);
    tf_api_ctx_free(ctx);
}

/* A cut progress truncates the cuts; the next solve without one has them whole. */
static void cut_progress_and_back(void **state)
{
    (void)state;
    tf_ctx *ctx = tf_api_ctx_new(0);
    tf_api_scene *s = tf_api_scene_load(ctx, CUT, NULL, 0);
    assert_non_null(s);
    size_t n = tf_api_scene_nodes(s, NULL), whole, half, again;
    unsigned corners;
    double *u[3];
    const double f[3] = {1, 0, 0};
    const double progress[3] = {NAN, 0.5, NAN};
    size_t *cells[3] = {&whole, &half, &again};
    for (int k = 0; k < 3; ++k) {
        u[k] = malloc(3 * n * sizeof *u[k]);
        assert_int_equal(tf_api_solve(ctx, s, NULL, f, progress[k], u[k], NULL), 0);
        assert_int_equal(tf_api_cells(ctx, s, cells[k], &corners, NULL), 0);
    }
    assert_memory_equal(u[0], u[2], 3 * n * sizeof *u[0]);
    assert_memory_not_equal(u[0], u[1], 3 * n * sizeof *u[0]);
    assert_true(whole < half && half < 200); /* the incision's cells left out */
    assert_int_equal(whole, again);
    assert_int_equal(tf_api_solve(ctx, s, NULL, f, 1.5, u[1], NULL), -1);
    assert_string_equal(tf_api_ctx_error(ctx), "solve: --cut-progress '1.5' is not a number in [0, 1]");
    for (int k = 0; k < 3; ++k) {
        free(u[k]);
    }
    tf_api_scene_free(s);
    tf_api_ctx_free(ctx);
}

static void fit_statuses(void **state)
{
    (void)state;
    tf_ctx *ctx = tf_api_ctx_new(0);
    int status = -1;
    const char *none[] = {SEED};
    assert_int_equal(tf_api_fit(ctx, none, 1, &status), -1);
    assert_int_equal(status, 2);
    assert_string_equal(tf_api_ctx_error(ctx),
                        "fit: expected one scene file and -o FILE.h (see tissuefit fit --help)");
    const char *family[] = {SEED, "-o", "/tmp/tf_api_never.h", "--family", "cubic"};
    assert_int_equal(tf_api_fit(ctx, family, 5, &status), -1);
    assert_int_equal(status, 2);
    assert_non_null(strstr(tf_api_ctx_error(ctx), "fit: --family 'cubic': the forward families are"));
    tf_api_ctx_free(ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(errors_are_kept),
        cmocka_unit_test(solve_is_the_solvers),
        cmocka_unit_test(cut_progress_and_back),
        cmocka_unit_test(fit_statuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
