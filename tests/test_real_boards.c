/* test_real_boards.c: the images of the real boards, which nothing here can run.
 *
 * For every board in build/firmware/BOARD/ whose firmware.conf says emulated=0 (made
 * by `make firmware`, which `make test` runs first through firmware-run):
 *
 * - The link fits: every allocated section of firmware.elf lies inside a memory
 *   region of the link's own map (firmware.map, "Memory Configuration"), the loaded
 *   bytes inside FLASH, .data, .bss and the stack inside RAM (and on the RP2040 core
 *   1's stack, .scratch, in SRAM4-5, its region SCRATCH). The figures are printed.
 * - The vector table starts .text: its first word is the initial stack pointer, in
 *   RAM and 8-byte aligned, its second the ELF's entry (reset_handler) with the
 *   Thumb bit set. It sits at the start of flash, or right after boot2.
 * - A board with a .boot2 section (the RP2040): boot2 is the first 256 bytes of
 *   flash and its last 4 bytes are the CRC-32 of the first 252 as the bootrom
 *   computes it (recomputed here, with its own table, independently of
 *   firmware/tools/boot2_crc.c); firmware.uf2 is well formed: whole 512-byte blocks,
 *   the three magic numbers, the family-ID flag and the RP2040 family, 256-byte
 *   payloads, block numbers 0..n-1 of n, addresses contiguous from the start of
 *   flash, and payloads equal to the ELF's loaded bytes (zeros after them).
 *
 * The absence of floating-point helpers, the stack bound and the overflow messages
 * are checked by tests/check_firmware.sh and tests/check_real_boards.sh. */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "firmware_conf.h"

#define FIRMWARE_DIR "build/firmware"
#define BOARDS_MAX 16
#define REGIONS_MAX 8

#define UF2_BLOCK_BYTES 512u
#define UF2_PAYLOAD_BYTES 256u
#define RP2040_FAMILY 0xE48BFF56u
#define BOOT2_BYTES 256u

typedef struct {
    uint8_t *bytes;
    size_t size;
} blob;

static blob read_blob(const char *path)
{
    blob b = {NULL, 0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) return b;
    if (fseek(f, 0, SEEK_END) == 0) {
        long n = ftell(f);
        if (n > 0 && fseek(f, 0, SEEK_SET) == 0) {
            b.bytes = malloc((size_t)n);
            if (b.bytes != NULL && fread(b.bytes, 1, (size_t)n, f) == (size_t)n) b.size = (size_t)n;
        }
    }
    fclose(f);
    return b;
}

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint16_t le16(const uint8_t *p)
{
    return (uint16_t)(p[0] | p[1] << 8);
}

/* ---- the link's memory regions, from the map file ---- */

typedef struct {
    char name[32];
    uint32_t origin, length;
} region;

static size_t read_regions(const char *map_path, region *out, size_t max)
{
    blob map = read_blob(map_path);
    size_t n = 0;
    if (map.bytes == NULL) return 0;
    char *text = malloc(map.size + 1);
    memcpy(text, map.bytes, map.size);
    text[map.size] = '\0';
    char *p = strstr(text, "Memory Configuration");
    char *end = p ? strstr(p, "Linker script and memory map") : NULL;
    for (char *line = p; line != NULL && line < end && n < max; line = strchr(line + 1, '\n')) {
        char name[32];
        unsigned long origin, length;
        if (sscanf(line, " %31s 0x%lx 0x%lx", name, &origin, &length) == 3 &&
            strcmp(name, "*default*") != 0) {
            memcpy(out[n].name, name, sizeof name);
            out[n].origin = (uint32_t)origin;
            out[n].length = (uint32_t)length;
            n++;
        }
    }
    free(text);
    free(map.bytes);
    return n;
}

static const region *find_region(const region *regions, size_t n, const char *name)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(regions[i].name, name) == 0) return &regions[i];
    return NULL;
}

