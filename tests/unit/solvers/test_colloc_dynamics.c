/*
 * test_colloc_dynamics.c — time integration, the stable-step estimate,
 * dynamic relaxation, the sphere's two drives and thread determinism of
 * the collocation solver (solvers/collocation/colloc.h).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <omp.h>

#include "assert_close.h"
#include "base/rng.h"
#include "box_cloud.h"
#include "material_of.h"
#include "solvers/collocation/colloc.h"

/* A jittered 7 x 6 x 5 block [0,6] x [0,5] x [-4,0], bottom clamped. */
static tf_colloc *block(box_cloud *b, const char *law, double jitter)
{
    const size_t dims[3] = {7, 6, 5};
    const double lo[3] = {0, 0, -4}, hi[3] = {6, 5, 0};
    assert_int_equal(box_cloud_make(b, dims, lo, hi, jitter, 11), 0);
    for (size_t i = 0; i < b->n; ++i) {
        b->fixed[i] = b->X[3 * i + 2] == -4 ? TF_COLLOC_FIX_ALL : 0;
    }
    tf_colloc_body body = {.n = b->n, .X = b->X, .fixed = b->fixed, .volume = b->volume,
                           .material = tf_test_material(law, "E=0.5 nu=0.45"),
                           .density = 1e-9};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = tf_colloc_new(&ctx, &body, NULL);
    assert_non_null(c);
    return c;
}

static double max_abs(const double *x, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; ++i) {
        m = fabs(x[i]) > m ? fabs(x[i]) : m;
    }
    return m;
}

/* From the same small random velocity, 2000 steps just below the
 * estimated stable step stay bounded, just above it they blow up. */
static void stable_step_is_the_boundary(void **state)
{
    (void)state;
    box_cloud b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double growth[2];
    for (int above = 0; above < 2; ++above) {
        tf_colloc *c = block(&b, "linear", 0.2);
        double dt = tf_colloc_critical_dt(&ctx, c);
        assert_true(dt > 0);
        double ratio = dt / tf_colloc_wave_dt(c);
        assert_true(ratio > 0.3 && ratio < 3); /* the same order as the wave bound */
        double *v = tf_colloc_v(c);
        tf_rng r = {9};
        for (size_t q = 0; q < 3 * b.n; ++q) {
            v[q] = b.fixed[q / 3] ? 0 : tf_rng_range(&r, -1e-3, 1e-3);
        }
        int rc = tf_colloc_run(&ctx, c, dt * (above ? 1.02 : 0.98), 2000, 0);
        double u = max_abs(tf_colloc_u(c), 3 * b.n);
        growth[above] = rc != 0 ? INFINITY : u / (1e-3 * dt);
        if (rc != 0) {
            assert_non_null(strstr(ctx.err, "no longer finite"));
        }
        tf_colloc_free(c);
        box_cloud_free(&b);
    }
    assert_true(growth[0] < 1e3);
    assert_true(growth[1] > 1e6);
}

/* Without damping the scheme is symplectic: the energy of a free
 * vibration stays put (to second order in dt, no drift). */
