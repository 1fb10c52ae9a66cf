/* uf2: a flash image as a UF2 file, for bootloaders that take files (the RP2040's
 * BOOTSEL drive).
 *
 *   uf2 IMAGE.bin BASE FAMILY OUT.uf2
 *
 * IMAGE.bin holds the flash from address BASE on (objcopy -O binary). Each 512-byte
 * block carries 256 bytes of it: the first at BASE, each next one 256 bytes on, the
 * last padded with zeros. The format (github.com/microsoft/uf2, README):
 *
 *   offset  0  0x0A324655  first magic ("UF2\n")
 *           4  0x9E5D5157  second magic
 *           8  flags: 0x00002000, the family ID is present
 *          12  target address
 *          16  payload bytes (256)
 *          20  block number, from 0
 *          24  number of blocks
 *          28  family ID (RP2040: 0xE48BFF56)
 *          32  payload (476 bytes of room)
 *         508  0x0AB16F30  final magic
 *
 * All words little-endian. OUT.uf2 is written through a temporary file. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>

#define UF2_MAGIC_START0 0x0A324655u
#define UF2_MAGIC_START1 0x9E5D5157u
#define UF2_MAGIC_END 0x0AB16F30u
#define UF2_FLAG_FAMILY_ID_PRESENT 0x00002000u
#define UF2_BLOCK_BYTES 512u
#define UF2_PAYLOAD_BYTES 256u
#define UF2_DATA_OFFSET 32u
#define IMAGE_BYTES_MAX (16u * 1024u * 1024u) /* the RP2040's flash window */

static void put_u32(uint8_t *out, uint32_t value)
{
    for (unsigned i = 0; i < 4u; i++) out[i] = (uint8_t)(value >> (8u * i));
}

static int parse_u32(const char *text, uint32_t *value)
{
    char *end;
    errno = 0;
    unsigned long long v = strtoull(text, &end, 0);
    if (errno != 0 || end == text || *end != '\0' || v > 0xFFFFFFFFull) return 1;
    *value = (uint32_t)v;
    return 0;
}

int main(int argc, char **argv)
{
    uint32_t base, family;
    if (argc != 5) {
        fprintf(stderr, "usage: %s IMAGE.bin BASE FAMILY OUT.uf2\n", argv[0]);
        return 2;
    }
    if (parse_u32(argv[2], &base) != 0 || base % UF2_PAYLOAD_BYTES != 0) {
        fprintf(stderr, "uf2: BASE '%s': expected a 32-bit address, a multiple of 256\n", argv[2]);
        return 1;
    }
    if (parse_u32(argv[3], &family) != 0) {
        fprintf(stderr, "uf2: FAMILY '%s': expected a 32-bit number\n", argv[3]);
        return 1;
    }
    FILE *in = fopen(argv[1], "rb");
    if (in == NULL) {
        fprintf(stderr, "uf2: cannot read %s\n", argv[1]);
        return 1;
    }
    uint8_t *image = calloc(IMAGE_BYTES_MAX + 1u, 1);
    size_t size = image ? fread(image, 1, IMAGE_BYTES_MAX + 1u, in) : 0;
    int failed = image == NULL || ferror(in);
    fclose(in);
    if (failed || size == 0 || size > IMAGE_BYTES_MAX ||
        (uint64_t)base + size > 0x100000000ull) {
        fprintf(stderr, "uf2: %s: %s\n", argv[1],
                failed ? "read error" : size == 0 ? "empty" : "larger than the 16 MB flash window");
        free(image);
        return 1;
    }

    char tmp[4096];
    if (snprintf(tmp, sizeof tmp, "%s.tmp", argv[4]) >= (int)sizeof tmp) {
        fprintf(stderr, "uf2: output path too long\n");
        free(image);
        return 1;
    }
    FILE *out = fopen(tmp, "wb");
    if (out == NULL) {
        fprintf(stderr, "uf2: cannot write %s\n", tmp);
        free(image);
        return 1;
    }
    const uint32_t blocks = (uint32_t)((size + UF2_PAYLOAD_BYTES - 1u) / UF2_PAYLOAD_BYTES);
    int write_failed = 0;
    for (uint32_t i = 0; i < blocks && !write_failed; i++) {
        uint8_t block[UF2_BLOCK_BYTES];
        memset(block, 0, sizeof block);
        put_u32(block + 0, UF2_MAGIC_START0);
        put_u32(block + 4, UF2_MAGIC_START1);
        put_u32(block + 8, UF2_FLAG_FAMILY_ID_PRESENT);
        put_u32(block + 12, base + i * UF2_PAYLOAD_BYTES);
        put_u32(block + 16, UF2_PAYLOAD_BYTES);
        put_u32(block + 20, i);
        put_u32(block + 24, blocks);
        put_u32(block + 28, family);
        /* calloc'd past the end: the last block's tail is zeros */
        memcpy(block + UF2_DATA_OFFSET, image + (size_t)i * UF2_PAYLOAD_BYTES, UF2_PAYLOAD_BYTES);
        put_u32(block + UF2_BLOCK_BYTES - 4u, UF2_MAGIC_END);
        write_failed = fwrite(block, 1, sizeof block, out) != sizeof block;
    }
    free(image);
    if (fclose(out) != 0 || write_failed || rename(tmp, argv[4]) != 0) {
        fprintf(stderr, "uf2: cannot write %s\n", argv[4]);
        remove(tmp);
        return 1;
    }
    return 0;
}
