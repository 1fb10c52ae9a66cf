/* uart.h: qemu-rv32-400k's panel link, virt's NS16550A at 0x10000000 (byte
 * registers), for boards/common/qemu_rv32_io.c. THR takes a byte to send; LSR's
 * THRE bit (5) is set while the transmitter can take one. */
#ifndef TARN_QEMU_RV32_400K_UART_H
#define TARN_QEMU_RV32_400K_UART_H

#include <stdint.h>

#define UART_THR (*(volatile uint8_t *)0x10000000u)
#define UART_LCR (*(volatile uint8_t *)0x10000003u)
#define UART_LSR (*(volatile uint8_t *)0x10000005u)
#define UART_LSR_THRE 0x20u

static inline void uart_init(void)
{
    UART_LCR = 0x03u; /* 8 data bits, no parity, one stop bit; QEMU ignores the rate */
}

static inline int uart_tx_full(void)
{
    return (UART_LSR & UART_LSR_THRE) == 0;
}

static inline void uart_tx(uint8_t byte)
{
    UART_THR = byte;
}

#endif
