/* fuzz_core.c: the core itself, on scenes, cameras and quality settings built from
 * the fuzzer's bytes: any numbers in every field, indices and clusters that may run
 * past their arrays, textures of any size, water with any features, and static
 * vertices, bins and backdrops (tarn_scene.h) that need not agree with anything. The frame's
 * memory is exactly tarn_frame_memory_bytes() from the heap, so AddressSanitizer
 * sees any byte written outside it. A render either refuses (a config or scene
 * error, with nothing sent) or hands over every pixel of the frame exactly once,
 * each a 0x00RRGGBB colour. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_input.h"
#include "tarn/tarn_render.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define OBJECTS_MAX 3u
#define VERTICES_MAX 24u
#define TRIANGLES_MAX 24u
#define FRAME_MAX 40u

typedef struct {
    tarn_vec3 positions[VERTICES_MAX], normals[VERTICES_MAX];
    tarn_static_vertex static_vertices[VERTICES_MAX];
    tarn_uv uvs[VERTICES_MAX];
    uint32_t colours[VERTICES_MAX];
    uint16_t indices[3 * TRIANGLES_MAX];
    tarn_cluster clusters[2];
    tarn_mesh mesh;
    tarn_material material;
    tarn_water water;
} fuzz_object;

typedef struct {
    fuzz_object parts[OBJECTS_MAX];
    tarn_object objects[OBJECTS_MAX];
    tarn_underwater underwater;
    tarn_static_view static_view;
    tarn_vec3 static_positions[OBJECTS_MAX * VERTICES_MAX];
    tarn_cluster_bin bins[2 * OBJECTS_MAX];
    tarn_backdrop backdrop;
    uint32_t palette[16];
    uint16_t colour[FRAME_MAX * FRAME_MAX]; /* at most 16 bits a pixel */
    uint16_t row_spans[FRAME_MAX + 1];
    tarn_backdrop_span spans[2 * FRAME_MAX]; /* at most two a row */
    uint32_t depth[FRAME_MAX * FRAME_MAX];  /* either form of depth */
    tarn_scene scene;
    uint8_t texels[2][16 * 16 * 3];
    tarn_texture textures[2];
} fuzz_scene;

/* A Q16.16 number: mostly small, sometimes anything at all. */
static tarn_q16 number(fuzz_reader *r)
{
    const uint8_t kind = fuzz_u8(r);
    const uint32_t bits = fuzz_u32(r);
    if (kind < 192) return (tarn_q16)(int16_t)bits * 64; /* within +-512 units */
    return (tarn_q16)bits;
}

/* A Q16.16 number in [lo, hi], or (one time in sixteen) any number at all: fields
 * the scene check bounds get mostly values it accepts, so that frames get drawn. */
static tarn_q16 number_in(fuzz_reader *r, tarn_q16 lo, tarn_q16 hi)
{
    const uint8_t kind = fuzz_u8(r);
    const uint32_t bits = fuzz_u32(r);
    if ((kind & 0xF0u) == 0xF0u) return (tarn_q16)bits;
    return (tarn_q16)((int64_t)lo + (int64_t)(bits % ((uint64_t)((int64_t)hi - lo) + 1u)));
}

static tarn_vec3 vector(fuzz_reader *r)
{
    tarn_vec3 v = {number(r), number(r), number(r)};
    return v;
}

/* Textures of 1 to 16 texels a side; a side that is no power of two is malformed. */
static void make_textures(fuzz_scene *s, fuzz_reader *r)
{
    for (int t = 0; t < 2; t++) {
        /* sides of 1 to 16 texels, a power of two fifteen times in sixteen */
        const uint8_t w = fuzz_u8(r), h = fuzz_u8(r);
        s->textures[t].width = (uint16_t)((w & 0xF0u) == 0xF0u ? 1u + w % 16u : 1u << (w % 5u));
        s->textures[t].height = (uint16_t)((h & 0xF0u) == 0xF0u ? 1u + h % 16u : 1u << (h % 5u));
        for (size_t i = 0; i < sizeof s->texels[t]; i++) s->texels[t][i] = (uint8_t)(i * 37u + fuzz_u8(r));
        s->textures[t].rgb = s->texels[t];
    }
}

static const tarn_texture *texture_or_null(fuzz_scene *s, fuzz_reader *r)
{
    const uint8_t pick = fuzz_u8(r) % 3u;
    return pick == 2u ? NULL : &s->textures[pick];
}

static tarn_panning panning(fuzz_reader *r)
{
    tarn_panning p = {number(r), number(r), number(r)};
    return p;
}

