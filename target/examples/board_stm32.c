/*
 * board_stm32.c — the haptic loop on an STM32F407 (HAPTIC_CORE_M4F) or
 * STM32H743 (HAPTIC_CORE_M7) with the linker scripts of linker/: SysTick
 * at HAPTIC_SERVO_HZ from the core clock, the loop in thread mode between
 * ticks (WFI).  No vendor HAL: the sensor and actuator are the two volatile
 * buffers below, which the integrator's drivers fill and read (an ADC DMA
 * interrupt, a DAC or PWM update).  Clock tree set-up (PLL to 168/480 MHz,
 * flash wait states, caches) belongs to the integrator's SystemInit.
 */
#include "board.h"
#include "haptic_loop.h"
#include "startup.h"

#ifndef HAPTIC_CORE_HZ
#error "board_stm32.c needs HAPTIC_CORE_M4F or HAPTIC_CORE_M7 (haptic_loop.h)"
#endif

#define SYST_CSR (*(volatile uint32_t *)0xe000e010u)
#define SYST_RVR (*(volatile uint32_t *)0xe000e014u)
#define SYST_CVR (*(volatile uint32_t *)0xe000e018u)
#define SYST_ENABLE_TICKINT_CORECLK 7u

/* Sensor input and actuator output, shared with the integrator's drivers. */
volatile float board_force_sensor[3];    /* N */
volatile float board_position_sensor[3]; /* mm */
volatile float board_actuator_force[3];  /* N */
volatile int32_t board_last_status;
/* Surface displacements for the graphics side: the loop writes them every
 * tick; a display task or DMA reads them. */
const float *volatile board_surface;
volatile uint32_t board_surface_points;

static volatile uint32_t ticks;

void SysTick_Handler(void)
{
    ++ticks;
}

void board_init(void)
{
    SYST_RVR = HAPTIC_CORE_HZ / HAPTIC_SERVO_HZ - 1u;
    SYST_CVR = 0u;
    SYST_CSR = SYST_ENABLE_TICKINT_CORECLK;
}

int board_wait_tick(void)
{
    const uint32_t seen = ticks;
    while (ticks == seen) {
        __asm__ volatile("wfi");
    }
    return 1; /* a servo loop runs until power-off */
}

void board_read_force(float force[3])
{
    for (int i = 0; i < 3; ++i) {
        force[i] = board_force_sensor[i];
    }
}

void board_read_position(float disp[3])
{
    for (int i = 0; i < 3; ++i) {
        disp[i] = board_position_sensor[i];
    }
}

void board_publish(const float *u, uint32_t n_points, const float contact_force[3], int status)
{
    for (int i = 0; i < 3; ++i) {
        board_actuator_force[i] = contact_force[i];
    }
    board_last_status = status;
    board_surface = u;
    board_surface_points = n_points;
}

int board_finish(void)
{
    return 0;
}

void board_fail(const char *why)
{
    (void)why; /* visible in a debugger: the halt below stops here */
    __asm__ volatile("bkpt 0");
    for (;;) {
    }
}

void board_exit(int status)
{
    (void)status;
    for (;;) {
        __asm__ volatile("wfi");
    }
}
