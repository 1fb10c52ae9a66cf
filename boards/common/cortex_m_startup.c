/* cortex_m_startup.c: the vector table, reset (stack paint, .data copy, .bss zero,
 * main, exit) and the SysTick counter, for ARMv6-M and ARMv7-M. The linker script
 * (cortex_m_sections.ld) provides the symbols; stack_peak.c reads the paint back. */
#include <stdint.h>
#include "cortex_m.h"
#include "board.h"
#include "stack_paint.h"

extern uint32_t __stack_limit[], __stack_top[];
extern uint32_t __data_load[], __data_start[], __data_end[], __bss_start[], __bss_end[];
int main(void);

void reset_handler(void) __attribute__((noreturn, used));
void reset_handler(void)
{
    /* Paint the stack below this function's own frame so that the deepest call
     * can be found afterwards, then lay out RAM as C expects. */
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (uint32_t *p = __stack_limit; p < sp - 16; p++) *p = STACK_PAINT;
    const uint32_t *src = __data_load;
    for (uint32_t *p = __data_start; p < __data_end; p++) *p = *src++;
    for (uint32_t *p = __bss_start; p < __bss_end; p++) *p = 0;
    board_exit(main());
}

/* A fault ends the run with a status that says so instead of hanging the test. */
static void fault_handler(void)
{
    board_exit(3);
}

static volatile uint32_t systick_wraps;

static void systick_handler(void)
{
    systick_wraps++;
}

typedef void (*vector)(void);

__attribute__((section(".vectors"), used))
static const vector vectors[16] = {
    (vector)(uintptr_t)__stack_top,
    reset_handler,
    fault_handler, /* NMI */
    fault_handler, /* HardFault */
    fault_handler, /* MemManage (ARMv7-M) */
    fault_handler, /* BusFault (ARMv7-M) */
    fault_handler, /* UsageFault (ARMv7-M) */
    0, 0, 0, 0,
    fault_handler, /* SVCall */
    0, 0,
    fault_handler, /* PendSV */
    systick_handler
};

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define ICSR_PENDSTSET (1u << 26)
#define SYST_PERIOD 0x01000000u

void systick_start(void)
{
    SYST_CSR = 0;
    systick_wraps = 0;
    SYST_RVR = SYST_PERIOD - 1u;
    SYST_CVR = 0;                /* any write clears it; it reloads on the next tick */
    SYST_CSR = 7;                /* enable, interrupt on wrap, processor clock */
    while (SYST_CVR == 0) {}     /* loaded: from here every wrap raises the interrupt */
}

/* The counter runs PERIOD-1 .. 0 and raises the interrupt as it reaches 0, so a
 * value of 0 already belongs to the next period; a wrap whose interrupt is still
 * pending counts too. Reads repeat until the wrap count, the pending bit and the
 * value agree. */
uint64_t systick_ticks(void)
{
    uint32_t wraps, pending, value;
    do {
        wraps = systick_wraps;
        pending = SCB_ICSR & ICSR_PENDSTSET;
        value = SYST_CVR;
    } while (wraps != systick_wraps || pending != (SCB_ICSR & ICSR_PENDSTSET));
    if (pending) wraps++;
    return ((uint64_t)wraps + 1u) * SYST_PERIOD - (value == 0 ? SYST_PERIOD : value);
}