static void make_water(fuzz_scene *s, tarn_water *w, fuzz_reader *r)
{
    w->features = fuzz_u16(r) & 0x1FFu;
    w->albedo_rgb = fuzz_u32(r);
    w->alpha = number_in(r, 0, TARN_Q16_ONE);
    w->fog_rgb = fuzz_u32(r);
    w->fog_density = number(r);
    w->absorb_rgb = fuzz_u32(r);
    w->absorption = number(r);
    w->absorption_squared = fuzz_u8(r) & 1u;
    w->shallow_rgb = fuzz_u32(r);
    w->deep_rgb = fuzz_u32(r);
    w->depth_scale = number_in(r, 1, 64 * TARN_Q16_ONE);
    w->colour_ramp = texture_or_null(s, r);
    w->normal_a = texture_or_null(s, r);
    w->normal_b = texture_or_null(s, r);
    w->pan_a = panning(r);
    w->pan_b = panning(r);
    w->normal_strength = number_in(r, 0, 8 * TARN_Q16_ONE);
    w->normal_xy_max = number_in(r, 0, TARN_Q16_ONE);
    w->refraction = number_in(r, 0, TARN_Q16_ONE / 64);
    w->fresnel = number_in(r, 0, TARN_Q16_ONE);
    w->specular = number_in(r, 0, 4 * TARN_Q16_ONE);
    w->specular_power = (uint16_t)number_in(r, 1, 256);
    w->foam_texture = texture_or_null(s, r);
    w->foam_pan = panning(r);
    w->foam_distance = number_in(r, 1, 64 * TARN_Q16_ONE);
    w->foam_line_speed = number(r);
    w->foam_line_count = fuzz_u8(r);
    w->foam_rgb = fuzz_u32(r);
    w->foam_opacity = number_in(r, 0, TARN_Q16_ONE);
    w->sparkle_amount = number(r);
    w->sparkle_rgb = fuzz_u32(r);
}

static void make_object(fuzz_scene *s, unsigned k, fuzz_reader *r)
{
    fuzz_object *o = &s->parts[k];
    tarn_mesh *m = &o->mesh;
    m->vertex_count = (uint16_t)(fuzz_u8(r) % (VERTICES_MAX + 1u));
    m->triangle_count = (uint16_t)(fuzz_u8(r) % (TRIANGLES_MAX + 1u));
    for (unsigned v = 0; v < m->vertex_count; v++) {
        o->positions[v] = vector(r);
        o->normals[v] = vector(r);
        o->uvs[v].u = number(r);
        o->uvs[v].v = number(r);
        o->colours[v] = fuzz_u32(r);
    }
    const int past_the_end = fuzz_u8(r) >= 240; /* sometimes an index past the vertices */
    for (unsigned i = 0; i < 3u * m->triangle_count; i++)
        o->indices[i] = (uint16_t)(past_the_end ? fuzz_u16(r) : fuzz_u8(r) % (m->vertex_count > 0 ? m->vertex_count : 1u));
    m->positions = o->positions;
    m->normals = o->normals;
    const uint8_t optional = fuzz_u8(r);
    m->uvs = optional & 1u ? o->uvs : NULL;
    m->colours = optional & 2u ? o->colours : NULL;
    m->indices = o->indices;
    m->cluster_count = optional & 4u ? 2u : 0u;
    m->clusters = m->cluster_count ? o->clusters : NULL;
    /* two runs that cover the triangles, or (rarely) any runs at all */
    const int any_runs = fuzz_u8(r) >= 240;
    const uint16_t split = (uint16_t)(fuzz_u8(r) % (m->triangle_count + 1u));
    for (unsigned c = 0; c < m->cluster_count; c++) {
        o->clusters[c].centre = vector(r);
        o->clusters[c].radius = number(r);
        o->clusters[c].first_triangle = any_runs ? fuzz_u8(r) : (c == 0 ? 0u : split);
        o->clusters[c].triangle_count = any_runs ? fuzz_u8(r) : (uint16_t)(c == 0 ? split : m->triangle_count - split);
    }
    tarn_material *mat = &o->material;
    mat->colour_rgb = fuzz_u32(r);
    mat->texture = texture_or_null(s, r);
    mat->cull = fuzz_u8(r) % 4u; /* 3 is no mode */
    mat->unlit = fuzz_u8(r) & 1u;
    mat->water = NULL;
    if (optional & 8u) {
        make_water(s, &o->water, r);
        mat->water = &o->water;
    }
    tarn_object *obj = &s->objects[k];
    obj->mesh = m;
    obj->material = mat;
    obj->position = vector(r);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) obj->rotation[i][j] = fuzz_u8(r) < 200 ? (i == j ? TARN_Q16_ONE : 0) : number(r);
    obj->scale = number(r);
}

