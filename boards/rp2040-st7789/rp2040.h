/* rp2040.h: the RP2040 registers this board uses, and only those, named as the
 * RP2040 datasheet names them (addresses: datasheet §2.2, the address map; offsets
 * and bits: each block's register list, given with each group). Written for tarn,
 * not taken from the Pico SDK's headers.
 *
 * Every peripheral register also has aliases that set (+0x2000) or clear (+0x3000)
 * the bits written, atomically (datasheet §2.1.2). */
#ifndef TARN_RP2040_H
#define TARN_RP2040_H

#include <stdint.h>

#define RP_REG(address) (*(volatile uint32_t *)(uintptr_t)(address))
#define RP_ALIAS_SET 0x2000u
#define RP_ALIAS_CLR 0x3000u

/* RESETS, datasheet §2.14: a block stays in reset until its bit is cleared, and is
 * usable once RESET_DONE shows the bit. */
#define RESETS_BASE 0x4000C000u
#define RESETS_RESET RP_REG(RESETS_BASE + 0x0u)
#define RESETS_RESET_CLR RP_REG(RESETS_BASE + RP_ALIAS_CLR + 0x0u)
#define RESETS_RESET_SET RP_REG(RESETS_BASE + RP_ALIAS_SET + 0x0u)
#define RESETS_RESET_DONE RP_REG(RESETS_BASE + 0x8u)
#define RESETS_DMA (1u << 2)
#define RESETS_IO_BANK0 (1u << 5)
#define RESETS_PADS_BANK0 (1u << 8)
#define RESETS_PLL_SYS (1u << 12)
#define RESETS_SPI0 (1u << 16)
#define RESETS_TIMER (1u << 21)

/* Crystal oscillator XOSC, datasheet §2.16 */
#define XOSC_BASE 0x40024000u
#define XOSC_CTRL RP_REG(XOSC_BASE + 0x00u)
#define XOSC_CTRL_FREQ_RANGE_1_15MHZ 0xAA0u /* bits 11:0 */
#define XOSC_CTRL_ENABLE_Pos 12u            /* bits 23:12 */
#define XOSC_CTRL_ENABLE_VALUE 0xFABu
#define XOSC_STATUS RP_REG(XOSC_BASE + 0x04u)
#define XOSC_STATUS_STABLE (1u << 31)
#define XOSC_STARTUP RP_REG(XOSC_BASE + 0x0Cu) /* DELAY, bits 13:0, in 256-cycle units */

/* System PLL, datasheet §2.18: FOUTVCO = FREF / REFDIV * FBDIV (400..1600 MHz),
 * output = FOUTVCO / (POSTDIV1 * POSTDIV2). */
#define PLL_SYS_BASE 0x40028000u
#define PLL_CS RP_REG(PLL_SYS_BASE + 0x0u)
#define PLL_CS_LOCK (1u << 31)
#define PLL_PWR RP_REG(PLL_SYS_BASE + 0x4u)
#define PLL_PWR_PD (1u << 0)
#define PLL_PWR_POSTDIVPD (1u << 3)
#define PLL_PWR_VCOPD (1u << 5)
#define PLL_FBDIV_INT RP_REG(PLL_SYS_BASE + 0x8u)
#define PLL_PRIM RP_REG(PLL_SYS_BASE + 0xCu)
#define PLL_PRIM_POSTDIV1_Pos 16u /* bits 18:16 */
#define PLL_PRIM_POSTDIV2_Pos 12u /* bits 14:12 */

/* CLOCKS, datasheet §2.15.7. A glitchless clock (clk_ref, clk_sys) switches its SRC
 * and reports the one it runs from, one-hot, in its _SELECTED register. */
#define CLOCKS_BASE 0x40008000u
#define CLK_REF_CTRL RP_REG(CLOCKS_BASE + 0x30u)
#define CLK_REF_CTRL_SRC_XOSC 2u /* SRC bits 1:0: xosc_clksrc */
#define CLK_REF_SELECTED RP_REG(CLOCKS_BASE + 0x38u)
#define CLK_SYS_CTRL RP_REG(CLOCKS_BASE + 0x3Cu)
#define CLK_SYS_CTRL_SRC_AUX 1u      /* SRC bit 0: 0 clk_ref, 1 clksrc_clk_sys_aux */
#define CLK_SYS_CTRL_AUXSRC_Pos 5u   /* bits 7:5: 0 clksrc_pll_sys */
#define CLK_SYS_CTRL_AUXSRC_Msk (7u << CLK_SYS_CTRL_AUXSRC_Pos)
#define CLK_SYS_SELECTED RP_REG(CLOCKS_BASE + 0x44u)
#define CLK_PERI_CTRL RP_REG(CLOCKS_BASE + 0x48u)
#define CLK_PERI_CTRL_ENABLE (1u << 11)
#define CLK_PERI_CTRL_AUXSRC_CLK_SYS (0u << 5) /* AUXSRC bits 7:5: 0 clk_sys */

/* IO_BANK0, datasheet §2.19.6.1: GPIOn_CTRL at 0x04 + 8n, FUNCSEL in bits 4:0 */
#define IO_BANK0_BASE 0x40014000u
#define IO_BANK0_GPIO_CTRL(n) RP_REG(IO_BANK0_BASE + 0x04u + 8u * (n))
#define GPIO_FUNC_SPI 1u
#define GPIO_FUNC_SIO 5u

