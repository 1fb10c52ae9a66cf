/* test_boot2.c: the RP2040's second stage (boards/rp2040-st7789/boot2.S), the very
 * 256 bytes the board boots with (build/firmware/rp2040-st7789/boot2.bin, made by
 * `make firmware BOARD=rp2040-st7789`, which make test runs before), run on a core
 * for its instructions (thumb_subset.c) against a model of the XIP SSI and the
 * Pico's W25Q16JV flash (qspi_flash.c):
 *
 * - from a flash whose QE bit is clear, it sets QE (one status write, after a write
 *   enable, status register 1 kept), waits out BUSY, puts the flash in continuous
 *   Fast Read Quad I/O mode, and leaves the SSI reading it so: each XIP word of the
 *   image then reads back through the model as the flash holds it;
 * - from one whose QE is set, it writes no status;
 * - either way it enters the program: VTOR at the image's vector table, SP and the
 *   pc from its first two words;
 * - the pads: SCLK at 8 mA with fast slew, no Schmitt trigger on the data pads.
 * The model fails on a register the SSI ignores while enabled, a phase of the
 * wrong width or lines, a command the flash does not take. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "qspi_flash.h"
#include "thumb_subset.h"

#define BOOT2_PATH "build/firmware/rp2040-st7789/boot2.bin"
#define BOOT2_BASE 0x20041F00u /* where the bootrom copies it */
#define IMAGE_BYTES 4096u
#define STACK_TOP 0x20042000u
#define RESET_HANDLER 0x100001C1u
#define SR1_PROTECTED 0x1Cu /* block protect bits set: kept as they are */

typedef struct {
    uint8_t code[256];
    uint32_t code_size;
    uint8_t image[IMAGE_BYTES];
    qspi_flash flash;
    thumb_core core;
} boot;

static void load_boot2(boot *b)
{
    FILE *f = fopen(BOOT2_PATH, "rb");
    if (f == NULL) fail_msg("%s: not built (make firmware BOARD=rp2040-st7789)", BOOT2_PATH);
    b->code_size = (uint32_t)fread(b->code, 1, sizeof b->code, f);
    fclose(f);
    if (b->code_size == 0u || b->code_size > 252u) fail_msg("%s: %u bytes, expected 1..252", BOOT2_PATH, b->code_size);
}

/* The flash: a vector table at 0x100 after 256 bytes of boot2, and bytes that differ
 * from word to word everywhere else. */
static void make_image(boot *b)
{
    for (uint32_t k = 0; k < IMAGE_BYTES; k++) b->image[k] = (uint8_t)(k * 37u + (k >> 8) * 11u + 5u);
    const uint32_t vectors[2] = {STACK_TOP, RESET_HANDLER};
    for (int w = 0; w < 2; w++)
        for (int k = 0; k < 4; k++) b->image[0x100 + 4 * w + k] = (uint8_t)(vectors[w] >> (8 * k));
}

/* Boots from a flash with the given status register 2; fails with the model's or
 * the core's reason. */
static void run_boot2(boot *b, uint8_t status2)
{
    load_boot2(b);
    make_image(b);
    qspi_flash_init(&b->flash, b->image, sizeof b->image, SR1_PROTECTED, status2);
    memset(&b->core, 0, sizeof b->core);
    b->core.r[13] = BOOT2_BASE + 0x100u - 16u; /* the bootrom's stack */
    const thumb_memory memory = {qspi_flash_load, qspi_flash_store, &b->flash, b->code, BOOT2_BASE, b->code_size};
    const int left = thumb_run(&b->core, &memory, BOOT2_BASE, 100000);
    if (b->flash.error[0] != '\0') fail_msg("boot2 against the flash model: %s", b->flash.error);
    if (left != 0) fail_msg("boot2: %s", b->core.fault);
}

/* What either boot leaves: the program entered, the SSI reading the flash in
 * continuous quad mode, every word of the image read back through it. */
static void assert_entered_in_quad_mode(boot *b)
{
    assert_int_equal(b->core.r[15], RESET_HANDLER & ~1u);
    assert_int_equal(b->core.r[13], STACK_TOP);
    assert_int_equal(b->flash.vtor, 0x10000100u);
    assert_true(b->flash.status2 & 0x02u);
    assert_int_equal(b->flash.status1, SR1_PROTECTED);
    if (!b->flash.continuous) fail_msg("the flash is not left in continuous read mode");
    assert_int_equal(b->flash.baudr, 4);
    assert_int_equal(b->flash.pads[1], 0x21); /* SCLK: 8 mA, fast slew */
    for (int k = 2; k < 6; k++) assert_int_equal(b->flash.pads[k] & 0x02u, 0); /* SD0..SD3: no Schmitt */
    for (uint32_t a = 0; a < IMAGE_BYTES; a += 4u) {
        const uint32_t expected = (uint32_t)b->image[a] | (uint32_t)b->image[a + 1] << 8 |
                                  (uint32_t)b->image[a + 2] << 16 | (uint32_t)b->image[a + 3] << 24;
        const uint32_t word = qspi_flash_load(&b->flash, 0x10000000u + a);
        if (b->flash.error[0] != '\0') fail_msg("XIP read at 0x%08X: %s", 0x10000000u + a, b->flash.error);
        if (word != expected) fail_msg("XIP read at 0x%08X: 0x%08X, the flash holds 0x%08X", 0x10000000u + a, word, expected);
    }
}

static void test_boot2_sets_the_quad_enable_bit_once(void **state)
{
    (void)state;
    static boot b;
    run_boot2(&b, 0x00);
    assert_int_equal(b.flash.status_writes, 1);
    assert_entered_in_quad_mode(&b);
}

static void test_boot2_leaves_a_quad_flash_unwritten(void **state)
{
    (void)state;
    static boot b;
    run_boot2(&b, 0x02);
    assert_int_equal(b.flash.status_writes, 0);
    assert_entered_in_quad_mode(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_boot2_sets_the_quad_enable_bit_once),
        cmocka_unit_test(test_boot2_leaves_a_quad_flash_unwritten),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
