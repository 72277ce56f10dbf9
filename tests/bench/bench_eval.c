/*
 * bench_eval.c — native cost of every model of one generated header, float
 * and Q31 forms: each call timed on its own (CLOCK_MONOTONIC around it,
 * minus the median cost of an empty interval), over CALLS calls cycling
 * through the model's in-envelope golden inputs.
 *
 *   bench_eval time [CALLS]   one line per model:
 *       float|q31 SET n_out median_ns p99_ns max_ns n_coef
 *   (n_coef: coefficients of the float table, words of the Q31 one)
 *   bench_eval count CALLS    the same calls without timing, one callgrind
 *                             dump per model (instructions per call)
 *
 * Compiled per header with -DGOLDEN_H, -DGOLDEN_SETS, -DGOLDEN_Q31_SETS and
 * -DTFIT_NAME_IMPLEMENTATION, like the golden runners.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <valgrind/callgrind.h>

#include GOLDEN_H

#define IN_ENVELOPE 26 /* golden design: zero, centre, 24 inside (header-format.md §7) */

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

static double timer_cost(double *t, long calls)
{
    for (long i = 0; i < calls; ++i) {
        double t0 = now_ns();
        t[i] = now_ns() - t0;
    }
    qsort(t, (size_t)calls, sizeof *t, by_value);
    return t[calls / 2];
}

static void report(const char *kind, size_t set, uint32_t n_out, uint32_t n_coef, double *t,
                   long calls, double overhead)
{
    for (long i = 0; i < calls; ++i) {
        t[i] = t[i] - overhead;
    }
    qsort(t, (size_t)calls, sizeof *t, by_value);
    printf("%s %zu %u %.1f %.1f %.1f %u\n", kind, set, n_out, t[calls / 2], t[calls * 99 / 100],
           t[calls - 1], n_coef);
}

static void float_models(int timed, long calls, double *t, double overhead)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    for (size_t s = 0; s < sizeof sets / sizeof sets[0]; ++s) {
        const tfit_model *m = sets[s]->model;
        float *out = malloc(3 * m->n_out * sizeof *out);
        const int contact = m->family == TFIT_FAMILY_CONTACT;
        const int prony = m->family == TFIT_FAMILY_PRONY; /* a tick of its state */
        float state[TFIT_PRONY_MAX_STATE];
        if (prony) {
            tfit_prony_reset(m, state);
        }
        if (!timed) {
            CALLGRIND_ZERO_STATS;
        }
        for (long i = 0; i < calls; ++i) {
            float x[3];
            memcpy(x, sets[s]->in + 3 * (i % IN_ENVELOPE), sizeof x);
            double t0 = timed ? now_ns() : 0;
            if (prony) {
                tfit_prony_step(m, state, x, out);
            } else if (contact) {
                tfit_contact_force(m, x, out);
            } else {
                tfit_displacements(m, x, out);
            }
            if (timed) {
                t[i] = now_ns() - t0;
            }
        }
        if (timed) {
            report("float", s, m->n_out, m->n_coef, t, calls, overhead);
        } else {
            char label[32];
            snprintf(label, sizeof label, "float %zu", s);
            CALLGRIND_DUMP_STATS_AT(label);
        }
        free(out);
    }
}

static void q31_models(int timed, long calls, double *t, double overhead)
{
    static const tfit_golden_q31 *const sets[] = GOLDEN_Q31_SETS;
    for (size_t s = 0; sets[s] != NULL; ++s) {
        const tfit_model_q31 *m = sets[s]->model;
        int32_t *out = malloc(3 * m->n_out * sizeof *out);
        const int contact = m->family == TFIT_FAMILY_CONTACT;
        const int prony = m->family == TFIT_FAMILY_PRONY; /* one tick per call */
        int32_t state[TFIT_PRONY_Q31_STATE_WORDS(TFIT_PRONY_MAX_TERMS)];
        if (prony) {
            tfit_prony_reset_q31(m, state);
        }
        if (!timed) {
            CALLGRIND_ZERO_STATS;
        }
        for (long i = 0; i < calls; ++i) {
            const int32_t *x = sets[s]->in + 3 * (i % IN_ENVELOPE);
            double t0 = timed ? now_ns() : 0;
            if (prony) {
                tfit_prony_step_q31(m, state, x, out);
            } else if (contact) {
                tfit_contact_force_q31(m, x, out);
            } else {
                tfit_displacements_q31(m, x, out);
            }
            if (timed) {
                t[i] = now_ns() - t0;
            }
        }
        if (timed) {
            report("q31", s, m->n_out, m->n_words, t, calls, overhead);
        } else {
            char label[32];
            snprintf(label, sizeof label, "q31 %zu", s);
            CALLGRIND_DUMP_STATS_AT(label);
        }
        free(out);
    }
}

int main(int argc, char **argv)
{
    const int timed = argc >= 2 && strcmp(argv[1], "time") == 0;
    if (argc < 2 || (!timed && strcmp(argv[1], "count") != 0)) {
        fprintf(stderr, "usage: bench_eval time|count [CALLS]\n");
        return 2;
    }
    long calls = argc > 2 ? strtol(argv[2], NULL, 10) : 100000;
    double *t = malloc((size_t)calls * sizeof *t);
    if (t == NULL || calls < 100) {
        return 2;
    }
    double overhead = timed ? timer_cost(t, calls) : 0;
    float_models(timed, calls, t, overhead);
    q31_models(timed, calls, t, overhead);
    free(t);
    return 0;
}
