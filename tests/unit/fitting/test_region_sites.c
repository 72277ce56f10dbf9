/*
 * test_region_sites.c — a contact region's solves and fits on a small box:
 * a probe's load vectors carry the unit force and solve as the same load
 * at a contact site does; the patch-averaged compliance is symmetric and
 * positive definite; a combination of site loads solves as the
 * combination of their solves; the fitted law reproduces every fitted
 * site's stiffness, the full-rank surface every fitted site's responses,
 * and its site modes the true cross compliance between fitted sites.
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

#include "fitting/region_fit.h"
#include "problem/region_chart.h"
#include "scene/scene.h"
#include "solvers/probe.h"

static const char *text =
    "name: r\n"
    "geometry:\n"
    "  box: {min: [0, 0, 0], max: [12, 12, 3]}\n"
    "  grid: [7, 7, 3]\n"
    "material: {E: 1.0, nu: 0.3}\n"
    "fixed:\n"
    "  - face: z-\n"
    "contact:\n"
    "  - region: {face: z+, rect: [2, 10, 2, 10]}\n"
    "    tip: {shape: rect, size: [2, 2]}\n"
    "    spacing: 2\n"
    "outputs: {select: face, face: z+}\n";

typedef struct fixture {
    tf_scene *scene;
    tf_ctx ctx;
    tf_solver *solver;
} fixture;

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    tf_ctx ec;
    tf_ctx_init(&ec);
    *state = f;
    f->scene = tf_scene_load_text(&ec, text, strlen(text), "r.yaml", NULL, 0);
    if (f->scene == NULL) {
        fprintf(stderr, "%s\n", ec.err);
        return -1;
    }
    tf_ctx_init(&f->ctx);
    f->ctx.level = TF_LOG_ERROR;
    f->solver = tf_solver_create(&f->scene->problem, NULL, &f->ctx);
    return f->solver ? 0 : -1;
}

static int teardown(void **state)
{
    fixture *f = *state;
    tf_solver_destroy(f->solver);
    tf_scene_free(f->scene);
    free(f);
    return 0;
}

static void loads_carry_the_unit_force(void **state)
{
    fixture *f = *state;
    const tf_problem *p = &f->scene->problem;
    size_t n3 = 3 * p->cloud.n;
    double *L = malloc(3 * n3 * sizeof *L), *u = malloc(3 * n3 * sizeof *u);
    double *v = malloc(3 * n3 * sizeof *v), x[3];
    /* at the centre: the contact's own patch */
    assert_int_equal(tf_region_site_loads(&f->ctx, f->solver, p, &p->contacts[0].region, 4, 4, L,
                                          x),
                     0);
    assert_true(x[0] == 6 && x[1] == 6 && x[2] == 3);
    for (int k = 0; k < 3; ++k) { /* the chart's axes are the scene's on z+ */
        for (int a = 0; a < 3; ++a) {
            double sum = 0;
            for (size_t i = 0; i < p->cloud.n; ++i) {
                sum += L[(size_t)k * n3 + 3 * i + (size_t)a];
            }
            assert_true(fabs(sum - (k == a)) < 1e-12);
        }
    }
    const double unit[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    assert_int_equal(tf_solver_solve_loads(f->solver, L, 3, u), 0);
    assert_int_equal(tf_solver_solve(f->solver, 0, unit, 3, NULL, v), 0);
    for (size_t d = 0; d < 3 * n3; ++d) {
        assert_true(fabs(u[d] - v[d]) <= 1e-12 * (1 + fabs(v[d])));
    }
    free(L);
    free(u);
    free(v);
}

static void compliance_is_symmetric_and_combinations_superpose(void **state)
{
    fixture *f = *state;
    const tf_problem *p = &f->scene->problem;
    const double ab[6] = {0.5, 1, 4, 4, 7.5, 2};
    tf_region_sites t;
    assert_int_equal(
        tf_region_sites_solve(&f->ctx, f->solver, p, &p->contacts[0].region, ab, 3, NULL, 0, &t), 0);
    assert_true(t.asym < 1e-12);
    for (size_t s = 0; s < 3; ++s) {
        double lam[3];
        tf_sym3_eigenvalues(t.C + 9 * s, lam);
        assert_true(lam[0] > 0);
    }
    /* 2 x site 1 along n plus site 2 along e1 solve as the combination of
     * the two sites' solves */
    size_t n3 = 3 * p->cloud.n, idx[2] = {1, 2};
    const double coef[6] = {0, 0, 2, 1, 0, 0};
    double *u = malloc(n3 * sizeof *u), *out = malloc(3 * t.n_out * sizeof *out);
    assert_int_equal(tf_region_sites_combine(&f->ctx, f->solver, &t, idx, 2, coef, 1, u), 0);
    assert_int_equal(tf_solver_probe_outputs(&f->ctx, f->solver, p, u, out), 0);
    size_t rows = 3 * t.n_out;
    const double *U1 = t.U + 9 * t.n_out, *U2 = t.U + 18 * t.n_out;
    for (size_t r = 0; r < rows; ++r) { /* outputs superpose */
        assert_true(fabs(out[r] - (2 * U1[2 * rows + r] + U2[r])) < 1e-12);
    }
    free(u);
    free(out);
    tf_region_sites_free(&t);
}

