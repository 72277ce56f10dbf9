/*
 * semihost.h — Arm semihosting for the QEMU images: text to the host's
 * console and the exit status of the run (QEMU with
 * -semihosting-config enable=on,target=native).  Also the board hooks of
 * startup.h for QEMU.
 */
#ifndef TFIT_SEMIHOST_H
#define TFIT_SEMIHOST_H

#include <stdint.h>

void semihost_puts(const char *s);
/* Decimal, without a division (ARMv6-M has no divide instruction). */
void semihost_put_u32(uint32_t v);
/* Ends the QEMU process with this exit status. */
void semihost_exit(int status) __attribute__((noreturn));

#endif /* TFIT_SEMIHOST_H */