static void make_scene(fuzz_scene *s, fuzz_reader *r)
{
    memset(s, 0, sizeof *s);
    make_textures(s, r);
    s->scene.object_count = (uint16_t)(fuzz_u8(r) % (OBJECTS_MAX + 1u));
    for (unsigned k = 0; k < s->scene.object_count; k++) make_object(s, k, r);
    s->scene.objects = s->objects;
    s->scene.camera.position = vector(r);
    s->scene.camera.target = vector(r);
    s->scene.camera.fov_y_degrees = number(r);
    s->scene.camera.near = number_in(r, 1, 4 * TARN_Q16_ONE);
    s->scene.camera.far = number_in(r, 2 * TARN_Q16_ONE, 1000 * TARN_Q16_ONE);
    s->scene.light.direction = vector(r);
    s->scene.light.colour_rgb = fuzz_u32(r);
    s->scene.light.ambient_rgb = fuzz_u32(r);
    s->scene.background_rgb = fuzz_u32(r);
    if (fuzz_u8(r) < 64) {
        s->underwater.level = number(r);
        s->underwater.normal_map = texture_or_null(s, r);
        s->underwater.pan = panning(r);
        s->underwater.distortion = number(r);
        s->underwater.tint_rgb = fuzz_u32(r);
        s->underwater.tint_density = number(r);
        s->scene.underwater = &s->underwater;
    }
}

/* A value from the valid ones, or (one time in sixteen) any byte at all. */
static uint8_t pick(fuzz_reader *r, const uint8_t *valid, unsigned count)
{
    const uint8_t choice = fuzz_u8(r);
    return (choice & 0xF0u) == 0xF0u ? fuzz_u8(r) : valid[choice % count];
}

static tarn_frame_config make_config(fuzz_reader *r)
{
    const uint8_t w = fuzz_u8(r), h = fuzz_u8(r);
    tarn_frame_config c = {(uint16_t)(w == 0xFFu ? 0u : 1u + w % FRAME_MAX),
                           (uint16_t)(h == 0xFFu ? 0u : 1u + h % FRAME_MAX), tarn_quality_default(), fuzz_u32(r)};
    if (fuzz_u8(r) < 96) return c; /* the default quality, or any knob's values */
    static const uint8_t entries_log2[] = {3, 4, 5, 6, 7, 8}, steps[] = {0, 1, 2}, bits[] = {1, 2, 4, 6, 8},
                         modes[] = {0, 1, 2}, spans[] = {2, 4, 8, 16, 32, 64}, depths[] = {16, 32},
                         tiles[] = {8, 13, 16, 24, 32, 64}, aprons[] = {0, 1, 4, 32, 255}, flags[] = {0, 1},
                         fog_bits[] = {4, 11, 16}, blocks[] = {1, 2, 2, 3}, depth_modes[] = {0, 1, 2},
                         vertex_modes[] = {0, 1, 2, 3};
    c.quality.exp2.entries = (uint16_t)(1u << (pick(r, entries_log2, 6) & 15u));
    c.quality.exp2.interpolate = pick(r, flags, 2);
    c.quality.recip_newton_steps = pick(r, steps, 3);
    c.quality.subpixel_bits = pick(r, bits, 5);
    c.quality.perspective = pick(r, modes, 3);
    c.quality.perspective_span = pick(r, spans, 6);
    c.quality.depth_bits = pick(r, depths, 2);
    c.quality.tile_size = pick(r, tiles, 6);
    c.quality.refraction_apron = pick(r, aprons, 5);
    c.quality.cluster_bins = pick(r, flags, 2);
    c.quality.fog_argument_bits = pick(r, fog_bits, 3);
    c.quality.water_block = pick(r, blocks, 4); /* 3, and 2 with tile 13, are refused */
    c.quality.depth_interpolation = pick(r, depth_modes, 3); /* 2 is refused */
    c.quality.refraction_normal = pick(r, depth_modes, 3);   /* 2 is refused */
    c.quality.frame_shape = pick(r, depth_modes, 3);         /* 2 is refused */
    c.quality.vertex_pass = pick(r, vertex_modes, 4);        /* 3 is refused */
    c.quality.lit_colour = pick(r, depth_modes, 3);          /* 2 is refused */
    c.quality.water_coordinates = pick(r, depth_modes, 3);   /* 2 is refused */
    return c;
}

