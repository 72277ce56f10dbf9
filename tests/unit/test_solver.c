/*
 * test_solver.c — the RPIM Galerkin solver through the solver interface
 * on block48 (GUIDE §5): equilibrium of reactions and load, x <-> y mirror
 * symmetry, 1/E scaling, elimination against the seed's penalty, many load
 * cases through one factorisation, the same bits whatever the thread count,
 * the capabilities it declares and the interface's argument checks.
 */
#include <math.h>
#include <omp.h>
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
#include "solvers/galerkin/galerkin.h"
#include "solvers/solver.h"

#define BLOCK48 "coeffs/block48.yaml"

static const double unit_forces[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}; /* fx, fy, fz */

typedef struct run {
    tf_ctx ctx;
    tf_scene *scene;
    const tf_problem *p;
    tf_solver *solver;
    double *u; /* 3N x ncases */
} run;

/* A quiet context with the given thread count (0: OpenMP's). */
static void quiet(tf_ctx *ctx, int threads)
{
    tf_ctx_init(ctx);
    ctx->level = TF_LOG_ERROR;
    ctx->threads = threads;
}

static run *solve_on(const char *scene, const char *const *sets, size_t n_sets, int threads,
                     const double (*forces)[3], size_t ncases)
{
    char err[512];
    run *r = calloc(1, sizeof *r);
    quiet(&r->ctx, threads);
    r->scene = tf_scene_load(scene, sets, n_sets, err, sizeof err);
    if (r->scene == NULL) {
        fail_msg("%s", err);
    }
    r->p = &r->scene->problem;
    r->solver = tf_solver_create(r->p, NULL, &r->ctx);
    if (r->solver == NULL) {
        fail_msg("%s", r->ctx.err);
    }
    r->u = malloc(3 * r->p->cloud.n * ncases * sizeof *r->u);
    if (tf_solver_solve(r->solver, forces ? 0 : -1, forces, ncases, NULL, r->u) != 0) {
        fail_msg("%s", r->ctx.err);
    }
    return r;
}

static run *solve(const char *const *sets, size_t n_sets, const double (*forces)[3],
                  size_t ncases)
{
    return solve_on(BLOCK48, sets, n_sets, 0, forces, ncases);
}

static void done(run *r)
{
    free(r->u);
    tf_solver_destroy(r->solver);
    tf_scene_free(r->scene);
    free(r);
}

static double max_abs(const double *v, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        m = fmax(m, fabs(v[i]));
    }
    return m;
}

static void reactions_balance_the_applied_force(void **state)
{
    (void)state;
    const char *point[] = {"contact.0={node: 61}"}; /* a point force instead of the patch */
    for (int variant = 0; variant < 2; ++variant) {
        run *r = solve(point, (size_t)variant, unit_forces, 3);
        size_t n3 = 3 * r->p->cloud.n;
        double *react = malloc(n3 * sizeof *react);
        unsigned char *fixed = malloc(n3);
        tf_problem_fixed_dofs(r->p, fixed);
        for (int c = 0; c < 3; ++c) {
            double sum[3] = {0, 0, 0}, resid = 0;
            assert_int_equal(
                tf_solver_reactions(r->solver, 0, unit_forces[c], r->u + c * n3, react), 0);
            for (size_t d = 0; d < n3; ++d) {
                if (fixed[d]) {
                    sum[d % 3] += react[d];
                } else {
                    resid = fmax(resid, fabs(react[d]));
                }
            }
            for (int a = 0; a < 3; ++a) {
                assert_true(fabs(sum[a] + unit_forces[c][a]) < 1e-6);
            }
            assert_true(resid < 1e-10);
        }
        free(fixed);
        free(react);
        done(r);
    }
}

static void fx_and_fy_mirror_each_other(void **state)
{
    (void)state;
    run *r = solve(NULL, 0, unit_forces, 3);
    const tf_cloud *c = &r->p->cloud;
    size_t n3 = 3 * c->n;
    const double *ux = r->u, *uy = r->u + n3, *uz = r->u + 2 * n3;
    double scale = max_abs(r->u, 3 * n3), worst = 0;
    for (unsigned k = 0; k < 3; ++k) {
        for (unsigned j = 0; j < 11; ++j) {
            for (unsigned i = 0; i < 11; ++i) {
                size_t a = tf_cloud_index(c, i, j, k), b = tf_cloud_index(c, j, i, k);
                /* the fx case mirrored about x = y is the fy case */
                worst = fmax(worst, fabs(ux[3 * a] - uy[3 * b + 1]));
                worst = fmax(worst, fabs(ux[3 * a + 1] - uy[3 * b]));
                worst = fmax(worst, fabs(ux[3 * a + 2] - uy[3 * b + 2]));
                /* the fz case is symmetric about both centre lines */
                size_t m = tf_cloud_index(c, 10 - i, j, k);
                worst = fmax(worst, fabs(uz[3 * a + 2] - uz[3 * m + 2]));
                worst = fmax(worst, fabs(uz[3 * a] + uz[3 * m]));
            }
        }
    }
    assert_true(worst < 1e-9 * scale);
    assert_true(uz[3 * 60 + 2] < 0 && ux[3 * 60] > 0); /* node 61 moves with the force */
    done(r);
}

