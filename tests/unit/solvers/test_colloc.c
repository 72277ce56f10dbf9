/*
 * test_colloc.c — the MLS collocation core (solvers/collocation/colloc.h):
 * the gradient of a linear field, forces against the energy's derivative,
 * rigid motions, mirror planes against the whole body, volumes, refusals.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "assert_close.h"
#include "base/rng.h"
#include "box_cloud.h"
#include "material_of.h"
#include "solvers/collocation/colloc.h"

static tf_colloc *make(const box_cloud *b, const char *law, const tf_colloc_opts *o, int volumes)
{
    tf_colloc_body body = {.n = b->n,
                           .X = b->X,
                           .fixed = b->fixed,
                           .volume = volumes ? b->volume : NULL,
                           .material = tf_test_material(law, "E=2.0 nu=0.3"),
                           .density = 1e-9};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = tf_colloc_new(&ctx, &body, o);
    if (c == NULL) {
        print_error("%s\n", ctx.err);
    }
    assert_non_null(c);
    return c;
}

static void jittered(box_cloud *b, double jitter)
{
    const size_t dims[3] = {6, 5, 7};
    const double lo[3] = {0, 0, 0}, hi[3] = {5, 4, 3};
    assert_int_equal(box_cloud_make(b, dims, lo, hi, jitter, 7), 0);
}

/* The MLS fit (eqs 6-9) reproduces a linear field at every particle. */
static void linear_field_gives_exact_gradient(void **state)
{
    (void)state;
    box_cloud b;
    jittered(&b, 0.3);
    tf_colloc *c = make(&b, "svk", NULL, 1);
    const double H[9] = {0.1, -0.2, 0.05, 0.3, 0.02, -0.1, 0.04, 0.2, -0.15}, t[3] = {1, -2, 3};
    double *u = malloc(3 * b.n * sizeof *u), *F = malloc(9 * b.n * sizeof *F);
    for (size_t i = 0; i < b.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            const double *x = b.X + 3 * i;
            u[3 * i + a] = t[a] + H[3 * a] * x[0] + H[3 * a + 1] * x[1] + H[3 * a + 2] * x[2];
        }
    }
    tf_colloc_deformation(c, u, F);
    for (size_t i = 0; i < b.n; ++i) {
        for (int k = 0; k < 9; ++k) {
            assert_close(F[9 * i + k], H[k] + (k % 4 == 0), 1e-12);
        }
    }
    free(u);
    free(F);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

/* f = -dU/du (eq 11) for the nonlinear laws, the volume term (eq 12) and
 * the residual term, by central differences of the energy. */
static void check_gradient(const box_cloud *b, const char *law, const tf_colloc_mirror *mirrors,
                           size_t n_mirrors)
{
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    o.kv = 0.5;
    o.stab = 0.3;
    /* The default support (1.5 mean neighbour distances, made for grids)
     * leaves the farthest neighbour of an edge particle of this jittered cloud
     * outside the radius, which set-up refuses; 2 keeps every one inside. */
    o.support = 2;
    tf_colloc_body body = {.n = b->n, .X = b->X, .fixed = b->fixed, .volume = NULL,
                           .total_volume = 60,
                           .material = tf_test_material(law, "E=2.0 nu=0.3"),
                           .density = 1e-9, .mirrors = mirrors, .n_mirrors = n_mirrors};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = tf_colloc_new(&ctx, &body, &o);
    if (c == NULL) {
        print_error("%s\n", ctx.err);
    }
    assert_non_null(c);
    size_t n3 = 3 * b->n;
    double *u = malloc(n3 * sizeof *u), *f = malloc(n3 * sizeof *f), *g = malloc(n3 * sizeof *g);
    tf_rng r = {3};
    for (size_t q = 0; q < n3; ++q) {
        u[q] = tf_rng_range(&r, -0.05, 0.05); /* strains of order 0.1 */
    }
    double U;
    assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, f, &U), 0);
    double fmax = 0;
    for (size_t q = 0; q < n3; ++q) {
        fmax = fmax > fabs(f[q]) ? fmax : fabs(f[q]);
    }
    for (int t = 0; t < 40; ++t) {
        size_t q = tf_rng_below(&r, (uint32_t)n3);
        double h = 1e-6, save = u[q], up, um;
        u[q] = save + h;
        assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, g, &up), 0);
        u[q] = save - h;
        assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, g, &um), 0);
        u[q] = save;
        assert_close(f[q], -(up - um) / (2 * h), 1e-6 * fmax);
    }
    free(u);
    free(f);
    free(g);
    tf_colloc_free(c);
}

