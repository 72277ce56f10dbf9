/*
 * golden_run.c — the consumer projects' program (tests/cmake/): runs every
 * golden set of one generated header through the linked libtfit and prints
 *   LABEL float: N passed, M failed (V vectors, W words, X mismatching)
 *   LABEL q31: ...
 * Exit status 0 only when every model passes tfit_model_check() and every
 * word of every golden vector matches the host's bits.  Natively it writes
 * to stdout; on a Cortex-M image through semihosting (QEMU).
 *
 * Compiled with -DGOLDEN_H='"NAME_golden.h"', -DGOLDEN_SETS=..._GOLDEN_SETS,
 * -DGOLDEN_Q31_SETS=..._GOLDEN_Q31_SETS, -DTFIT_NAME_IMPLEMENTATION and
 * -DLABEL='"..."'.  -DPLANT_MISMATCH runs the first float set against a
 * copy of its expected statuses with one word changed: that build must
 * report exactly one mismatching word and fail, which shows the check
 * judging these programs would notice a library that differs.
 */
#include <stdint.h>

#include GOLDEN_H

#if defined(__arm__)
#include "semihost.h"
#include "startup.h"
static void put(const char *s) { semihost_puts(s); }
static void put_u32(uint32_t v) { semihost_put_u32(v); }
#else
#include <stdio.h>
static void put(const char *s) { fputs(s, stdout); }
static void put_u32(uint32_t v) { printf("%lu", (unsigned long)v); }
#endif

#define SCRATCH_WORDS (3u * 8192u)
static union {
    float f[SCRATCH_WORDS];
    int32_t q[SCRATCH_WORDS];
} scratch;

static void report(const char *kind, uint32_t passed, uint32_t failed, uint32_t vectors,
                   uint32_t words, uint32_t bad)
{
    put(LABEL " ");
    put(kind);
    put(": ");
    put_u32(passed);
    put(" passed, ");
    put_u32(failed);
    put(" failed (");
    put_u32(vectors);
    put(" vectors, ");
    put_u32(words);
    put(" words, ");
    put_u32(bad);
    put(" mismatching)\n");
}

static int fits(uint32_t n_out)
{
    if (3u * n_out > SCRATCH_WORDS) {
        put(LABEL ": a model is too large for the scratch buffer\n");
        return 0;
    }
    return 1;
}

#ifdef PLANT_MISMATCH
static int32_t planted_status[4096];
/* The set with its first expected status changed: one mismatching word. */
static const tfit_golden *planted(const tfit_golden *g)
{
    static tfit_golden copy;
    if (g->n_vec > sizeof planted_status / sizeof planted_status[0]) {
        return g;
    }
    for (uint32_t v = 0u; v < g->n_vec; ++v) {
        planted_status[v] = g->status[v];
    }
    planted_status[0] ^= 1;
    copy = *g;
    copy.status = planted_status;
    return &copy;
}
#endif

static uint32_t run_float(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const uint32_t n_sets = (uint32_t)(sizeof sets / sizeof sets[0]);
    uint32_t passed = 0u, vectors = 0u, words = 0u, bad_words = 0u;
    for (uint32_t i = 0u; i < n_sets; ++i) {
        const tfit_golden *g = sets[i];
#ifdef PLANT_MISMATCH
        if (i == 0u) {
            g = planted(g);
        }
#endif
        if (!fits(g->model->n_out)) {
            continue;
        }
        const tfit_status st = tfit_model_check(g->model);
        const uint32_t bad = tfit_golden_run(g, scratch.f);
        vectors += g->n_vec;
        words += g->n_vec * (3u * g->model->n_out + 1u);
        bad_words += bad;
        if (st == TFIT_OK && bad == 0u) {
            ++passed;
        }
    }
    report("float", passed, n_sets - passed, vectors, words, bad_words);
    return n_sets - passed;
}

#ifdef GOLDEN_Q31_SETS
static uint32_t run_q31(void)
{
    static const tfit_golden_q31 *const sets[] = GOLDEN_Q31_SETS; /* null-terminated */
    uint32_t n_sets = 0u, passed = 0u, vectors = 0u, words = 0u, bad_words = 0u;
    for (; sets[n_sets] != 0; ++n_sets) {
        const tfit_golden_q31 *g = sets[n_sets];
        if (!fits(g->model->n_out)) {
            continue;
        }
        const tfit_status st = tfit_model_check_q31(g->model);
        const uint32_t bad = tfit_golden_run_q31(g, scratch.q);
        vectors += g->n_vec;
        words += g->n_vec * (3u * g->model->n_out + 1u);
        bad_words += bad;
        if (st == TFIT_OK && bad == 0u) {
            ++passed;
        }
    }
    report("q31", passed, n_sets - passed, vectors, words, bad_words);
    return n_sets - passed;
}
#endif

int main(void)
{
    uint32_t failed = run_float();
#ifdef GOLDEN_Q31_SETS
    failed += run_q31();
#endif
    return failed == 0u ? 0 : 1;
}
