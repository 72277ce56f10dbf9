/*
 * haptic_script.c — see haptic_script.h.  Piecewise linear, no libm.
 */
#include "haptic_script.h"

#define PRESS_END 300u
#define SWEEP_END 700u
#define RELEASE_END 900u
#define BEYOND_END 950u
#define GLITCH 950u
/* The forces below are for block48's 1 N envelope; -DHAPTIC_FORCE_SCALE=2.1f
 * scales them to a 2.1 N one (block48_nh, coeffs/demo.mk). */
#ifndef HAPTIC_FORCE_SCALE
#define HAPTIC_FORCE_SCALE 1.0f
#endif
#define DEPTH_N (0.8f * HAPTIC_FORCE_SCALE) /* normal force at full press */
#define SWEEP_N (0.5f * HAPTIC_FORCE_SCALE) /* lateral force amplitude */
/* ten times the envelope: beyond every shipped envelope (1 N, 2.1 N) even
 * unscaled, and clamped onto the same point as any push along -z beyond it */
#define BEYOND_N (10.0f * HAPTIC_FORCE_SCALE)
#define MM_PER_N 10.0f      /* position script: a soft spring */

static float ramp(uint32_t t, uint32_t t0, uint32_t t1)
{
    return (float)(t - t0) / (float)(t1 - t0);
}

static float quiet_nan(void)
{
    union {
        uint32_t u;
        float f;
    } v = {0x7fc00000u};
    return v.f;
}

#ifdef HAPTIC_SCRIPT_PRESS_HOLD
/* A creeping body's script (-DHAPTIC_SCRIPT_PRESS_HOLD): press in 200 ms,
 * hold 500 ms (the tissue creeps), release in 200 ms, rest 100 ms; a
 * little off-axis, inside the envelope. */
#define HOLD_FROM 200u
#define HOLD_TO 700u
#define REST_FROM 900u
void haptic_script_force(uint32_t t, float f[3])
{
    float s = 0.0f;
    if (t < HOLD_FROM) {
        s = ramp(t, 0u, HOLD_FROM);
    } else if (t < HOLD_TO) {
        s = 1.0f;
    } else if (t < REST_FROM) {
        s = 1.0f - ramp(t, HOLD_TO, REST_FROM);
    }
    f[0] = 0.2f * s;
    f[1] = -0.1f * s;
    f[2] = -DEPTH_N * s;
    (void)quiet_nan;
}
#else
void haptic_script_force(uint32_t t, float f[3])
{
    f[0] = 0.0f;
    f[1] = 0.0f;
    f[2] = 0.0f;
    if (t < PRESS_END) {
        f[2] = -DEPTH_N * ramp(t, 0u, PRESS_END);
    } else if (t < SWEEP_END) {
        float s = ramp(t, PRESS_END, SWEEP_END);
        f[0] = SWEEP_N * (2.0f * s - 1.0f);
        f[1] = 0.5f * SWEEP_N * (1.0f - 2.0f * s);
        f[2] = -DEPTH_N;
    } else if (t < RELEASE_END) {
        f[2] = -DEPTH_N * (1.0f - ramp(t, SWEEP_END, RELEASE_END));
    } else if (t < BEYOND_END) {
        f[2] = -BEYOND_N;
    } else if (t == GLITCH) {
        f[2] = quiet_nan();
    }
}
#endif

void haptic_script_position(uint32_t t, float d[3])
{
    haptic_script_force(t, d);
    d[0] = d[0] * MM_PER_N;
    d[1] = d[1] * MM_PER_N;
    d[2] = d[2] * MM_PER_N;
}
