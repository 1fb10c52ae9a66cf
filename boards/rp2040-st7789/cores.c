/* cores.c: the RP2040's second core, for a frame drawn in two parts (board.h).
 *
 * - Core 1 sleeps in the bootrom after reset until core 0 sends it, over the FIFO
 *   from core 0 to core 1, the words 0, 0, 1, the vector table, the stack pointer
 *   and the entry point, each echoed back; a word that comes back different starts
 *   the sequence again, and before each 0 core 0 empties its own FIFO and signals
 *   an event (SEV), which wakes core 1 (datasheet §2.8.2).
 * - The FIFOs (§2.3.1.4) carry the frames' times and statuses between the cores;
 *   a strip pipeline's counts of strips done are words of SRAM both read.
 * - The panel's lock is hardware spinlock 31, the strips' spinlock 30 (§2.3.1.3):
 *   reading one claims it when it reads non-zero, writing it frees it. */
#include "board.h"
#include "rp2040.h"

#define PANEL_SPINLOCK 31u
#define STRIPS_SPINLOCK 30u
#define START_TIMEOUT_MS 1000u

static void send_event(void)
{
    __asm__ volatile("sev");
}

void board_core_send(uint32_t word)
{
    while ((SIO_FIFO_ST & SIO_FIFO_ST_RDY) == 0u) {}
    SIO_FIFO_WR = word;
    send_event();
}

uint32_t board_core_receive(void)
{
    while ((SIO_FIFO_ST & SIO_FIFO_ST_VLD) == 0u) {}
    return SIO_FIFO_RD;
}

/* The next word from core 1 into *word: 0, or non-zero when none came within
 * START_TIMEOUT_MS of `start` (board_milliseconds). */
static int receive_by(uint32_t start, uint32_t *word)
{
    while ((SIO_FIFO_ST & SIO_FIFO_ST_VLD) == 0u)
        if (board_milliseconds() - start > START_TIMEOUT_MS) return 1;
    *word = SIO_FIFO_RD;
    return 0;
}

int board_second_core_start(void (*entry)(void), uint32_t *stack_top)
{
    const uint32_t sequence[6] = {0u, 0u, 1u, SCB_VTOR, (uint32_t)(uintptr_t)stack_top, (uint32_t)(uintptr_t)entry};
    const uint32_t start = board_milliseconds();
    for (unsigned k = 0; k < 6u;) {
        if (sequence[k] == 0u) {
            while (SIO_FIFO_ST & SIO_FIFO_ST_VLD) (void)SIO_FIFO_RD;
            send_event();
        }
        board_core_send(sequence[k]);
        uint32_t echo;
        if (receive_by(start, &echo) != 0) return 1;
        k = echo == sequence[k] ? k + 1u : 0u;
    }
    return 0;
}

/* The Cortex-M0+ keeps its own stores in order and the SRAM has no cache; the
 * barrier keeps the compiler from moving a store past the count, and the core from
 * running ahead of its stores (ARMv6-M: DMB). */
void board_cores_order(void)
{
    __asm__ volatile("dmb" ::: "memory");
}

/* Spinlock n claimed, waiting while the other core holds it; and freed. The claim
 * and the release order memory as a barrier does: what one core wrote under the
 * lock, the other reads after taking it. */
static void spinlock_claim(unsigned n)
{
    while (SIO_SPINLOCK(n) == 0u) {}
    board_cores_order();
}

static void spinlock_release(unsigned n)
{
    board_cores_order();
    SIO_SPINLOCK(n) = 1u;
}

void board_panel_lock(void)
{
    spinlock_claim(PANEL_SPINLOCK);
}

void board_panel_unlock(void)
{
    spinlock_release(PANEL_SPINLOCK);
}

void board_strips_lock(void)
{
    spinlock_claim(STRIPS_SPINLOCK);
}

void board_strips_unlock(void)
{
    spinlock_release(STRIPS_SPINLOCK);
}
