/* crc32_boot2.h: the CRC-32 the RP2040 bootrom checks over the 252 bytes of the
 * second stage (RP2040 datasheet, section 2.8.1.3.1): polynomial 0x04C11DB7, most
 * significant bit first (not reflected), initial value 0xFFFFFFFF, no final xor
 * (the parameters known as CRC-32/MPEG-2; check value 0x0376E6E7 for "123456789"). */
#ifndef TARN_TOOLS_CRC32_BOOT2_H
#define TARN_TOOLS_CRC32_BOOT2_H

#include <stddef.h>
#include <stdint.h>

static uint32_t crc32_boot2(const uint8_t *bytes, size_t count)
{
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < count; i++) {
        crc ^= (uint32_t)bytes[i] << 24;
        for (int bit = 0; bit < 8; bit++)
            crc = (crc & 0x80000000u) ? (crc << 1) ^ 0x04C11DB7u : crc << 1;
    }
    return crc;
}

#endif
