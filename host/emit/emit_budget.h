/*
 * emit_budget.h — the firmware budget of a model in its generated header:
 * instructions, estimated cycles and microseconds per evaluation on
 * Cortex-M4F and Cortex-M7 (the family's cost: host/cost/cycles.c,
 * docs/firmware.md).  Called by emit_header.c for every model.
 */
#ifndef TF_EMIT_BUDGET_H
#define TF_EMIT_BUDGET_H

#include <stdio.h>

#include "fitting/families/family.h"

/* Banner line(s) for the model's header comment. */
void tf_emit_budget_banner(FILE *f, const tf_family_cost *cost);

/* The macros, prefix = "TFIT_" + upper-case model name:
 *   PREFIX_INSNS_ARMV7EM       instructions per call (arm-none-eabi-gcc -O2)
 *   PREFIX_CYCLES_M4F          upper bound, zero-wait-state memory
 *   PREFIX_CYCLES_M4F_MIN      the same stream at the fast end of each range
 *   PREFIX_US_M4F_168MHZ       PREFIX_CYCLES_M4F at 168 MHz
 *   PREFIX_CYCLES_M7           dual-issue model, +-30 %
 *   PREFIX_US_M7_480MHZ */
void tf_emit_budget_macros(FILE *f, const tf_family_cost *cost, const char *prefix);

/* The servo budget of a haptic loop at hz on a Cortex-M4F at 168 MHz
 * against the forward model and the contact inverse evaluated once each per
 * tick: a banner line and macros TFIT_<BASE>_SERVO_HZ,
 * _SERVO_CYCLES_M4F (one tick) and _TICK_CYCLES_M4F (both models' bound). */
void tf_emit_servo_banner(FILE *f, const tf_model *fwd, const tf_model *con, unsigned hz);
void tf_emit_servo_macros(FILE *f, const char *prefix, const tf_model *fwd, const tf_model *con,
                          unsigned hz);

#endif /* TF_EMIT_BUDGET_H */
