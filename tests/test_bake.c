/* test_bake.c: `tarn bake` loses nothing and writes nothing more.
 *
 * The real binary ($TARN_BIN) bakes a scene into a temporary directory; a small
 * main written here renders the baked scene.c, compiled with the host compiler
 * together with the core's sources, and the frame must match, byte for byte, the
 * same scene loaded from JSON and rendered in this process, at two clock times.
 * The baked file
 * must also compile for a Cortex-M0 under -pedantic -Werror, with .rodata exactly
 * the const bytes the baker reports; and every bad input must exit 2 with one line
 * and leave no file. Run from the repository root (as `make check` does). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "backdrop.h"
#include "core_render.h"
#include "scene_load.h"
#include "static_view.h"

#define PATH_SIZE 1024
#define COMMAND_SIZE 4096

/* Strict enough to catch any warning the baked source could raise. */
#define STRICT_C99 "-std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes"
#define M0_FLAGS "-std=c99 -pedantic -Wall -Wextra -Werror -mcpu=cortex-m0 -mthumb"

static char work_dir[] = "/tmp/tarn_bake_XXXXXX";
static char root[PATH_SIZE];

static const char *tarn_bin(void)
{
    const char *bin = getenv("TARN_BIN");
    return bin && *bin ? bin : "build/release/tarn";
}

static int shell(const char *format, ...) __attribute__((format(printf, 1, 2)));

/* Runs a shell command; its exit status, or -1 if it did not exit normally. */
static int shell(const char *format, ...)
{
    char command[COMMAND_SIZE];
    va_list args;
    va_start(args, format);
    int n = vsnprintf(command, sizeof command, format, args);
    va_end(args);
    assert_true(n > 0 && (size_t)n < sizeof command);
    int status = system(command);
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The whole file, NUL-terminated; `size` (may be NULL) gets its length. */
static char *read_all(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) fail_msg("cannot open %s", path);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    long length = ftell(f);
    assert_true(length >= 0);
    rewind(f);
    char *text = malloc((size_t)length + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)length, f), (size_t)length);
    fclose(f);
    text[length] = '\0';
    if (size) *size = (size_t)length;
    return text;
}

static size_t occurrences(const char *text, const char *needle)
{
    size_t n = 0;
    for (const char *at = strstr(text, needle); at; at = strstr(at + 1, needle)) n++;
    return n;
}

static int file_exists(const char *path)
{
    struct stat info;
    return stat(path, &info) == 0;
}

/* The core compiled into the suite's directory, in DIR, with extra C flags (a link
 * header's -include, a switch's -D); the shell's status. */
static int compile_core(const char *dir, const char *flags)
{
    return shell("mkdir %s/%s && cd %s/%s && cc -std=c99 -O1 %s -I'%s/core' -I'%s/core/include' -c '%s'/core/*/*.c",
                 work_dir, dir, work_dir, dir, flags, root, root, root);
}

/* The suite's directory holds the core compiled once, in core/, shared by every
 * round trip; a test that needs other switches compiles its own beside it. */
static int suite_setup(void **state)
{
    (void)state;
    if (!getcwd(root, sizeof root) || !mkdtemp(work_dir)) return -1;
    return compile_core("core", "") == 0 ? 0 : -1;
}

static int suite_teardown(void **state)
{
    (void)state;
    return shell("rm -rf %s", work_dir) == 0 ? 0 : -1;
}

/* ---- baking ------------------------------------------------------------------- */

typedef struct {
    char source[PATH_SIZE]; /* DIR/NAME.c */
    char header[PATH_SIZE]; /* DIR/NAME.h */
    size_t const_bytes, memory_bytes;
} baked;

/* `tarn bake SCENE -o DIR/NAME.c EXTRA` must succeed and report NAME. */
static void bake(const char *scene, const char *name, const char *extra, baked *out)
{
    char stdout_path[PATH_SIZE], expected[256];
    snprintf(out->source, sizeof out->source, "%s/%s.c", work_dir, name);
    snprintf(out->header, sizeof out->header, "%s/%s.h", work_dir, name);
    snprintf(stdout_path, sizeof stdout_path, "%s/%s.stdout", work_dir, name);
    if (shell("%s bake %s -o %s %s > %s", tarn_bin(), scene, out->source, extra, stdout_path) != 0)
        fail_msg("tarn bake %s %s failed", scene, extra);
    char *line = read_all(stdout_path, NULL);
    unsigned long const_bytes = 0, memory_bytes = 0;
    snprintf(expected, sizeof expected, "bake scene=%s const_bytes=%%lu memory_bytes=%%lu", name);
    if (sscanf(line, expected, &const_bytes, &memory_bytes) != 2 || occurrences(line, "\n") != 1)
        fail_msg("stdout is not one 'bake scene=%s ...' line: %s", name, line);
    free(line);
    out->const_bytes = const_bytes;
    out->memory_bytes = memory_bytes;
}

