/*
 * bench_step.c — time per explicit step of the collocation solver at 6,000
 * particles (issue 16 acceptance 3; seed 004: 20.11 ms per step on an i5
 * at 2.67 GHz, SOFA, about 6,000 particles), in the same run as a
 * reference operation whose cost does not depend on this code: a 160 x 160
 * dense matrix product in plain C (8.2 Mflop), so that a slow or busy
 * machine shows in both.
 *
 *   bench_step [BATCHES [STEPS]]
 *
 * The body: a 20 x 20 x 15 grid (6,000 particles, 1 mm spacing), bottom
 * clamped, St. Venant-Kirchhoff, the default supports (k = 10: 18 with
 * ties), a rigid sphere pressing on the top and a force on one corner so
 * that every term works.
 * Each batch runs STEPS steps; the medians of BATCHES batches per thread
 * count are printed, as wall time and as processor time (the sum over
 * threads: on a shared machine the wall time of a thread that waits for a
 * core is not the code's).  Timing is printed, never asserted.
 */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "solvers/collocation/colloc.h"

#define NREF 160

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *t, size_t n)
{
    qsort(t, n, sizeof *t, cmp);
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/* Processor time of the whole process (all threads), s. */
static double cpu_time(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The reference: C = A B, 160 x 160, three plain loops (i, k, j); returns
 * the wall time and puts the processor time in *cpu. */
static double reference(double *a, double *b, double *c, double *cpu)
{
    double t0 = omp_get_wtime(), c0 = cpu_time();
    for (int i = 0; i < NREF; ++i) {
        for (int j = 0; j < NREF; ++j) {
            c[i * NREF + j] = 0;
        }
        for (int k = 0; k < NREF; ++k) {
            double aik = a[i * NREF + k];
            for (int j = 0; j < NREF; ++j) {
                c[i * NREF + j] += aik * b[k * NREF + j];
            }
        }
    }
    *cpu = cpu_time() - c0;
    return omp_get_wtime() - t0;
}

static tf_colloc *body(double *X, unsigned char *fixed, double *vol)
{
    size_t n = 0;
    for (int k = 0; k < 15; ++k) {
        for (int j = 0; j < 20; ++j) {
            for (int i = 0; i < 20; ++i, ++n) {
                X[3 * n] = i;
                X[3 * n + 1] = j;
                X[3 * n + 2] = k - 14;
                fixed[n] = k == 0 ? TF_COLLOC_FIX_ALL : 0;
                vol[n] = (i == 0 || i == 19 ? 0.5 : 1) * (j == 0 || j == 19 ? 0.5 : 1) *
                         (k == 0 || k == 14 ? 0.5 : 1);
            }
        }
    }
    tf_colloc_body b = {.n = n, .X = X, .fixed = fixed, .volume = vol,
                        .material = tf_material_of(tf_law_find("svk")),
                        .density = 1e-9};
    tf_material_set(&b.material, "E", 0.32);
    tf_material_set(&b.material, "nu", 0.45);
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    tf_colloc *c = tf_colloc_new(&ctx, &b, NULL);
    if (c == NULL) {
        fprintf(stderr, "bench_step: %s\n", ctx.err);
        exit(1);
    }
    tf_colloc_sphere s = {.centre = {9.5, 9.5, 10}, .dir = {0, 0, -1}, .radius = 10,
                          .drive = TF_COLLOC_INDENT};
    tf_colloc_set_sphere(&ctx, c, &s);
    tf_colloc_set_travel(c, 0.5);
    tf_colloc_fext(c)[3 * (n - 1)] = 1e-3;
    return c;
}

int main(int argc, char **argv)
{
    int batches = argc > 1 ? atoi(argv[1]) : 21, steps = argc > 2 ? atoi(argv[2]) : 50;
    if (batches < 1 || steps < 1) {
        fprintf(stderr, "usage: bench_step [BATCHES [STEPS]]\n");
        return 2;
    }
    double *X = malloc(3 * 6000 * sizeof *X), *vol = malloc(6000 * sizeof *vol);
    unsigned char *fixed = malloc(6000);
    double *a = malloc(3 * NREF * NREF * sizeof *a), *t = malloc((size_t)batches * sizeof *t);
    double *r = malloc((size_t)batches * sizeof *r), *tc = malloc((size_t)batches * sizeof *tc);
    double *rc = malloc((size_t)batches * sizeof *rc);
    for (int i = 0; i < NREF * NREF; ++i) {
        a[i] = 1.0 / (1 + i % 17);
        a[NREF * NREF + i] = 1.0 / (1 + i % 13);
    }
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    int maxt = omp_get_max_threads();
    printf("== collocation: time per explicit step at 6,000 particles ([Aras-MLS]: 20.11 ms; "
           "goal <= 1 ms) ==\n");
    for (int threads = 1; threads <= (maxt < 2 ? 2 : maxt); ++threads) {
        omp_set_num_threads(threads);
        tf_colloc *c = body(X, fixed, vol);
        double dcrit = tf_colloc_critical_dt(&ctx, c), dt = 0.9 * dcrit;
        if (threads == 1) {
            printf("stable step: %.4g s (Lanczos), wave bound min r / c_p %.4g s, ratio %.2f; "
                   "steps of 0.9 of it\n", dcrit, tf_colloc_wave_dt(c),
                   dcrit / tf_colloc_wave_dt(c));
        }
        tf_colloc_run(&ctx, c, dt, 5, 0); /* warm up */
        for (int k = 0; k < batches; ++k) {
            r[k] = reference(a, a + NREF * NREF, a + 2 * NREF * NREF, &rc[k]);
            double t0 = omp_get_wtime(), c0 = cpu_time();
            if (tf_colloc_run(&ctx, c, dt, (size_t)steps, 10) != 0) {
                fprintf(stderr, "bench_step: %s\n", ctx.err);
                return 1;
            }
            t[k] = (omp_get_wtime() - t0) / steps;
            tc[k] = (cpu_time() - c0) / steps;
        }
        double ms = 1e3 * median(t, (size_t)batches), ref = 1e3 * median(r, (size_t)batches);
        double cms = 1e3 * median(tc, (size_t)batches), cref = 1e3 * median(rc, (size_t)batches);
        printf("%d thread%s: %.3f ms per step wall (processor %.3f ms, all threads), median of "
               "%d x %d steps; reference 160^3 product %.3f ms wall (processor %.3f ms); "
               "step / reference %.2f wall, %.2f processor\n",
               threads, threads > 1 ? "s" : " ", ms, cms, batches, steps, ref, cref, ms / ref,
               cms / cref);
        tf_colloc_free(c);
    }
    free(X);
    free(vol);
    free(fixed);
    free(a);
    free(t);
    free(r);
    free(tc);
    free(rc);
    return 0;
}
