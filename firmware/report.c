/* report.c: the report line's text, numbers and counter check (report.h). */
#include "report.h"

#include "board.h"
#include "tarn/tarn_math.h"

void report_start(report *r)
{
    r->length = 0;
}

void report_text(report *r, const char *s)
{
    while (*s != '\0' && r->length < sizeof r->text) r->text[r->length++] = *s++;
}

void report_number(report *r, uint64_t value)
{
    const tarn_divisor ten = tarn_divisor_of(10);
    char digits[20];
    size_t n = 0;
    do {
        uint32_t digit;
        value = tarn_divide_u64(value, &ten, &digit);
        digits[n++] = (char)('0' + (int)digit);
    } while (value != 0);
    while (n > 0 && r->length < sizeof r->text) r->text[r->length++] = digits[--n];
}

void report_hex32(report *r, uint32_t value)
{
    static const char hex[] = "0123456789ABCDEF";
    for (int shift = 28; shift >= 0 && r->length < sizeof r->text; shift -= 4)
        r->text[r->length++] = hex[(value >> shift) & 0xFu];
}

int report_send(const report *r)
{
    return board_report(r->text, r->length);
}

uint64_t report_per_pixel(uint64_t instructions, uint32_t pixels)
{
    if (pixels == 0) return 0;
    const tarn_divisor divisor = tarn_divisor_of(pixels);
    return tarn_divide_u64(instructions + pixels / 2u, &divisor, NULL);
}

/* Exactly 2 * n instructions for n >= 1 (plus the call): a yardstick for the board's
 * counter. */
static void __attribute__((noinline)) spin(uint32_t n)
{
#if defined(__arm__)
    __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n bne 1b" : "+l"(n) : : "cc");
#elif defined(__riscv)
    __asm__ volatile("1: addi %0, %0, -1\n bnez %0, 1b" : "+r"(n));
#else
#error "spin: Arm or RISC-V"
#endif
}

uint64_t report_counter_check(void)
{
    uint64_t t0 = board_instructions();
    spin(1);
    uint64_t t1 = board_instructions();
    spin(1u + REPORT_COUNTER_CHECK_INSTRUCTIONS / 2u);
    uint64_t t2 = board_instructions();
    return (t2 - t1) - (t1 - t0);
}

void report_frame_header(report *r, const char *kind, const char *board, const char *scene,
                         uint32_t width, uint32_t height)
{
    report_text(r, kind);
    report_text(r, " board=");
    report_text(r, board);
    report_text(r, " scene=");
    report_text(r, scene);
    report_text(r, " size=");
    report_number(r, width);
    report_text(r, "x");
    report_number(r, height);
}