/* ---- round trips ---------------------------------------------------------------- */

/* Renders the baked scene, at the clock given on its command line, to raw RGB. */
static const char main_template[] =
    "#include <stdio.h>\n"
    "#include <stdlib.h>\n"
    "#include \"@NAME@.h\"\n"
    "\n"
    "static uint32_t memory[(@MACRO@_MEMORY_BYTES + 3) / 4];\n"
    "static uint8_t *frame;\n"
    "static uint16_t frame_width;\n"
    "\n"
    "static int copy_tile(void *user, const tarn_tile *tile)\n"
    "{\n"
    "    (void)user;\n"
    "    for (int y = 0; y < tile->height; y++) {\n"
    "        for (int x = 0; x < tile->width; x++) {\n"
    "            uint32_t pixel = tile->rgb[(size_t)y * tile->stride + (size_t)x];\n"
    "            uint8_t *to = frame + 3 * ((size_t)(tile->y + y) * frame_width + (size_t)(tile->x + x));\n"
    "            to[0] = (uint8_t)(pixel >> 16);\n"
    "            to[1] = (uint8_t)(pixel >> 8);\n"
    "            to[2] = (uint8_t)pixel;\n"
    "        }\n"
    "    }\n"
    "    return 0;\n"
    "}\n"
    "\n"
    "int main(int argc, char **argv)\n"
    "{\n"
    "    tarn_frame_config config = @NAME@_config;\n"
    "    if (argc != 3) return 2;\n"
    "    config.time_ms = (uint32_t)strtoul(argv[2], NULL, 10);\n"
    "    size_t bytes = 3u * config.width * config.height;\n"
    "    frame_width = config.width;\n"
    "    frame = malloc(bytes);\n"
    "    if (frame == NULL) return 3;\n"
    "    tarn_status status = tarn_render_frame(&@NAME@_scene, &config, memory, sizeof memory, copy_tile, NULL);\n"
    "    if (status != TARN_OK) {\n"
    "        fprintf(stderr, \"%s\\n\", tarn_status_text(status));\n"
    "        return 4;\n"
    "    }\n"
    "    FILE *out = fopen(argv[1], \"wb\");\n"
    "    if (out == NULL || fwrite(frame, bytes, 1, out) != 1 || fclose(out) != 0) return 5;\n"
    "    free(frame);\n"
    "    return 0;\n"
    "}\n";

/* The template with @NAME@ and @MACRO@ (NAME in capitals) filled in. */
static void write_main(const char *path, const char *name)
{
    char macro[64];
    size_t n = 0;
    for (; name[n] && n + 1 < sizeof macro; n++)
        macro[n] = name[n] >= 'a' && name[n] <= 'z' ? (char)(name[n] - 'a' + 'A') : name[n];
    macro[n] = '\0';
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (const char *c = main_template; *c;) {
        if (strncmp(c, "@NAME@", 6) == 0) {
            fputs(name, f);
            c += 6;
        } else if (strncmp(c, "@MACRO@", 7) == 0) {
            fputs(macro, f);
            c += 7;
        } else {
            fputc(*c++, f);
        }
    }
    assert_int_equal(fclose(f), 0);
}

/* The baked scene's frame at `time_ms`, from the compiled program. */
static uint8_t *render_baked(const char *program, const char *name, uint32_t time_ms, size_t *size)
{
    char frame_path[PATH_SIZE];
    snprintf(frame_path, sizeof frame_path, "%s/%s-%lu.rgb", work_dir, name, (unsigned long)time_ms);
    if (shell("%s %s %lu", program, frame_path, (unsigned long)time_ms) != 0)
        fail_msg("the baked %s did not render at %lu ms", name, (unsigned long)time_ms);
    return (uint8_t *)read_all(frame_path, size);
}

static void assert_same_frame(const uint8_t *baked_rgb, const uint8_t *loaded_rgb,
                              const tarn_frame_config *config, const char *name, uint32_t time_ms)
{
    size_t pixels = (size_t)config->width * config->height;
    for (size_t p = 0; p < pixels; p++) {
        if (memcmp(baked_rgb + 3 * p, loaded_rgb + 3 * p, 3) != 0)
            fail_msg("%s at %lu ms: pixel (%zu, %zu) is %02x%02x%02x baked, %02x%02x%02x loaded", name,
                     (unsigned long)time_ms, p % config->width, p / config->width, baked_rgb[3 * p],
                     baked_rgb[3 * p + 1], baked_rgb[3 * p + 2], loaded_rgb[3 * p], loaded_rgb[3 * p + 1],
                     loaded_rgb[3 * p + 2]);
    }
}

