/*
 * test_nonlinear.c — the nonlinear Galerkin solver: its tangent is the
 * derivative of its residual (central differences, every law, RPIM and
 * EFG); the small-load limit of every law is the linear solver's answer;
 * a starting displacement is continued from; a body that inverts or an
 * iteration that does not converge stops with a message naming the load
 * step, the force and the place.
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
#include "solvers/cholmod_solve.h"
#include "solvers/constraints.h"
#include "solvers/nonlinear/nl_internal.h"
#include "solvers/nonlinear/nonlinear.h"
#include "solvers/solver.h"

#define BLOCK48 "tests/solver/block48_seed.yaml"
/* block48 on a 7 x 7 x 3 grid: node 25 is the top centre */
#define SMALL_GRID "geometry.grid=7,7,3"
#define SMALL_NODE "contact.0.node=25"

static const char *const kelvin_k0 = "material={law: kelvin, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3}";
static const char *const kelvin_k = "material={law: kelvin, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3, k: 0.8}";
static const char *const kelvin_nh = "material={law: kelvin-neo-hookean, nu: 0.45, k1: 0.2, k2: 0.12, eta: 0.3}";

typedef struct run {
    tf_ctx ctx;
    tf_scene *scene;
    tf_solver *sv;
} run;

static run *open_run(const char *const *sets, size_t n)
{
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    run *r = calloc(1, sizeof *r);
    tf_ctx_init(&r->ctx);
    r->ctx.level = TF_LOG_ERROR;
    r->scene = tf_scene_load(&ctx, BLOCK48, sets, n);
    if (r->scene == NULL) {
        fail_msg("%s", ctx.err);
    }
    r->sv = tf_solver_create(&r->scene->problem, NULL, &r->ctx);
    if (r->sv == NULL) {
        fail_msg("%s", r->ctx.err);
    }
    return r;
}

static void close_run(run *r)
{
    tf_solver_destroy(r->sv);
    tf_scene_free(r->scene);
    free(r);
}

/* |K v - (r(d + h v) - r(d - h v)) / 2h| / |.| at a random d. */
static double tangent_error(run *r)
{
    nl_solver *s = (nl_solver *)r->sv;
    size_t n3 = 3 * r->scene->problem.cloud.n;
    double *d = calloc(n3, sizeof *d), *v = calloc(n3, sizeof *v), *kv = calloc(n3, sizeof *kv);
    double *rp = calloc(n3, sizeof *rp), *rm = calloc(n3, sizeof *rm), *dp = calloc(n3, sizeof *dp);
    uint64_t x = 12345;
    for (size_t i = 0; i < n3; ++i) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        d[i] = 0.2 * ((double)(x >> 11) / 9007199254740992.0 - 0.5);
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        v[i] = (double)(x >> 11) / 9007199254740992.0 - 0.5;
        if (!s->weak && s->bc.fixed[i]) {
            d[i] = v[i] = 0;
        }
    }
    nl_target t = {1, -1, {0, 0, 0}};
    nl_fault f = {0};
    double dt = 0.1, h = 1e-6;
    assert_int_equal(nl_assemble(s, d, &t, dt, 1, rp, NULL, &f), 0);
    nl_tangent_apply(s, v, kv);
    for (size_t i = 0; i < n3; ++i) {
        dp[i] = d[i] + h * v[i];
    }
    assert_int_equal(nl_assemble(s, dp, &t, dt, 0, rp, NULL, &f), 0);
    for (size_t i = 0; i < n3; ++i) {
        dp[i] = d[i] - h * v[i];
    }
    assert_int_equal(nl_assemble(s, dp, &t, dt, 0, rm, NULL, &f), 0);
    double num = 0, den = 0;
    for (size_t i = 0; i < n3; ++i) {
        if (!s->weak && s->bc.fixed[i]) {
            continue;
        }
        double fd = (rp[i] - rm[i]) / (2 * h);
        num += (fd - kv[i]) * (fd - kv[i]);
        den += fd * fd;
    }
    free(d);
    free(v);
    free(kv);
    free(rp);
    free(rm);
    free(dp);
    return sqrt(num / den);
}

