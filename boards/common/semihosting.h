/* semihosting.h: the semihosting calls the emulated boards use. QEMU answers them
 * with -semihosting-config enable=on,target=native, on Arm (BKPT 0xAB) and RISC-V
 * (the EBREAK between two marker shifts) alike. */
#ifndef TARN_SEMIHOSTING_H
#define TARN_SEMIHOSTING_H

#include <stddef.h>
#include <stdint.h>

/* SYS_OPEN for binary writing ("wb"): a handle, or -1. */
int32_t semihosting_open_write(const char *path);
/* SYS_WRITE: 0 when every byte was written. */
int semihosting_write(int32_t handle, const void *bytes, size_t count);
/* SYS_CLOSE */
void semihosting_close(int32_t handle);
/* The command line (SYS_GET_CMDLINE; QEMU joins the -semihosting-config arg=...
 * values with spaces, word 0 being the program's name) read into `buffer` and cut
 * into at most `max` words in place. Returns the number of words, 0 if there is no
 * command line. */
unsigned semihosting_words(char *buffer, size_t size, const char **words, unsigned max);
/* SYS_EXIT_EXTENDED with ADP_Stopped_ApplicationExit: QEMU exits with `status`. */
void semihosting_exit(int status) __attribute__((noreturn));

#endif
