/*
 * haptic_loop.h — configuration of the haptic-loop example.
 *
 * HAPTIC_SERVO_HZ       servo rate (default 1 kHz)
 * HAPTIC_BUDGET_PERCENT share of the servo period the model evaluations may
 *                       take; the rest belongs to sensing, control and
 *                       communication (default 50)
 * HAPTIC_CORE_M4F / HAPTIC_CORE_M7
 *                       build for an STM32F407-class (168 MHz) or
 *                       STM32H743-class (480 MHz) part: the budget is then
 *                       checked at compile time against the cycle estimates
 *                       the header carries (TFIT_NAME_CYCLES_M4F / _M7).
 */
#ifndef HAPTIC_LOOP_H
#define HAPTIC_LOOP_H

#ifndef HAPTIC_SERVO_HZ
#define HAPTIC_SERVO_HZ 1000u
#endif
#ifndef HAPTIC_BUDGET_PERCENT
#define HAPTIC_BUDGET_PERCENT 50u
#endif

#if defined(HAPTIC_CORE_M7)
#define HAPTIC_CORE_HZ 480000000u
#define HAPTIC_CYCLES_SUFFIX CYCLES_M7
#elif defined(HAPTIC_CORE_M4F)
#define HAPTIC_CORE_HZ 168000000u
#define HAPTIC_CYCLES_SUFFIX CYCLES_M4F
#endif

/* Ticks of the scripted runs (board_qemu.c, board_native.c). */
#define HAPTIC_SCRIPT_TICKS 1000u

#endif /* HAPTIC_LOOP_H */