static void tangent_is_the_derivative_of_the_residual(void **state)
{
    (void)state;
    const char *laws[] = {"material.law=svk", "material.law=neo-hookean", kelvin_k0, kelvin_k,
                          kelvin_nh};
    const char *methods[][2] = {{"solver.method=rpim-galerkin", "solver.volumetric=cell"},
                                {"solver.method=rpim-galerkin", "solver.volumetric=full"},
                                {"solver.method=efg-galerkin", "solver.bc=penalty"}};
    for (size_t l = 0; l < 5; ++l) {
        for (size_t m = 0; m < 3; ++m) {
            const char *sets[] = {SMALL_GRID, SMALL_NODE, laws[l], methods[m][0], methods[m][1]};
            run *r = open_run(sets, 5);
            double e = tangent_error(r);
            if (!(e < 1e-7)) {
                fail_msg("%s, %s %s: tangent error %.3g", laws[l], methods[m][0], methods[m][1],
                         e);
            }
            close_run(r);
        }
    }
}

/* A deliberately wrong tangent (the geometric part dropped) is seen. */
static void a_wrong_tangent_is_noticed(void **state)
{
    (void)state;
    const char *sets[] = {SMALL_GRID, SMALL_NODE, "material.law=neo-hookean"};
    run *r = open_run(sets, 3);
    nl_solver *s = (nl_solver *)r->sv;
    s->small = 1; /* small-strain B and no geometric stiffness with a finite-strain residual */
    double e = tangent_error(r);
    s->small = 0;
    assert_true(e > 1e-3);
    close_run(r);
}

/* u at a force of 1e-7 N against the linear solver's, relative to the
 * largest displacement. */
static double small_load_difference(const char *law, const char *method, const char *linear_e,
                                    const char *linear_bc)
{
    const double f[1][3] = {{0.3e-7, -0.2e-7, -1e-7}};
    const char *nl[] = {SMALL_GRID, SMALL_NODE, law, method};
    const char *li[] = {SMALL_GRID, SMALL_NODE, linear_e, method, linear_bc};
    run *a = open_run(nl, 4), *b = open_run(li, linear_bc ? 5 : 4);
    size_t n3 = 3 * a->scene->problem.cloud.n;
    double *ua = malloc(n3 * sizeof *ua), *ub = malloc(n3 * sizeof *ub);
    assert_int_equal(tf_solver_solve(a->sv, 0, f, 1, NULL, ua), 0);
    assert_int_equal(tf_solver_solve(b->sv, 0, f, 1, NULL, ub), 0);
    double worst = 0, scale = 0;
    for (size_t i = 0; i < n3; ++i) {
        worst = fmax(worst, fabs(ua[i] - ub[i]));
        scale = fmax(scale, fabs(ub[i]));
    }
    free(ua);
    free(ub);
    close_run(a);
    close_run(b);
    return worst / scale;
}

static void small_load_limit_is_the_linear_solution(void **state)
{
    (void)state;
    const char *methods[] = {"solver.method=rpim-galerkin", "solver.method=efg-galerkin"};
    /* EFG's Nitsche factor beta scales with the initial modulus, the Kelvin
     * laws' instantaneous k1 + k2 = 0.32: the linear solve with k1 = 0.2
     * takes the same beta */
    const char *same_beta[] = {NULL, "solver.nitsche=160"};
    for (int m = 0; m < 2; ++m) {
        /* elastic laws against the linear law with the same E, nu */
        assert_true(small_load_difference("material.law=svk", methods[m], "material.E=0.32", NULL) <
                    1e-6);
        assert_true(small_load_difference("material.law=neo-hookean", methods[m], "material.E=0.32",
                                          NULL) < 1e-6);
        /* a static solve of the Kelvin laws is the relaxed equilibrium: E = k1 */
        const char *lin = "material={E: 0.2, nu: 0.45}";
        assert_true(small_load_difference(kelvin_k, methods[m], lin, same_beta[m]) < 1e-6);
        assert_true(small_load_difference(kelvin_nh, methods[m], lin, same_beta[m]) < 1e-6);
        /* and the comparison can fail: the instantaneous modulus is not it */
        assert_true(small_load_difference(kelvin_k, methods[m], "material={E: 0.32, nu: 0.45}",
                                          NULL) > 0.1);
    }
}

