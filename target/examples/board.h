/*
 * board.h — what the haptic loop (haptic_loop.c) needs from a board.  One
 * implementation per target: board_stm32.c (Cortex-M4F/M7 parts, SysTick
 * servo tick), board_qemu.c (the QEMU mps2 boards, a scripted trajectory),
 * board_native.c (a host program, the same trajectory).
 */
#ifndef HAPTIC_BOARD_H
#define HAPTIC_BOARD_H

#include <stdint.h>

void board_init(void);

/* Blocks until the next servo period starts; returns 0 when the run ends. */
int board_wait_tick(void);

/* The force the user applies to the probe [N] (a force sensor). */
void board_read_force(float force[3]);

/* The probe's displacement at the contact site [mm], for an impedance loop
 * (used only when the header has a contact model but no forward model). */
void board_read_position(float disp[3]);

/* Results of one tick: the surface displacements [mm] (3 per output point)
 * for the graphics side, the force the actuator must render [N], and the
 * evaluation status (tfit_status; negative: input rejected). */
void board_publish(const float *u, uint32_t n_points, const float contact_force[3], int status);

/* After the last tick; returns main()'s exit status. */
int board_finish(void);

/* Fatal error: report it and stop (never returns). */
void board_fail(const char *why) __attribute__((noreturn));

#endif /* HAPTIC_BOARD_H */
