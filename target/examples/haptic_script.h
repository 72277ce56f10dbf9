/*
 * haptic_script.h — the scripted probe trajectory of the QEMU and native
 * runs of the haptic loop: HAPTIC_SCRIPT_TICKS ticks of press, lateral
 * sweep and release inside a 1 N envelope, then a push far beyond it
 * (projected onto the envelope: status TFIT_CLAMPED) and one sensor glitch
 * (NaN: TFIT_ERR_INPUT, zero outputs).
 */
#ifndef HAPTIC_SCRIPT_H
#define HAPTIC_SCRIPT_H

#include <stdint.h>

/* Force [N] at a tick. */
void haptic_script_force(uint32_t tick, float force[3]);

/* Ticks of the script the firmware must reject: the NaN glitch, none in
 * the creeping body's press-hold-release (-DHAPTIC_SCRIPT_PRESS_HOLD). */
#ifdef HAPTIC_SCRIPT_PRESS_HOLD
#define HAPTIC_SCRIPT_REJECTED 0u
#else
#define HAPTIC_SCRIPT_REJECTED 1u
#endif

/* Contact-site displacement [mm] at a tick (for contact-only headers). */
void haptic_script_position(uint32_t tick, float disp[3]);

#endif /* HAPTIC_SCRIPT_H */