/* The frame of `scene` loaded from its file, as `tarn render` would draw it. */
static void render_loaded(const tarn_loaded_scene *scene, const tarn_frame_config *config, uint8_t *rgb)
{
    tarn_error err;
    if (tarn_core_render(&scene->scene, config, rgb, NULL, &err) != 0) fail_msg("%s", err.message);
}

/* The baked scene's program from the bake `b` and the core in the suite's DIR. */
static void build_program(const char *name, const baked *b, const char *core_dir, char program[PATH_SIZE])
{
    char main_path[PATH_SIZE];
    snprintf(main_path, sizeof main_path, "%s/bake_main_%s.c", work_dir, name);
    snprintf(program, PATH_SIZE, "%s/bake_main_%s", work_dir, name);
    write_main(main_path, name);
    if (shell("cc " STRICT_C99 " -O1 -Icore/include -I%s -o %s %s %s %s/%s/*.o", work_dir, program, main_path,
              b->source, work_dir, core_dir) != 0)
        fail_msg("%s does not build with the host compiler and the core in %s", b->source, core_dir);
}

/* Bakes `scene` (with `extra` options), builds the baked program and compares its
 * frames at 0 ms and at `later_ms` with the loaded scene's, or with `still`, its
 * water's over a still-water backdrop made on the host. `config` starts as the
 * scene's own frame at default quality; `adjust`, if given, applies `extra` to it.
 * The program links the core compiled in the suite's `core_dir`. */