static void forces_are_minus_energy_gradient(void **state)
{
    (void)state;
    box_cloud b;
    jittered(&b, 0.3);
    check_gradient(&b, "svk", NULL, 0);
    check_gradient(&b, "neo-hookean", NULL, 0);
    check_gradient(&b, "linear", NULL, 0);
    /* With mirror planes x = 0 and y = 0: the reduced energy's gradient. */
    const tf_colloc_mirror m[2] = {{0, 0}, {1, 0}};
    check_gradient(&b, "svk", m, 2);
    box_cloud_free(&b);
}

/* A finite rotation and a translation strain nothing: no force, no energy
 * (SVK, eq 12 and the residual term are objective). */
static void rigid_motion_costs_nothing(void **state)
{
    (void)state;
    box_cloud b;
    jittered(&b, 0.3);
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    o.kv = 1;
    o.stab = 1;
    tf_colloc *c = make(&b, "svk", &o, 1);
    double th = 0.7, ax[3] = {0.48, 0.6, 0.64}, Rm[9]; /* |ax| = 1 */
    const double K[9] = {0, -ax[2], ax[1], ax[2], 0, -ax[0], -ax[1], ax[0], 0};
    for (int i = 0; i < 3; ++i) { /* Rodrigues: cos I + (1 - cos) a a^T + sin [a]x */
        for (int j = 0; j < 3; ++j) {
            Rm[3 * i + j] = (i == j) * cos(th) + (1 - cos(th)) * ax[i] * ax[j] + sin(th) * K[3 * i + j];
        }
    }
    double *u = malloc(3 * b.n * sizeof *u), *f = malloc(3 * b.n * sizeof *f), U;
    for (size_t i = 0; i < b.n; ++i) {
        for (int a = 0; a < 3; ++a) {
            const double *x = b.X + 3 * i;
            u[3 * i + a] = Rm[3 * a] * x[0] + Rm[3 * a + 1] * x[1] + Rm[3 * a + 2] * x[2] - x[a] + 2;
        }
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, f, &U), 0);
    for (size_t q = 0; q < 3 * b.n; ++q) {
        assert_close(f[q], 0, 1e-12); /* E h^2 ~ 2: forces of a unit strain ~ 1 */
    }
    assert_close(U, 0, 1e-13);
    /* The same field stretched by 1 % is not free: the test can see forces. */
    for (size_t q = 0; q < 3 * b.n; ++q) {
        u[q] += 0.01 * b.X[q];
    }
    assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, f, &U), 0);
    assert_true(U > 1e-4);
    free(u);
    free(f);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

/* A quarter with mirror planes x = 0, y = 0 is the whole body: under a
 * symmetric displacement, each quarter particle's force is its share
 * (1, 1/2 on a plane, 1/4 on the axis) of the whole body's. */
static void mirror_images_equal_the_whole_body(void **state)
{
    (void)state;
    box_cloud whole, quarter;
    const size_t dw[3] = {9, 9, 5}, dq[3] = {5, 5, 5};
    const double lw[3] = {-4, -4, -3}, hw[3] = {4, 4, 0}, lq[3] = {0, 0, -3};
    assert_int_equal(box_cloud_make(&whole, dw, lw, hw, 0, 1), 0);
    assert_int_equal(box_cloud_make(&quarter, dq, lq, hw, 0, 1), 0);
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    tf_colloc_body bw = {.n = whole.n, .X = whole.X, .fixed = whole.fixed, .total_volume = 192,
                         .material = tf_test_material("svk", "E=2 nu=0.3"),
                         .density = 1e-9};
    tf_colloc_body bq = bw;
    const tf_colloc_mirror m[2] = {{0, 0}, {1, 0}};
    bq.n = quarter.n;
    bq.X = quarter.X;
    bq.fixed = quarter.fixed;
    bq.total_volume = 48;
    bq.mirrors = m;
    bq.n_mirrors = 2;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *cw = tf_colloc_new(&ctx, &bw, &o), *cq = tf_colloc_new(&ctx, &bq, &o);
    assert_non_null(cw);
    assert_non_null(cq);
    assert_true(tf_colloc_ghosts(cq) > 0);
    /* u = (x phi, y phi, psi), phi and psi even in x and y. */
    double *uw = malloc(3 * whole.n * sizeof *uw), *fw = malloc(3 * whole.n * sizeof *fw);
    double *uq = malloc(3 * quarter.n * sizeof *uq), *fq = malloc(3 * quarter.n * sizeof *fq);
    for (int pass = 0; pass < 2; ++pass) {
        const box_cloud *b = pass ? &quarter : &whole;
        double *u = pass ? uq : uw;
        for (size_t i = 0; i < b->n; ++i) {
            const double *x = b->X + 3 * i;
            double r2 = x[0] * x[0] + x[1] * x[1], phi = 0.02 * exp(-r2 / 8) * (1 + x[2] / 3);
            u[3 * i] = x[0] * phi;
            u[3 * i + 1] = x[1] * phi;
            u[3 * i + 2] = -0.1 * exp(-r2 / 5) * (1 + x[2] / 3) + 0.01 * x[2];
        }
    }
    assert_int_equal(tf_colloc_forces(&ctx, cw, uw, 0, fw, NULL), 0);
    assert_int_equal(tf_colloc_forces(&ctx, cq, uq, 0, fq, NULL), 0);
    double fmax = 0;
    for (size_t q = 0; q < 3 * whole.n; ++q) {
        fmax = fmax > fabs(fw[q]) ? fmax : fabs(fw[q]);
    }
    assert_true(fmax > 1e-3);
    for (size_t k = 0; k < 5; ++k) {
        for (size_t j = 0; j < 5; ++j) {
            for (size_t i = 0; i < 5; ++i) {
                size_t pq = box_cloud_at(&quarter, i, j, k), pw = box_cloud_at(&whole, i + 4, j + 4, k);
                double share = (i == 0 ? 0.5 : 1) * (j == 0 ? 0.5 : 1);
                for (int a = 0; a < 3; ++a) {
                    if ((a == 0 && i == 0) || (a == 1 && j == 0)) {
                        continue; /* the plane's normal component is fixed */
                    }
                    assert_close(fq[3 * pq + a], share * fw[3 * pw + a], 1e-10 * fmax);
                }
            }
        }
    }
    free(uw);
    free(fw);
    free(uq);
    free(fq);
    tf_colloc_free(cw);
    tf_colloc_free(cq);
    box_cloud_free(&whole);
    box_cloud_free(&quarter);
}