static void displacement_scales_as_one_over_e(void **state)
{
    (void)state;
    run *ref = solve(NULL, 0, unit_forces, 3);
    size_t n = 9 * ref->p->cloud.n;
    const char *stiff[] = {"material.E=320"}, *soft[] = {"material.E=0.00032"};
    const double factor[2] = {1e-3, 1e3};
    for (int k = 0; k < 2; ++k) {
        run *r = solve(k ? soft : stiff, 1, unit_forces, 3);
        double worst = 0;
        for (size_t d = 0; d < n; ++d) {
            worst = fmax(worst, fabs(r->u[d] - factor[k] * ref->u[d]));
        }
        assert_true(worst < 1e-12 * factor[k] * max_abs(ref->u, n));
        done(r);
    }
    done(ref);
}

static double relative_difference(const double *a, const double *b, size_t n)
{
    double worst = 0;
    for (size_t d = 0; d < n; ++d) {
        worst = fmax(worst, fabs(a[d] - b[d]));
    }
    return worst / max_abs(b, n);
}

static void penalty_agrees_with_elimination(void **state)
{
    (void)state;
    run *elim = solve(NULL, 0, unit_forces, 3);
    size_t n = 9 * elim->p->cloud.n;
    const char *seed[] = {"solver.bc=penalty"};
    run *pen = solve(seed, 1, unit_forces, 3);
    assert_true(relative_difference(pen->u, elim->u, n) < 1e-6); /* lambda = 1e7 */
    done(pen);
    /* a small lambda does not hold the faces (error about 0.1 / lambda):
     * the check above can fail */
    const char *weak[] = {"solver.bc=penalty", "solver.penalty=10"};
    run *loose = solve(weak, 2, unit_forces, 3);
    assert_true(relative_difference(loose->u, elim->u, n) > 1e-3);
    done(loose);
    done(elim);
}

static void many_cases_through_one_factorisation(void **state)
{
    (void)state;
    double forces[6][3];
    for (int k = 0; k < 18; ++k) {
        forces[k / 3][k % 3] = sin(1.7 * k + 0.3); /* six arbitrary forces */
    }
    run *units = solve(NULL, 0, unit_forces, 3);
    run *many = solve(NULL, 0, (const double(*)[3])forces, 6);
    size_t n3 = 3 * units->p->cloud.n;
    double *one = malloc(n3 * sizeof *one);
    for (int k = 0; k < 6; ++k) {
        const double *f = forces[k], *u = many->u + k * n3;
        assert_int_equal(tf_solver_solve(many->solver, 0, &forces[k], 1, NULL, one), 0);
        for (size_t d = 0; d < n3; ++d) {
            /* linear: the superposition of the unit cases (fz case is -z) */
            double sup = f[0] * units->u[d] + f[1] * units->u[n3 + d] - f[2] * units->u[2 * n3 + d];
            assert_true(fabs(u[d] - sup) < 1e-12 * max_abs(units->u, 3 * n3));
            assert_true(fabs(u[d] - one[d]) < 1e-13 * max_abs(units->u, 3 * n3));
        }
    }
    assert_int_equal(tf_solver_info_of(many->solver)->solves, 12);
    free(one);
    done(many);
    done(units);
}

/* Through the context's thread count (the solver's parallel loops) and
 * OpenMP's default (the context left at 0). */
static void same_bits_whatever_the_thread_count(void **state)
{
    (void)state;
    int saved = omp_get_max_threads();
    const char *finer[] = {"geometry.grid=15,15,4", "contact.0.node=113"};
    run *one = solve_on(BLOCK48, finer, 2, 1, unit_forces, 3);
    run *two = solve_on(BLOCK48, finer, 2, 2, unit_forces, 3);
    omp_set_num_threads(2);
    run *dflt = solve_on(BLOCK48, finer, 2, 0, unit_forces, 3);
    omp_set_num_threads(saved);
    size_t n = 9 * one->p->cloud.n;
    assert_memory_equal(one->u, two->u, n * sizeof *one->u);
    assert_memory_equal(one->u, dflt->u, n * sizeof *one->u);
    done(one);
    done(two);
    done(dflt);
}

/* Compliance at node 61 under 1 N along -z. */
static double uz61(const char *nu, const char *volumetric, const char *centre)
{
    char a[64], b[64], c[64];
    snprintf(a, sizeof a, "material.nu=%s", nu);
    snprintf(b, sizeof b, "solver.volumetric=%s", volumetric);
    snprintf(c, sizeof c, "solver.centre=%s", centre);
    const char *sets[] = {a, b, c};
    run *r = solve(sets, 3, unit_forces + 2, 1);
    double uz = -r->u[3 * 60 + 2];
    done(r);
    return uz;
}

