/* cortex_m.h: what every Cortex-M board, emulated or real, shares: SysTick as an
 * extended counter. Startup is cortex_m_startup.c. */
#ifndef TARN_CORTEX_M_H
#define TARN_CORTEX_M_H

#include <stddef.h>
#include <stdint.h>

/* Starts SysTick on the processor clock, free-running over 2^24 ticks, with its
 * interrupt counting the wraps. */
void systick_start(void);
/* SysTick ticks since systick_start(), 64 bits wide. */
uint64_t systick_ticks(void);

#endif
