/* semihosted_io.c: board_init, board_write, board_report and board_exit for the
 * emulated Cortex-M boards: the panel stream and the report each go to a host file
 * through semihosting. The files are the command line's words 1 and 2 (QEMU:
 * -semihosting-config enable=on,target=native,arg=firmware,arg=STREAM,arg=REPORT),
 * "panel.stream" and "report.txt" in QEMU's working directory without them. */
#include "board.h"
#include "cortex_m.h"
#include "semihosting.h"

static int32_t stream = -1, report = -1;

int board_init(void)
{
    char cmdline[256];
    const char *words[3] = {"firmware", "panel.stream", "report.txt"};
    (void)semihosting_words(cmdline, sizeof cmdline, words, 3);
    stream = semihosting_open_write(words[1]);
    report = semihosting_open_write(words[2]);
    systick_start();
    return stream < 0 || report < 0;
}

int board_write(const void *bytes, size_t count)
{
    if (stream < 0) return 1;
    return count == 0 ? 0 : semihosting_write(stream, bytes, count);
}

int board_report(const char *text, size_t count)
{
    if (report < 0) return 1;
    return count == 0 ? 0 : semihosting_write(report, text, count);
}

void board_exit(int status)
{
    if (stream >= 0) semihosting_close(stream);
    if (report >= 0) semihosting_close(report);
    stream = report = -1;
    semihosting_exit(status);
}
