/* string.c: the four string.h functions the core and the compiler call, for boards
 * whose toolchain has no C library (the RISC-V one is freestanding). Built with
 * -fno-builtin -fno-tree-loop-distribute-patterns so that the compiler does not turn
 * these loops back into calls to themselves. Word-at-a-time when both pointers
 * allow it: the core clears its tile buffers with memset. */
#include <stddef.h>
#include <stdint.h>
#include "string.h"

void *memset(void *destination, int value, size_t count)
{
    uint8_t *d = destination;
    uint8_t byte = (uint8_t)value;
    while (count > 0 && ((uintptr_t)d & 3u) != 0) {
        *d++ = byte;
        count--;
    }
    uint32_t word = 0x01010101u * byte;
    for (; count >= 4; count -= 4, d += 4) *(uint32_t *)(void *)d = word;
    while (count-- > 0) *d++ = byte;
    return destination;
}

void *memcpy(void *restrict destination, const void *restrict source, size_t count)
{
    uint8_t *d = destination;
    const uint8_t *s = source;
    if ((((uintptr_t)d | (uintptr_t)s) & 3u) == 0) {
        for (; count >= 4; count -= 4, d += 4, s += 4)
            *(uint32_t *)(void *)d = *(const uint32_t *)(const void *)s;
    }
    while (count-- > 0) *d++ = *s++;
    return destination;
}

void *memmove(void *destination, const void *source, size_t count)
{
    uint8_t *d = destination;
    const uint8_t *s = source;
    if (d == s || count == 0) return destination;
    if (d < s || d >= s + count) return memcpy(destination, source, count);
    while (count-- > 0) d[count] = s[count];
    return destination;
}

int memcmp(const void *a, const void *b, size_t count)
{
    const uint8_t *p = a, *q = b;
    for (size_t i = 0; i < count; i++)
        if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
    return 0;
}