static int inside(const region *r, uint32_t address, uint32_t size)
{
    return r != NULL && address >= r->origin &&
           (uint64_t)address + size <= (uint64_t)r->origin + r->length;
}

/* ---- ELF32, little-endian, as the Arm toolchain writes it ---- */

typedef struct {
    const char *name;
    uint32_t type, flags, address, offset, size;
} section;

typedef struct {
    blob file;
    uint32_t entry;
    section sections[64];
    size_t section_count;
} elf_image;

static void read_elf(const char *path, elf_image *elf)
{
    memset(elf, 0, sizeof *elf);
    elf->file = read_blob(path);
    const uint8_t *f = elf->file.bytes;
    assert_non_null(f);
    assert_true(elf->file.size >= 52);
    assert_memory_equal(f, "\177ELF", 4);
    assert_int_equal(f[4], 1);             /* ELFCLASS32 */
    assert_int_equal(f[5], 1);             /* little-endian */
    assert_int_equal(le16(f + 18), 40);    /* EM_ARM */
    elf->entry = le32(f + 24);
    const uint32_t shoff = le32(f + 32);
    const uint16_t shentsize = le16(f + 46), shnum = le16(f + 48), shstrndx = le16(f + 50);
    assert_true(shentsize >= 40 && shnum <= 64 && shstrndx < shnum);
    assert_true((uint64_t)shoff + (uint64_t)shnum * shentsize <= elf->file.size);
    const uint8_t *names_header = f + shoff + (size_t)shstrndx * shentsize;
    const uint32_t names_offset = le32(names_header + 16), names_size = le32(names_header + 20);
    assert_true((uint64_t)names_offset + names_size <= elf->file.size && names_size > 0);
    assert_int_equal(f[names_offset + names_size - 1], 0);
    for (uint16_t i = 0; i < shnum; i++) {
        const uint8_t *h = f + shoff + (size_t)i * shentsize;
        section *s = &elf->sections[elf->section_count++];
        const uint32_t name = le32(h);
        assert_true(name < names_size);
        s->name = (const char *)f + names_offset + name;
        s->type = le32(h + 4);
        s->flags = le32(h + 8);
        s->address = le32(h + 12);
        s->offset = le32(h + 16);
        s->size = le32(h + 20);
        if (s->type != 8 /* SHT_NOBITS */) assert_true((uint64_t)s->offset + s->size <= elf->file.size);
    }
}

static const section *find_section(const elf_image *elf, const char *name)
{
    for (size_t i = 0; i < elf->section_count; i++)
        if (strcmp(elf->sections[i].name, name) == 0) return &elf->sections[i];
    return NULL;
}

/* The flash image the program headers load (physical addresses), from `base`:
 * what a programmer writes, and what the UF2 must carry. */
static uint8_t *flash_image(const elf_image *elf, uint32_t base, uint32_t length, size_t *size)
{
    const uint8_t *f = elf->file.bytes;
    const uint32_t phoff = le32(f + 28);
    const uint16_t phentsize = le16(f + 42), phnum = le16(f + 44);
    assert_true((uint64_t)phoff + (uint64_t)phnum * phentsize <= elf->file.size);
    uint8_t *image = calloc(length, 1);
    assert_non_null(image);
    *size = 0;
    for (uint16_t i = 0; i < phnum; i++) {
        const uint8_t *h = f + phoff + (size_t)i * phentsize;
        const uint32_t type = le32(h), offset = le32(h + 4), paddr = le32(h + 12),
                       filesz = le32(h + 16);
        if (type != 1 /* PT_LOAD */ || filesz == 0) continue;
        assert_true(paddr >= base && (uint64_t)paddr - base + filesz <= length);
        assert_true((uint64_t)offset + filesz <= elf->file.size);
        memcpy(image + (paddr - base), f + offset, filesz);
        if (paddr - base + filesz > *size) *size = paddr - base + filesz;
    }
    return image;
}

