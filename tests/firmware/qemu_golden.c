/*
 * qemu_golden.c — runs every golden set of one generated header on the
 * device (QEMU boards, semihosting) and prints, per arithmetic,
 *   LABEL float: N passed, M failed (V vectors, W words); stack used S bytes
 *   LABEL q31: ...
 * Exit status 0 only when every model passes its check and every word of
 * every golden vector matches the host's bits.
 *
 * Compiled per header and core with -DGOLDEN_H='"NAME_golden.h"',
 * -DTFIT_NAME_IMPLEMENTATION, -DLABEL='"NAME/board"' and
 * -DGOLDEN_SETS=TFIT_NAME_GOLDEN_SETS (float; omitted on cores without an
 * FPU) and/or -DGOLDEN_Q31_SETS=TFIT_NAME_GOLDEN_Q31_SETS; for an affine
 * region header -DGOLDEN_PAIR=TFIT_NAME_GOLDEN_PAIR too.
 */
#include "semihost.h"
#include "startup.h"

#include GOLDEN_H

#ifndef SCRATCH_WORDS /* -DSCRATCH_WORDS on boards with little RAM */
#define SCRATCH_WORDS (3u * 8192u)
#endif

static union {
    float f[SCRATCH_WORDS];
    int32_t q[SCRATCH_WORDS];
} scratch;

static void report_set(const char *kind, uint32_t i, int check_ok, uint32_t bad)
{
    semihost_puts(LABEL " ");
    semihost_puts(kind);
    semihost_puts(": set ");
    semihost_put_u32(i);
    semihost_puts(check_ok ? ": " : ": model check failed, ");
    semihost_put_u32(bad);
    semihost_puts(" mismatching words\n");
}

static void report(const char *kind, uint32_t passed, uint32_t failed, uint32_t vectors,
                   uint32_t words)
{
    semihost_puts(LABEL " ");
    semihost_puts(kind);
    semihost_puts(": ");
    semihost_put_u32(passed);
    semihost_puts(" passed, ");
    semihost_put_u32(failed);
    semihost_puts(" failed (");
    semihost_put_u32(vectors);
    semihost_puts(" vectors, ");
    semihost_put_u32(words);
    semihost_puts(" words); stack used ");
    semihost_put_u32(startup_stack_used());
    semihost_puts(" bytes\n");
}

static uint32_t out_words(uint32_t n_out)
{
    if (3u * n_out > SCRATCH_WORDS) {
        board_fail(LABEL ": model too large for the runner's scratch buffer");
    }
    return 3u * n_out;
}

#ifdef GOLDEN_SETS
static uint32_t run_float(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const uint32_t n_sets = (uint32_t)(sizeof sets / sizeof sets[0]);
    uint32_t passed = 0u, vectors = 0u, words = 0u;
    for (uint32_t i = 0u; i < n_sets; ++i) {
        const tfit_golden *g = sets[i];
        const uint32_t n = out_words(g->model->n_out);
        tfit_status st = tfit_model_check(g->model);
        uint32_t bad = tfit_golden_run(g, scratch.f);
        vectors += g->n_vec;
        words += g->n_vec * (n + 1u);
        if (st == TFIT_OK && bad == 0u) {
            ++passed;
        } else {
            report_set("float", i, st == TFIT_OK, bad);
        }
    }
    report("float", passed, n_sets - passed, vectors, words);
    return n_sets - passed;
}
#endif

#ifdef GOLDEN_Q31_SETS
static uint32_t run_q31(void)
{
    static const tfit_golden_q31 *const sets[] = GOLDEN_Q31_SETS; /* null-terminated */
    uint32_t passed = 0u, failed = 0u, vectors = 0u, words = 0u;
    for (uint32_t i = 0u; sets[i] != 0; ++i) {
        const tfit_golden_q31 *g = sets[i];
        const uint32_t n = out_words(g->model->n_out);
        tfit_status st = tfit_model_check_q31(g->model);
        uint32_t bad = tfit_golden_run_q31(g, scratch.q);
        vectors += g->n_vec;
        words += g->n_vec * (n + 1u);
        if (st == TFIT_OK && bad == 0u) {
            ++passed;
        } else {
            ++failed;
            report_set("q31", i, st == TFIT_OK, bad);
        }
    }
    report("q31", passed, failed, vectors, words);
    return failed;
}
#endif

#if defined(GOLDEN_SETS) && defined(GOLDEN_PAIR)
/* An affine region header's two-instrument ticks and surface pairs. */
static uint32_t run_pair(void)
{
    const tfit_golden_pair *g = GOLDEN_PAIR;
    const uint32_t n = out_words(g->surf->n_out);
    (void)tfit_model_check(g->law); /* starts the pair ticks' set in a trace */
    const uint32_t bad = tfit_golden_run_pair(g, scratch.f);
    if (bad != 0u) {
        report_set("two instruments", 0u, 1, bad);
    }
    report("two instruments", bad == 0u, bad != 0u, g->n_tick + g->n_surf,
           g->n_tick * 7u + g->n_surf * (n + 1u));
    return bad != 0u;
}
#endif

int main(void)
{
    uint32_t failed = 0u;
#ifdef GOLDEN_SETS
    failed += run_float();
#endif
#if defined(GOLDEN_SETS) && defined(GOLDEN_PAIR)
    failed += run_pair();
#endif
#ifdef GOLDEN_Q31_SETS
    failed += run_q31();
#endif
    return failed == 0u ? 0 : 1;
}
