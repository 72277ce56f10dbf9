/*
 * tick_tu.c — a firmware file that states its servo period before
 * including a header with a prony model (check-prony-tick compiles it with
 * -DTFIT_TICK_NS=... or -DTFIT_TICK_US=...): it must compile for the
 * model's own tick and stop with the header's #error for any other.
 */
#include "haptic.h"

int tick_tu_models(void);

int tick_tu_models(void)
{
    return (int)TFIT_HAPTIC_CREEP_STATE_WORDS;
}
