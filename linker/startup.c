/*
 * startup.c — reset handler and vector table for the Cortex-M images
 * (M0+/M3 without an FPU, M4F, M7), used with the scripts in linker/.
 *
 * Order at reset, before any other code runs:
 *   1. enable the FPU (CPACR CP10/CP11 full access) — first, because any
 *      float instruction before that faults (NOCP usage fault);
 *   2. copy .fast_text (the evaluator, to ITCM where the script says so),
 *      .fast_rodata (the model tables, to CCM/DTCM) and .data from their
 *      load addresses, zero .bss, paint the unused stack;
 *   3. check that the FPU exists and that FPSCR and FPDSCR hold the IEEE
 *      defaults the bit-exact contract needs (GUIDE §4);
 *   4. main(), then board_exit(status).
 * The copy loops write through volatile pointers so that the compiler
 * cannot turn them into memcpy/memset calls: the images link without libc.
 */
#include "startup.h"

extern uint32_t __fast_text_start[], __fast_text_end[], __fast_text_load[];
extern uint32_t __fast_rodata_start[], __fast_rodata_end[], __fast_rodata_load[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_limit[], __stack_top[];

int main(void);
void Reset_Handler(void);

#define STACK_PAINT 0x5afe57acu

#define SCB_CPACR ((volatile uint32_t *)0xe000ed88u)
#define CPACR_CP10_CP11 (0xfu << 20) /* full access to the FPU coprocessors */
#define FPU_FPDSCR ((volatile uint32_t *)0xe000ef3cu)
/* FPSCR/FPDSCR: RMode [23:22] (00 = nearest), FZ [24], DN [25]. */
#define FPSCR_NOT_IEEE ((3u << 22) | (1u << 24) | (1u << 25))

static void copy_words(volatile uint32_t *dst, const uint32_t *src, const uint32_t *end)
{
    if ((const uint32_t *)dst == src) {
        return; /* section runs where it is loaded (flash): nothing to copy */
    }
    while ((const uint32_t *)dst < end) {
        *dst++ = *src++;
    }
}

static void fill_words(volatile uint32_t *dst, const uint32_t *end, uint32_t value)
{
    while ((const uint32_t *)dst < end) {
        *dst++ = value;
    }
}

static inline uint32_t *stack_pointer(void)
{
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

#if defined(__ARM_FP)
void startup_check_fpu(void)
{
    uint32_t fpscr;
    __asm__ volatile("vmrs %0, fpscr" : "=r"(fpscr));
    if ((fpscr & FPSCR_NOT_IEEE) != 0u) {
        board_fail("startup: FPSCR is not round-to-nearest with flush-to-zero and default-NaN "
                   "off: float results would differ from the host's golden bits");
    }
    if ((*FPU_FPDSCR & FPSCR_NOT_IEEE) != 0u) {
        board_fail("startup: FPDSCR (the FPSCR of exception handlers) is not round-to-nearest "
                   "with flush-to-zero and default-NaN off");
    }
}
#endif

uint32_t startup_stack_used(void)
{
    const uint32_t *p = __stack_limit;
    while (p < __stack_top && *p == STACK_PAINT) {
        ++p;
    }
    return (uint32_t)((__stack_top - p) * (int)sizeof *p);
}

void Reset_Handler(void)
{
#if defined(__ARM_FP)
    *SCB_CPACR |= CPACR_CP10_CP11;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    copy_words(__fast_text_start, __fast_text_load, __fast_text_end);
    copy_words(__fast_rodata_start, __fast_rodata_load, __fast_rodata_end);
    copy_words(__data_start, __data_load, __data_end);
    fill_words(__bss_start, __bss_end, 0u);
    /* Leave 64 bytes under the current frame alone. */
    fill_words(__stack_limit, stack_pointer() - 16, STACK_PAINT);
    /* The copied code must be visible to instruction fetch before it runs. */
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#if defined(__ARM_FP)
    if ((*SCB_CPACR & CPACR_CP10_CP11) != CPACR_CP10_CP11) {
        board_fail("startup: this core has no FPU, but the image was built for one");
    }
    startup_check_fpu();
#endif
    board_exit(main());
}

static void fault_handler(void)
{
    board_fail("startup: processor fault (HardFault, MemManage, BusFault or UsageFault)");
}

static void unexpected_handler(void)
{
    board_fail("startup: unexpected exception (NMI, SVC, DebugMon or PendSV)");
}

/* SysTick is the one interrupt a board may use (the servo tick); a board
 * that does not enable it never takes it. */
void SysTick_Handler(void) __attribute__((weak, alias("unexpected_handler")));

typedef union vector {
    void (*handler)(void);
    const uint32_t *stack_top;
} vector;

/* The core exceptions of ARMv6-M/ARMv7-M (B1.5.2 of the ARMv7-M ARM). */
__attribute__((section(".vectors"), used)) const vector vector_table[16] = {
    {.stack_top = __stack_top},
    {.handler = Reset_Handler},
    {.handler = unexpected_handler}, /* NMI */
    {.handler = fault_handler},      /* HardFault */
    {.handler = fault_handler},      /* MemManage */
    {.handler = fault_handler},      /* BusFault */
    {.handler = fault_handler},      /* UsageFault */
    {0},
    {0},
    {0},
    {0},
    {.handler = unexpected_handler}, /* SVCall */
    {.handler = unexpected_handler}, /* DebugMonitor */
    {0},
    {.handler = unexpected_handler}, /* PendSV */
    {.handler = SysTick_Handler},
};
