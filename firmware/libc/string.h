/* string.h for toolchains without a C library (riscv64-unknown-elf here): the four
 * functions core/ and the compiler use, implemented in string.c beside it. */
#ifndef TARN_FIRMWARE_STRING_H
#define TARN_FIRMWARE_STRING_H

#include <stddef.h>

void *memset(void *destination, int value, size_t count);
void *memcpy(void *restrict destination, const void *restrict source, size_t count);
void *memmove(void *destination, const void *source, size_t count);
int memcmp(const void *a, const void *b, size_t count);

#endif