/* Eqs 2-3 volumes are scaled to the body's volume when it is given; a
 * regular grid's interior particles all get the same. */
static void seed_volumes_sum_to_the_body(void **state)
{
    (void)state;
    box_cloud b;
    jittered(&b, 0);
    tf_colloc_body body = {.n = b.n, .X = b.X, .fixed = b.fixed, .total_volume = 60,
                           .material = tf_test_material("svk", "E=2 nu=0.3"),
                           .density = 1e-9};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = tf_colloc_new(&ctx, &body, NULL);
    assert_non_null(c);
    const double *v = tf_colloc_volumes(c), *m = tf_colloc_masses(c);
    double sum = 0;
    for (size_t i = 0; i < b.n; ++i) {
        sum += v[i];
        assert_close(m[i], 1e-9 * v[i], 1e-22);
    }
    assert_close(sum, 60, 1e-12);
    assert_close(v[box_cloud_at(&b, 2, 2, 3)], v[box_cloud_at(&b, 3, 2, 3)], 1e-12);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

/* A cloud whose supports are flat has a singular moment matrix: refused,
 * naming the particle and its neighbour count. */
static void flat_supports_are_refused(void **state)
{
    (void)state;
    box_cloud b;
    const size_t dims[3] = {8, 8, 2};
    const double lo[3] = {0, 0, 0}, hi[3] = {7, 7, 0.001};
    assert_int_equal(box_cloud_make(&b, dims, lo, hi, 0, 1), 0);
    for (size_t i = 0; i < b.n; ++i) {
        b.X[3 * i + 2] = 0; /* one plane: every support flat */
    }
    tf_colloc_body body = {.n = b.n, .X = b.X, .volume = b.volume,
                           .material = tf_test_material("svk", "E=2 nu=0.3"),
                           .density = 1e-9};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_null(tf_colloc_new(&ctx, &body, NULL));
    assert_non_null(strstr(ctx.err, "particle 0 at (0, 0, 0) mm"));
    assert_non_null(strstr(ctx.err, "moment matrix"));
    assert_non_null(strstr(ctx.err, "neighbours"));
    tf_colloc_opts o;
    tf_colloc_defaults(&o);
    o.neighbours = 2;
    assert_null(tf_colloc_new(&ctx, &body, &o));
    assert_non_null(strstr(ctx.err, "neighbours = 2"));
    tf_material_set(&body.material, "nu", 0.5);
    assert_null(tf_colloc_new(&ctx, &body, NULL));
    assert_non_null(strstr(ctx.err, "material.nu"));
    box_cloud_free(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(linear_field_gives_exact_gradient),
        cmocka_unit_test(forces_are_minus_energy_gradient),
        cmocka_unit_test(rigid_motion_costs_nothing),
        cmocka_unit_test(mirror_images_equal_the_whole_body),
        cmocka_unit_test(seed_volumes_sum_to_the_body),
        cmocka_unit_test(flat_supports_are_refused),
    };
    return cmocka_run_group_tests_name("colloc", tests, NULL, NULL);
}
