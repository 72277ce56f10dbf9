/*
 * fpscr_reject.c — negative test of the startup FPU check: sets one
 * non-IEEE bit (flush-to-zero in FPSCR, or default-NaN in FPDSCR with
 * -DPOKE_FPDSCR) and runs startup_check_fpu() again.  The check must stop
 * the image through board_fail() (exit status 3 under QEMU); reaching the
 * end means the check let a wrong FPU state through.
 */
#include <stdint.h>

#include "semihost.h"
#include "startup.h"

int main(void)
{
#ifdef POKE_FPDSCR
    *(volatile uint32_t *)0xe000ef3cu |= 1u << 25; /* FPDSCR.DN */
#else
    uint32_t fpscr;
    __asm__ volatile("vmrs %0, fpscr" : "=r"(fpscr));
    fpscr |= 1u << 24; /* FPSCR.FZ */
    __asm__ volatile("vmsr fpscr, %0" : : "r"(fpscr));
#endif
    startup_check_fpu();
    semihost_puts("fpscr_reject: startup_check_fpu() accepted a non-IEEE FPU state\n");
    return 0;
}
