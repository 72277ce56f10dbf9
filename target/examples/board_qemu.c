/*
 * board_qemu.c — the haptic loop on the QEMU mps2 boards: the scripted
 * trajectory instead of a sensor, a summary over semihosting at the end
 * (board_fail and the exit status: linker/semihost.c).
 */
#include "board.h"
#include "haptic_loop.h"
#include "haptic_script.h"
#include "semihost.h"
#include "startup.h"

static uint32_t tick_no, ok, clamped, rejected;
static uint32_t zero_outputs_when_rejected = 1u;

void board_init(void)
{
    tick_no = 0u;
}

int board_wait_tick(void)
{
    return tick_no < HAPTIC_SCRIPT_TICKS;
}

void board_read_force(float force[3])
{
    haptic_script_force(tick_no, force);
}

void board_read_position(float disp[3])
{
    haptic_script_position(tick_no, disp);
}

void board_publish(const float *u, uint32_t n_points, const float contact_force[3], int status)
{
    if (status < 0) {
        ++rejected;
        for (uint32_t i = 0u; i < 3u * n_points; ++i) {
            zero_outputs_when_rejected &= u[i] == 0.0f;
        }
    } else if (status == 1) {
        ++clamped;
    } else {
        ++ok;
    }
    (void)contact_force;
    ++tick_no;
}

int board_finish(void)
{
    semihost_puts("haptic loop: ");
    semihost_put_u32(tick_no);
    semihost_puts(" ticks, ");
    semihost_put_u32(ok);
    semihost_puts(" in the envelope, ");
    semihost_put_u32(clamped);
    semihost_puts(" clamped, ");
    semihost_put_u32(rejected);
    semihost_puts(zero_outputs_when_rejected ? " rejected with zero outputs" : " rejected");
    semihost_puts("; stack used ");
    semihost_put_u32(startup_stack_used());
    semihost_puts(" bytes\n");
    return (rejected == 1u && clamped > 0u && zero_outputs_when_rejected) ? 0 : 1;
}
