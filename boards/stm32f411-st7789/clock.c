/* clock.c: HSI -> PLL -> 100 MHz on the STM32F411, from RM0383:
 *
 * - 100 MHz needs the regulator's scale 1 (PWR_CR VOS = 0b11, RM0383 §5.1.3 and
 *   §5.4.1) and three flash wait states at 2.7-3.6 V (RM0383 §3.4.1, the table of
 *   wait states against HCLK: 3 WS for 90 < HCLK <= 100 MHz). The wait states are
 *   set, and read back, before the clock rises (RM0383 §3.4.2).
 * - The PLL (RM0383 §6.2.3 and §6.3.2): VCO input = 16 MHz / PLLM, which should be
 *   2 MHz to limit jitter, so PLLM = 8; VCO = 2 MHz * PLLN = 400 MHz with PLLN = 200
 *   (100..432 MHz allowed); SYSCLK = VCO / PLLP = 100 MHz with PLLP = 4. PLLQ = 8
 *   gives 50 MHz on the unused USB/SDIO output (it must not exceed 48 MHz only when
 *   USB is used).
 * - APB1 must stay at or under 50 MHz: /2. APB2 (SPI1) may run at 100 MHz: /1.
 *
 * Every wait is a bounded loop: a clock that does not come up makes board_init fail
 * (the board then resets) rather than hang. */
#include "clock.h"
#include "stm32f411.h"
#include "wait_for_bits.h"

#define PLLM 8u
#define PLLN 200u
#define PLLP_DIV4 1u
#define PLLQ 8u
#define FLASH_WAIT_STATES 3u
#define PPRE1_DIV2 4u

int clock_init(void)
{
    RCC_APB1ENR |= RCC_APB1ENR_PWREN;
    (void)RCC_APB1ENR; /* the clock is on before PWR is written */
    PWR_CR = (PWR_CR & ~PWR_CR_VOS_Msk) | (3u << PWR_CR_VOS_Pos);

    RCC_CR |= RCC_CR_HSION; /* on since reset; said again for a warm start */
    if (wait_for_bits(&RCC_CR, RCC_CR_HSIRDY, RCC_CR_HSIRDY) != 0) return 1;

    FLASH_ACR = FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN |
                (FLASH_WAIT_STATES << FLASH_ACR_LATENCY_Pos);
    if (wait_for_bits(&FLASH_ACR, FLASH_ACR_LATENCY_Msk,
                      FLASH_WAIT_STATES << FLASH_ACR_LATENCY_Pos) != 0)
        return 1;

    RCC_CR &= ~RCC_CR_PLLON; /* the PLL takes a new configuration only while off */
    if (wait_for_bits(&RCC_CR, RCC_CR_PLLRDY, 0) != 0) return 1;
    RCC_PLLCFGR = (PLLM << RCC_PLLCFGR_PLLM_Pos) | (PLLN << RCC_PLLCFGR_PLLN_Pos) |
                  (PLLP_DIV4 << RCC_PLLCFGR_PLLP_Pos) | (PLLQ << RCC_PLLCFGR_PLLQ_Pos);
    RCC_CR |= RCC_CR_PLLON;
    if (wait_for_bits(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY) != 0) return 1;
    /* VOSRDY: the regulator has reached scale 1, which it does once the PLL is on */
    if (wait_for_bits(&PWR_CSR, PWR_CSR_VOSRDY, PWR_CSR_VOSRDY) != 0) return 1;

    RCC_CFGR = (0u << RCC_CFGR_HPRE_Pos) | (PPRE1_DIV2 << RCC_CFGR_PPRE1_Pos) |
               (0u << RCC_CFGR_PPRE2_Pos) | (RCC_CFGR_SW_PLL << RCC_CFGR_SW_Pos);
    return wait_for_bits(&RCC_CFGR, RCC_CFGR_SWS_Msk, RCC_CFGR_SW_PLL << RCC_CFGR_SWS_Pos);
}