static void cell_averaged_volume_strain_relieves_locking(void **state)
{
    (void)state;
    /* From nu = 0.49 to 0.499 the compliance barely changes in the
     * continuum; full integration locks (loses 29 %), B-bar does not. */
    assert_true(uz61("0.499", "full", "cell") < 0.8 * uz61("0.49", "full", "cell"));
    assert_true(uz61("0.499", "cell", "cell") > 0.95 * uz61("0.49", "cell", "cell"));
    assert_true(uz61("0.499", "cell", "point") > 0.95 * uz61("0.49", "cell", "point"));
    assert_true(uz61("0.49", "cell", "cell") > 1.1 * uz61("0.49", "full", "cell"));
}

static void nodes_are_exposed_in_scene_numbering(void **state)
{
    (void)state;
    run *r = solve(NULL, 0, unit_forces, 1);
    assert_int_equal(tf_solver_node_count(r->solver), 363);
    assert_int_equal(tf_problem_node_number(r->p, 60), 61);
    const double *x = tf_solver_coords(r->solver) + 3 * 60;
    assert_true(x[0] == 24 && x[1] == 24 && x[2] == 6);
    /* the interface refuses a contact site the problem does not have */
    r->ctx.err[0] = '\0';
    assert_int_equal(tf_solver_solve(r->solver, 1, unit_forces, 1, NULL, r->u), -1);
    assert_non_null(strstr(r->ctx.err, "no contact site 1"));
    assert_int_equal(tf_solver_solve(r->solver, 0, NULL, 1, NULL, r->u), -1);
    assert_int_equal(tf_solver_reactions(r->solver, 2, unit_forces[0], r->u, r->u), -1);
    done(r);
}

/* block48 has no loads and clamped faces: linear.  The cantilever carries
 * a traction and prescribed values: affine only.  Both name the solver
 * they asked for, and an unknown one is refused with the list. */
static void capabilities_follow_the_problem(void **state)
{
    (void)state;
    run *b = solve(NULL, 0, unit_forces, 1);
    assert_int_equal(tf_solver_caps_of(b->solver), TF_SOLVER_AFFINE | TF_SOLVER_LINEAR);
    assert_string_equal(tf_solver_name(b->solver), "rpim-galerkin");
    assert_non_null(tf_galerkin_info_of(b->solver));
    assert_true(tf_galerkin_info_of(b->solver)->nnz_k > 0);
    tf_solver_opts o = b->p->solver;
    snprintf(o.method, sizeof o.method, "fem");
    assert_null(tf_solver_create(b->p, &o, &b->ctx));
    assert_non_null(strstr(b->ctx.err, "no solver 'fem'"));
    assert_non_null(strstr(b->ctx.err, "rpim-galerkin"));
    done(b);
    run *c = solve_on("coeffs/cantilever.yaml", NULL, 0, 0, NULL, 1);
    assert_int_equal(tf_solver_caps_of(c->solver), TF_SOLVER_AFFINE);
    done(c);
}

/* A static solver's history is its cases solved one by one: the same bits
 * as the batch, and a non-positive step is refused. */
static void a_static_history_is_the_batch(void **state)
{
    (void)state;
    const double steps[4][3] = {{0, 0, 0}, {0.2, 0, -0.1}, {0.4, -0.3, -0.5}, {0, 0, -1}};
    run *r = solve(NULL, 0, steps, 4);
    size_t n = 4 * 3 * r->p->cloud.n;
    double *h = malloc(n * sizeof *h);
    assert_int_equal(tf_solver_history(r->solver, 0, steps, 4, 1e-3, h), 0);
    assert_memory_equal(h, r->u, n * sizeof *h);
    assert_int_equal(tf_solver_history(r->solver, 0, steps, 4, 0, h), -1);
    assert_non_null(strstr(r->ctx.err, "time step"));
    free(h);
    done(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(reactions_balance_the_applied_force),
        cmocka_unit_test(fx_and_fy_mirror_each_other),
        cmocka_unit_test(displacement_scales_as_one_over_e),
        cmocka_unit_test(penalty_agrees_with_elimination),
        cmocka_unit_test(many_cases_through_one_factorisation),
        cmocka_unit_test(same_bits_whatever_the_thread_count),
        cmocka_unit_test(cell_averaged_volume_strain_relieves_locking),
        cmocka_unit_test(nodes_are_exposed_in_scene_numbering),
        cmocka_unit_test(capabilities_follow_the_problem),
        cmocka_unit_test(a_static_history_is_the_batch),
    };
    return cmocka_run_group_tests_name("solver", tests, NULL, NULL);
}
