/* consumer.c: a program that uses tarn as an installed or added library would, through
 * tarn/tarn.h alone. tests/check_packages.sh builds it three ways (make install and
 * pkg-config; CMake with add_subdirectory of core/; CMake for a bare Cortex-M0) and
 * compares what they print.
 *
 * It draws a 32x24 frame of a small scene held in C: an opaque floor of two triangles
 * and, above it, a pond of two triangles whose water material has fog, so that the
 * frame runs the opaque and the water passes. It folds the tiles into
 * tarn_checksum_tile and prints
 *     consumer version=X.Y.Z checksum=XXXXXXXX
 * or one line saying what went wrong, with a non-zero exit.
 *
 * Built with CONSUMER_NO_STDIO (the Cortex-M0 build, which has no stdio) it prints
 * nothing: main's return value alone tells. */
#include "tarn/tarn.h"

#include <string.h>
#ifndef CONSUMER_NO_STDIO
#include <stdio.h>
#endif

#define ONE TARN_Q16_ONE
#define FRAME_WIDTH 32u
#define FRAME_HEIGHT 24u

/* Two quads in the plane y = 0 of their objects, counter-clockwise seen from above
 * (+y), which is the side the camera sees. */
static const tarn_vec3 quad_positions[4] = {
    {-ONE, 0, ONE}, {ONE, 0, ONE}, {ONE, 0, -ONE}, {-ONE, 0, -ONE}};
static const tarn_vec3 quad_normals[4] = {{0, ONE, 0}, {0, ONE, 0}, {0, ONE, 0}, {0, ONE, 0}};
static const uint16_t quad_indices[6] = {0, 1, 2, 0, 2, 3};
static const tarn_mesh quad = {quad_positions, quad_normals, NULL, NULL, quad_indices, 4, 2, NULL, 0, NULL};

static const tarn_material floor_material = {0xB08050u, NULL, TARN_CULL_BACK, 0, NULL};

static tarn_water pond_water(void)
{
    tarn_water w;
    memset(&w, 0, sizeof w);
    w.features = TARN_WATER_FOG;
    w.albedo_rgb = 0x2060A0u;
    w.alpha = ONE / 4;
    w.fog_rgb = 0x184060u;
    w.fog_density = ONE;
    w.specular_power = 1;
    return w;
}

static tarn_object object_at(const tarn_material *material, tarn_q16 y, tarn_q16 scale)
{
    tarn_object o;
    memset(&o, 0, sizeof o);
    o.mesh = &quad;
    o.material = material;
    o.position.y = y;
    o.rotation[0][0] = o.rotation[1][1] = o.rotation[2][2] = ONE;
    o.scale = scale;
    return o;
}

typedef struct {
    uint32_t checksum;
    uint32_t pixels;
} frame_sum;

static int sum_tile(void *user, const tarn_tile *tile)
{
    frame_sum *sum = (frame_sum *)user;
    sum->checksum = tarn_checksum_tile(sum->checksum, tile);
    sum->pixels += (uint32_t)tile->width * tile->height;
    return 0;
}

/* Working memory for the frame, 4 KB: main checks that tarn_frame_memory_bytes asks
 * for no more. */
static uint32_t frame_memory[1024];

/* One line on stderr (where there is one), and the exit status of a failure. */
static int fail(const char *what, const char *detail)
{
#ifdef CONSUMER_NO_STDIO
    (void)what;
    (void)detail;
#else
    fprintf(stderr, "consumer: %s%s%s\n", what, detail != NULL ? ": " : "", detail != NULL ? detail : "");
#endif
    return 1;
}

int main(void)
{
    if (strcmp(tarn_version(), TARN_VERSION_STRING) != 0)
        return fail("tarn_version() is not the TARN_VERSION_STRING of the headers", tarn_version());

    const tarn_water water = pond_water();
    tarn_material pond_material = {0xFFFFFFu, NULL, TARN_CULL_BACK, 0, NULL};
    pond_material.water = &water;
    const tarn_object objects[2] = {object_at(&floor_material, -ONE / 2, 2 * ONE),
                                    object_at(&pond_material, 0, ONE)};

    tarn_scene scene;
    memset(&scene, 0, sizeof scene);
    scene.objects = objects;
    scene.object_count = 2;
    scene.camera.position.y = 2 * ONE;
    scene.camera.position.z = 3 * ONE;
    scene.camera.fov_y_degrees = 60 * ONE;
    scene.camera.near = ONE / 10;
    scene.camera.far = 100 * ONE;
    scene.light.direction.y = ONE;
    scene.light.colour_rgb = 0xFFFFFFu;
    scene.light.ambient_rgb = 0x404040u;
    scene.background_rgb = 0x000000u;

    tarn_frame_config config;
    memset(&config, 0, sizeof config);
    config.width = FRAME_WIDTH;
    config.height = FRAME_HEIGHT;
    config.quality = tarn_quality_default();
    config.quality.tile_size = 16;
    config.time_ms = 0;

    const size_t need = tarn_frame_memory_bytes(&config, &scene);
    if (need == 0) return fail("tarn_frame_memory_bytes refused the frame config", NULL);
    if (need > sizeof frame_memory) return fail("the frame needs more memory than frame_memory holds", NULL);

    frame_sum sum = {0, 0};
    const tarn_status status = tarn_render_frame(&scene, &config, frame_memory, sizeof frame_memory, sum_tile, &sum);
    if (status != TARN_OK) return fail("tarn_render_frame did not return TARN_OK", tarn_status_text(status));
    if (sum.pixels != FRAME_WIDTH * FRAME_HEIGHT) return fail("the tiles did not cover the frame once", NULL);

#ifndef CONSUMER_NO_STDIO
    printf("consumer version=%s checksum=%08lx\n", tarn_version(), (unsigned long)sum.checksum);
#endif
    return 0;
}
