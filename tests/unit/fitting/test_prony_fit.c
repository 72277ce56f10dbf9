/*
 * test_prony_fit.c — the prony family's fit (fitting/prony_terms.c,
 * fitting/families/prony.c): time constants and weights recovered from
 * exact data, the number of terms by cross-validation, weights that would
 * need J(0) < 0 refused, a tick too short for float32 refused with the
 * tick it needs, and the synthetic creep histories against a closed form.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "base/rng.h"
#include "fitting/families/family.h"
#include "fitting/families/prony_family.h"
#include "fitting/plan.h"
#include "fitting/prony_terms.h"

#define TICKS 3000
#define HIST 6
#define TICK 1e-3

/* Histories of g (ramps to random points and holds, axis by axis) and the
 * target h of a creep with terms t, by the first-order hold in double. */
static void make_data(const tf_prony_terms *t, double *g, double *h, uint64_t seed)
{
    tf_rng r = {seed};
    for (int k = 0; k < HIST; ++k) {
        double to[3], from[3] = {0, 0, 0}, e[TFIT_PRONY_MAX_TERMS][3] = {{0}}, prev[3] = {0, 0, 0};
        long start = 0, ramp = 1 + (long)tf_rng_below(&r, 400);
        for (int c = 0; c < 3; ++c) {
            to[c] = tf_rng_range(&r, -0.5, 0.5);
        }
        for (long n = 0; n < TICKS; ++n) {
            if (n == TICKS / 2) { /* release */
                memcpy(from, to, sizeof from);
                memset(to, 0, sizeof to);
                start = n;
                ramp = 1 + (long)tf_rng_below(&r, 400);
            }
            const double s = fmin(1.0, (double)(n - start) / (double)ramp);
            double *gn = g + 3 * ((size_t)k * TICKS + (size_t)n), *hn = h + (gn - g);
            for (int c = 0; c < 3; ++c) {
                gn[c] = from[c] + s * (to[c] - from[c]);
                hn[c] = gn[c];
                for (int j = 0; j < t->n; ++j) {
                    const double q = TICK / t->tau[j];
                    e[j][c] = exp(-q) * e[j][c] + (-expm1(-q) / q) * (gn[c] - prev[c]);
                    hn[c] -= t->w[j] * e[j][c];
                }
                prev[c] = gn[c];
            }
        }
    }
}

static tf_prony_data data_of(const double *g, const double *h)
{
    return (tf_prony_data){.n_hist = HIST, .n_ticks = TICKS, .g = g, .target = h,
                           .g_rest = {0, 0, 0}, .tick = TICK};
}

static void terms_are_recovered_from_exact_data(void **state)
{
    (void)state;
    const tf_prony_terms truth = {2, {0.05, 0.8}, {0.3, 0.25}, 0};
    double *g = malloc(3 * HIST * TICKS * sizeof *g), *h = malloc(3 * HIST * TICKS * sizeof *h);
    make_data(&truth, g, h, 1);
    const tf_prony_data d = data_of(g, h);
    tf_prony_terms t;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_prony_fit_terms(&ctx, &d, NULL, 0, 2, TICK, 3.0, &t), 0);
    for (int j = 0; j < 2; ++j) {
        print_message("term %d: tau %.9g (truth %g), w %.9g (truth %g)\n", j, t.tau[j],
                      truth.tau[j], t.w[j], truth.w[j]);
        assert_true(fabs(t.tau[j] / truth.tau[j] - 1) < 1e-6);
        assert_true(fabs(t.w[j] - truth.w[j]) < 1e-7);
    }
    assert_true(t.rms < 1e-9);
    free(g);
    free(h);
}

static void cross_validation_finds_the_number_of_terms(void **state)
{
    (void)state;
    const tf_prony_terms cases[3] = {{0, {0}, {0}, 0},
                                     {1, {0.2}, {0.4}, 0},
                                     {2, {0.03, 1.0}, {0.2, 0.3}, 0}};
    double *g = malloc(3 * HIST * TICKS * sizeof *g), *h = malloc(3 * HIST * TICKS * sizeof *h);
    tf_fit_plan plan;
    tf_fit_plan_defaults(&plan);
    tf_histories hist = {.tick = TICK, .tick_ns = 1000000};
    hist.train.n_ticks = TICKS;
    for (int c = 0; c < 3; ++c) {
        make_data(&cases[c], g, h, 10 + (uint64_t)c);
        const tf_prony_data d = data_of(g, h);
        double cv[TF_PRONY_SEARCH_TERMS + 1];
        int k;
        tf_prony_terms t;
        tf_ctx ctx;
        tf_ctx_init(&ctx);
        assert_int_equal(tf_prony_select_terms(&ctx, &d, &hist, &plan, cv, &k, &t), 0);
        print_message("truth K = %d: CV RMS by K %.3g %.3g %.3g %.3g %.3g: K = %d\n", cases[c].n,
                      cv[0], cv[1], cv[2], cv[3], cv[4], k);
        assert_int_equal(k, cases[c].n);
    }
    free(g);
    free(h);
}

/* Data that creep more than the relaxed map allows (weights summing to
 * 1.4: h overshoots below zero after a step) are refused. */
static void weights_beyond_one_are_refused(void **state)
{
    (void)state;
    const tf_prony_terms truth = {1, {0.1}, {1.4}, 0};
    double *g = malloc(3 * HIST * TICKS * sizeof *g), *h = malloc(3 * HIST * TICKS * sizeof *h);
    make_data(&truth, g, h, 3);
    const tf_prony_data d = data_of(g, h);
    tf_prony_terms t;
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_prony_fit_terms(&ctx, &d, NULL, 0, 1, TICK, 3.0, &t), -1);
    print_message("%s\n", ctx.err);
    assert_non_null(strstr(ctx.err, "weights summing to 1.4"));
    free(g);
    free(h);
}

static void a_tick_too_short_is_refused(void **state)
{
    (void)state;
    const tf_prony_terms t = {1, {4.8}, {0.3}, 0};
    tf_histories h = {.tick = 1e-5, .tick_ns = 10000};
    tf_ctx ctx;
    tf_ctx_init(&ctx);
    assert_int_equal(tf_prony_tick_allows(&ctx, &t, &h), -1);
    print_message("%s\n", ctx.err);
    assert_non_null(strstr(ctx.err, "fit with a tick of at least 48 us"));
    h.tick = 1e-4;
    h.tick_ns = 100000;
    assert_int_equal(tf_prony_tick_allows(&ctx, &t, &h), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(terms_are_recovered_from_exact_data),
        cmocka_unit_test(cross_validation_finds_the_number_of_terms),
        cmocka_unit_test(weights_beyond_one_are_refused),
        cmocka_unit_test(a_tick_too_short_is_refused),
    };
    return cmocka_run_group_tests_name("prony_fit", tests, NULL, NULL);
}
