/* fuzz_input.c: see fuzz_input.h. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "fuzz_input.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char scratch[PATH_MAX];

/* The scratch directory holds only what the targets write (a handful of names) and
 * the two links; all of it goes when the fuzzer exits. */
static void remove_scratch(void)
{
    static const char *const names[] = {"s/scene.json", "s/baked.c", "s/baked.h", "s/baked_link.h", "mesh.obj",
                                        "texture.png", "s/assets", "assets"};
    char path[PATH_MAX + 32];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", scratch, names[i]);
        unlink(path);
    }
    snprintf(path, sizeof path, "%s/s", scratch);
    rmdir(path);
    rmdir(scratch);
}

static void make_scratch(void)
{
    char assets[PATH_MAX], link_path[PATH_MAX + 16];
    snprintf(scratch, sizeof scratch, "/tmp/tarn-fuzz-XXXXXX");
    if (mkdtemp(scratch) == NULL || realpath("scenes/assets", assets) == NULL) {
        perror("fuzz: scratch directory (run from the repository's root)");
        abort();
    }
    /* the demo's scenes name "assets/..." or, from scenes/effects/, "../assets/...":
     * files are written to s/, so both resolve */
    static const char *const links[] = {"assets", "s/assets"};
    snprintf(link_path, sizeof link_path, "%s/s", scratch);
    if (mkdir(link_path, 0700) != 0) {
        perror("fuzz: scratch directory");
        abort();
    }
    for (int i = 0; i < 2; i++) {
        snprintf(link_path, sizeof link_path, "%s/%s", scratch, links[i]);
        if (symlink(assets, link_path) != 0) {
            perror("fuzz: assets link");
            abort();
        }
    }
    atexit(remove_scratch);
}

const char *fuzz_path(const char *name)
{
    static char path[PATH_MAX + 64];
    if (scratch[0] == '\0') make_scratch();
    snprintf(path, sizeof path, "%s/%s", scratch, name);
    return path;
}

const char *fuzz_write_file(const char *name, const uint8_t *data, size_t size)
{
    const char *path = fuzz_path(name);
    FILE *f = fopen(path, "wb");
    if (f == NULL || (size > 0 && fwrite(data, 1, size, f) != size) || fclose(f) != 0) {
        perror(path);
        abort();
    }
    return path;
}

int fuzz_error_is_one_line(const tarn_error *err)
{
    return err->message[0] != '\0' && strchr(err->message, '\n') == NULL;
}

uint8_t fuzz_u8(fuzz_reader *r)
{
    return r->at < r->size ? r->data[r->at++] : 0u;
}

uint16_t fuzz_u16(fuzz_reader *r)
{
    const uint16_t low = fuzz_u8(r);
    return (uint16_t)(low | (uint16_t)fuzz_u8(r) << 8);
}

uint32_t fuzz_u32(fuzz_reader *r)
{
    const uint32_t low = fuzz_u16(r);
    return low | (uint32_t)fuzz_u16(r) << 16;
}