static void the_fit_reproduces_its_sites(void **state)
{
    fixture *f = *state;
    const tf_problem *p = &f->scene->problem;
    tf_region_targets tg = tf_region_targets_default();
    tf_region_result res;
    assert_int_equal(tf_region_fit(&f->ctx, f->solver, p, 0, &tg, &res), 0);
    assert_int_equal(res.n_levels, 1); /* the scene fixes the spacing */
    const tf_region_level *lv = &res.level[0];
    assert_true(lv->nx == 5 && lv->ny == 5 && lv->h[0] == 2 && lv->min_stiffness > 0);
    assert_true(strstr(res.why, "the scene's spacing") != NULL);
    /* the law: K(g_s) C_s = I at every fitted site */
    for (size_t i = 0; i < 25; ++i) {
        size_t s = lv->train[i];
        double K[9], M[9];
        tf_region_law_stiffness(&lv->law, res.sites.ab[2 * s], res.sites.ab[2 * s + 1], K);
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
                const double *C = res.sites.C + 9 * s;
                M[3 * a + b] = K[3 * a] * C[b] + K[3 * a + 1] * C[3 + b] + K[3 * a + 2] * C[6 + b];
                assert_true(fabs(M[3 * a + b] - (a == b)) < 1e-10);
            }
        }
    }
    /* the full-rank surface: every fitted site's responses and cross
     * compliances (75 output rows, 75 columns of 25 sites: full rank) */
    tf_region_surface sf;
    const tf_region_modes *m = &lv->modes;
    assert_int_equal(m->r_max, 75);
    assert_int_equal(tf_region_surface_fit(&f->ctx, m, 5, 5, lv->h, 1, m->r_max, &sf), 0);
    size_t rows = 3 * res.sites.n_out, n3 = 3 * p->cloud.n;
    double *model = malloc(rows * sizeof *model), *u = malloc(3 * n3 * sizeof *u);
    double *L = malloc(3 * n3 * sizeof *L);
    for (size_t i = 0; i < 25; i += 6) {
        size_t s = lv->train[i];
        const double F[3] = {0.3, -0.5, 0.8};
        tf_region_surface_eval(&sf, res.sites.ab[2 * s], res.sites.ab[2 * s + 1], F, model);
        const double *U = res.sites.U + 9 * res.sites.n_out * s;
        for (size_t r = 0; r < rows; ++r) {
            double want = U[r] * F[0] + U[rows + r] * F[1] + U[2 * rows + r] * F[2];
            assert_true(fabs(model[r] - want) < 1e-9);
        }
    }
    size_t s1 = lv->train[3], s2 = lv->train[17];
    double C12[9];
    tf_region_surface_cross(&sf, res.sites.ab[2 * s1], res.sites.ab[2 * s1 + 1],
                            res.sites.ab[2 * s2], res.sites.ab[2 * s2 + 1], C12);
    assert_int_equal(tf_region_site_loads(&f->ctx, f->solver, p, &p->contacts[0].region,
                                          res.sites.ab[2 * s2], res.sites.ab[2 * s2 + 1], L, NULL),
                     0);
    assert_int_equal(tf_solver_solve_loads(f->solver, L, 3, u), 0);
    for (int l = 0; l < 3; ++l) {
        double avg[3];
        tf_region_sites_average(&res.sites, s1, u + (size_t)l * n3, avg);
        for (int k = 0; k < 3; ++k) {
            assert_true(fabs(C12[3 * k + l] - avg[k]) < 1e-9);
        }
    }
    free(model);
    free(u);
    free(L);
    tf_region_surface_free(&sf);
    tf_region_result_free(&res);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(loads_carry_the_unit_force),
        cmocka_unit_test(compliance_is_symmetric_and_combinations_superpose),
        cmocka_unit_test(the_fit_reproduces_its_sites),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