static void round_trip_against(const char *scene_path, const char *name, const char *extra,
                               void (*adjust)(tarn_frame_config *config), uint32_t later_ms, int still,
                               const char *core_dir)
{
    baked b;
    bake(scene_path, name, extra, &b);
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load(scene_path, &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {scene.width, scene.height, tarn_quality_default(), 0};
    if (adjust) adjust(&config);
    tarn_backdrop_scene over;
    if (still && tarn_backdrop_scene_make(&scene.scene, &config, tarn_backdrop_of(TARN_BACKDROP_STILL), 0, &over, &err) != 0)
        fail_msg("%s", err.message);
    tarn_loaded_scene reference = scene;
    if (still) reference.scene = over.water.scene;
    /* the bake's static view gives the frame its bins from flash */
    assert_int_equal(b.memory_bytes, still ? tarn_frame_memory_bytes(&config, &reference.scene)
                                           : tarn_static_memory_bytes(&config, &scene.scene, &config));

    char program[PATH_SIZE];
    build_program(name, &b, core_dir, program);

    size_t bytes = 3u * config.width * config.height, got;
    uint8_t *loaded_rgb = malloc(bytes);
    assert_non_null(loaded_rgb);
    const uint32_t times[2] = {0, later_ms};
    for (int k = 0; k < 2; k++) {
        config.time_ms = times[k];
        render_loaded(&reference, &config, loaded_rgb);
        uint8_t *baked_rgb = render_baked(program, name, times[k], &got);
        assert_int_equal(got, bytes);
        assert_same_frame(baked_rgb, loaded_rgb, &config, name, times[k]);
        free(baked_rgb);
    }
    free(loaded_rgb);
    if (still) tarn_backdrop_scene_free(&over);
    tarn_scene_free(&scene);
}

static void round_trip(const char *scene_path, const char *name, const char *extra,
                       void (*adjust)(tarn_frame_config *config), uint32_t later_ms)
{
    round_trip_against(scene_path, name, extra, adjust, later_ms, 0, "core");
}

/* The pond's flat water keeps its plane, and the default quality (balanced) links
 * the code that takes its texture coordinates from it: the baked frames are the
 * loaded scene's. */
static void test_pond_bakes_without_loss(void **state)
{
    (void)state;
    round_trip("scenes/pond.json", "pond", "", NULL, 2750);
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/pond.c", work_dir);
    char *source = read_all(path, NULL);
    assert_int_equal(occurrences(source, "static const tarn_uv_plane "), 1);
    free(source);
    snprintf(path, sizeof path, "%s/pond_link.h", work_dir);
    source = read_all(path, NULL);
    assert_non_null(strstr(source, "#define TARN_LINK_WATER_PLANE 1\n"));
    free(source);
}

/* A moving scene keeps its motion: the baked frames (camera, light and objects posed
 * by the firmware's core) are the loaded scene's, and nothing is frozen. */
static void test_moving_scenes_bake_without_loss(void **state)
{
    (void)state;
    round_trip("scenes/pond-orbit.json", "pond_orbit", "--name pond_orbit", NULL, 5000);
    round_trip("scenes/lake-drift.json", "lake_drift", "--name lake_drift", NULL, 10500);
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/pond_orbit.c", work_dir);
    char *source = read_all(path, NULL);
    assert_non_null(strstr(source, "The scene moves (the camera, 2 objects): nothing is frozen"));
    assert_null(strstr(source, "static_vertices["));
    free(source);
    snprintf(path, sizeof path, "%s/pond_orbit_link.h", work_dir);
    source = read_all(path, NULL);
    assert_non_null(strstr(source, "#define TARN_LINK_MOTION 1\n"));
    free(source);
}

static void test_foam_bakes_without_loss(void **state)
{
    (void)state;
    round_trip("scenes/effects/foam.json", "foam", "", NULL, 4321);
}

static void small_foam(tarn_frame_config *config)
{
    config->width = 100;
    config->height = 60;
    config->quality.tile_size = 16;
    config->quality.depth_bits = 16;
    config->quality.perspective = TARN_PERSPECTIVE_SPAN;
    config->quality.perspective_span = 8;
    config->quality.exp2.entries = 32;
    config->quality.exp2.interpolate = 0;
}

/* --size and the quality knobs become the baked config; --name the symbols. */
static void test_size_quality_and_name_are_baked(void **state)
{
    (void)state;
    round_trip("scenes/effects/foam.json", "foam_small",
               "--name foam_small --size 100x60 --tile 16 --depth 16 --perspective span:8 --exp2 32:nearest",
               small_foam, 900);
}

/* The underwater block and its normal map, and pointers to textures by water. */
static void test_underwater_bakes_without_loss(void **state)
{
    (void)state;
    round_trip("scenes/effects/underwater.json", "underwater", "", NULL, 1500);
}

static void fast_quality(tarn_frame_config *config)
{
    config->quality = tarn_quality_preset(TARN_PRESET_FAST);
}

/* The same over still water, whose coordinates are its plane's (--backdrop still
 * sets the quality so). */
static void fast_still_quality(tarn_frame_config *config)
{
    fast_quality(config);
    config->quality.water_coordinates = TARN_WATER_UV_PLANE;
}

/* --backdrop on: the water objects alone, with the picture of the rest, render the
 * loaded scene's frames; the ground's texture and meshes are left out. */
static void test_backdrop_bakes_without_loss(void **state)
{
    (void)state;
    round_trip("scenes/pond.json", "pond_backdrop", "--name pond_backdrop --quality fast --backdrop on",
               fast_quality, 2750);
    round_trip("scenes/effects/underwater.json", "underwater_backdrop", "--name underwater_backdrop --backdrop on",
               NULL, 1500);
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/pond_backdrop.c", work_dir);
    char *source = read_all(path, NULL);
    assert_int_equal(occurrences(source, "ground.png"), 0);
    assert_int_equal(occurrences(source, "static const tarn_mesh "), 1);
    assert_non_null(strstr(source, "static const tarn_object pond_backdrop_objects[1] = {"));
    assert_non_null(strstr(source, "static const uint32_t pond_backdrop_backdrop_palette[5719] = {"));
    assert_non_null(strstr(source, "the 5719 colours the opaque objects draw, ascending, each named by a 13-bit index"));
    assert_non_null(strstr(source, "    .backdrop = &pond_backdrop_backdrop,\n    .positions = pond_backdrop_static_positions\n"));
    assert_non_null(strstr(source, " *   backdrop "));
    free(source);
    snprintf(path, sizeof path, "%s/pond_backdrop_link.h", work_dir);
    char *link = read_all(path, NULL);
    assert_non_null(strstr(link, "#define TARN_LINK_BACKDROP 1\n"));
    free(link);
}

/* --backdrop still: the water's moving terms over the picture of the rest and the
 * still water render as the host draws them; only the shading the backdrop holds
 * is left out of the build. */
static void test_still_water_bakes_without_loss(void **state)
{
    (void)state;
    round_trip_against("scenes/pond.json", "pond_still", "--name pond_still --quality fast --backdrop still",
                       fast_still_quality, 2750, 1, "core");
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/pond_still.c", work_dir);
    char *source = read_all(path, NULL);
    assert_non_null(strstr(source, "the opaque objects and the still water (with its marks) draw, ascending, "
                                   "each named by a 14-bit index"));
    assert_non_null(strstr(source, "where foam can show"));
    free(source);
    snprintf(path, sizeof path, "%s/pond_still_link.h", work_dir);
    char *link = read_all(path, NULL);
    assert_non_null(strstr(link, "#define TARN_LINK_STILL_WATER 1\n"));
    assert_non_null(strstr(link, "#define TARN_LINK_WATER_SHADING 0\n"));
    free(link);
}

/* tests/bake_unused.json: an unused material with its own texture, and two boxes
 * of identical mesh data. Only the used texture and material are baked, the mesh
 * once; and the result still renders the same. */
static void test_only_what_is_used_is_baked(void **state)
{
    (void)state;
    round_trip("tests/bake_unused.json", "bake_unused", "", NULL, 0);
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/bake_unused.c", work_dir);
    char *source = read_all(path, NULL);
    assert_int_equal(occurrences(source, "foam.png"), 1);
    assert_int_equal(occurrences(source, "ground.png"), 0);
    assert_int_equal(occurrences(source, "static const tarn_texture "), 1);
    assert_int_equal(occurrences(source, "static const tarn_material "), 1);
    assert_int_equal(occurrences(source, "static const tarn_mesh "), 1);
    assert_int_equal(occurrences(source, ".mesh = &bake_unused_mesh_0,"), 2);
    assert_non_null(strstr(source, "#include \"tarn/tarn_render.h\"\n"));
    assert_non_null(strstr(source, " *   tarn bake tests/bake_unused.json -o "));
    free(source);
}

/* Two water materials, fog and fresnel and fog alone: the link header links both
 * effects and names fog the one every material has, which no water pixel then asks
 * for; the core compiled with that header draws the loaded scene's frame, and one
 * told that every material has fresnel refuses the scene. */
static void test_effects_every_water_has_are_not_asked(void **state)
{
    (void)state;
    baked b;
    bake("tests/bake_two_waters.json", "two_waters", "--name two_waters", &b);
    char path[PATH_SIZE], flags[2 * PATH_SIZE], program[PATH_SIZE];
    snprintf(path, sizeof path, "%s/two_waters_link.h", work_dir);
    char *header = read_all(path, NULL);
    if (strstr(header, "#define TARN_LINK_WATER_FEATURES (TARN_WATER_FOG | TARN_WATER_FRESNEL)\n") == NULL ||
        strstr(header, "#define TARN_LINK_WATER_FEATURES_ALL (TARN_WATER_FOG)\n") == NULL)
        fail_msg("two_waters_link.h links other water effects than fog and fresnel, fog in both:\n%s", header);
    free(header);

    snprintf(flags, sizeof flags, "-include '%s'", path);
    if (compile_core("core-two-waters", flags) != 0) fail_msg("the core does not compile with %s", flags);
    build_program("two_waters", &b, "core-two-waters", program);
    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load("tests/bake_two_waters.json", &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {scene.width, scene.height, tarn_quality_default(), 0};
    size_t bytes = 3u * config.width * config.height, got;
    uint8_t *loaded_rgb = malloc(bytes);
    assert_non_null(loaded_rgb);
    render_loaded(&scene, &config, loaded_rgb);
    uint8_t *baked_rgb = render_baked(program, "two_waters", 0, &got);
    assert_int_equal(got, bytes);
    assert_same_frame(baked_rgb, loaded_rgb, &config, "two_waters", 0);
    free(baked_rgb);
    free(loaded_rgb);
    tarn_scene_free(&scene);

    if (compile_core("core-all-fresnel", "-DTARN_LINK_WATER_FEATURES_ALL=TARN_WATER_FRESNEL") != 0)
        fail_msg("the core does not compile with TARN_LINK_WATER_FEATURES_ALL=TARN_WATER_FRESNEL");
    build_program("two_waters", &b, "core-all-fresnel", program);
    char frame_path[PATH_SIZE];
    snprintf(frame_path, sizeof frame_path, "%s/two_waters-refused.rgb", work_dir);
    char stderr_path[PATH_SIZE];
    snprintf(stderr_path, sizeof stderr_path, "%s/two_waters.stderr", work_dir);
    const int status = shell("%s %s 0 2> %s", program, frame_path, stderr_path);
    char *said = read_all(stderr_path, NULL);
    if (status != 4 || strstr(said, "malformed scene data") == NULL)
        fail_msg("a core told every water has fresnel drew the puddle without it: status %d, '%s'", status, said);
    free(said);
}

/* The companion header: the memory macro and both declarations. */
static void test_header_declares_memory_and_objects(void **state)
{
    (void)state;
    baked b;
    bake("scenes/effects/foam.json", "foam_header", "--name foam_header --size 64x64", &b);
    char *header = read_all(b.header, NULL);
    char define[128];
    snprintf(define, sizeof define, "#define FOAM_HEADER_MEMORY_BYTES %zu\n", b.memory_bytes);
    assert_non_null(strstr(header, define));
    assert_non_null(strstr(header, "extern const tarn_scene foam_header_scene;\n"));
    assert_non_null(strstr(header, "extern const tarn_frame_config foam_header_config;\n"));
    assert_null(strstr(header, "_PIPELINE_MEMORY_BYTES")); /* a frame in tiles has no strip pipeline */
    free(header);
    char *source = read_all(b.source, NULL);
    snprintf(define, sizeof define, " *   %-15s %9zu\n", "total", b.const_bytes);
    assert_non_null(strstr(source, define));
    assert_non_null(strstr(source, "const tarn_scene foam_header_scene = {\n"));
    assert_non_null(strstr(source, "const tarn_frame_config foam_header_config = {\n    .width = 64,\n"));
    free(source);
}

/* A frame in strips: the header gives a strip pipeline's memory too, a strip of
 * the ring and the second worker's water strip (the pond refracts, so its water is
 * drawn from a copy of the strip: 64 pixels, 16 rows, 4 bytes of colour and 4 of
 * depth each) and the workers' state more than the frame's. */
static void test_header_gives_a_strip_pipeline_memory(void **state)
{
    (void)state;
    baked b;
    bake("scenes/pond.json", "pond_strips", "--name pond_strips --size 64x64 --quality exact --frame strips --tile 16",
         &b);
    char *header = read_all(b.header, NULL);
    const char *define = strstr(header, "#define POND_STRIPS_PIPELINE_MEMORY_BYTES ");
    if (define == NULL) fail_msg("no POND_STRIPS_PIPELINE_MEMORY_BYTES in %s", b.header);
    const unsigned long bytes = strtoul(define + strlen("#define POND_STRIPS_PIPELINE_MEMORY_BYTES "), NULL, 10);
    const unsigned long strip = 64ul * 16ul * 8ul;
    if (bytes < b.memory_bytes + 2ul * strip || bytes > b.memory_bytes + 2ul * strip + 8192ul)
        fail_msg("the pipeline's memory is %lu bytes, the frame's %zu", bytes, b.memory_bytes);
    free(header);
}

/* --points FILE: the qualities as NAME_points, their count, the largest memory of
 * all, and the link header keeping span perspective when only a point uses it. */
static void test_points_are_baked(void **state)
{
    (void)state;
    char points[PATH_SIZE], extra[COMMAND_SIZE];
    snprintf(points, sizeof points, "%s/points.txt", work_dir);
    FILE *f = fopen(points, "w");
    assert_non_null(f);
    fputs("# three points\n\n--tile 32   # more memory than the bake's 16\n"
          "  --perspective span:8 --depth 16\n"
          "--tile 16 --quality fast   # the preset is the base, wherever it stands\n", f);
    assert_int_equal(fclose(f), 0);
    baked b;
    snprintf(extra, sizeof extra, "--name swept --size 64x64 --tile 16 --perspective pixel --points %s", points);
    bake("scenes/effects/foam.json", "swept", extra, &b);

    tarn_loaded_scene scene;
    tarn_error err;
    if (tarn_scene_load("scenes/effects/foam.json", &scene, &err) != 0) fail_msg("%s", err.message);
    tarn_frame_config config = {64, 64, tarn_quality_default(), 0};
    config.quality.tile_size = 16;
    config.quality.perspective = TARN_PERSPECTIVE_PIXEL;
    const tarn_frame_config baked_config = config;
    size_t own = tarn_static_memory_bytes(&config, &scene.scene, &baked_config);
    config.quality.tile_size = 32;
    size_t largest = tarn_static_memory_bytes(&config, &scene.scene, &baked_config);
    tarn_scene_free(&scene);
    assert_true(largest > own);
    assert_int_equal(b.memory_bytes, largest);

    char *header = read_all(b.header, NULL), define[128];
    snprintf(define, sizeof define, "#define SWEPT_MEMORY_BYTES %zu\n", largest);
    assert_non_null(strstr(header, define));
    assert_non_null(strstr(header, "#define SWEPT_POINT_COUNT 3\n"));
    assert_non_null(strstr(header, "extern const tarn_quality swept_points[];\n"));
    free(header);
    char *source = read_all(b.source, NULL);
    const char *array = strstr(source, "const tarn_quality swept_points[3] = {\n");
    assert_non_null(array);
    assert_null(strstr(source, "static const tarn_quality swept_points"));
    const char *second = strstr(array, "    },\n    {\n");
    assert_non_null(second);
    /* point 1: the bake's quality with --tile 32; point 2: span:8 and depth 16 at tile 16 */
    const char *tile32 = strstr(array, ".tile_size = 32,"), *span = strstr(array, ".perspective_span = 8,");
    assert_true(tile32 != NULL && tile32 < second);
    assert_true(span != NULL && span > second);
    assert_non_null(strstr(second, ".depth_bits = 16,"));
    assert_non_null(strstr(second, ".tile_size = 16,"));
    const char *third = strstr(second + 1, "    },\n    {\n");
    assert_non_null(third);
    assert_true(strstr(second, ".depth_bits = 16,") < third);
    /* point 3: the fast preset (16 exp2 entries, nearest), not the bake's 64, at tile 16 */
    assert_non_null(strstr(third, ".entries = 16,\n            .interpolate = 0"));
    assert_non_null(strstr(third, ".tile_size = 16,"));
    free(source);

    char link[PATH_SIZE];
    snprintf(link, sizeof link, "%s/swept_link.h", work_dir);
    char *link_text = read_all(link, NULL);
    assert_non_null(strstr(link_text, "#define TARN_LINK_PERSPECTIVE_SPAN 1\n"));
    assert_non_null(strstr(link_text, "#define TARN_LINK_APRON 1\n")); /* the bake's own quality has one */
    free(link_text);
    if (shell("command -v arm-none-eabi-gcc > /dev/null") == 0 &&
        shell("arm-none-eabi-gcc " M0_FLAGS " -Icore/include -c %s -o %s/swept-m0.o", b.source, work_dir) != 0)
        fail_msg("%s does not compile for Cortex-M0", b.source);
}

/* ---- Cortex-M0 ------------------------------------------------------------------ */

/* `arm-none-eabi-gcc` with the flags firmware uses, and .rodata the size reported. */
static void assert_builds_for_m0(const char *scene_path, const char *name)
{
    baked b;
    char extra[128];
    snprintf(extra, sizeof extra, "--name %s", name);
    bake(scene_path, name, extra, &b);
    char object[PATH_SIZE], sizes[PATH_SIZE];
    snprintf(object, sizeof object, "%s/%s-m0.o", work_dir, name);
    snprintf(sizes, sizeof sizes, "%s/%s-m0.size", work_dir, name);
    if (shell("arm-none-eabi-gcc " M0_FLAGS " -Icore/include -c %s -o %s", b.source, object) != 0)
        fail_msg("%s does not compile for Cortex-M0", b.source);
    if (shell("command -v arm-none-eabi-size > /dev/null") != 0) return;
    assert_int_equal(shell("arm-none-eabi-size -A %s | awk '$1 == \".rodata\" {print $2}' > %s", object, sizes), 0);
    char *text = read_all(sizes, NULL);
    unsigned long rodata = strtoul(text, NULL, 10);
    free(text);
    if (rodata != b.const_bytes)
        fail_msg("%s: .rodata holds %lu bytes, the bake reported const_bytes=%zu", name, rodata, b.const_bytes);
}

static void test_baked_source_compiles_for_cortex_m0(void **state)
{
    (void)state;
    if (shell("command -v arm-none-eabi-gcc > /dev/null") != 0) {
        print_message("arm-none-eabi-gcc is not installed: the Cortex-M0 compile is skipped (CI has it)\n");
        skip();
    }
    assert_builds_for_m0("scenes/pond.json", "pond_m0");
    assert_builds_for_m0("scenes/effects/foam.json", "foam_m0");
    assert_builds_for_m0("scenes/pond-orbit.json", "orbit_m0");
}

/* ---- bad input ------------------------------------------------------------------ */

/* Names in `dir` other than "." and ".." and `allowed` (may be NULL); 0 if none. */
static int stray_file(const char *dir, const char *allowed, char *name, size_t size)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int found = 0;
    for (struct dirent *e; !found && (e = readdir(d)) != NULL;) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        if (allowed && strcmp(e->d_name, allowed) == 0) continue;
        snprintf(name, size, "%s", e->d_name);
        found = 1;
    }
    closedir(d);
    return found;
}

