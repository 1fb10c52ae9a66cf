/* uart.h: qemu-rv32's panel link, sifive_e's UART0 (the FE310's, at 0x10013000),
 * for boards/common/qemu_rv32_io.c. Writing txdata queues a byte; reading it has
 * bit 31 set while the transmit FIFO is full. */
#ifndef TARN_QEMU_RV32_UART_H
#define TARN_QEMU_RV32_UART_H

#include <stdint.h>

#define UART0_TXDATA (*(volatile uint32_t *)0x10013000u)
#define UART0_TXCTRL (*(volatile uint32_t *)0x10013008u)
#define UART_TX_FULL 0x80000000u

static inline void uart_init(void)
{
    UART0_TXCTRL = 1u; /* txen, one stop bit */
}

static inline int uart_tx_full(void)
{
    return (UART0_TXDATA & UART_TX_FULL) != 0;
}

static inline void uart_tx(uint8_t byte)
{
    UART0_TXDATA = byte;
}

#endif
