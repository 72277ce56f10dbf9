/*
 * semihost.c — Arm semihosting calls (the "Semihosting for AArch32 and
 * AArch64" specification: BKPT 0xAB on M-profile, operation in r0, argument
 * block in r1), and the QEMU board's startup hooks.
 */
#include "semihost.h"

#include "startup.h"

#define SYS_WRITE0 0x04u
#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

static uint32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void semihost_puts(const char *s)
{
    semihost_call(SYS_WRITE0, s);
}

void semihost_put_u32(uint32_t v)
{
    static const uint32_t powers[] = {1000000000u, 100000000u, 10000000u, 1000000u, 100000u,
                                      10000u, 1000u, 100u, 10u, 1u};
    char buf[11];
    uint32_t n = 0u;
    for (uint32_t i = 0u; i < 10u; ++i) {
        char digit = '0';
        while (v >= powers[i]) {
            v -= powers[i];
            ++digit;
        }
        if (digit != '0' || n > 0u || i == 9u) {
            buf[n++] = digit;
        }
    }
    buf[n] = '\0';
    semihost_puts(buf);
}

void semihost_exit(int status)
{
    /* SYS_EXIT_EXTENDED carries the status on 32-bit targets too. */
    const uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    semihost_call(SYS_EXIT_EXTENDED, block);
    for (;;) {
    }
}

void board_fail(const char *why)
{
    semihost_puts(why);
    semihost_puts("\n");
    semihost_exit(3);
}

void board_exit(int status)
{
    semihost_exit(status);
}
