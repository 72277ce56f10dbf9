/*
 * test_weak_bc.c — the EFG Galerkin solver and weak essential conditions:
 * with corrected gradients (VCI) and Nitsche's method the patch test passes
 * to rounding for EFG and RPIM on a jittered cloud, and fails without
 * either; EFG's cantilever converges at rate 2; EFG returns displacements
 * at the nodes (its field there), not parameters; the penalty's error falls
 * with its factor; the scene refuses what EFG cannot do.
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
#include "scene/scene.h"
#include "scene/scene_levels.h"
#include "solvers/solver.h"
#include "verify/verify.h"

#define PATCH "tests/solver/patch.yaml"
#define CANTILEVER "coeffs/cantilever.yaml"

static void quiet(tf_ctx *ctx)
{
    tf_ctx_init(ctx);
    ctx->level = TF_LOG_ERROR;
}

static tf_verify_row level(const char *path, const char *const *sets, size_t n_sets, tf_vary vary,
                           unsigned k)
{
    unsigned label;
    tf_ctx ctx;
    quiet(&ctx);
    tf_scene *s = tf_scene_level(&ctx, path, sets, n_sets, vary, k, &label);
    if (s == NULL) {
        fail_msg("%s", ctx.err);
    }
    tf_verify_row row;
    if (tf_verify_problem(&s->problem, label, &ctx, &row) != 0) {
        fail_msg("%s", ctx.err);
    }
    tf_scene_free(s);
    return row;
}

/* The patch test's L2 error with gauss^3 points per cell. */
static double patch(const char *method, const char *bc, const char *integration,
                    const char *centre, unsigned gauss)
{
    char a[64], b[64], c[64], d[64];
    snprintf(a, sizeof a, "solver.method=%s", method);
    snprintf(b, sizeof b, "solver.bc=%s", bc);
    snprintf(c, sizeof c, "solver.integration=%s", integration);
    snprintf(d, sizeof d, "solver.centre=%s", centre);
    const char *sets[] = {a, b, c, d};
    return level(PATCH, sets, 4, TF_VARY_GAUSS, gauss - 1).error_l2;
}

static void corrected_gradients_and_nitsche_pass_the_patch_test(void **state)
{
    (void)state;
    for (unsigned g = 1; g <= 3; g += 2) {
        assert_true(patch("efg-galerkin", "nitsche", "vci", "cell", g) < 1e-12);
        assert_true(patch("rpim-galerkin", "nitsche", "vci", "cell", g) < 1e-12);
        assert_true(patch("rpim-galerkin", "nitsche", "vci", "point", g) < 1e-12);
    }
    /* either ingredient alone leaves an error: plain Gauss points miss the
     * divergence theorem; eliminating RPIM's boundary values drops the
     * boundary terms of interior nodes */
    assert_true(patch("efg-galerkin", "nitsche", "gauss", "cell", 3) > 1e-5);
    assert_true(patch("rpim-galerkin", "nitsche", "gauss", "cell", 3) > 1e-4);
    assert_true(patch("rpim-galerkin", "elimination", "vci", "cell", 3) > 1e-4);
    assert_true(patch("efg-galerkin", "penalty", "vci", "cell", 3) > 1e-9);
}

static void efg_cantilever_converges_at_rate_two(void **state)
{
    (void)state;
    const char *sets[] = {"solver.method=efg-galerkin"};
    tf_verify_row rows[2];
    for (unsigned k = 0; k < 2; ++k) {
        rows[k] = level(CANTILEVER, sets, 1, TF_VARY_GRID, k);
    }
    tf_verify_rates(rows, 2);
    assert_true(rows[1].rate > 1.8); /* 2.05 (docs/validation.md) */
    assert_true(rows[1].error_energy < 0.6 * rows[0].error_energy);
    assert_true(rows[1].error_l2 < 3e-3);
}

typedef struct efg_run {
    tf_ctx ctx;
    tf_scene *s;
    tf_solver *sv;
    double *u;
} efg_run;

static efg_run *run_block48(const char *const *sets, size_t n_sets)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    efg_run *r = calloc(1, sizeof *r);
    quiet(&r->ctx);
    r->s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", sets, n_sets);
    if (r->s == NULL) {
        fail_msg("%s", ctx.err);
    }
    r->sv = tf_solver_create(&r->s->problem, NULL, &r->ctx);
    if (r->sv == NULL) {
        fail_msg("%s", r->ctx.err);
    }
    const double f[1][3] = {{0.3, -0.2, -1}};
    r->u = malloc(3 * r->s->problem.cloud.n * sizeof *r->u);
    if (tf_solver_solve(r->sv, 0, f, 1, NULL, r->u) != 0) {
        fail_msg("%s", r->ctx.err);
    }
    return r;
}