/* The caller's starting displacement is continued from: the solution
 * itself needs no iteration and is returned. */
static void a_start_is_continued_from(void **state)
{
    (void)state;
    const char *sets[] = {SMALL_GRID, SMALL_NODE, "material.law=neo-hookean"};
    run *r = open_run(sets, 3);
    size_t n3 = 3 * r->scene->problem.cloud.n;
    const double f[1][3] = {{0.5, 0, -1.5}};
    double *u = malloc(n3 * sizeof *u), *v = malloc(n3 * sizeof *v);
    assert_int_equal(tf_solver_solve(r->sv, 0, f, 1, NULL, u), 0);
    tf_nonlinear_info a, b;
    assert_int_equal(tf_nonlinear_info_of(r->sv, &a), 0);
    assert_true(a.iterations >= 3);
    assert_int_equal(tf_solver_solve(r->sv, 0, f, 1, u, v), 0);
    assert_int_equal(tf_nonlinear_info_of(r->sv, &b), 0);
    assert_true(b.iterations - a.iterations <= 1);
    double worst = 0;
    for (size_t i = 0; i < n3; ++i) {
        worst = fmax(worst, fabs(u[i] - v[i]));
    }
    assert_true(worst < 1e-8);
    assert_int_equal(tf_solver_caps_of(r->sv) & TF_SOLVER_AFFINE, 0);
    free(u);
    free(v);
    close_run(r);
}

/* A cube pressed to less than nothing between its z faces. */
static const char crushed_cube[] = "name: cube\n"
                                   "geometry: {box: {min: [0, 0, 0], max: [10, 10, 10]}, grid: [4, 4, 4]}\n"
                                   "material: {law: neo-hookean, E: 1.0, nu: 0.3}\n"
                                   "fixed:\n"
                                   "  - {face: z-}\n"
                                   "  - {face: z+, displacement: [0, 0, -11]}\n"
                                   "outputs: {select: all}\n"
                                   "solver: {newton: {cuts: 4}}\n";

/* Full Newton, modified Newton, Newton-Krylov, BFGS and the patch tangent
 * reach the same equilibrium (to the tolerance), the cheaper ones with
 * fewer factorisations; and the Kelvin law's unsymmetric tangent (GMRES)
 * too, where the patch tangent does not apply (it is BFGS there). */
static void every_strategy_reaches_the_same_equilibrium(void **state)
{
    (void)state;
    const char *kinds[] = {"solver.newton.tangent=full", "solver.newton.tangent=modified",
                           "solver.newton.tangent=krylov", "solver.newton.tangent=bfgs",
                           "solver.newton={tangent: patch, patch_radius: 10}"};
    const char *laws[] = {"material.law=neo-hookean", kelvin_k};
    const double f[1][3] = {{0.5, 0, -1.5}};
    for (int l = 0; l < 2; ++l) {
        double *ref = NULL;
        size_t fact_full = 0;
        for (int k = 0; k < 5; ++k) {
            const char *sets[] = {SMALL_GRID, SMALL_NODE, laws[l], kinds[k]};
            run *r = open_run(sets, 4);
            size_t n3 = 3 * r->scene->problem.cloud.n;
            double *u = malloc(n3 * sizeof *u), worst = 0, scale = 0;
            if (tf_solver_solve(r->sv, 0, f, 1, NULL, u) != 0) {
                fail_msg("%s %s: %s", laws[l], kinds[k], r->ctx.err);
            }
            tf_nonlinear_info in;
            assert_int_equal(tf_nonlinear_info_of(r->sv, &in), 0);
            if (k == 4) { /* the patch works for the elastic law, not for Kelvin's */
                assert_true(l == 0 ? in.patch_dofs > 0 && in.patches > in.patch_kept
                                   : in.patch_dofs == 0 && in.patches == 0);
            }
            if (k == 0) {
                ref = u;
                fact_full = in.factorisations;
                close_run(r);
                continue;
            }
            for (size_t i = 0; i < n3; ++i) {
                worst = fmax(worst, fabs(u[i] - ref[i]));
                scale = fmax(scale, fabs(ref[i]));
            }
            if (!(worst < 1e-7 * scale)) {
                fail_msg("%s %s: %.3g from full Newton", laws[l], kinds[k], worst / scale);
            }
            assert_true(in.factorisations < fact_full);
            free(u);
            close_run(r);
        }
        free(ref);
    }
}

