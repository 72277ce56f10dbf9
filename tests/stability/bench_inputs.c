/*
 * bench_inputs.c — native time per evaluation by kind of input, for every
 * float32 model of one header: inside the envelope, subnormal-sized
 * (1e-40 per component), 1e30 times beyond it, and NaN.  The evaluation
 * executes the same instructions for all of them (make check-insncount),
 * but x86 cores take a microcode assist on every operation with a
 * subnormal operand or result, so the time is not the same
 * (docs/stability.md §3).  Printed, never asserted (GUIDE §7).
 *
 *   bench_inputs [CALLS]      one line per model: median ns per kind
 *
 * Compiled per header like run_invariants.c (-DGOLDEN_H, -DGOLDEN_SETS,
 * -DGOLDEN_Q31_SETS, -DTFIT_NAME_IMPLEMENTATION).
 */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include GOLDEN_H
#include "invariants.h"

#define BATCH 64
enum { INSIDE, SUBNORMAL, FAR, NAN_INPUT, N_KINDS };
static const char *const kind_names[N_KINDS] = {"inside", "subnormal", "1e30x beyond", "NaN"};

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median over batches of BATCH calls, ns per call. */
static double median_ns(stab_float *c, const float x[3], long batches, double *t)
{
    for (long b = 0; b < batches; ++b) {
        const double t0 = now_ns();
        for (int i = 0; i < BATCH; ++i) {
            stab_float_eval(c, x, c->y);
        }
        t[b] = (now_ns() - t0) / BATCH;
    }
    qsort(t, (size_t)batches, sizeof *t, by_value);
    return t[batches / 2];
}

int main(int argc, char **argv)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const long calls = argc > 1 ? atol(argv[1]) : 64000;
    const long batches = calls / BATCH > 0 ? calls / BATCH : 1;
    double *t = malloc((size_t)batches * sizeof *t);
    if (t == NULL) {
        return 1;
    }
    const double diagonal[3] = {0.5773502691896258, 0.5773502691896258, 0.5773502691896258};
    for (size_t s = 0; s < sizeof sets / sizeof sets[0]; ++s) {
        stab_float c;
        if (stab_float_init(&c, sets[s]->model, "bench") != 0) {
            free(t);
            return 1;
        }
        float x[N_KINDS][3] = {{0}, {1e-40f, -1e-40f, 1e-40f}, {0}, {NAN, 0, 0}};
        stab_float_along(&c, diagonal, 0.5, x[INSIDE]);
        stab_float_along(&c, diagonal, 1e30, x[FAR]);
        printf("float %zu n_out=%-4u", s, c.m->n_out);
        for (int k = 0; k < N_KINDS; ++k) {
            printf("  %s %.0f ns", kind_names[k], median_ns(&c, x[k], batches, t));
        }
        printf("\n");
        stab_float_free(&c);
    }
    free(t);
    return 0;
}