static void run_free(efg_run *r)
{
    free(r->u);
    tf_solver_destroy(r->sv);
    tf_scene_free(r->s);
    free(r);
}

/* EFG's outputs are u(x_I) = sum phi_J(x_I) d_J: its own field at the
 * nodes gives them back; the clamped faces hardly move. */
static void efg_returns_displacements_at_the_nodes(void **state)
{
    (void)state;
    const char *sets[] = {"solver.method=efg-galerkin"};
    efg_run *r = run_block48(sets, 1);
    const tf_cloud *c = &r->s->problem.cloud;
    size_t n3 = 3 * c->n;
    double *uh = malloc(n3 * sizeof *uh), *g = malloc(3 * n3 * sizeof *g), scale = 0, worst = 0;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_solver_field(&ctx, r->sv, r->u, c->xyz, c->n, uh, g), 0);
    for (size_t d = 0; d < n3; ++d) {
        scale = fmax(scale, fabs(r->u[d]));
        worst = fmax(worst, fabs(uh[d] - r->u[d]));
    }
    assert_true(worst < 1e-12 * scale);
    assert_true(fabs(r->u[3 * 0]) < 1e-3 * scale); /* node 1, a clamped corner */
    assert_true(r->u[3 * 60 + 2] < -0.5);          /* node 61 moves down */
    assert_string_equal(tf_solver_name(r->sv), "efg-galerkin");
    free(uh);
    free(g);
    run_free(r);
}

/* The penalty approaches Nitsche's answer as its factor grows, until it
 * over-constrains the boundary (it then holds every boundary point, which
 * the MLS space cannot do without stiffening). */
static void penalty_error_falls_with_its_factor(void **state)
{
    (void)state;
    const char *nit[] = {"solver.method=efg-galerkin"};
    efg_run *ref = run_block48(nit, 1);
    size_t n3 = 3 * ref->s->problem.cloud.n;
    double diff[3];
    const char *factors[3] = {"solver.penalty=0.1", "solver.penalty=10", "solver.penalty=1e4"};
    for (int k = 0; k < 3; ++k) {
        const char *sets[] = {"solver.method=efg-galerkin", "solver.bc=penalty", factors[k]};
        efg_run *r = run_block48(sets, 3);
        double worst = 0, scale = 0;
        for (size_t d = 0; d < n3; ++d) {
            scale = fmax(scale, fabs(ref->u[d]));
            worst = fmax(worst, fabs(r->u[d] - ref->u[d]));
        }
        diff[k] = worst / scale;
        run_free(r);
    }
    assert_true(diff[0] > 0.1);  /* 0.16: the faces move */
    assert_true(diff[1] < 0.02); /* 0.013 */
    assert_true(diff[2] > 0.1);  /* 0.18: boundary locking */
    run_free(ref);
}

static void scene_refuses_what_efg_cannot_do(void **state)
{
    (void)state;
    const char *elim[] = {"solver.method=efg-galerkin", "solver.bc=elimination"};
    tf_ctx ctx;
    quiet(&ctx);
    assert_null(tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", elim, 2));
    assert_non_null(strstr(ctx.err, "solver.bc"));
    const char *box[] = {"solver.method=efg-galerkin",
                         "fixed.4={box: {min: [0, 0, 0], max: [1, 1, 1]}}"};
    tf_scene *s = tf_scene_load(&ctx, "tests/solver/block48_seed.yaml", box, 2);
    assert_non_null(s);
    assert_null(tf_solver_create(&s->problem, NULL, &ctx));
    assert_non_null(strstr(ctx.err, "fixed region 4 is not a face"));
    tf_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(corrected_gradients_and_nitsche_pass_the_patch_test),
        cmocka_unit_test(efg_cantilever_converges_at_rate_two),
        cmocka_unit_test(efg_returns_displacements_at_the_nodes),
        cmocka_unit_test(penalty_error_falls_with_its_factor),
        cmocka_unit_test(scene_refuses_what_efg_cannot_do),
    };
    return cmocka_run_group_tests_name("weak_bc", tests, NULL, NULL);
}
