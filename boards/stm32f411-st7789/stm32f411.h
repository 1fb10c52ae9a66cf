/* stm32f411.h: the STM32F411 registers this board uses, and only those, named and
 * spelled as the reference manual RM0383 names them. Addresses: RM0383 §2.3 (memory
 * map, register boundary addresses); offsets and bits: the register section of each
 * peripheral's chapter, given with each group. Written for tarn, not taken from a
 * vendor header. */
#ifndef TARN_STM32F411_H
#define TARN_STM32F411_H

#include <stdint.h>

#define STM32_REG(address) (*(volatile uint32_t *)(uintptr_t)(address))

/* Embedded flash interface, RM0383 §3.8 (FLASH_ACR) */
#define FLASH_ACR STM32_REG(0x40023C00u)
#define FLASH_ACR_LATENCY_Pos 0u /* wait states, bits 3:0 */
#define FLASH_ACR_LATENCY_Msk (0xFu << FLASH_ACR_LATENCY_Pos)
#define FLASH_ACR_PRFTEN (1u << 8)
#define FLASH_ACR_ICEN (1u << 9)
#define FLASH_ACR_DCEN (1u << 10)

/* Power controller, RM0383 §5.4 (PWR_CR, PWR_CSR) */
#define PWR_CR STM32_REG(0x40007000u)
#define PWR_CR_VOS_Pos 14u /* regulator voltage scaling, bits 15:14; 0b11: scale 1 */
#define PWR_CR_VOS_Msk (3u << PWR_CR_VOS_Pos)
#define PWR_CSR STM32_REG(0x40007004u)
#define PWR_CSR_VOSRDY (1u << 14)

/* Reset and clock control, RM0383 §6.3 */
#define RCC_BASE 0x40023800u
#define RCC_CR STM32_REG(RCC_BASE + 0x00u)
#define RCC_CR_HSION (1u << 0)
#define RCC_CR_HSIRDY (1u << 1)
#define RCC_CR_PLLON (1u << 24)
#define RCC_CR_PLLRDY (1u << 25)
#define RCC_PLLCFGR STM32_REG(RCC_BASE + 0x04u)
#define RCC_PLLCFGR_PLLM_Pos 0u  /* bits 5:0, 2..63 */
#define RCC_PLLCFGR_PLLN_Pos 6u  /* bits 14:6, 50..432 */
#define RCC_PLLCFGR_PLLP_Pos 16u /* bits 17:16: 0b00 /2, 0b01 /4, 0b10 /6, 0b11 /8 */
#define RCC_PLLCFGR_PLLSRC (1u << 22) /* 0: HSI */
#define RCC_PLLCFGR_PLLQ_Pos 24u /* bits 27:24, 2..15 */
#define RCC_CFGR STM32_REG(RCC_BASE + 0x08u)
#define RCC_CFGR_SW_Pos 0u  /* bits 1:0: 0b00 HSI, 0b01 HSE, 0b10 PLL */
#define RCC_CFGR_SW_Msk (3u << RCC_CFGR_SW_Pos)
#define RCC_CFGR_SWS_Pos 2u /* bits 3:2, the clock in use, same coding */
#define RCC_CFGR_SWS_Msk (3u << RCC_CFGR_SWS_Pos)
#define RCC_CFGR_SW_PLL 2u
#define RCC_CFGR_HPRE_Pos 4u   /* AHB prescaler, bits 7:4; 0: /1 */
#define RCC_CFGR_PPRE1_Pos 10u /* APB1 prescaler, bits 12:10; 0b100: /2 */
#define RCC_CFGR_PPRE2_Pos 13u /* APB2 prescaler, bits 15:13; 0: /1 */
#define RCC_AHB1ENR STM32_REG(RCC_BASE + 0x30u)
#define RCC_AHB1ENR_GPIOAEN (1u << 0)
#define RCC_AHB1ENR_GPIOBEN (1u << 1)
#define RCC_AHB1ENR_DMA2EN (1u << 22)
#define RCC_APB1ENR STM32_REG(RCC_BASE + 0x40u)
#define RCC_APB1ENR_PWREN (1u << 28)
#define RCC_APB2ENR STM32_REG(RCC_BASE + 0x44u)
#define RCC_APB2ENR_SPI1EN (1u << 12)

