/*
 * emit_budget.c — see emit_budget.h.  Cycle macros are integers (rounded
 * up) so that firmware can _Static_assert them against its servo budget.
 */
#include "emit/emit_budget.h"

#include <math.h>

#include "cost/cycles.h"

void tf_emit_budget_banner(FILE *f, const tf_family_cost *cost)
{
    const tf_cycles m4 = cost->m4f, m7 = cost->m7;
    fprintf(f,
            " *       %llu instructions; Cortex-M4F <= %.0f cycles (%.2f us at 168 MHz), "
            "Cortex-M7 ~%.0f (%.2f us at 480 MHz)\n",
            (unsigned long long)m4.instructions, ceil(m4.cycles), m4.cycles / 168.0,
            ceil(m7.cycles), m7.cycles / 480.0);
}

void tf_emit_budget_macros(FILE *f, const tf_family_cost *cost, const char *p)
{
    const tf_cycles m4 = cost->m4f, m7 = cost->m7;
    fprintf(f, "#define %s_INSNS_ARMV7EM %llu /* per call, gcc -O2 (docs/firmware.md) */\n", p,
            (unsigned long long)m4.instructions);
    fprintf(f, "#define %s_CYCLES_M4F %.0fu /* upper bound, zero-wait-state tables */\n", p,
            ceil(m4.cycles));
    fprintf(f, "#define %s_CYCLES_M4F_MIN %.0fu\n", p, ceil(m4.cycles_low));
    fprintf(f, "#define %s_US_M4F_168MHZ %.2f\n", p, m4.cycles / tf_core_mhz(TF_CORE_M4F));
    fprintf(f, "#define %s_CYCLES_M7 %.0fu /* estimate, +-30 %% */\n", p, ceil(m7.cycles));
    fprintf(f, "#define %s_US_M7_480MHZ %.2f\n", p, m7.cycles / tf_core_mhz(TF_CORE_M7));
}

/* Cycles of one tick: both models' upper bounds, and the tick's length. */
static void servo(const tf_model *fwd, const tf_model *con, unsigned hz, double *use,
                  double *tick)
{
    *use = ceil(tf_model_cycles(fwd, TF_CORE_M4F).cycles) +
           ceil(tf_model_cycles(con, TF_CORE_M4F).cycles);
    *tick = floor(tf_core_mhz(TF_CORE_M4F) * 1e6 / hz);
}

void tf_emit_servo_banner(FILE *f, const tf_model *fwd, const tf_model *con, unsigned hz)
{
    double use, tick;
    servo(fwd, con, hz, &use, &tick);
    fprintf(f,
            " * Servo budget: %u Hz on a Cortex-M4F at %.0f MHz is %.0f cycles a tick;\n"
            " * tfit_%s + tfit_%s take at most %.0f (%.2f %% of it).\n",
            hz, tf_core_mhz(TF_CORE_M4F), tick, fwd->name, con->name, use, 100 * use / tick);
}

void tf_emit_servo_macros(FILE *f, const char *prefix, const tf_model *fwd, const tf_model *con,
                          unsigned hz)
{
    double use, tick;
    servo(fwd, con, hz, &use, &tick);
    fprintf(f, "\n#define %s_SERVO_HZ %uu /* the haptic loop's rate */\n", prefix, hz);
    fprintf(f, "#define %s_SERVO_CYCLES_M4F %.0fu /* one tick at %.0f MHz */\n", prefix, tick,
            tf_core_mhz(TF_CORE_M4F));
    fprintf(f, "#define %s_TICK_CYCLES_M4F %.0fu /* forward + contact, upper bounds */\n", prefix,
            use);
}
