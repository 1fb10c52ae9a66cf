/* child_process.h: another program run by tarn (valgrind, make, gnuplot), its
 * output going to a log file that the error names when it fails. */
#ifndef TARN_HOST_CHILD_PROCESS_H
#define TARN_HOST_CHILD_PROCESS_H

#include <sys/types.h>
#include "error.h"

typedef struct {
    const char *program; /* argv[0], looked up in PATH */
    const char *log;     /* stdout and stderr go here */
    const char *install; /* what to run when the program is missing, for the message */
    pid_t pid;
} tarn_child;

/* Starts `argv` (argv[0] is the program, NULL-terminated). 0, or -1 with `err`
 * saying the program is missing and how to install it, or why it did not start. */
int tarn_child_start(tarn_child *child, char *const argv[], tarn_error *err);

/* Waits for it: 0 when it exited with status 0, else -1 with `err` naming the log. */
int tarn_child_finish(const tarn_child *child, tarn_error *err);

/* 0 when the program is in PATH (an executable file), else -1 with `err` saying
 * it is missing and how to install it: for a command to check before its work. */
int tarn_child_installed(const tarn_child *child, tarn_error *err);

/* Both, one after the other. */
int tarn_child_run(tarn_child *child, char *const argv[], tarn_error *err);

#endif