/* ---- the bootrom's CRC-32, table-driven ---- */

/* Polynomial 0x04C11DB7, most significant bit first, initial 0xFFFFFFFF, no final
 * xor (RP2040 datasheet §2.8.1.3.1; the parameters known as CRC-32/MPEG-2). */
static uint32_t bootrom_crc32(const uint8_t *bytes, size_t count)
{
    static uint32_t table[256];
    if (table[1] == 0)
        for (uint32_t i = 0; i < 256; i++) {
            uint32_t c = i << 24;
            for (int k = 0; k < 8; k++) c = c & 0x80000000u ? c << 1 ^ 0x04C11DB7u : c << 1;
            table[i] = c;
        }
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < count; i++) crc = crc << 8 ^ table[(crc >> 24 ^ bytes[i]) & 0xFFu];
    return crc;
}

static void test_crc_check_value(void **state)
{
    (void)state;
    /* the catalogued check value of CRC-32/MPEG-2: the table above is that CRC */
    assert_int_equal(bootrom_crc32((const uint8_t *)"123456789", 9), 0x0376E6E7u);
}

/* ---- the checks of one board ---- */

/* The region of the map a section lies wholly inside, NULL for none. */
static const region *region_holding(const region *regions, size_t n, uint32_t address, uint32_t size)
{
    for (size_t i = 0; i < n; i++)
        if (inside(&regions[i], address, size)) return &regions[i];
    return NULL;
}

static void check_link_fit(const char *board, const elf_image *elf, const region *regions, size_t n)
{
    const region *flash = find_region(regions, n, "FLASH"), *ram = find_region(regions, n, "RAM");
    assert_non_null(flash);
    assert_non_null(ram);
    uint32_t end[REGIONS_MAX];
    for (size_t r = 0; r < n; r++) end[r] = regions[r].origin;
    for (size_t i = 0; i < elf->section_count; i++) {
        const section *s = &elf->sections[i];
        if (!(s->flags & 2u /* SHF_ALLOC */) || s->size == 0) continue;
        const region *holder = region_holding(regions, n, s->address, s->size);
        if (holder == NULL)
            fail_msg("%s: section %s (0x%08x, %u bytes) lies outside every region of the link's map", board,
                     s->name, (unsigned)s->address, (unsigned)s->size);
        const int ram_only = strcmp(s->name, ".data") == 0 || strcmp(s->name, ".bss") == 0 ||
                             strcmp(s->name, ".stack") == 0;
        if (ram_only && holder != ram)
            fail_msg("%s: section %s (0x%08x) lies in %s, not RAM", board, s->name, (unsigned)s->address,
                     holder->name);
        const size_t r = (size_t)(holder - regions);
        if (s->address + s->size > end[r]) end[r] = s->address + s->size;
    }
    size_t loaded;
    uint8_t *image = flash_image(elf, flash->origin, flash->length, &loaded); /* asserts LMAs */
    free(image);
    const size_t f = (size_t)(flash - regions);
    if (flash->origin + loaded > end[f]) end[f] = flash->origin + (uint32_t)loaded;
    for (size_t r = 0; r < n; r++)
        print_message("%s: %s %u of %u bytes (%u free)\n", board, regions[r].name,
                      (unsigned)(end[r] - regions[r].origin), (unsigned)regions[r].length,
                      (unsigned)(regions[r].origin + regions[r].length - end[r]));
}