/* A static vertex: mostly in the ranges the scene check takes, sometimes anything. */
static tarn_static_vertex static_vertex(fuzz_reader *r)
{
    tarn_static_vertex v;
    const uint8_t kind = fuzz_u8(r);
    v.inv_depth = kind & 1u ? 0u : (kind & 0xF0u) == 0xF0u ? fuzz_u32(r) : 1u + fuzz_u32(r) % (1u << 30);
    v.screen_x = (int16_t)((kind & 0xF0u) == 0xF0u ? fuzz_u16(r) : fuzz_u16(r) % 2048u);
    v.screen_y = (int16_t)((kind & 0xF0u) == 0xE0u ? fuzz_u16(r) : fuzz_u16(r) % 2048u);
    for (int c = 0; c < 3; c++) v.lit[c] = (uint16_t)((kind & 0x0Eu) == 0x0Eu ? fuzz_u16(r) : fuzz_u16(r) % 65281u);
    v.fresnel = (uint16_t)((kind & 0x0Eu) == 0x0Cu ? fuzz_u16(r) : fuzz_u16(r) % 32769u);
    return v;
}

/* A quality knob of the backdrop: mostly the frame's, so that it applies. */
static uint8_t mostly(fuzz_reader *r, uint8_t frames)
{
    const uint8_t kind = fuzz_u8(r);
    return kind < 224 ? frames : fuzz_u8(r);
}

/* A backdrop over 1 to 4 index bits, whose palette, spans and depth are mostly
 * sized right and hold anything. */
static void make_backdrop(fuzz_scene *s, const tarn_frame_config *config, fuzz_reader *r)
{
    tarn_backdrop *b = &s->backdrop;
    const tarn_quality *q = &config->quality;
    b->recip_newton_steps = mostly(r, q->recip_newton_steps);
    b->perspective = mostly(r, q->perspective);
    b->perspective_span = mostly(r, q->perspective_span);
    b->depth_bits = mostly(r, q->depth_bits);
    b->depth_interpolation = mostly(r, q->depth_interpolation);
    b->still_water = mostly(r, fuzz_u8(r) & 1u);
    b->water_block = mostly(r, q->water_block);
    b->fog_argument_bits = mostly(r, q->fog_argument_bits);
    b->exp2_interpolate = mostly(r, q->exp2.interpolate);
    b->exp2_entries = fuzz_u8(r) < 224 ? q->exp2.entries : fuzz_u16(r);
    b->index_bits = mostly(r, (uint8_t)(1u + fuzz_u8(r) % 4u));
    b->palette_count = fuzz_u8(r) < 240 ? 1u << (b->index_bits & 31u) : fuzz_u32(r);
    /* over still water, a colour may carry a water object's number, 0 to 2 */
    for (size_t k = 0; k < 16; k++) {
        const uint32_t object = b->still_water == 1u ? (uint32_t)(fuzz_u8(r) % 3u) << TARN_BACKDROP_STILL_SHIFT : 0u;
        s->palette[k] = fuzz_u8(r) < 250 ? (fuzz_u32(r) & 0xFFFFFFu) | object : fuzz_u32(r);
    }
    /* a palette longer than this one goes as NULL, which the scene check refuses */
    b->palette = fuzz_u8(r) < 250 && b->palette_count <= 16u ? s->palette : NULL;
    for (size_t k = 0; k < FRAME_MAX * FRAME_MAX; k++) s->colour[k] = fuzz_u16(r);
    b->colour = s->colour;
    /* mostly in order, apart and packed; sometimes anywhere */
    uint16_t spans = 0;
    uint32_t kept = 0;
    for (size_t j = 0; j < config->height; j++) {
        s->row_spans[j] = spans;
        uint32_t end = 0;
        for (unsigned n = fuzz_u8(r) % 3u; n > 0; n--, spans++) {
            tarn_backdrop_span *span = &s->spans[spans];
            const int ordered = fuzz_u8(r) < 240;
            span->x0 = (uint16_t)(ordered ? end + fuzz_u8(r) % 8u : fuzz_u8(r) % (FRAME_MAX + 2u));
            span->x1 = (uint16_t)(ordered ? span->x0 + 1u + fuzz_u8(r) % 16u : fuzz_u8(r) % (FRAME_MAX + 2u));
            span->first = ordered ? kept : fuzz_u16(r) % (FRAME_MAX * FRAME_MAX + 2u);
            kept += span->x1 > span->x0 ? (uint32_t)(span->x1 - span->x0) : 0u;
            end = span->x1;
        }
    }
    s->row_spans[config->height] = spans;
    b->depth_count = fuzz_u8(r) < 240 && kept <= FRAME_MAX * FRAME_MAX ? kept : fuzz_u16(r) % (FRAME_MAX * FRAME_MAX + 1u);
    if (fuzz_u8(r) >= 248) s->row_spans[fuzz_u8(r) % (config->height + 1u)] = fuzz_u16(r);
    b->row_spans = s->row_spans;
    b->spans = s->spans;
    b->span_count = fuzz_u8(r) < 248 ? spans : fuzz_u32(r);
    for (size_t k = 0; k < FRAME_MAX * FRAME_MAX; k++) s->depth[k] = fuzz_u32(r);
    b->depth = s->depth;
    s->static_view.backdrop = b;
}

