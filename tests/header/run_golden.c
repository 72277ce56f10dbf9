/*
 * run_golden.c — runs the golden vectors of one generated header through the
 * target library this binary is linked with.  Compiled once per header and
 * per compiler configuration with
 *   -DGOLDEN_H='"NAME_golden.h"' -DGOLDEN_SETS=TFIT_NAME_GOLDEN_SETS
 *   -DTFIT_NAME_IMPLEMENTATION
 * and optionally -DGOLDEN_Q31_SETS=TFIT_NAME_GOLDEN_Q31_SETS (the Q31 forms'
 * vectors too) and -DGOLDEN_PAIR=TFIT_NAME_GOLDEN_PAIR (an affine region
 * header's two-instrument vectors).  Prints "N passed, M failed" (sets of vectors) and exits
 * non-zero on any mismatch or failed model check.
 */
#include <stdio.h>
#include <stdlib.h>

#include GOLDEN_H

int main(int argc, char **argv)
{
    static const tfit_golden *const sets[] = GOLDEN_SETS;
    const char *label = argc > 1 ? argv[1] : "golden";
    unsigned passed = 0, failed = 0;
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; ++i) {
        const tfit_golden *g = sets[i];
        float *scratch = malloc(3 * g->model->n_out * sizeof *scratch);
        tfit_status st = tfit_model_check(g->model);
        uint32_t bad = tfit_golden_run(g, scratch);
        free(scratch);
        if (st != TFIT_OK || bad != 0) {
            fprintf(stderr, "%s: set %zu: model check %d, %u mismatching words\n", label, i,
                    (int)st, bad);
            failed++;
        } else {
            passed++;
        }
    }
#ifdef GOLDEN_Q31_SETS
    static const tfit_golden_q31 *const q31[] = GOLDEN_Q31_SETS; /* null-terminated */
    for (size_t i = 0; q31[i] != NULL; ++i) {
        int32_t *scratch = malloc(3 * q31[i]->model->n_out * sizeof *scratch);
        tfit_status st = tfit_model_check_q31(q31[i]->model);
        uint32_t bad = tfit_golden_run_q31(q31[i], scratch);
        free(scratch);
        if (st != TFIT_OK || bad != 0) {
            fprintf(stderr, "%s: q31 set %zu: model check %d, %u mismatching words\n", label, i,
                    (int)st, bad);
            failed++;
        } else {
            passed++;
        }
    }
#endif
#ifdef GOLDEN_PAIR
    {
        const tfit_golden_pair *g = GOLDEN_PAIR;
        float *scratch = malloc(3 * g->surf->n_out * sizeof *scratch);
        uint32_t bad = tfit_golden_run_pair(g, scratch);
        free(scratch);
        if (bad != 0) {
            fprintf(stderr, "%s: two instruments: %u mismatching words\n", label, bad);
            failed++;
        } else {
            passed++;
        }
    }
#endif
    printf("%-16s %u passed, %u failed\n", label, passed, failed);
    return failed == 0 ? 0 : 1;
}