static void check_vector_table(const char *board, const elf_image *elf, const region *regions, size_t n)
{
    const region *flash = find_region(regions, n, "FLASH"), *ram = find_region(regions, n, "RAM");
    const section *text = find_section(elf, ".text"), *boot2 = find_section(elf, ".boot2");
    assert_non_null(text);
    assert_true(text->size >= 8);
    const uint32_t expected = flash->origin + (boot2 != NULL ? BOOT2_BYTES : 0u);
    if (text->address != expected)
        fail_msg("%s: the vector table is at 0x%08x, expected 0x%08x", board,
                 (unsigned)text->address, (unsigned)expected);
    const uint32_t sp = le32(elf->file.bytes + text->offset);
    const uint32_t reset = le32(elf->file.bytes + text->offset + 4);
    if (sp <= ram->origin || sp > ram->origin + ram->length || sp % 8u != 0)
        fail_msg("%s: initial SP 0x%08x is not 8-byte aligned inside RAM", board, (unsigned)sp);
    if ((reset & 1u) == 0) fail_msg("%s: reset vector 0x%08x lacks the Thumb bit", board, (unsigned)reset);
    if ((reset | 1u) != (elf->entry | 1u))
        fail_msg("%s: reset vector 0x%08x is not the entry 0x%08x", board, (unsigned)reset,
                 (unsigned)elf->entry);
    if (!inside(flash, reset & ~1u, 2))
        fail_msg("%s: reset vector 0x%08x is outside flash", board, (unsigned)reset);
    print_message("%s: vector table at 0x%08x: SP 0x%08x, reset 0x%08x\n", board,
                  (unsigned)text->address, (unsigned)sp, (unsigned)reset);
}

static void check_boot2_and_uf2(const char *board, const elf_image *elf, const region *regions, size_t n)
{
    const region *flash = find_region(regions, n, "FLASH");
    const section *boot2 = find_section(elf, ".boot2");
    assert_non_null(boot2);
    assert_int_equal(boot2->address, flash->origin);
    assert_int_equal(boot2->size, BOOT2_BYTES);
    const uint8_t *b2 = elf->file.bytes + boot2->offset;
    const uint32_t stored = le32(b2 + BOOT2_BYTES - 4u), computed = bootrom_crc32(b2, BOOT2_BYTES - 4u);
    if (stored != computed)
        fail_msg("%s: boot2 carries CRC 0x%08x, its 252 bytes give 0x%08x", board,
                 (unsigned)stored, (unsigned)computed);

    size_t loaded;
    uint8_t *image = flash_image(elf, flash->origin, flash->length, &loaded);
    char path[512];
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.uf2", board);
    blob uf2 = read_blob(path);
    if (uf2.bytes == NULL) fail_msg("%s: no %s (make firmware BOARD=%s)", board, path, board);
    if (uf2.size % UF2_BLOCK_BYTES != 0) fail_msg("%s: %zu bytes, not whole 512-byte blocks", path, uf2.size);
    const uint32_t blocks = (uint32_t)(uf2.size / UF2_BLOCK_BYTES);
    const uint32_t expected_blocks = (uint32_t)((loaded + UF2_PAYLOAD_BYTES - 1u) / UF2_PAYLOAD_BYTES);
    if (blocks != expected_blocks)
        fail_msg("%s: %u blocks for %zu bytes of image, expected %u", path, (unsigned)blocks, loaded,
                 (unsigned)expected_blocks);
    for (uint32_t i = 0; i < blocks; i++) {
        const uint8_t *block = uf2.bytes + (size_t)i * UF2_BLOCK_BYTES;
        const uint32_t address = flash->origin + i * UF2_PAYLOAD_BYTES;
        if (le32(block) != 0x0A324655u || le32(block + 4) != 0x9E5D5157u ||
            le32(block + 508) != 0x0AB16F30u)
            fail_msg("%s: block %u: wrong magic numbers", path, (unsigned)i);
        if (le32(block + 8) != 0x00002000u) fail_msg("%s: block %u: flags 0x%08x", path, (unsigned)i, (unsigned)le32(block + 8));
        if (le32(block + 12) != address)
            fail_msg("%s: block %u: address 0x%08x, expected 0x%08x", path, (unsigned)i,
                     (unsigned)le32(block + 12), (unsigned)address);
        if (le32(block + 16) != UF2_PAYLOAD_BYTES || le32(block + 20) != i || le32(block + 24) != blocks ||
            le32(block + 28) != RP2040_FAMILY)
            fail_msg("%s: block %u: payload size, numbering or family wrong", path, (unsigned)i);
        if (memcmp(block + 32, image + (size_t)i * UF2_PAYLOAD_BYTES, UF2_PAYLOAD_BYTES) != 0)
            fail_msg("%s: block %u (0x%08x) differs from the ELF's flash image", path, (unsigned)i,
                     (unsigned)address);
    }
    print_message("%s: boot2 CRC 0x%08x; %s: %u blocks, 0x%08x..0x%08x\n", board, (unsigned)computed,
                  path, (unsigned)blocks, (unsigned)flash->origin,
                  (unsigned)(flash->origin + blocks * UF2_PAYLOAD_BYTES));
    free(uf2.bytes);
    free(image);
}