/* `tarn bake ARGS` with -o into `out_dir` must exit 2 with one "tarn: " line
 * containing `expect`, and leave nothing in `out_dir` but `allowed`. */
static void assert_bake_refused(const char *args, const char *out_dir, const char *allowed,
                                const char *expect)
{
    char err_path[PATH_SIZE], stray[256];
    snprintf(err_path, sizeof err_path, "%s/bad.stderr", work_dir);
    int status = shell("%s bake %s > /dev/null 2> %s", tarn_bin(), args, err_path);
    char *text = read_all(err_path, NULL);
    if (status != 2) fail_msg("tarn bake %s: exit status %d, expected 2", args, status);
    if (strncmp(text, "tarn: ", 6) != 0 || occurrences(text, "\n") != 1 || text[strlen(text) - 1] != '\n')
        fail_msg("tarn bake %s: stderr is not one 'tarn: ' line: %s", args, text);
    if (!strstr(text, expect)) fail_msg("tarn bake %s: '%s' lacks '%s'", args, text, expect);
    if (stray_file(out_dir, allowed, stray, sizeof stray))
        fail_msg("tarn bake %s: left %s behind", args, stray);
    free(text);
}

static void test_bad_input_exits_2_and_writes_nothing(void **state)
{
    (void)state;
    char out[PATH_SIZE], args[COMMAND_SIZE];
    snprintf(out, sizeof out, "%s/bad_out", work_dir);
    assert_int_equal(shell("mkdir -p %s && touch %s/plain_file", out, out), 0);

    snprintf(args, sizeof args, "%s/missing.json -o %s/x.c", work_dir, out);
    assert_bake_refused(args, out, "plain_file", "missing.json: cannot open");
    snprintf(args, sizeof args, "scenes/pond-orbit.json -o %s/x.c --backdrop on", out);
    assert_bake_refused(args, out, "plain_file",
                        "scenes/pond-orbit.json: --backdrop: the scene moves (the camera, 2 objects), and a backdrop "
                        "is one frame's picture; use --backdrop off");

    snprintf(args, sizeof args, "scenes/pond.json -o %s/plain_file/x.c", out);
    assert_bake_refused(args, out, "plain_file", "cannot create");
    snprintf(args, sizeof args, "scenes/pond.json -o %s/no_such_dir/x.c", out);
    assert_bake_refused(args, out, "plain_file", "cannot create");

    static const char *const bad_names[] = {"3d", "my-scene", "''", "tarn_pond", "TARN", "a.b"};
    for (size_t k = 0; k < sizeof bad_names / sizeof bad_names[0]; k++) {
        snprintf(args, sizeof args, "scenes/pond.json -o %s/x.c --name %s", out, bad_names[k]);
        assert_bake_refused(args, out, "plain_file", "--name: ");
    }
    snprintf(args, sizeof args, "scenes/pond.json -o %s/x.c --name abcdefghijklmnopqrstuvwxyz_abcdefghijklmnop", out);
    assert_bake_refused(args, out, "plain_file", "at most 40 characters");

    snprintf(args, sizeof args, "scenes/pond.json -o %s/x.txt", out);
    assert_bake_refused(args, out, "plain_file", "ending in .c");
    snprintf(args, sizeof args, "scenes/effects/foam.json -o %s/x.c --size 1024x1024 --subpixel 8", out);
    assert_bake_refused(args, out, "plain_file", "1024x1024");

    /* a points file: each bad line named, nothing written */
    static const struct {
        const char *text, *expect;
    } bad_points[] = {
        {"--tile 28\n\n--depth 8\n", "points.txt:3: --depth: expected 16 or 32, got '8'"},
        {"# c\n--tile 28 --frobnicate 3\n", "points.txt:2: unknown quality option '--frobnicate'"},
        {"tile 28\n", "points.txt:1: expected a quality option"},
        {"--tile\n", "points.txt:1: --tile: expected a whole number"},
        {"--tile 64 --subpixel 8\n", "points.txt:1: 1024x1024 with these quality settings"},
        {"--quality nope\n", "points.txt:1: --quality: expected fast, balanced or exact"},
        {"# nothing\n\n", "points.txt: no points"}};
    for (size_t k = 0; k < sizeof bad_points / sizeof bad_points[0]; k++) {
        char points[PATH_SIZE];
        snprintf(points, sizeof points, "%s/points.txt", work_dir);
        FILE *f = fopen(points, "w");
        assert_non_null(f);
        fputs(bad_points[k].text, f);
        assert_int_equal(fclose(f), 0);
        snprintf(args, sizeof args, "scenes/effects/foam.json -o %s/x.c --size 1024x1024 --subpixel 4 --points %s",
                 out, points);
        assert_bake_refused(args, out, "plain_file", bad_points[k].expect);
    }
    snprintf(args, sizeof args, "scenes/effects/foam.json -o %s/x.c --points %s/none.txt", out, work_dir);
    assert_bake_refused(args, out, "plain_file", "none.txt: cannot open: No such file or directory");

}

