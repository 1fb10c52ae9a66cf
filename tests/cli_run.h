/* cli_run.h: the `tarn` binary run as a user runs it, for the command-line tests:
 * its exit status, its stdout and stderr captured, and killed if it outlives a
 * timeout, so that a hang fails the test instead of stopping the suite. */
#ifndef TARN_TESTS_CLI_RUN_H
#define TARN_TESTS_CLI_RUN_H

#include <stddef.h>

#define CLI_OUTPUT_MAX 65536

typedef struct {
    int status;    /* the exit status; -1 when killed by a signal */
    int timed_out; /* killed after the timeout */
    double seconds; /* from start to exit */
    char out[CLI_OUTPUT_MAX], err[CLI_OUTPUT_MAX];
    size_t out_length, err_length;
} cli_result;

/* Runs argv (argv[0] the program). stdin_fd >= 0 is its stdin (else /dev/null);
 * stderr_fd >= 0 takes its stderr (a terminal, say) instead of the capture. */
void cli_run(char *const argv[], int stdin_fd, int stderr_fd, unsigned timeout_s, cli_result *r);

/* Whether r->err is exactly one line. */
int cli_one_line(const cli_result *r);

/* The binary under test: $TARN_BIN, which make check sets; the test fails without. */
const char *cli_tarn(void);

/* A fresh folder for each test, as cmocka's setup and teardown, and a file's path
 * in it (the last four stay valid). */
int cli_make_folder(void **state);
int cli_remove_folder(void **state);
const char *cli_in_folder(const char *name);

#endif