/* SIO, datasheet §2.3.1.7: the processor's own GPIO outputs; §2.3.1.4 the FIFOs
 * between the cores (each core writes to the other's and reads its own); §2.3.1.3
 * the 32 hardware spinlocks (a read claims, non-zero when it did; a write frees). */
#define SIO_BASE 0xD0000000u
#define SIO_FIFO_ST RP_REG(SIO_BASE + 0x050u)
#define SIO_FIFO_ST_VLD (1u << 0) /* a word to read */
#define SIO_FIFO_ST_RDY (1u << 1) /* room to write */
#define SIO_FIFO_WR RP_REG(SIO_BASE + 0x054u)
#define SIO_FIFO_RD RP_REG(SIO_BASE + 0x058u)
#define SIO_SPINLOCK(n) RP_REG(SIO_BASE + 0x100u + 4u * (n))
#define SIO_GPIO_OUT_SET RP_REG(SIO_BASE + 0x014u)
#define SIO_GPIO_OUT_CLR RP_REG(SIO_BASE + 0x018u)
#define SIO_GPIO_OE_SET RP_REG(SIO_BASE + 0x024u)

/* SPI0, an ARM PrimeCell PL022, datasheet §4.4.4. Bit rate = clk_peri / (CPSDVSR *
 * (1 + SCR)), CPSDVSR even, 2..254. */
#define SPI0_BASE 0x4003C000u
#define SPI0_SSPCR0 RP_REG(SPI0_BASE + 0x000u)
#define SSPCR0_DSS_8BIT 7u  /* bits 3:0: data size - 1 */
#define SSPCR0_SPO (1u << 6)
#define SSPCR0_SPH (1u << 7)
#define SSPCR0_SCR_Pos 8u   /* bits 15:8 */
#define SPI0_SSPCR1 RP_REG(SPI0_BASE + 0x004u)
#define SSPCR1_SSE (1u << 1) /* enable; MS (bit 2) = 0: master */
#define SPI0_SSPDR_ADDRESS (SPI0_BASE + 0x008u)
#define SPI0_SSPSR RP_REG(SPI0_BASE + 0x00Cu)
#define SSPSR_TFE (1u << 0) /* transmit FIFO empty */
#define SSPSR_BSY (1u << 4)
#define SPI0_SSPCPSR RP_REG(SPI0_BASE + 0x010u)
#define SPI0_SSPDMACR RP_REG(SPI0_BASE + 0x024u)
#define SSPDMACR_TXDMAE (1u << 1)

/* The watchdog's tick (§4.7.2): clk_ref divided by CYCLES, the TIMER's microsecond;
 * and the TIMER (§4.6.5), read raw: the high word, the low, the high again. */
#define WATCHDOG_TICK RP_REG(0x40058000u + 0x02Cu)
#define WATCHDOG_TICK_ENABLE (1u << 9) /* CYCLES: bits 8:0 */
#define TIMER_TIMERAWH RP_REG(0x40054000u + 0x024u)
#define TIMER_TIMERAWL RP_REG(0x40054000u + 0x028u)

/* The core's System Control Block: the vector table's address (VTOR), which boot2
 * set and core 1 takes too. */
#define SCB_VTOR RP_REG(0xE000ED08u)

/* DMA, datasheet §2.5.7: channel 0's registers, the abort register, and the
 * transfer request of SPI0's transmit FIFO (DREQ_SPI0_TX, §2.5.3.1). */
#define DMA_BASE 0x50000000u
#define DMA_CH0_READ_ADDR RP_REG(DMA_BASE + 0x000u)
#define DMA_CH0_WRITE_ADDR RP_REG(DMA_BASE + 0x004u)
#define DMA_CH0_TRANS_COUNT RP_REG(DMA_BASE + 0x008u)
#define DMA_CH0_CTRL_TRIG RP_REG(DMA_BASE + 0x00Cu) /* writing it starts the channel */
#define DMA_CH0_AL1_CTRL RP_REG(DMA_BASE + 0x010u)  /* the same CTRL, without the trigger */
#define DMA_CTRL_EN (1u << 0)
#define DMA_CTRL_HIGH_PRIORITY (1u << 1)
#define DMA_CTRL_DATA_SIZE_BYTE (0u << 2)
#define DMA_CTRL_INCR_READ (1u << 4)
#define DMA_CTRL_CHAIN_TO_Pos 11u /* bits 14:11; a channel chained to itself: no chaining */
#define DMA_CTRL_TREQ_SEL_Pos 15u /* bits 20:15 */
#define DMA_CTRL_BUSY (1u << 24)
#define DMA_CTRL_WRITE_ERROR (1u << 29) /* write 1 to clear */
#define DMA_CTRL_READ_ERROR (1u << 30)  /* write 1 to clear */
#define DMA_CTRL_AHB_ERROR (1u << 31)   /* read-only: either of the two */
#define DMA_CHAN_ABORT RP_REG(DMA_BASE + 0x444u)
#define DREQ_SPI0_TX 16u

#endif