/* The header cannot be renamed into place (a non-empty directory has its name):
 * the source, already renamed, is removed again, so no half of the pair remains. */
static void test_a_failed_header_removes_the_source(void **state)
{
    (void)state;
    char out[PATH_SIZE], args[COMMAND_SIZE], source[PATH_SIZE + 8];
    snprintf(out, sizeof out, "%s/pair_out", work_dir);
    assert_int_equal(shell("mkdir -p %s/x.h && touch %s/x.h/inside", out, out), 0);
    snprintf(args, sizeof args, "scenes/effects/foam.json -o %s/x.c", out);
    assert_bake_refused(args, out, "x.h", "x.h: is a directory");
    snprintf(source, sizeof source, "%s/x.c", out);
    assert_false(file_exists(source));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pond_bakes_without_loss),
        cmocka_unit_test(test_moving_scenes_bake_without_loss),
        cmocka_unit_test(test_foam_bakes_without_loss),
        cmocka_unit_test(test_size_quality_and_name_are_baked),
        cmocka_unit_test(test_underwater_bakes_without_loss),
        cmocka_unit_test(test_backdrop_bakes_without_loss),
        cmocka_unit_test(test_still_water_bakes_without_loss),
        cmocka_unit_test(test_only_what_is_used_is_baked),
        cmocka_unit_test(test_effects_every_water_has_are_not_asked),
        cmocka_unit_test(test_header_declares_memory_and_objects),
        cmocka_unit_test(test_header_gives_a_strip_pipeline_memory),
        cmocka_unit_test(test_points_are_baked),
        cmocka_unit_test(test_baked_source_compiles_for_cortex_m0),
        cmocka_unit_test(test_bad_input_exits_2_and_writes_nothing),
        cmocka_unit_test(test_a_failed_header_removes_the_source),
    };
    return cmocka_run_group_tests(tests, suite_setup, suite_teardown);
}
