/* qemu_rv32_io.c: board.h's side for the emulated RISC-V boards (qemu-rv32 on
 * sifive_e, qemu-rv32-400k on virt). The panel stream leaves through the machine's
 * UART (QEMU: -serial file:STREAM), through the board's own uart.h; the report goes
 * to a host file through semihosting (word 1 of the command line:
 * -semihosting-config enable=on,target=native,arg=firmware,arg=REPORT), and a
 * semihosting exit ends the run. The counter is the minstret CSR, which QEMU derives
 * from -icount on every machine: with shift=0 it is the exact number of
 * instructions retired (mcycle reads the same value; the CLINT's mtime runs at
 * 10 MHz of virtual time). */
#include "board.h"
#include "semihosting.h"
#include "uart.h"

static int32_t report = -1;

int board_init(void)
{
    uart_init();
    char cmdline[256];
    const char *words[2] = {"firmware", "report.txt"};
    (void)semihosting_words(cmdline, sizeof cmdline, words, 2);
    report = semihosting_open_write(words[1]);
    return report < 0;
}

/* Polls of a full transmit FIFO before the write gives up: the FIFO drains a byte in
 * a few hundred instructions at most, so a UART that stays full this long is
 * stuck, and the frame ends with an error instead of hanging. */
#define UART_FULL_POLLS_MAX 1000000u

int board_write(const void *bytes, size_t count)
{
    const uint8_t *p = bytes;
    for (size_t i = 0; i < count; i++) {
        uint32_t polls = 0;
        while (uart_tx_full())
            if (++polls == UART_FULL_POLLS_MAX) return -1;
        uart_tx(p[i]);
    }
    return 0;
}

uint64_t board_instructions(void)
{
    uint32_t hi, lo, again;
    do {
        __asm__ volatile("csrr %0, minstreth" : "=r"(hi));
        __asm__ volatile("csrr %0, minstret" : "=r"(lo));
        __asm__ volatile("csrr %0, minstreth" : "=r"(again));
    } while (hi != again);
    return ((uint64_t)hi << 32) | lo;
}

int board_report(const char *text, size_t count)
{
    if (report < 0) return 1;
    return count == 0 ? 0 : semihosting_write(report, text, count);
}

void board_exit(int status)
{
    if (report >= 0) semihosting_close(report);
    report = -1;
    semihosting_exit(status);
}