/* BFGS and modified Newton keep their positive definite factor through a
 * tangent that is not (nl_linear.c: keeps_factor): the attempt is counted,
 * the factor and its solutions do not change; only a second indefinite
 * tangent in a row gets the LDL^T factorisation; a positive definite one
 * replaces the factor. */
static void an_indefinite_tangent_keeps_the_factor(void **state)
{
    (void)state;
    const char *sets[] = {SMALL_GRID, SMALL_NODE, "material.law=neo-hookean",
                          "solver.newton.tangent=bfgs"};
    run *r = open_run(sets, 4);
    nl_solver *s = (nl_solver *)r->sv;
    size_t n3 = 3 * r->scene->problem.cloud.n;
    const double f[1][3] = {{0, 0, -0.5}};
    double *u = malloc(n3 * sizeof *u), *b = malloc(n3 * sizeof *b);
    double *x0 = malloc(n3 * sizeof *x0), *x1 = malloc(n3 * sizeof *x1);
    assert_int_equal(tf_solver_solve(r->sv, 0, f, 1, NULL, u), 0);
    assert_true(s->chol_ok && !s->use_ldl);
    for (size_t i = 0; i < n3; ++i) {
        b[i] = 1e-3 * (double)(i % 7) - 2e-3;
    }
    nl_qn_reset(s);
    assert_int_equal(nl_linear_solve(s, b, x0, 0), 0);
    size_t fact = s->st.factorisations, ldl = s->st.indefinite;
    const tf_chol *held = s->chol;
    for (size_t q = 0; q < s->k.nnz; ++q) { /* the tangent, negated: negative definite */
        s->k.x[q] = -s->k.x[q];
    }
    assert_int_equal(nl_factor(s), 0);
    assert_int_equal(s->st.kept, 1);
    assert_int_equal(s->st.factorisations, fact + 1);
    assert_int_equal(s->st.indefinite, ldl);
    assert_ptr_equal(s->chol, held);
    assert_true(s->chol_ok && !s->use_ldl);
    assert_int_equal(nl_linear_solve(s, b, x1, 0), 0);
    assert_memory_equal(x0, x1, n3 * sizeof *x0);
    assert_int_equal(nl_factor(s), 0); /* indefinite again: now LDL^T */
    assert_int_equal(s->st.indefinite, ldl + 1);
    assert_true(s->use_ldl);
    for (size_t q = 0; q < s->k.nnz; ++q) { /* positive definite again: a new Cholesky */
        s->k.x[q] = -s->k.x[q];
    }
    assert_int_equal(nl_factor(s), 0);
    assert_true(s->chol_ok && !s->use_ldl && !s->indef_kept);
    free(u);
    free(b);
    free(x0);
    free(x1);
    close_run(r);
    /* the patch tangent keeps its factor through indefinite tangents in a
     * row: no LDL^T (at 41 x 41 x 9 it took minutes of CPU time) */
    const char *patch[] = {SMALL_GRID, SMALL_NODE, "material.law=neo-hookean",
                           "solver.newton={tangent: patch, patch_radius: 10}"};
    r = open_run(patch, 4);
    s = (nl_solver *)r->sv;
    u = malloc(3 * r->scene->problem.cloud.n * sizeof *u);
    assert_int_equal(tf_solver_solve(r->sv, 0, f, 1, NULL, u), 0);
    assert_true(s->patch.on && s->chol_ok && !s->use_ldl);
    nl_fault fault = {0}; /* the whole tangent at the solution (the last was the patch's) */
    assert_int_equal(nl_assemble(s, s->d, &s->at, 0, 1, s->r, NULL, &fault), 0);
    held = s->chol;
    ldl = s->st.indefinite;
    for (int twice = 0; twice < 2; ++twice) {
        for (size_t q = 0; q < s->k.nnz; ++q) {
            s->k.x[q] = -s->k.x[q];
        }
        assert_int_equal(nl_factor(s), 0);
        for (size_t q = 0; q < s->k.nnz; ++q) {
            s->k.x[q] = -s->k.x[q];
        }
    }
    assert_int_equal(s->st.indefinite, ldl);
    assert_ptr_equal(s->chol, held);
    assert_true(s->chol_ok && !s->use_ldl && s->indef_kept);
    assert_int_equal(nl_factor(s), 0); /* positive definite: a new factor */
    assert_true(s->chol != held && !s->indef_kept && s->patch.on);
    free(u);
    close_run(r);
}

