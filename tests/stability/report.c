/*
 * report.c — one line per model and form for the invariant runs.
 */
#include <stdio.h>

#include "invariants.h"

void stab_print(int q31, const char *label, const stab_stats *st, double tol, double seconds)
{
    const char *unit = q31 ? "LSB" : "ulps";
    printf("%-44s %8llu inputs: %llu ok, %llu clamped, %llu NaN/Inf; worst clamp %.3g %s "
           "(tolerance %.3g)",
           label, (unsigned long long)st->n, (unsigned long long)st->ok,
           (unsigned long long)st->clamped, (unsigned long long)st->bad_input, st->worst, unit,
           tol);
    if (st->worst > 0) {
        if (q31) {
            printf(" at {%d, %d, %d}", (int)st->worst_in[0], (int)st->worst_in[1],
                   (int)st->worst_in[2]);
        } else {
            printf(" at bits {%08x %08x %08x}", st->worst_in[0], st->worst_in[1], st->worst_in[2]);
        }
    }
    if (st->sensitive > 0) {
        printf("; %llu within the projection allowance (worst %.2f of its tolerance)",
               (unsigned long long)st->sensitive, st->worst_ratio);
    }
    if (st->unasserted > 0) {
        printf("; %llu beyond it from a modal_q15 that saturates inside its envelope (continuity "
               "not asserted)",
               (unsigned long long)st->unasserted);
    }
    printf("; %.2f s%s\n", seconds, st->failures ? "  FAILED" : "");
}
