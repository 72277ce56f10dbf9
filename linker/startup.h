/*
 * startup.h — reset-time services of linker/startup.c and the two hooks a
 * board support file must provide.
 */
#ifndef TFIT_STARTUP_H
#define TFIT_STARTUP_H

#include <stdint.h>

/* Provided by the board (linker/semihost.c under QEMU, a real board's own
 * file on hardware).  Neither returns. */
void board_fail(const char *why) __attribute__((noreturn)); /* fatal: report, stop */
void board_exit(int status) __attribute__((noreturn));      /* main() returned */

/* Verifies the FPU state GUIDE §4 needs for bit-exact float32: FPSCR (and
 * FPDSCR, the FPSCR every exception handler starts with) round to nearest,
 * flush-to-zero off, default-NaN off.  Calls board_fail() otherwise.  Run by
 * Reset_Handler before main(); callable again, e.g. after an RTOS or a
 * vendor HAL touched the FPU.  Only exists in builds with an FPU. */
void startup_check_fpu(void);

/* Bytes of the main stack ever used since reset: the stack is painted with a
 * pattern before main(), this finds the deepest overwritten word. */
uint32_t startup_stack_used(void);

#endif /* TFIT_STARTUP_H */