/* Sometimes a static view: mostly the scene's camera and light and the frame's
 * size, with static vertices on some objects (whose positions may then be gone),
 * any view positions or none, and any bins at all. Never for an input that ran out of bytes (they read as 0), so the
 * seeds made before static views still draw what they drew. */
static void make_static_view(fuzz_scene *s, const tarn_frame_config *config, fuzz_reader *r)
{
    if (fuzz_u8(r) < 160) return;
    tarn_static_view *v = &s->static_view;
    const uint8_t kind = fuzz_u8(r);
    v->camera = s->scene.camera;
    v->light = s->scene.light;
    if ((kind & 0x0Fu) == 0x0Fu) v->camera.near ^= 1;
    v->width = (kind & 0x30u) == 0x30u ? fuzz_u16(r) : config->width;
    v->height = config->height;
    v->subpixel_bits = (kind & 0xC0u) == 0xC0u ? fuzz_u8(r) : config->quality.subpixel_bits;
    for (size_t b = 0; b < sizeof s->bins / sizeof s->bins[0]; b++) {
        const tarn_cluster_bin bin = {fuzz_u8(r), fuzz_u8(r), fuzz_u8(r), fuzz_u8(r)};
        s->bins[b] = bin;
    }
    v->bins = fuzz_u8(r) < 200 ? s->bins : NULL;
    v->backdrop = NULL;
    if (fuzz_u8(r) >= 192) make_backdrop(s, config, r);
    s->scene.static_view = v;
    for (unsigned k = 0; k < s->scene.object_count; k++) {
        const uint8_t use = fuzz_u8(r);
        if (use < 64) continue;
        fuzz_object *o = &s->parts[k];
        for (unsigned i = 0; i < o->mesh.vertex_count; i++) o->static_vertices[i] = static_vertex(r);
        s->objects[k].static_vertices = o->static_vertices;
        if (use >= 192) o->mesh.positions = o->mesh.normals = NULL;
    }
    for (size_t i = 0; i < OBJECTS_MAX * VERTICES_MAX; i++) s->static_positions[i] = vector(r);
    v->positions = fuzz_u8(r) < 128 ? s->static_positions : NULL;
}

typedef struct {
    uint16_t width, height;
    uint8_t seen[FRAME_MAX * FRAME_MAX];
} coverage;

static int count_tile(void *user, const tarn_tile *tile)
{
    coverage *c = user;
    if (tile->width == 0 || tile->height == 0 || tile->x + tile->width > c->width ||
        tile->y + tile->height > c->height)
        abort(); /* a tile outside the frame */
    for (unsigned y = 0; y < tile->height; y++)
        for (unsigned x = 0; x < tile->width; x++) {
            if (tile->rgb[(size_t)y * tile->stride + x] > 0xFFFFFFu) abort();
            c->seen[(size_t)(tile->y + y) * c->width + tile->x + x]++;
        }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_reader r = {data, size, 0};
    static fuzz_scene s;
    make_scene(&s, &r);
    const tarn_frame_config config = make_config(&r);
    make_static_view(&s, &config, &r);
    const size_t bytes = tarn_frame_memory_bytes(&config, &s.scene);
    void *memory = malloc(bytes > 0 ? bytes : 1);
    static coverage seen;
    memset(&seen, 0, sizeof seen);
    seen.width = config.width;
    seen.height = config.height;
    const tarn_status status = tarn_render_frame(&s.scene, &config, memory, bytes, count_tile, &seen);
    free(memory);
    if (bytes == 0 && status != TARN_ERR_CONFIG && status != TARN_ERR_SCENE && status != TARN_ERR_MEMORY) abort();
    if (status == TARN_OK) {
        for (size_t p = 0; p < (size_t)config.width * config.height; p++)
            if (seen.seen[p] != 1) abort(); /* a pixel never sent, or sent twice */
    } else if (status == TARN_ERR_CONFIG || status == TARN_ERR_SCENE) {
        for (size_t p = 0; p < (size_t)config.width * config.height; p++)
            if (seen.seen[p] != 0) abort(); /* refused after sending part of a frame */
    }
    return 0;
}