/* The matrix CHOLMOD factorises couples no fixed DOF (nl_factored): the
 * tangent's values in the free block, unit diagonal entries at the fixed
 * DOFs, and a factor as small as that of the free block alone (the linear
 * solver's, tf_constraints_reduce) plus those diagonal entries, where the
 * full pattern with its eliminated zeros fills more.  The fill is compared
 * under AMD: METIS's result moves with the graph (isolated vertices
 * included; here 175077 against 147150 entries, at 41 x 41 x 9 1.01e8
 * against 9.99e7: docs/validation.md §13). */
static void the_factor_holds_no_fixed_couplings(void **state)
{
    (void)state;
    const char *sets[] = {"geometry.grid=11,11,3", "material.law=neo-hookean"};
    run *r = open_run(sets, 2);
    nl_solver *s = (nl_solver *)r->sv;
    size_t n3 = s->k.n, nfixed = 0;
    nl_target t = {1, -1, {0, 0, 0}};
    nl_fault f = {0};
    double *d = calloc(n3, sizeof *d), *res = malloc(n3 * sizeof *res);
    assert_int_equal(nl_assemble(s, d, &t, 0, 1, res, NULL, &f), 0);
    nl_eliminate(s);
    const tf_csc *kf = nl_factored(s);
    assert_ptr_equal(kf, &s->kf);
    for (size_t j = 0; j < n3; ++j) {
        nfixed += s->bc.fixed[j];
        for (int q = kf->p[j]; q < kf->p[j + 1]; ++q) {
            size_t i = (size_t)kf->i[q];
            assert_true(i == j || (!s->bc.fixed[i] && !s->bc.fixed[j]));
            assert_true(i != j || !s->bc.fixed[j] || kf->x[q] == 1.0);
        }
    }
    assert_true(nfixed > 0 && kf->nnz < s->k.nnz);
    tf_csc kr = {0};
    assert_int_equal(tf_constraints_reduce(&s->bc, &s->k, &kr), 0);
    tf_chol_info full = {0}, reduced = {0}, used = {0};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_chol *cf = tf_chol_analyse(&ctx, &s->k, TF_ORDER_AMD, 0, &full);
    tf_chol *cr = tf_chol_analyse(&ctx, &kr, TF_ORDER_AMD, 0, &reduced);
    tf_chol *cu = tf_chol_analyse(&ctx, kf, TF_ORDER_AMD, 0, &used);
    assert_non_null(cf);
    assert_non_null(cr);
    assert_non_null(cu);
    if (!(used.nnz_l <= 1.02 * (reduced.nnz_l + (double)nfixed) &&
          used.nnz_l < 0.75 * full.nnz_l)) {
        fail_msg("L entries: factorised %g, free block %g + %zu fixed, full pattern %g",
                 used.nnz_l, reduced.nnz_l, nfixed, full.nnz_l);
    }
    print_message("L entries: factorised %g, free block %g + %zu fixed, full pattern %g\n",
                  used.nnz_l, reduced.nnz_l, nfixed, full.nnz_l);
    tf_chol_free(cf);
    tf_chol_free(cr);
    tf_chol_free(cu);
    tf_csc_free(&kr);
    free(d);
    free(res);
    close_run(r);
}

