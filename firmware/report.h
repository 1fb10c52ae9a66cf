/* report.h: the text the emulated boards send on their report channel
 * (board_report), assembled without stdio, and the counter's yardstick. Shared by
 * firmware/main.c and firmware/sweep_main.c. */
#ifndef TARN_FIRMWARE_REPORT_H
#define TARN_FIRMWARE_REPORT_H

#include <stddef.h>
#include <stdint.h>

/* One line being assembled; text past the buffer is dropped, so it holds the longest
 * line (a board of two cores sharing a ring of strips: about 300 characters). */
typedef struct {
    char text[384];
    size_t length;
} report;

/* An empty line: only its length is set, the text being written up to it (zeroing
 * the whole buffer cost each caller a template in flash as large). */
void report_start(report *r);
void report_text(report *r, const char *s);

/* Decimal, through the core's tarn_divide, so that the image links no 64-bit
 * division of the compiler's own (tests/check_firmware.sh counts the code bytes). */
void report_number(report *r, uint64_t value);

/* Eight hexadecimal digits, upper case. */
void report_hex32(report *r, uint32_t value);

/* "KIND board=BOARD scene=SCENE size=WxH": how both programs' report lines begin. */
void report_frame_header(report *r, const char *kind, const char *board, const char *scene,
                         uint32_t width, uint32_t height);

/* The board and the scene that report lines name: firmware.mk gives both programs
 * the board's folder in boards/ and the scene file's name; these stand in for a
 * build without it. */
#ifndef FW_BOARD_NAME
#define FW_BOARD_NAME "board"
#endif
#ifndef FW_SCENE_LABEL
#define FW_SCENE_LABEL "scene"
#endif

/* board_report of the text so far: 0, or non-zero when the link failed. */
int report_send(const report *r);

/* instructions / pixels, rounded to nearest; 0 for no pixels. */
uint64_t report_per_pixel(uint64_t instructions, uint32_t pixels);

#define REPORT_COUNTER_CHECK_INSTRUCTIONS 2000000u

/* What the board's counter says REPORT_COUNTER_CHECK_INSTRUCTIONS take (the board's
 * tick-to-instruction ratio, checked): a long spin minus a spin of one iteration,
 * which cancels the calls and the counter reads. */
uint64_t report_counter_check(void);

#endif
