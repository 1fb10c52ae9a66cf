/* thumb_subset.h: a Cortex-M0+ core for the few instructions the RP2040's second
 * stage uses (boards/rp2040-st7789/boot2.S), so that tests/test_boot2.c can run the
 * very bytes the board boots with against models of what they drive. An
 * instruction outside the subset stops the run with its address and halfword. */
#ifndef TARN_TEST_THUMB_SUBSET_H
#define TARN_TEST_THUMB_SUBSET_H

#include <stdint.h>

/* The memory the core sees: 32-bit loads and stores at word-aligned addresses
 * (the only ones boot2 makes), and the fetch of its own code. */
typedef struct {
    uint32_t (*load)(void *bus, uint32_t address);
    void (*store)(void *bus, uint32_t address, uint32_t value);
    void *bus;
    const uint8_t *code; /* the code's bytes, at code_base */
    uint32_t code_base, code_size;
} thumb_memory;

typedef struct {
    uint32_t r[16]; /* r13 the stack pointer (MSP), r14 lr, r15 pc */
    int z, n;       /* the flags the subset sets and tests */
    char fault[160]; /* why the run stopped, "" while it runs */
} thumb_core;

/* Runs from `entry` until the pc leaves the code (the jump to the program: its
 * address is then r[15]) or a fault, at most `steps` instructions; 0 when it left
 * the code, -1 with core->fault set otherwise. */
int thumb_run(thumb_core *core, const thumb_memory *memory, uint32_t entry, long steps);

#endif