/* The patch tangent's block update (nl_patch.c): with the DOFs near the
 * contact last in the factor, replacing the trailing block by
 * chol(S0 + dK) factorises K0 + dK (dK the patch cells' tangent at d1
 * minus theirs at rest) without refactorising: the patched factor solves
 * that matrix to rounding. */
static void the_patch_update_factorises_the_patched_matrix(void **state)
{
    (void)state;
    const char *sets[] = {"geometry.grid=9,9,3", "contact.0.node=41", "material.law=neo-hookean",
                          "solver.newton.tangent=patch", "solver.newton.patch_radius=6"};
    run *r = open_run(sets, 5);
    nl_solver *s = (nl_solver *)r->sv;
    size_t n3 = 3 * r->scene->problem.cloud.n, nnz = s->k.nnz;
    assert_true(s->patch.on);
    if (!(s->patch.m > 30 && s->patch.m < n3 / 2)) {
        fail_msg("|A| = %zu of %zu", s->patch.m, n3);
    }
    double *d0 = calloc(n3, sizeof *d0), *d1 = calloc(n3, sizeof *d1), *res = malloc(n3 * 8);
    double *kh = malloc(nnz * sizeof *kh), *b = malloc(n3 * sizeof *b), *x = malloc(n3 * 8);
    double *y = malloc(n3 * sizeof *y);
    uint64_t q = 99;
    for (size_t i = 0; i < n3; ++i) {
        q = q * 6364136223846793005ULL + 1442695040888963407ULL;
        d1[i] = s->bc.fixed[i] ? 0 : 0.3 * ((double)(q >> 11) / 9007199254740992.0 - 0.5);
        b[i] = s->bc.fixed[i] ? 0 : (double)(i % 11) - 5;
    }
    nl_target t = {1, -1, {0, 0, 0}};
    nl_fault f = {0};
    assert_int_equal(nl_assemble(s, d0, &t, 0, 1, res, NULL, &f), 0);
    memcpy(kh, s->k.x, nnz * sizeof *kh);            /* K0 */
    assert_int_equal(nl_factor(s), 0);
    assert_int_equal(nl_patch_k0(s, d0, 0, &f), 0);
    assert_true(s->patch.base);
    for (size_t e = 0; e < nnz; ++e) {
        kh[e] -= s->k.x[e];                          /* - the patch cells at rest */
    }
    assert_int_equal(nl_assemble_patch(s, d1, 0, &f), 0);
    for (size_t e = 0; e < nnz; ++e) {
        kh[e] += s->k.x[e];                          /* + the patch cells at d1 */
    }
    double *x0 = malloc(n3 * sizeof *x0), differ = 0, big = 0;
    assert_int_equal(tf_chol_solve(&r->ctx, s->chol, b, x0, 1), 0);
    assert_int_equal(nl_patch_update(s), 0);
    assert_int_equal(tf_chol_solve(&r->ctx, s->chol, b, x, 1), 0);
    for (size_t i = 0; i < n3; ++i) { /* the patch made a difference: K0's factor is not it */
        differ = fmax(differ, fabs(x[i] - x0[i]));
        big = fmax(big, fabs(x[i]));
    }
    free(x0);
    assert_true(differ > 1e-3 * big);
    for (size_t j = 0; j < n3; ++j) { /* the eliminated K0 + dK, as factorised */
        for (int e = s->k.p[j]; e < s->k.p[j + 1]; ++e) {
            size_t i = (size_t)s->k.i[e];
            s->k.x[e] = s->bc.fixed[i] || s->bc.fixed[j] ? (i == j ? 1.0 : 0.0) : kh[e];
        }
    }
    nl_tangent_apply(s, x, y);
    double num = 0, den = 0, same = 0;
    for (size_t i = 0; i < n3; ++i) {
        num += (y[i] - b[i]) * (y[i] - b[i]);
        den += b[i] * b[i];
    }
    if (!(sqrt(num / den) < 1e-10)) {
        fail_msg("patched factor: |K x - b| / |b| = %.3g", sqrt(num / den));
    }
    assert_int_equal(nl_factor(s), 0); /* a full factorisation of K0 + dK: the same x */
    assert_int_equal(tf_chol_solve(&r->ctx, s->chol, b, y, 1), 0);
    for (size_t i = 0; i < n3; ++i) {
        same = fmax(same, fabs(x[i] - y[i]));
    }
    if (!(same < 1e-10 * big)) {
        fail_msg("patched and full factor differ by %.3g of %.3g", same, big);
    }
    free(d0);
    free(d1);
    free(res);
    free(kh);
    free(b);
    free(x);
    free(y);
    close_run(r);
    /* weak essential conditions (EFG): no patch, the strategy is BFGS */
    const char *efg[] = {"geometry.grid=9,9,3", "contact.0.node=41", "material.law=neo-hookean",
                         "solver.newton.tangent=patch", "solver.method=efg-galerkin"};
    r = open_run(efg, 5);
    s = (nl_solver *)r->sv;
    assert_true(s->weak && !s->patch.on && s->patch.m == 0 && s->qmax > 0);
    close_run(r);
}

