/* semihosting.c: semihosting for ARMv6-M/ARMv7-M (BKPT 0xAB) and RISC-V (EBREAK
 * between `slli zero, zero, 0x1f` and `srai zero, zero, 7`, uncompressed). */
#include "semihosting.h"

enum {
    SYS_OPEN = 0x01,
    SYS_CLOSE = 0x02,
    SYS_WRITE = 0x05,
    SYS_GET_CMDLINE = 0x15,
    SYS_EXIT_EXTENDED = 0x20,
    ADP_STOPPED_APPLICATION_EXIT = 0x20026,
    OPEN_MODE_WB = 5
};

static int32_t semihosting_call(uint32_t operation, const void *parameters)
{
#if defined(__arm__)
    register uint32_t r0 __asm__("r0") = operation;
    register const void *r1 __asm__("r1") = parameters;
    __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
#elif defined(__riscv)
    register uint32_t a0 __asm__("a0") = operation;
    register const void *a1 __asm__("a1") = parameters;
    __asm__ volatile(".balign 16\n .option push\n .option norvc\n"
                     "slli zero, zero, 0x1f\n ebreak\n srai zero, zero, 7\n"
                     ".option pop"
                     : "+r"(a0) : "r"(a1) : "memory");
    return (int32_t)a0;
#else
#error "semihosting: Arm or RISC-V only"
#endif
}

static size_t text_length(const char *text)
{
    size_t n = 0;
    while (text[n] != '\0') n++;
    return n;
}

int32_t semihosting_open_write(const char *path)
{
    uint32_t block[3] = {(uint32_t)(uintptr_t)path, OPEN_MODE_WB, (uint32_t)text_length(path)};
    return semihosting_call(SYS_OPEN, block);
}

int semihosting_write(int32_t handle, const void *bytes, size_t count)
{
    uint32_t block[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)bytes, (uint32_t)count};
    return semihosting_call(SYS_WRITE, block) != 0; /* the bytes NOT written */
}

void semihosting_close(int32_t handle)
{
    uint32_t block[1] = {(uint32_t)handle};
    (void)semihosting_call(SYS_CLOSE, block);
}

unsigned semihosting_words(char *buffer, size_t size, const char **words, unsigned max)
{
    uint32_t block[2] = {(uint32_t)(uintptr_t)buffer, (uint32_t)size};
    unsigned n = 0;
    if (size == 0 || semihosting_call(SYS_GET_CMDLINE, block) != 0) return 0;
    buffer[size - 1] = '\0';
    for (char *p = buffer; *p != '\0' && n < max;) {
        if (*p == ' ') {
            *p++ = '\0';
            continue;
        }
        words[n++] = p;
        while (*p != ' ' && *p != '\0') p++;
    }
    return n;
}

void semihosting_exit(int status)
{
    uint32_t block[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    for (;;) (void)semihosting_call(SYS_EXIT_EXTENDED, block);
}