/* Whether an object of the link (a path ending in obj/FILE.o) is one of the board's
 * BOARD_RAM_CODE entries (folders or .c files of the source tree, space-separated). */
static int in_ram_code(const char *object, const char *ram_code)
{
    const char *file = strstr(object, "/obj/");
    if (file == NULL) return 0;
    file += 5;
    char entries[512];
    snprintf(entries, sizeof entries, "%s", ram_code);
    for (char *entry = strtok(entries, " "); entry != NULL; entry = strtok(NULL, " ")) {
        const size_t n = strlen(entry);
        if (n > 2 && strcmp(entry + n - 2, ".c") == 0) {
            if (strncmp(file, entry, n - 2) == 0 && strcmp(file + n - 2, ".o") == 0) return 1;
        } else if (strncmp(file, entry, n) == 0 && file[n] == '/') {
            return 1;
        }
    }
    return 0;
}

/* The code of the board's BOARD_RAM_CODE runs from RAM and every other function
 * from flash: each input code section of the map (.text.NAME, or .ram.text.NAME once
 * firmware.mk renamed it) is placed by its object. Its load image in flash is
 * checked with the rest (flash_image). */
static void check_ram_code(const char *board, const char *map_path, const char *ram_code,
                           const region *regions, size_t n)
{
    const region *ram = find_region(regions, n, "RAM");
    blob map = read_blob(map_path);
    assert_non_null(map.bytes);
    char *text = malloc(map.size + 1);
    assert_non_null(text);
    memcpy(text, map.bytes, map.size);
    text[map.size] = '\0';
    unsigned long ram_bytes = 0, flash_bytes = 0;
    char *line = strstr(text, "Linker script and memory map");
    for (; line != NULL; line = strchr(line + 1, '\n')) {
        char name[256], object[512];
        unsigned long address, size;
        const char *at = line + 1; /* past the newline (or the heading's first letter) */
        if (at[0] != ' ' || at[1] != '.') continue; /* an input section: one space, its name */
        if (sscanf(at, " %255s", name) != 1) continue;
        if (strncmp(name, ".text", 5) != 0 && strncmp(name, ".ram.text", 9) != 0) continue;
        if (sscanf(at, " %*s 0x%lx 0x%lx %511s", &address, &size, object) != 3) {
            const char *next = strchr(at, '\n'); /* a long name: the rest is on the next line */
            if (next == NULL || sscanf(next + 1, " 0x%lx 0x%lx %511s", &address, &size, object) != 3) continue;
        }
        if (size == 0 || strstr(object, "/obj/") == NULL) continue;
        const int wanted = in_ram_code(object, ram_code), placed = inside(ram, (uint32_t)address, (uint32_t)size);
        if (wanted != placed)
            fail_msg("%s: %s of %s is at 0x%08lx, in %s; BOARD_RAM_CODE (\"%s\") puts it in %s", board, name,
                     object, address, placed ? "RAM" : "flash", ram_code, wanted ? "RAM" : "flash");
        if (placed)
            ram_bytes += size;
        else
            flash_bytes += size;
    }
    if (ram_code[0] != '\0' && ram_bytes == 0)
        fail_msg("%s: BOARD_RAM_CODE is \"%s\", but no code of the map lies in RAM", board, ram_code);
    print_message("%s: %lu bytes of the firmware's own code in RAM (%s), %lu in flash\n", board, ram_bytes,
                  ram_code[0] != '\0' ? ram_code : "none", flash_bytes);
    free(text);
    free(map.bytes);
}