static void inversion_and_divergence_are_named(void **state)
{
    (void)state;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    ctx.level = TF_LOG_ERROR;
    tf_scene *cube =
        tf_scene_load_text(&ctx, crushed_cube, strlen(crushed_cube), "cube.yaml", NULL, 0);
    assert_non_null(cube);
    tf_solver *sv = tf_solver_create(&cube->problem, NULL, &ctx);
    assert_non_null(sv);
    double *uc = malloc(3 * cube->problem.cloud.n * sizeof *uc);
    assert_int_equal(tf_solver_solve(sv, -1, NULL, 1, NULL, uc), -1);
    assert_non_null(strstr(ctx.err, "load step"));
    assert_non_null(strstr(ctx.err, "load factor"));
    assert_non_null(strstr(ctx.err, "at the quadrature point ("));
    assert_non_null(strstr(ctx.err, "<= 0"));
    free(uc);
    tf_solver_destroy(sv);
    tf_scene_free(cube);
    const char *strict[] = {SMALL_GRID, SMALL_NODE, "material.law=neo-hookean",
                            "solver.newton.cuts=0", "solver.newton.iterations=2"};
    run *r = open_run(strict, 5);
    double *u = malloc(3 * r->scene->problem.cloud.n * sizeof *u);
    const double f[1][3] = {{0, 0, -2}};
    assert_int_equal(tf_solver_solve(r->sv, 0, f, 1, NULL, u), -1);
    assert_non_null(strstr(r->ctx.err, "did not converge in 2 iterations"));
    assert_non_null(strstr(r->ctx.err, "force (0, 0, -2) N"));
    assert_non_null(strstr(r->ctx.err, "at node"));
    free(u);
    close_run(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tangent_is_the_derivative_of_the_residual),
        cmocka_unit_test(a_wrong_tangent_is_noticed),
        cmocka_unit_test(small_load_limit_is_the_linear_solution),
        cmocka_unit_test(a_start_is_continued_from),
        cmocka_unit_test(every_strategy_reaches_the_same_equilibrium),
        cmocka_unit_test(an_indefinite_tangent_keeps_the_factor),
        cmocka_unit_test(the_factor_holds_no_fixed_couplings),
        cmocka_unit_test(the_patch_update_factorises_the_patched_matrix),
        cmocka_unit_test(inversion_and_divergence_are_named),
    };
    return cmocka_run_group_tests_name("nonlinear", tests, NULL, NULL);
}
