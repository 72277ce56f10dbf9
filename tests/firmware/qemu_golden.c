/*
 * qemu_golden.c — runs every golden set of one generated header on the
 * device (QEMU mps2 boards, semihosting) and prints
 *   LABEL: N passed, M failed (V vectors, W words)
 * Exit status 0 only when every model passes its check and every word of
 * every golden vector matches the host's bits.
 *
 * Compiled per header and core with -DGOLDEN_H='"NAME_golden.h"',
 * -DGOLDEN_SETS=TFIT_NAME_GOLDEN_SETS, -DTFIT_NAME_IMPLEMENTATION and
 * -DLABEL='"NAME/core"'.
 */
#include "semihost.h"
#include "startup.h"

#include GOLDEN_H

#define SCRATCH_FLOATS (3u * 8192u)

static float scratch[SCRATCH_FLOATS];

static void report_set(uint32_t i, tfit_status st, uint32_t bad)
{
    semihost_puts(LABEL ": set ");
    semihost_put_u32(i);
    semihost_puts(st == TFIT_OK ? ": " : ": model check failed, ");
    semihost_put_u32(bad);
    semihost_puts(" mismatching words\n");
}

int main(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const uint32_t n_sets = (uint32_t)(sizeof sets / sizeof sets[0]);
    uint32_t passed = 0u, vectors = 0u, words = 0u;

    for (uint32_t i = 0u; i < n_sets; ++i) {
        const tfit_golden *g = sets[i];
        const uint32_t n = 3u * g->model->n_out;
        if (n > SCRATCH_FLOATS) {
            board_fail(LABEL ": model too large for the runner's scratch buffer");
        }
        tfit_status st = tfit_model_check(g->model);
        uint32_t bad = tfit_golden_run(g, scratch);
        vectors += g->n_vec;
        words += g->n_vec * (n + 1u);
        if (st == TFIT_OK && bad == 0u) {
            ++passed;
        } else {
            report_set(i, st, bad);
        }
    }
    semihost_puts(LABEL ": ");
    semihost_put_u32(passed);
    semihost_puts(" passed, ");
    semihost_put_u32(n_sets - passed);
    semihost_puts(" failed (");
    semihost_put_u32(vectors);
    semihost_puts(" vectors, ");
    semihost_put_u32(words);
    semihost_puts(" words); stack used ");
    semihost_put_u32(startup_stack_used());
    semihost_puts(" bytes\n");
    return passed == n_sets ? 0 : 1;
}