/* General-purpose I/Os, RM0383 §8.4: two bits per pin in MODER, OSPEEDR and PUPDR,
 * four per pin in AFRL (pins 0..7) and AFRH (8..15); BSRR sets a pin with bit n and
 * resets it with bit n + 16, in one write. */
#define GPIOA_BASE 0x40020000u
#define GPIOB_BASE 0x40020400u
#define GPIO_MODER(base) STM32_REG((base) + 0x00u)
#define GPIO_OSPEEDR(base) STM32_REG((base) + 0x08u)
#define GPIO_BSRR(base) STM32_REG((base) + 0x18u)
#define GPIO_AFRL(base) STM32_REG((base) + 0x20u)
#define GPIO_MODER_OUTPUT 1u
#define GPIO_MODER_AF 2u
#define GPIO_OSPEEDR_HIGH 2u
#define GPIO_AF5_SPI1 5u /* RM0383 §8.3.2 and the datasheet's alternate function table */

/* Serial peripheral interface SPI1, RM0383 §20.5 */
#define SPI1_BASE 0x40013000u
#define SPI1_CR1 STM32_REG(SPI1_BASE + 0x00u)
#define SPI_CR1_CPHA (1u << 0)
#define SPI_CR1_CPOL (1u << 1)
#define SPI_CR1_MSTR (1u << 2)
#define SPI_CR1_BR_Pos 3u /* bits 5:3: f_PCLK / 2^(BR+1) */
#define SPI_CR1_SPE (1u << 6)
#define SPI_CR1_SSI (1u << 8)
#define SPI_CR1_SSM (1u << 9)
#define SPI_CR1_BIDIOE (1u << 14)
#define SPI_CR1_BIDIMODE (1u << 15)
#define SPI1_CR2 STM32_REG(SPI1_BASE + 0x04u)
#define SPI_CR2_TXDMAEN (1u << 1)
#define SPI1_SR STM32_REG(SPI1_BASE + 0x08u)
#define SPI_SR_TXE (1u << 1)
#define SPI_SR_BSY (1u << 7)
#define SPI1_DR_ADDRESS (SPI1_BASE + 0x0Cu)

/* DMA controller DMA2, RM0383 §9.5. Stream x's registers start at 0x10 + 0x18 * x.
 * SPI1_TX is request channel 3 of stream 3 (or 5): RM0383 §9.3.3, the DMA2 request
 * mapping table. Stream 3's flags are bits 22..27 of LISR, cleared through LIFCR. */
#define DMA2_BASE 0x40026400u
#define DMA2_LISR STM32_REG(DMA2_BASE + 0x00u)
#define DMA2_LIFCR STM32_REG(DMA2_BASE + 0x08u)
#define DMA_STREAM3_FEIF (1u << 22)
#define DMA_STREAM3_DMEIF (1u << 24)
#define DMA_STREAM3_TEIF (1u << 25)
#define DMA_STREAM3_HTIF (1u << 26)
#define DMA_STREAM3_TCIF (1u << 27)
#define DMA_STREAM3_ALL_FLAGS (DMA_STREAM3_FEIF | DMA_STREAM3_DMEIF | DMA_STREAM3_TEIF | \
                               DMA_STREAM3_HTIF | DMA_STREAM3_TCIF)
#define DMA2_S3CR STM32_REG(DMA2_BASE + 0x10u + 0x18u * 3u)
#define DMA2_S3NDTR STM32_REG(DMA2_BASE + 0x14u + 0x18u * 3u)
#define DMA2_S3PAR STM32_REG(DMA2_BASE + 0x18u + 0x18u * 3u)
#define DMA2_S3M0AR STM32_REG(DMA2_BASE + 0x1Cu + 0x18u * 3u)
#define DMA2_S3FCR STM32_REG(DMA2_BASE + 0x24u + 0x18u * 3u)
#define DMA_SxCR_EN (1u << 0)
#define DMA_SxCR_DIR_M2P (1u << 6) /* DIR bits 7:6 = 0b01, memory to peripheral */
#define DMA_SxCR_MINC (1u << 10)
#define DMA_SxCR_PL_HIGH (2u << 16)
#define DMA_SxCR_CHSEL_Pos 25u /* bits 27:25 */

#endif