static void test_real_board(void **state)
{
    const char *board = *state;
    char path[512];
    region regions[REGIONS_MAX];
    static elf_image elf;
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.map", board);
    const size_t n = read_regions(path, regions, REGIONS_MAX);
    if (n == 0) fail_msg("%s: no memory regions in %s (make firmware BOARD=%s)", board, path, board);
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.elf", board);
    read_elf(path, &elf);
    check_link_fit(board, &elf, regions, n);
    check_vector_table(board, &elf, regions, n);
    if (find_section(&elf, ".boot2") != NULL) check_boot2_and_uf2(board, &elf, regions, n);
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.conf", board);
    char *conf = firmware_read_file(path, NULL);
    assert_non_null(conf);
    char ram_code[512];
    firmware_conf_value(ram_code, sizeof ram_code, conf, "ram_code");
    free(conf);
    snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.map", board);
    check_ram_code(board, path, ram_code, regions, n);
    free(elf.file.bytes);
}

static void test_no_real_board_built(void **state)
{
    (void)state;
    print_message("no real board built in " FIRMWARE_DIR ": make firmware (make test does it)\n");
    skip();
}

/* Boards whose build says they are not emulated (firmware.conf has emulated=0). */
static size_t find_real_boards(char names[][64], size_t max)
{
    DIR *dir = opendir(FIRMWARE_DIR);
    size_t n = 0;
    if (dir == NULL) return 0;
    for (struct dirent *e; (e = readdir(dir)) != NULL && n < max;) {
        char path[512];
        if (e->d_name[0] == '.' || strlen(e->d_name) >= 64) continue;
        snprintf(path, sizeof path, FIRMWARE_DIR "/%s/firmware.conf", e->d_name);
        blob conf = read_blob(path);
        if (conf.bytes == NULL) continue;
        int real = 0;
        for (size_t i = 0; i + 11 <= conf.size; i++)
            if ((i == 0 || conf.bytes[i - 1] == '\n') && memcmp(conf.bytes + i, "emulated=0\n", 11) == 0)
                real = 1;
        free(conf.bytes);
        if (real) memcpy(names[n++], e->d_name, strlen(e->d_name) + 1);
    }
    closedir(dir);
    firmware_sort_board_names(names, n); /* a stable order */
    return n;
}

int main(void)
{
    static char boards[BOARDS_MAX][64];
    static char names[BOARDS_MAX][96];
    static const char suffix[] = " image is sound";
    static void *states[BOARDS_MAX];
    struct CMUnitTest tests[BOARDS_MAX + 1];
    size_t count = 0;
    tests[count++] = (struct CMUnitTest){"bootrom CRC-32 check value", test_crc_check_value, NULL, NULL, NULL};
    size_t n = find_real_boards(boards, BOARDS_MAX);
    for (size_t i = 0; i < n; i++) {
        memcpy(names[i], boards[i], 64);
        memcpy(names[i] + strlen(boards[i]), suffix, sizeof suffix);
        states[i] = boards[i];
        tests[count++] = (struct CMUnitTest){names[i], test_real_board, NULL, NULL, states[i]};
    }
    if (n == 0)
        tests[count++] = (struct CMUnitTest){"no real board built", test_no_real_board_built, NULL, NULL, NULL};
    return _cmocka_run_group_tests("real_boards", tests, count, NULL, NULL);
}
