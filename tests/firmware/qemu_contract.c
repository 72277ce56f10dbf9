/*
 * qemu_contract.c — the boot check against a library whose float arithmetic
 * is not the host's (issue 19): linked with a libtfit built so that GCC
 * contracts a*b + c into VFMA, every float model of one header is checked
 * with tfit_model_check() and run over its golden vectors.  Prints
 *   LABEL: N models, K give other bits: C caught (TFIT_ERR_ARITH), M missed;
 *   R more refused (TFIT_ERR_ARITH) whose golden vectors happen to pass
 * and exits 0 only when some model gives other bits and every such model is
 * caught, and every refusal is TFIT_ERR_ARITH.  R counts models whose
 * outputs do not depend on the arithmetic that changed (p = 0: the
 * projection's result is not used), refused all the same: the build is
 * not the host's arithmetic, which is what the status says.  (That a build
 * with the host's arithmetic passes every check is check-qemu's part.)
 *
 * Compiled like qemu_golden.c (-DGOLDEN_H, -DGOLDEN_SETS,
 * -DTFIT_NAME_IMPLEMENTATION, -DLABEL).
 */
#include "semihost.h"
#include "startup.h"

#include GOLDEN_H

#define SCRATCH_WORDS (3u * 8192u)

static float scratch[SCRATCH_WORDS];

static void put(const char *label, uint32_t v)
{
    semihost_puts(label);
    semihost_put_u32(v);
}

int main(void)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const uint32_t n_sets = (uint32_t)(sizeof sets / sizeof sets[0]);
    uint32_t differ = 0u, caught = 0u, missed = 0u, refused = 0u, other = 0u;
    for (uint32_t i = 0u; i < n_sets; ++i) {
        const tfit_golden *g = sets[i];
        if (3u * g->model->n_out > SCRATCH_WORDS) {
            board_fail(LABEL ": model too large for the runner's scratch buffer");
        }
        const tfit_status st = tfit_model_check(g->model);
        const uint32_t bad = tfit_golden_run(g, scratch);
        if (bad != 0u && st != TFIT_ERR_ARITH) {
            put(LABEL ": missed set ", i);
            put(" (status ", (uint32_t)st);
            put(", mismatching words ", bad);
            semihost_puts(")\n");
        }
        differ += bad != 0u;
        caught += bad != 0u && st == TFIT_ERR_ARITH;
        missed += bad != 0u && st != TFIT_ERR_ARITH;
        refused += bad == 0u && st == TFIT_ERR_ARITH;
        other += st != TFIT_OK && st != TFIT_ERR_ARITH;
    }
    semihost_puts(LABEL);
    put(": ", n_sets);
    put(" models, ", differ);
    put(" give other bits: ", caught);
    put(" caught (TFIT_ERR_ARITH), ", missed);
    put(" missed; ", refused);
    semihost_puts(" more refused whose golden vectors happen to pass");
    if (other != 0u) {
        put("; other statuses: ", other);
    }
    semihost_puts("\n");
    return (differ > 0u && missed == 0u && other == 0u) ? 0 : 1;
}