static void undamped_motion_keeps_its_energy(void **state)
{
    (void)state;
    box_cloud b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = block(&b, "svk", 0.2);
    double dt = 0.3 * tf_colloc_critical_dt(&ctx, c);
    double *u = tf_colloc_u(c), *v = tf_colloc_v(c), *f = malloc(3 * b.n * sizeof *f);
    const double *m = tf_colloc_masses(c);
    for (size_t i = 0; i < b.n; ++i) { /* a smooth initial bend */
        if (!b.fixed[i]) {
            u[3 * i] = 0.05 * (b.X[3 * i + 2] + 4) * (b.X[3 * i + 2] + 4) / 16;
        }
    }
    double e[2];
    for (int k = 0; k < 2; ++k) {
        double U, T = 0;
        assert_int_equal(tf_colloc_forces(&ctx, c, u, 0, f, &U), 0);
        for (size_t q = 0; q < 3 * b.n; ++q) {
            T += 0.5 * m[q / 3] * v[q] * v[q];
        }
        e[k] = U + T;
        assert_int_equal(tf_colloc_run(&ctx, c, dt, 1500, 0), 0);
    }
    assert_true(e[0] > 0);
    assert_close(e[1], e[0], 0.02 * e[0]); /* T at half steps: O(dt^2) offset */
    free(f);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

/* A run and a relaxation with a sphere and nodal forces give the same bits
 * on 1, 2 and 3 threads. */
static void same_bits_for_any_thread_count(void **state)
{
    (void)state;
    box_cloud b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    double *ref = NULL;
    double fref = 0;
    for (int threads = 1; threads <= 3; ++threads) {
        omp_set_num_threads(threads);
        tf_colloc *c = block(&b, "svk", 0.2);
        tf_colloc_sphere s = {.centre = {3, 2.5, 5}, .dir = {0, 0, -1}, .radius = 5,
                              .drive = TF_COLLOC_INDENT};
        assert_int_equal(tf_colloc_set_sphere(&ctx, c, &s), 0);
        tf_colloc_set_travel(c, 0.2);
        tf_colloc_fext(c)[3 * box_cloud_at(&b, 6, 5, 4)] = 1e-3;
        double dt = 0.5 * tf_colloc_critical_dt(&ctx, c);
        assert_int_equal(tf_colloc_run(&ctx, c, dt, 50, 100), 0);
        tf_colloc_relax_opts o;
        tf_colloc_relax_defaults(&o);
        o.max_steps = 200;
        assert_true(tf_colloc_relax(&ctx, c, &o, NULL) >= 0);
        const double *u = tf_colloc_u(c);
        if (ref == NULL) {
            ref = malloc(3 * b.n * sizeof *ref);
            memcpy(ref, u, 3 * b.n * sizeof *ref);
            fref = tf_colloc_contact_force(c);
            assert_true(fref > 0);
        } else {
            assert_memory_equal(ref, u, 3 * b.n * sizeof *ref);
            assert_memory_equal(&fref, &(double){tf_colloc_contact_force(c)}, sizeof fref);
        }
        tf_colloc_free(c);
        box_cloud_free(&b);
    }
    omp_set_num_threads(1);
    free(ref);
}

/* Relaxation ends in equilibrium: the residual is below the tolerance, and
 * the forces the supports exert balance the applied load (linear law). */
static void relaxation_balances_the_load(void **state)
{
    (void)state;
    box_cloud b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = block(&b, "linear", 0.2);
    double *fext = tf_colloc_fext(c), load = 0;
    for (size_t i = 0; i < b.n; ++i) {
        if (b.X[3 * i + 2] == 0) {
            fext[3 * i] = 1e-3 * b.volume[i];   /* shear on the top */
            fext[3 * i + 2] = -2e-3 * b.volume[i];
            load += fext[3 * i];
        }
    }
    tf_colloc_relax_opts o;
    tf_colloc_relax_defaults(&o);
    o.tol = 1e-8;
    tf_colloc_relax_stats st;
    assert_int_equal(tf_colloc_relax(&ctx, c, &o, &st), 0);
    assert_true(st.converged && st.residual <= 1e-8 && st.steps > 10);
    double *f = malloc(3 * b.n * sizeof *f), react = 0, resid = 0;
    assert_int_equal(tf_colloc_forces(&ctx, c, tf_colloc_u(c), 0, f, NULL), 0);
    for (size_t i = 0; i < b.n; ++i) {
        if (b.fixed[i]) {
            react += f[3 * i] + fext[3 * i]; /* minus the support's force */
        } else {
            resid = fmax(resid, fabs(f[3 * i] + fext[3 * i]));
        }
    }
    assert_close(react, load, 1e-6 * load); /* translation invariance: sum f = 0 */
    assert_true(resid < 1e-7 * load);
    free(f);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

/* The sphere pushed with the force that an indentation d needs comes to
 * rest at d; and a damped dynamic run at fixed indentation ends with the
 * momentum force equal to the static one. */
static void sphere_drives_agree(void **state)
{
    (void)state;
    box_cloud b;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = block(&b, "svk", 0.2);
    tf_colloc_sphere s = {.centre = {3, 2.5, 8}, .dir = {0, 0, -1}, .radius = 8,
                          .drive = TF_COLLOC_INDENT};
    assert_int_equal(tf_colloc_set_sphere(&ctx, c, &s), 0);
    tf_colloc_set_travel(c, 0.3);
    tf_colloc_relax_opts o;
    tf_colloc_relax_defaults(&o);
    o.tol = 1e-9;
    assert_int_equal(tf_colloc_relax(&ctx, c, &o, NULL), 0);
    double F = tf_colloc_contact_force(c);
    assert_true(F > 0 && tf_colloc_contacts(c) >= 3);
    s.drive = TF_COLLOC_FORCE;
    s.force = F;
    assert_int_equal(tf_colloc_set_sphere(&ctx, c, &s), 0);
    memset(tf_colloc_u(c), 0, 3 * b.n * sizeof(double));
    assert_int_equal(tf_colloc_relax(&ctx, c, &o, NULL), 0);
    assert_close(tf_colloc_travel(c), 0.3, 1e-5);
    /* Dynamics at the same indentation, damped until at rest. */
    s.drive = TF_COLLOC_INDENT;
    assert_int_equal(tf_colloc_set_sphere(&ctx, c, &s), 0);
    tf_colloc_set_travel(c, 0.3);
    memset(tf_colloc_u(c), 0, 3 * b.n * sizeof(double));
    double dt = 0.9 * tf_colloc_critical_dt(&ctx, c);
    assert_int_equal(tf_colloc_run(&ctx, c, dt, 20000, 0.02 / dt), 0);
    assert_close(tf_colloc_contact_force(c), F, 1e-4 * F);
    tf_colloc_free(c);
    box_cloud_free(&b);
}

int main(void)
{
    omp_set_num_threads(1);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stable_step_is_the_boundary),
        cmocka_unit_test(undamped_motion_keeps_its_energy),
        cmocka_unit_test(same_bits_for_any_thread_count),
        cmocka_unit_test(relaxation_balances_the_load),
        cmocka_unit_test(sphere_drives_agree),
    };
    return cmocka_run_group_tests_name("colloc_dynamics", tests, NULL, NULL);
}
