/* bake.c: the scene as C source. Three steps:
 *  1. types:  a table per struct of core/include/tarn/tarn_scene.h and tarn_water.h says what each
 *             member is (one STRUCT_TYPE each, an entry a member), so that one
 *             printer writes any of them, and one layout rule sizes them for a
 *             32-bit target (checked against this host's own layout before every
 *             bake, so a member added to a core struct and not here stops the
 *             baker instead of silently baking as 0);
 *  2. plan:   the list of objects to define, in an order where each is defined
 *             before its first use, and where each pointer of the loaded scene goes;
 *  3. emit:   the plan written out through atomic_file.h. */
#include "bake.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "progress.h"
#include "bake_points.h"
#include "backdrop.h"
#include "static_view.h"
#include "tarn/tarn_motion.h"

/* ---- 1. types ------------------------------------------------------------------ */

typedef enum {
    V_U8,       /* decimal */
    V_U16,
    V_I16,      /* signed decimal */
    V_U32,      /* decimal with a u suffix */
    V_Q16,      /* signed decimal */
    V_RGB,      /* 0xRRGGBBu */
    V_BYTE,     /* 0xNN: texels */
    V_FEATURES, /* TARN_WATER_* names joined by | */
    V_REF,      /* a pointer: the symbol of the baked object it points to, or NULL */
    V_MATRIX,   /* tarn_q16[3][3] */
    V_STRUCT
} value_kind;

typedef struct bake_type bake_type;

typedef struct {
    const char *name;
    size_t offset; /* on this host */
    const bake_type *type;
} bake_field;

struct bake_type {
    const char *c_name;
    value_kind kind;
    size_t host_size;         /* sizeof on this host */
    const bake_field *fields; /* V_STRUCT: every member, in declaration order */
    size_t field_count;
    int one_line;             /* V_STRUCT: positional on one line, {1, 2, 3} */
};

enum { BLOCK = 0, ONE_LINE = 1 }; /* how a struct is written: designated members, or {1, 2, 3} */

#define SCALAR(name, kind, c_type) { name, kind, sizeof(c_type), NULL, 0, 0 }
#define FIELD(s, member, type) { #member, offsetof(s, member), &type }
#define COUNT(array) (sizeof array / sizeof array[0])

/* A struct's table and its type in one declaration: the type T of struct s, written
 * as a BLOCK or on ONE_LINE, every member FIELD(s, member, type) in declaration
 * order (table_matches_host holds the list to the compiler's layout). */
#define STRUCT_TYPE(T, s, layout, ...)                    \
    static const bake_field T##_fields[] = {__VA_ARGS__}; \
    static const bake_type T = { #s, V_STRUCT, sizeof(s), T##_fields, COUNT(T##_fields), layout }

/* element_c[3], written positionally like a ONE_LINE struct. */
#define TRIPLE_TYPE(T, element_c, element)                                                    \
    STRUCT_TYPE(T, element_c[3], ONE_LINE, { "0", 0, &element }, { "1", sizeof(element_c), &element }, \
                { "2", 2 * sizeof(element_c), &element })

static const bake_type T_U8 = SCALAR("uint8_t", V_U8, uint8_t);
static const bake_type T_U16 = SCALAR("uint16_t", V_U16, uint16_t);
static const bake_type T_I16 = SCALAR("int16_t", V_I16, int16_t);
static const bake_type T_U32 = SCALAR("uint32_t", V_U32, uint32_t);
static const bake_type T_Q16 = SCALAR("tarn_q16", V_Q16, tarn_q16);
static const bake_type T_I32 = SCALAR("int32_t", V_Q16, int32_t); /* written as a tarn_q16 is */
static const bake_type T_RGB = SCALAR("uint32_t", V_RGB, uint32_t);
static const bake_type T_BYTE = SCALAR("uint8_t", V_BYTE, uint8_t);
static const bake_type T_FEATURES = SCALAR("uint32_t", V_FEATURES, uint32_t);
static const bake_type T_REF = SCALAR("const void *", V_REF, const void *);
static const bake_type T_MATRIX = SCALAR("tarn_q16[3][3]", V_MATRIX, tarn_q16[3][3]);

TRIPLE_TYPE(T_U16_TRIPLE, uint16_t, T_U16);
TRIPLE_TYPE(T_I32_TRIPLE, int32_t, T_I32);

STRUCT_TYPE(T_VEC3, tarn_vec3, ONE_LINE,
            FIELD(tarn_vec3, x, T_Q16), FIELD(tarn_vec3, y, T_Q16), FIELD(tarn_vec3, z, T_Q16));
STRUCT_TYPE(T_UV, tarn_uv, ONE_LINE, FIELD(tarn_uv, u, T_Q16), FIELD(tarn_uv, v, T_Q16));
STRUCT_TYPE(T_CLUSTER, tarn_cluster, ONE_LINE,
            FIELD(tarn_cluster, centre, T_VEC3), FIELD(tarn_cluster, radius, T_Q16),
            FIELD(tarn_cluster, first_triangle, T_U16), FIELD(tarn_cluster, triangle_count, T_U16));
STRUCT_TYPE(T_TEXTURE, tarn_texture, BLOCK,
            FIELD(tarn_texture, width, T_U16), FIELD(tarn_texture, height, T_U16), FIELD(tarn_texture, rgb, T_REF),
            FIELD(tarn_texture, red_only, T_U8));
/* int32_t[2][3], the plane's two gradients, positionally */
STRUCT_TYPE(T_I32_TRIPLE_PAIR, int32_t[2][3], ONE_LINE, {"0", 0, &T_I32_TRIPLE}, {"1", 3 * sizeof(int32_t), &T_I32_TRIPLE});
STRUCT_TYPE(T_UV_PLANE, tarn_uv_plane, ONE_LINE,
            FIELD(tarn_uv_plane, normal, T_I32_TRIPLE), FIELD(tarn_uv_plane, offset, T_Q16),
            FIELD(tarn_uv_plane, uv_origin, T_UV), FIELD(tarn_uv_plane, uv_gradient, T_I32_TRIPLE_PAIR),
            FIELD(tarn_uv_plane, uv_gradient_bits, T_U8));
STRUCT_TYPE(T_MESH, tarn_mesh, BLOCK,
            FIELD(tarn_mesh, positions, T_REF),     FIELD(tarn_mesh, normals, T_REF),
            FIELD(tarn_mesh, uvs, T_REF),           FIELD(tarn_mesh, colours, T_REF),
            FIELD(tarn_mesh, indices, T_REF),       FIELD(tarn_mesh, vertex_count, T_U16),
            FIELD(tarn_mesh, triangle_count, T_U16), FIELD(tarn_mesh, clusters, T_REF),
            FIELD(tarn_mesh, cluster_count, T_U16), FIELD(tarn_mesh, plane, T_REF));
STRUCT_TYPE(T_PANNING, tarn_panning, BLOCK,
            FIELD(tarn_panning, scale, T_Q16), FIELD(tarn_panning, speed_u, T_Q16),
            FIELD(tarn_panning, speed_v, T_Q16));
STRUCT_TYPE(T_WATER, tarn_water, BLOCK,
            FIELD(tarn_water, features, T_FEATURES),    FIELD(tarn_water, albedo_rgb, T_RGB),
            FIELD(tarn_water, alpha, T_Q16),            FIELD(tarn_water, fog_rgb, T_RGB),
            FIELD(tarn_water, fog_density, T_Q16),      FIELD(tarn_water, absorb_rgb, T_RGB),
            FIELD(tarn_water, absorption, T_Q16),       FIELD(tarn_water, absorption_squared, T_U8),
            FIELD(tarn_water, shallow_rgb, T_RGB),      FIELD(tarn_water, deep_rgb, T_RGB),
            FIELD(tarn_water, depth_scale, T_Q16),      FIELD(tarn_water, colour_ramp, T_REF),
            FIELD(tarn_water, normal_a, T_REF),         FIELD(tarn_water, normal_b, T_REF),
            FIELD(tarn_water, pan_a, T_PANNING),        FIELD(tarn_water, pan_b, T_PANNING),
            FIELD(tarn_water, normal_strength, T_Q16),  FIELD(tarn_water, normal_xy_max, T_Q16),
            FIELD(tarn_water, refraction, T_Q16),       FIELD(tarn_water, fresnel, T_Q16),
            FIELD(tarn_water, specular, T_Q16),         FIELD(tarn_water, specular_power, T_U16),
            FIELD(tarn_water, foam_texture, T_REF),     FIELD(tarn_water, foam_pan, T_PANNING),
            FIELD(tarn_water, foam_distance, T_Q16),    FIELD(tarn_water, foam_line_speed, T_Q16),
            FIELD(tarn_water, foam_line_count, T_U8),   FIELD(tarn_water, foam_rgb, T_RGB),
            FIELD(tarn_water, foam_opacity, T_Q16),     FIELD(tarn_water, sparkle_amount, T_Q16),
            FIELD(tarn_water, sparkle_rgb, T_RGB));
STRUCT_TYPE(T_UNDERWATER, tarn_underwater, BLOCK,
            FIELD(tarn_underwater, level, T_Q16),      FIELD(tarn_underwater, normal_map, T_REF),
            FIELD(tarn_underwater, pan, T_PANNING),    FIELD(tarn_underwater, distortion, T_Q16),
            FIELD(tarn_underwater, tint_rgb, T_RGB),   FIELD(tarn_underwater, tint_density, T_Q16));
STRUCT_TYPE(T_MATERIAL, tarn_material, BLOCK,
            FIELD(tarn_material, colour_rgb, T_RGB), FIELD(tarn_material, texture, T_REF),
            FIELD(tarn_material, cull, T_U8),        FIELD(tarn_material, unlit, T_U8),
            FIELD(tarn_material, water, T_REF));
STRUCT_TYPE(T_STATIC_VERTEX, tarn_static_vertex, ONE_LINE,
            FIELD(tarn_static_vertex, inv_depth, T_U32),
            FIELD(tarn_static_vertex, screen_x, T_I16), FIELD(tarn_static_vertex, screen_y, T_I16),
            FIELD(tarn_static_vertex, lit, T_U16_TRIPLE), FIELD(tarn_static_vertex, fresnel, T_U16));
STRUCT_TYPE(T_KEY_CURVE, tarn_key_curve, BLOCK,
            FIELD(tarn_key_curve, times_ms, T_REF),   FIELD(tarn_key_curve, values, T_REF),
            FIELD(tarn_key_curve, key_count, T_U16),  FIELD(tarn_key_curve, channels, T_U8),
            FIELD(tarn_key_curve, loop_ms, T_U32));
STRUCT_TYPE(T_CAMERA_PATH, tarn_camera_path, BLOCK,
            FIELD(tarn_camera_path, kind, T_U8),      FIELD(tarn_camera_path, centre, T_VEC3),
            FIELD(tarn_camera_path, radius, T_Q16),   FIELD(tarn_camera_path, height, T_Q16),
            FIELD(tarn_camera_path, period_ms, T_U32), FIELD(tarn_camera_path, start_turns_q32, T_U32),
            FIELD(tarn_camera_path, clockwise, T_U8), FIELD(tarn_camera_path, target, T_VEC3),
            FIELD(tarn_camera_path, keys, T_KEY_CURVE));
STRUCT_TYPE(T_OBJECT_MOTION, tarn_object_motion, BLOCK,
            FIELD(tarn_object_motion, bob, T_VEC3),   FIELD(tarn_object_motion, bob_period_ms, T_U32),
            FIELD(tarn_object_motion, bob_phase_q32, T_U32), FIELD(tarn_object_motion, spin_axis, T_VEC3),
            FIELD(tarn_object_motion, spin_period_ms, T_U32), FIELD(tarn_object_motion, path, T_KEY_CURVE));
STRUCT_TYPE(T_LIGHT_MOTION, tarn_light_motion, BLOCK,
            FIELD(tarn_light_motion, spin_axis, T_VEC3), FIELD(tarn_light_motion, spin_period_ms, T_U32),
            FIELD(tarn_light_motion, direction, T_KEY_CURVE));
STRUCT_TYPE(T_OBJECT, tarn_object, BLOCK,
            FIELD(tarn_object, mesh, T_REF),          FIELD(tarn_object, material, T_REF),
            FIELD(tarn_object, position, T_VEC3),     FIELD(tarn_object, rotation, T_MATRIX),
            FIELD(tarn_object, scale, T_Q16),         FIELD(tarn_object, static_vertices, T_REF),
            FIELD(tarn_object, motion, T_REF));
STRUCT_TYPE(T_CAMERA, tarn_camera, BLOCK,
            FIELD(tarn_camera, position, T_VEC3),     FIELD(tarn_camera, target, T_VEC3),
            FIELD(tarn_camera, fov_y_degrees, T_Q16), FIELD(tarn_camera, near, T_Q16),
            FIELD(tarn_camera, far, T_Q16));
STRUCT_TYPE(T_LIGHT, tarn_light, BLOCK,
            FIELD(tarn_light, direction, T_VEC3), FIELD(tarn_light, colour_rgb, T_RGB),
            FIELD(tarn_light, ambient_rgb, T_RGB));
STRUCT_TYPE(T_BIN, tarn_cluster_bin, ONE_LINE,
            FIELD(tarn_cluster_bin, x0, T_U8), FIELD(tarn_cluster_bin, y0, T_U8),
            FIELD(tarn_cluster_bin, x1, T_U8), FIELD(tarn_cluster_bin, y1, T_U8));
STRUCT_TYPE(T_STILL_PLANE, tarn_still_plane, ONE_LINE,
            FIELD(tarn_still_plane, depth, T_I32_TRIPLE), FIELD(tarn_still_plane, u, T_I32_TRIPLE),
            FIELD(tarn_still_plane, v, T_I32_TRIPLE), FIELD(tarn_still_plane, uv_shift, T_U8),
            FIELD(tarn_still_plane, lit, T_U16_TRIPLE));
STRUCT_TYPE(T_BACKDROP_SPAN, tarn_backdrop_span, ONE_LINE,
            FIELD(tarn_backdrop_span, x0, T_U16), FIELD(tarn_backdrop_span, x1, T_U16),
            FIELD(tarn_backdrop_span, first, T_U32));
STRUCT_TYPE(T_BACKDROP, tarn_backdrop, BLOCK,
            FIELD(tarn_backdrop, recip_newton_steps, T_U8), FIELD(tarn_backdrop, perspective, T_U8),
            FIELD(tarn_backdrop, perspective_span, T_U8),   FIELD(tarn_backdrop, depth_bits, T_U8),
            FIELD(tarn_backdrop, depth_interpolation, T_U8), FIELD(tarn_backdrop, still_water, T_U8),
            FIELD(tarn_backdrop, water_block, T_U8),         FIELD(tarn_backdrop, fog_argument_bits, T_U8),
            FIELD(tarn_backdrop, exp2_interpolate, T_U8),    FIELD(tarn_backdrop, exp2_entries, T_U16),
            FIELD(tarn_backdrop, planes, T_REF),
            FIELD(tarn_backdrop, index_bits, T_U8),
            FIELD(tarn_backdrop, palette, T_REF),
            FIELD(tarn_backdrop, palette_count, T_U32),     FIELD(tarn_backdrop, colour, T_REF),
            FIELD(tarn_backdrop, row_spans, T_REF),         FIELD(tarn_backdrop, spans, T_REF),
            FIELD(tarn_backdrop, span_count, T_U32),        FIELD(tarn_backdrop, depth, T_REF),
            FIELD(tarn_backdrop, depth_count, T_U32));
STRUCT_TYPE(T_STATIC_VIEW, tarn_static_view, BLOCK,
            FIELD(tarn_static_view, camera, T_CAMERA), FIELD(tarn_static_view, light, T_LIGHT),
            FIELD(tarn_static_view, width, T_U16),     FIELD(tarn_static_view, height, T_U16),
            FIELD(tarn_static_view, subpixel_bits, T_U8), FIELD(tarn_static_view, bins, T_REF),
            FIELD(tarn_static_view, backdrop, T_REF),  FIELD(tarn_static_view, positions, T_REF));
STRUCT_TYPE(T_SCENE, tarn_scene, BLOCK,
            FIELD(tarn_scene, objects, T_REF),        FIELD(tarn_scene, object_count, T_U16),
            FIELD(tarn_scene, camera, T_CAMERA),      FIELD(tarn_scene, light, T_LIGHT),
            FIELD(tarn_scene, background_rgb, T_RGB), FIELD(tarn_scene, underwater, T_REF),
            FIELD(tarn_scene, static_view, T_REF),    FIELD(tarn_scene, camera_path, T_REF),
            FIELD(tarn_scene, light_motion, T_REF));
STRUCT_TYPE(T_EXP2, tarn_exp2_config, BLOCK,
            FIELD(tarn_exp2_config, entries, T_U16), FIELD(tarn_exp2_config, interpolate, T_U8));
STRUCT_TYPE(T_QUALITY, tarn_quality, BLOCK,
            FIELD(tarn_quality, exp2, T_EXP2),
            FIELD(tarn_quality, recip_newton_steps, T_U8), FIELD(tarn_quality, subpixel_bits, T_U8),
            FIELD(tarn_quality, perspective, T_U8),        FIELD(tarn_quality, perspective_span, T_U8),
            FIELD(tarn_quality, depth_bits, T_U8),         FIELD(tarn_quality, depth_interpolation, T_U8),
            FIELD(tarn_quality, tile_size, T_U8),
            FIELD(tarn_quality, refraction_apron, T_U8),   FIELD(tarn_quality, cluster_bins, T_U8),
            FIELD(tarn_quality, fog_argument_bits, T_U8),  FIELD(tarn_quality, water_block, T_U8),
            FIELD(tarn_quality, refraction_normal, T_U8), FIELD(tarn_quality, frame_shape, T_U8),
            FIELD(tarn_quality, vertex_pass, T_U8), FIELD(tarn_quality, lit_colour, T_U8),
            FIELD(tarn_quality, water_coordinates, T_U8));
STRUCT_TYPE(T_CONFIG, tarn_frame_config, BLOCK,
            FIELD(tarn_frame_config, width, T_U16), FIELD(tarn_frame_config, height, T_U16),
            FIELD(tarn_frame_config, quality, T_QUALITY), FIELD(tarn_frame_config, time_ms, T_U32));

static const bake_type *const all_structs[] = {
    &T_VEC3,  &T_UV,       &T_CLUSTER,  &T_TEXTURE, &T_MESH,  &T_PANNING,
    &T_WATER, &T_UNDERWATER, &T_MATERIAL, &T_OBJECT, &T_CAMERA, &T_LIGHT,
    &T_SCENE, &T_EXP2,     &T_QUALITY,  &T_CONFIG, &T_U16_TRIPLE, &T_STATIC_VERTEX, &T_BIN,
    &T_I32_TRIPLE, &T_I32_TRIPLE_PAIR, &T_UV_PLANE, &T_STILL_PLANE, &T_BACKDROP_SPAN, &T_BACKDROP, &T_STATIC_VIEW,
    &T_KEY_CURVE, &T_CAMERA_PATH, &T_OBJECT_MOTION, &T_LIGHT_MOTION};

/* Bytes on a 32-bit target (Cortex-M, rv32): what the header comment reports. */
#define TARGET_POINTER_BYTES 4u

typedef struct {
    size_t size, align;
} layout;

static size_t round_up(size_t n, size_t multiple)
{
    return (n + multiple - 1) / multiple * multiple;
}

static layout scalar_layout(value_kind kind, size_t pointer_bytes)
{
    switch (kind) {
    case V_U8:
    case V_BYTE: return (layout){1, 1};
    case V_U16:
    case V_I16: return (layout){2, 2};
    case V_REF: return (layout){pointer_bytes, pointer_bytes};
    case V_MATRIX: return (layout){9 * 4, 4};
    default: return (layout){4, 4};
    }
}

/* The usual C ABI rule, on the host and on 32-bit targets alike: each member at the
 * next multiple of its alignment, the whole padded to its largest alignment. */
static layout type_layout(const bake_type *t, size_t pointer_bytes)
{
    if (t->kind != V_STRUCT) return scalar_layout(t->kind, pointer_bytes);
    layout whole = {0, 1};
    for (size_t i = 0; i < t->field_count; i++) {
        layout member = type_layout(t->fields[i].type, pointer_bytes);
        whole.size = round_up(whole.size, member.align) + member.size;
        if (member.align > whole.align) whole.align = member.align;
    }
    whole.size = round_up(whole.size, whole.align);
    return whole;
}

/* The table, laid out by the rule with this host's pointers, must give the
 * compiler's offsets and size: a member missing from it would shift them. */
static int table_matches_host(const bake_type *t)
{
    size_t offset = 0;
    for (size_t i = 0; i < t->field_count; i++) {
        layout member = type_layout(t->fields[i].type, sizeof(void *));
        offset = round_up(offset, member.align);
        if (offset != t->fields[i].offset) return 0;
        offset += member.size;
    }
    return type_layout(t, sizeof(void *)).size == t->host_size;
}

static int check_tables(tarn_error *err)
{
    for (size_t i = 0; i < COUNT(all_structs); i++) {
        if (!table_matches_host(all_structs[i]))
            return tarn_fail(err, "internal error: host/bake/bake.c does not describe every member of %s; "
                             "update its table", all_structs[i]->c_name);
    }
    return 0;
}

/* ---- 2. plan ------------------------------------------------------------------- */

typedef enum {
    BYTES_MESH, BYTES_TEXTURE, BYTES_MATERIAL, BYTES_WATER, BYTES_OBJECT, BYTES_STATIC, BYTES_BACKDROP,
    BYTES_MOTION, BYTES_SCENE, BYTES_KINDS
} byte_kind;

static const char *const byte_kind_names[BYTES_KINDS] = {
    "mesh", "texture", "material", "water", "object", "static vertices", "backdrop", "motion", "scene"};

#define SYMBOL_MAX 96
#define NOTE_MAX 200

typedef struct {
    char symbol[SYMBOL_MAX];
    const bake_type *type;
    const void *data;
    size_t count; /* elements of an array; 0: a single object */
    byte_kind kind;
    int exported; /* NAME_scene and NAME_config: not static */
    char note[NOTE_MAX]; /* a comment above the definition, or "" */
} bake_item;

#define NO_ITEM ((size_t)-1) /* an empty array: pointers to it are baked as NULL */

/* Where a pointer of the loaded scene goes: one item may stand for several
 * addresses (a mesh whose data repeats an earlier one). */
typedef struct {
    const void *address;
    size_t item;
} bake_alias;

typedef struct {
    const tarn_loaded_scene *scene;
    const char *name;
    tarn_frame_config config;
    bake_item *items;
    size_t item_count, item_capacity;
    bake_alias *aliases;
    size_t alias_count, alias_capacity;
    int out_of_memory;
    const tarn_bake_points *points; /* --points: qualities baked as NAME_points; count 0 without */
    uint32_t static_bin_count;      /* the static view's bins, when the scene has one */
    size_t backdrop_colour_words;   /* its backdrop's packed indices, when it has one */
} bake_plan;

/* `array` with room for one element past `count`: itself, moved, or NULL when out
 * of memory (and then left as it was). */
static void *room_for_one_more(void *array, size_t *capacity, size_t count, size_t element)
{
    if (count < *capacity) return array;
    size_t larger = *capacity ? 2 * *capacity : 32;
    void *moved = realloc(array, larger * element);
    if (moved) *capacity = larger;
    return moved;
}

static void add_alias(bake_plan *p, const void *address, size_t item)
{
    bake_alias *aliases = room_for_one_more(p->aliases, &p->alias_capacity, p->alias_count, sizeof *aliases);
    if (!aliases) {
        p->out_of_memory = 1;
        return;
    }
    p->aliases = aliases;
    p->aliases[p->alias_count++] = (bake_alias){address, item};
}

/* An item defining `data` (`count` elements, or one object when 0), which pointers
 * to `data` will name. NULL when out of memory. */
static bake_item *add_item(bake_plan *p, byte_kind kind, const bake_type *type, const void *data,
                           size_t count, const char *symbol_format, ...)
    __attribute__((format(printf, 6, 7)));

static bake_item *add_item(bake_plan *p, byte_kind kind, const bake_type *type, const void *data,
                           size_t count, const char *symbol_format, ...)
{
    bake_item *items = room_for_one_more(p->items, &p->item_capacity, p->item_count, sizeof *items);
    if (!items) {
        p->out_of_memory = 1;
        return NULL;
    }
    p->items = items;
    bake_item *item = &p->items[p->item_count];
    memset(item, 0, sizeof *item);
    va_list args;
    va_start(args, symbol_format);
    vsnprintf(item->symbol, sizeof item->symbol, symbol_format, args);
    va_end(args);
    item->type = type;
    item->data = data;
    item->count = count;
    item->kind = kind;
    add_alias(p, data, p->item_count++);
    return item;
}

/* The comment above `item`'s definition; none for NULL (out of memory, which the
 * plan already records). */
static void note(bake_item *item, const char *format, ...) __attribute__((format(printf, 2, 3)));

static void note(bake_item *item, const char *format, ...)
{
    if (item == NULL) return;
    va_list args;
    va_start(args, format);
    vsnprintf(item->note, sizeof item->note, format, args);
    va_end(args);
}

static int material_used(const tarn_scene *scene, const tarn_material *material)
{
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (scene->objects[i].material == material) return 1;
    return 0;
}

static int water_samples(const tarn_water *w, const tarn_texture *t)
{
    return w && (w->colour_ramp == t || w->normal_a == t || w->normal_b == t || w->foam_texture == t);
}

/* A texture some used material, its water or the underwater view points to. */
static int texture_used(const tarn_scene *scene, const tarn_texture *t)
{
    if (scene->underwater && scene->underwater->normal_map == t) return 1;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_material *m = scene->objects[i].material;
        if (m->texture == t || water_samples(m->water, t)) return 1;
    }
    return 0;
}

static void plan_textures(bake_plan *p)
{
    const tarn_loaded_scene *s = p->scene;
    for (size_t k = 0; k < s->texture_count; k++) {
        const tarn_texture *t = &s->textures[k];
        if (!texture_used(&s->scene, t)) continue;
        note(add_item(p, BYTES_TEXTURE, &T_BYTE, t->rgb, (t->red_only ? 1u : 3u) * t->width * t->height,
                      "%s_texture_%zu_rgb", p->name, k),
             "%s: %ux%u texels, %s, rows top to bottom", s->texture_paths[k], t->width, t->height,
             t->red_only ? "red only (a foam map)" : "R G B");
        add_item(p, BYTES_TEXTURE, &T_TEXTURE, t, 0, "%s_texture_%zu", p->name, k);
    }
}

/* The arrays a mesh points to, and how many elements each holds. */
typedef enum { PER_VERTEX, PER_INDEX, PER_CLUSTER, ONE } array_length;

static const struct mesh_array {
    const char *suffix;
    size_t offset;
    const bake_type *type;
    array_length length;
} mesh_arrays[] = {
    {"positions", offsetof(tarn_mesh, positions), &T_VEC3, PER_VERTEX},
    {"normals", offsetof(tarn_mesh, normals), &T_VEC3, PER_VERTEX},
    {"uvs", offsetof(tarn_mesh, uvs), &T_UV, PER_VERTEX},
    {"colours", offsetof(tarn_mesh, colours), &T_RGB, PER_VERTEX},
    {"indices", offsetof(tarn_mesh, indices), &T_U16, PER_INDEX},
    {"clusters", offsetof(tarn_mesh, clusters), &T_CLUSTER, PER_CLUSTER},
    {"plane", offsetof(tarn_mesh, plane), &T_UV_PLANE, ONE}};

#define MESH_ARRAYS COUNT(mesh_arrays)

static const void *read_pointer(const void *at)
{
    const void *value;
    memcpy(&value, at, sizeof value);
    return value;
}

static const void *mesh_array_data(const tarn_mesh *m, const struct mesh_array *a)
{
    return read_pointer((const char *)m + a->offset);
}

static size_t mesh_array_count(const tarn_mesh *m, const struct mesh_array *a)
{
    switch (a->length) {
    case PER_VERTEX: return m->vertex_count;
    case PER_INDEX: return 3u * m->triangle_count;
    case PER_CLUSTER: return m->cluster_count;
    default: return 1u;
    }
}

/* Same counts and the same bytes in every array (none of their types has padding). */
static int meshes_equal(const tarn_mesh *a, const tarn_mesh *b)
{
    if (a->vertex_count != b->vertex_count || a->triangle_count != b->triangle_count ||
        a->cluster_count != b->cluster_count)
        return 0;
    for (size_t k = 0; k < MESH_ARRAYS; k++) {
        const void *x = mesh_array_data(a, &mesh_arrays[k]), *y = mesh_array_data(b, &mesh_arrays[k]);
        size_t bytes = mesh_array_count(a, &mesh_arrays[k]) * mesh_arrays[k].type->host_size;
        if ((x == NULL) != (y == NULL) || (x && bytes && memcmp(x, y, bytes) != 0)) return 0;
    }
    return 1;
}

/* The first object whose mesh holds the same data as object i's. */
static size_t first_same_mesh(const tarn_scene *scene, size_t i)
{
    size_t j = 0;
    while (j < i && !meshes_equal(scene->objects[j].mesh, scene->objects[i].mesh)) j++;
    return j;
}

static size_t later_same_meshes(const tarn_scene *scene, size_t i)
{
    size_t n = 0;
    for (size_t k = i + 1; k < scene->object_count; k++)
        n += meshes_equal(scene->objects[k].mesh, scene->objects[i].mesh);
    return n;
}

static void note_mesh(bake_item *item, const tarn_scene *scene, size_t i)
{
    const tarn_mesh *m = scene->objects[i].mesh;
    size_t repeats = later_same_meshes(scene, i);
    char shared[80] = "";
    if (repeats) snprintf(shared, sizeof shared, ", also used for %zu later object(s) with the same data", repeats);
    note(item, "objects[%zu]'s mesh%s; vertices: %u, triangles: %u, clusters: %u", i, shared, m->vertex_count,
         m->triangle_count, m->cluster_count);
}

/* Whether some quality the bake holds takes flat water's texture coordinates from
 * its plane (tarn_water_coordinates): else no mesh's plane is written, and the
 * meshes point to none. */
static int bakes_planes(const bake_plan *p)
{
    int any = p->config.quality.water_coordinates == TARN_WATER_UV_PLANE;
    for (size_t i = 0; i < p->points->count; i++)
        any |= p->points->qualities[i].water_coordinates == TARN_WATER_UV_PLANE;
    return any;
}

static void plan_mesh(bake_plan *p, size_t i)
{
    const tarn_mesh *m = p->scene->scene.objects[i].mesh;
    for (size_t k = 0; k < MESH_ARRAYS; k++) {
        const void *data = mesh_array_data(m, &mesh_arrays[k]);
        size_t count = mesh_array_count(m, &mesh_arrays[k]);
        if (data == NULL) continue;
        if (count == 0 || (mesh_arrays[k].length == ONE && !bakes_planes(p))) {
            add_alias(p, data, NO_ITEM); /* C has no empty arrays; a plane no quality reads */
            continue;
        }
        bake_item *item = add_item(p, BYTES_MESH, mesh_arrays[k].type, data, count, "%s_mesh_%zu_%s",
                                   p->name, i, mesh_arrays[k].suffix);
        if (item && k == 0) note_mesh(item, &p->scene->scene, i);
    }
    add_item(p, BYTES_MESH, &T_MESH, m, 0, "%s_mesh_%zu", p->name, i);
}

static size_t find_alias(const bake_plan *p, const void *address, int *found)
{
    for (size_t k = 0; k < p->alias_count; k++) {
        if (p->aliases[k].address == address) {
            *found = 1;
            return p->aliases[k].item;
        }
    }
    *found = 0;
    return NO_ITEM;
}

/* One definition per distinct mesh; an object repeating another's mesh data (the
 * same OBJ placed several times) points to the first one's. */
static void plan_meshes(bake_plan *p)
{
    const tarn_scene *scene = &p->scene->scene;
    for (size_t i = 0; i < scene->object_count; i++) {
        size_t first = first_same_mesh(scene, i);
        int found;
        if (first == i) plan_mesh(p, i);
        else add_alias(p, scene->objects[i].mesh, find_alias(p, scene->objects[first].mesh, &found));
    }
}

static void plan_materials(bake_plan *p)
{
    const tarn_loaded_scene *s = p->scene;
    for (size_t k = 0; k < s->material_count; k++) {
        const tarn_material *m = &s->materials[k];
        if (!material_used(&s->scene, m) || !m->water) continue;
        note(add_item(p, BYTES_WATER, &T_WATER, m->water, 0, "%s_water_%zu", p->name, k), "materials.%s.water",
             s->material_names[k]);
    }
    if (s->scene.underwater)
        add_item(p, BYTES_WATER, &T_UNDERWATER, s->scene.underwater, 0, "%s_underwater", p->name);
    for (size_t k = 0; k < s->material_count; k++) {
        const tarn_material *m = &s->materials[k];
        if (!material_used(&s->scene, m)) continue;
        note(add_item(p, BYTES_MATERIAL, &T_MATERIAL, m, 0, "%s_material_%zu", p->name, k), "materials.%s",
             s->material_names[k]);
    }
}

/* The static view's backdrop (backdrop.h), when it has one. */
static void plan_backdrop(bake_plan *p, const tarn_static_view *view)
{
    const tarn_backdrop *b = view->backdrop;
    if (b == NULL) return;
    note(add_item(p, BYTES_BACKDROP, &T_RGB, b->palette, b->palette_count, "%s_backdrop_palette", p->name),
         "backdrop: the %lu colours the opaque objects%s draw, ascending, each named by a %u-bit index",
         (unsigned long)b->palette_count, b->still_water ? " and the still water (with its marks)" : "", b->index_bits);
    note(add_item(p, BYTES_BACKDROP, &T_U16, b->colour, p->backdrop_colour_words, "%s_backdrop_colour", p->name),
         "backdrop: a %u-bit palette index per pixel, rows top to bottom, packed low bits first", b->index_bits);
    if (!b->still_water)
        add_alias(p, b->planes, NO_ITEM);
    else
        note(add_item(p, BYTES_BACKDROP, &T_STILL_PLANE, b->planes, p->scene->scene.object_count,
                      "%s_backdrop_planes", p->name),
             "backdrop: each water object's surface as the frame sees it, at pixel (0, 0), per pixel right, per "
             "pixel down");
    note(add_item(p, BYTES_BACKDROP, &T_U16, b->row_spans, view->height + 1u, "%s_backdrop_row_spans", p->name),
         "backdrop: row j's spans of kept depth are spans[row_spans[j] .. row_spans[j + 1])");
    if (b->span_count == 0) add_alias(p, b->spans, NO_ITEM);
    else add_item(p, BYTES_BACKDROP, &T_BACKDROP_SPAN, b->spans, b->span_count, "%s_backdrop_spans", p->name);
    if (b->depth_count == 0) {
        add_alias(p, b->depth, NO_ITEM);
    } else {
        bake_item *item = add_item(p, BYTES_BACKDROP, b->depth_bits == 16 || b->still_water ? &T_U16 : &T_U32,
                                   b->depth, b->depth_count, "%s_backdrop_depth", p->name);
        if (b->still_water)
            note(item, "backdrop: each span's pixels' place in the foam band (Q0.16), where foam can show");
        else
            note(item, "backdrop: near/d (%s) of each span's pixels [x0, x1), where water may draw or sample",
                 b->depth_bits == 16 ? "tarn_depth16 codes" : "Q1.30");
    }
    add_item(p, BYTES_BACKDROP, &T_BACKDROP, b, 0, "%s_backdrop", p->name);
}

/* Each object's static vertices and the view they were made for (static_view.h). */
static void plan_static_vertices(bake_plan *p)
{
    const tarn_scene *scene = &p->scene->scene;
    if (scene->static_view == NULL) return;
    for (size_t i = 0; i < scene->object_count; i++) {
        const tarn_object *object = &scene->objects[i];
        if (object->mesh->vertex_count == 0) {
            add_alias(p, object->static_vertices, NO_ITEM);
            continue;
        }
        note(add_item(p, BYTES_STATIC, &T_STATIC_VERTEX, object->static_vertices, object->mesh->vertex_count,
                      "%s_object_%zu_static_vertices", p->name, i),
             "objects[%zu] from the scene's camera: near/d and screen position (subpixels), lit colour (Q8.8), "
             "fresnel (Q1.15)", i);
    }
    size_t vertex_count = 0;
    for (size_t i = 0; i < scene->object_count; i++) vertex_count += scene->objects[i].mesh->vertex_count;
    if (vertex_count == 0)
        add_alias(p, scene->static_view->positions, NO_ITEM); /* C has no empty arrays */
    else
        note(add_item(p, BYTES_STATIC, &T_VEC3, scene->static_view->positions, vertex_count, "%s_static_positions",
                      p->name),
             "each vertex's view position from the scene's camera (Q16.16 right, up, depth), every object's in "
             "scene order: read only for a triangle the frame clips");
    note(add_item(p, BYTES_STATIC, &T_BIN, scene->static_view->bins, p->static_bin_count, "%s_static_bins", p->name),
         "each cluster's screen box in 4-pixel cells, every object's in scene order");
    plan_backdrop(p, scene->static_view);
    add_item(p, BYTES_STATIC, &T_STATIC_VIEW, scene->static_view, 0, "%s_static_view", p->name);
}

/* A curve's keys, named after what moves by it ("camera_path"). */
static void plan_keys(bake_plan *p, const tarn_key_curve *c, const char *what)
{
    if (c->key_count == 0) return;
    note(add_item(p, BYTES_MOTION, &T_U32, c->times_ms, c->key_count, "%s_%s_times", p->name, what),
         "%s: each key's time, ms", what);
    note(add_item(p, BYTES_MOTION, &T_Q16, c->values, (size_t)c->key_count * c->channels, "%s_%s_values", p->name,
                  what),
         "%s: each key's %u channels, Q16.16", what, c->channels);
}

/* The camera's path, the light's motion and each moving object's (tarn_motion.h):
 * firmware poses the scene each frame. */
static void plan_motion(bake_plan *p)
{
    const tarn_scene *scene = &p->scene->scene;
    char what[SYMBOL_MAX];
    if (scene->camera_path != NULL) {
        plan_keys(p, &scene->camera_path->keys, "camera_path");
        add_item(p, BYTES_MOTION, &T_CAMERA_PATH, scene->camera_path, 0, "%s_camera_path", p->name);
    }
    if (scene->light_motion != NULL) {
        plan_keys(p, &scene->light_motion->direction, "light_motion");
        add_item(p, BYTES_MOTION, &T_LIGHT_MOTION, scene->light_motion, 0, "%s_light_motion", p->name);
    }
    for (size_t i = 0; i < scene->object_count; i++) {
        const tarn_object_motion *m = scene->objects[i].motion;
        if (m == NULL) continue;
        snprintf(what, sizeof what, "object_%zu_motion", i);
        plan_keys(p, &m->path, what);
        add_item(p, BYTES_MOTION, &T_OBJECT_MOTION, m, 0, "%s_%s", p->name, what);
    }
}

static void plan_scene(bake_plan *p)
{
    const tarn_scene *scene = &p->scene->scene;
    if (scene->object_count == 0) add_alias(p, scene->objects, NO_ITEM);
    else add_item(p, BYTES_OBJECT, &T_OBJECT, scene->objects, scene->object_count, "%s_objects", p->name);
    bake_item *item = add_item(p, BYTES_SCENE, &T_SCENE, scene, 0, "%s_scene", p->name);
    if (item) item->exported = 1;
    item = add_item(p, BYTES_SCENE, &T_CONFIG, &p->config, 0, "%s_config", p->name);
    if (item) item->exported = 1;
    if (p->points->count == 0) return;
    item = add_item(p, BYTES_SCENE, &T_QUALITY, p->points->qualities, p->points->count, "%s_points", p->name);
    if (item == NULL) return;
    item->exported = 1;
    note(item, "--points %s: %zu qualities, each %s_config's with one line's options", p->points->path,
         p->points->count, p->name);
}

/* Every definition in an order where each comes before its first use. */
static int plan_build(bake_plan *p, tarn_error *err)
{
    plan_textures(p);
    plan_meshes(p);
    plan_materials(p);
    plan_static_vertices(p);
    plan_motion(p);
    plan_scene(p);
    return p->out_of_memory ? tarn_fail(err, "out of memory planning the baked scene") : 0;
}

static void plan_free(bake_plan *p)
{
    free(p->items);
    free(p->aliases);
}

static size_t item_bytes(const bake_item *item)
{
    return type_layout(item->type, TARGET_POINTER_BYTES).size * (item->count ? item->count : 1);
}

static size_t plan_bytes(const bake_plan *p, size_t bytes[BYTES_KINDS])
{
    size_t total = 0;
    memset(bytes, 0, BYTES_KINDS * sizeof bytes[0]);
    for (size_t k = 0; k < p->item_count; k++) {
        bytes[p->items[k].kind] += item_bytes(&p->items[k]);
        total += item_bytes(&p->items[k]);
    }
    return total;
}

/* ---- 3. emit ------------------------------------------------------------------- */

#define LINE_WIDTH 100
#define INDENT "    "

typedef struct {
    FILE *out;
    const bake_plan *plan;
    int unresolved; /* a pointer to something the plan does not define: a bug */
} emitter;

/* A value's text, for values that fit on one line. */
typedef struct {
    char text[768];
    size_t length;
} text_buffer;

static void append(text_buffer *b, const char *format, ...) __attribute__((format(printf, 2, 3)));

static void append(text_buffer *b, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    int n = vsnprintf(b->text + b->length, sizeof b->text - b->length, format, args);
    va_end(args);
    if (n > 0) b->length += (size_t)n < sizeof b->text - b->length ? (size_t)n : sizeof b->text - b->length - 1;
}

static uint32_t read_u32(const void *at)
{
    uint32_t v;
    memcpy(&v, at, sizeof v);
    return v;
}

static uint16_t read_u16(const void *at)
{
    uint16_t v;
    memcpy(&v, at, sizeof v);
    return v;
}

/* INT32_MIN is written as an expression: 2147483648 alone is not an int. */
static void format_q16(text_buffer *b, int32_t v)
{
    if (v == INT32_MIN) append(b, "(-2147483647 - 1)");
    else append(b, "%ld", (long)v);
}

#define FEATURE(f) { f, #f }
static const struct {
    uint32_t bit;
    const char *name;
} water_features[] = {
    FEATURE(TARN_WATER_FOG),     FEATURE(TARN_WATER_ABSORPTION), FEATURE(TARN_WATER_DEPTH_COLOUR),
    FEATURE(TARN_WATER_REFRACTION), FEATURE(TARN_WATER_NORMALS), FEATURE(TARN_WATER_FRESNEL),
    FEATURE(TARN_WATER_SPECULAR), FEATURE(TARN_WATER_FOAM),     FEATURE(TARN_WATER_SPARKLES)};

static void format_features(text_buffer *b, uint32_t features)
{
    const char *separator = "";
    for (size_t k = 0; k < COUNT(water_features); k++) {
        if (!(features & water_features[k].bit)) continue;
        append(b, "%s%s", separator, water_features[k].name);
        features &= ~water_features[k].bit;
        separator = " | ";
    }
    if (features || !*separator) append(b, "%s0x%lxu", separator, (unsigned long)features);
}

static void format_ref(emitter *e, const void *address, text_buffer *b)
{
    int found;
    size_t item = address ? find_alias(e->plan, address, &found) : NO_ITEM;
    if (address && !found) e->unresolved = 1;
    if (item == NO_ITEM) {
        append(b, "NULL");
        return;
    }
    const bake_item *target = &e->plan->items[item];
    append(b, "%s%s", target->count ? "" : "&", target->symbol);
}

static void format_value(emitter *e, const bake_type *t, const void *at, text_buffer *b);

static void format_one_line_struct(emitter *e, const bake_type *t, const void *at, text_buffer *b)
{
    append(b, "{");
    for (size_t i = 0; i < t->field_count; i++) {
        if (i) append(b, ", ");
        format_value(e, t->fields[i].type, (const char *)at + t->fields[i].offset, b);
    }
    append(b, "}");
}

static void format_matrix(const void *at, text_buffer *b)
{
    tarn_q16 m[3][3];
    memcpy(m, at, sizeof m);
    for (int row = 0; row < 3; row++) {
        append(b, row ? ", {" : "{{");
        for (int col = 0; col < 3; col++) {
            if (col) append(b, ", ");
            format_q16(b, m[row][col]);
        }
        append(b, "}");
    }
    append(b, "}");
}

static void format_value(emitter *e, const bake_type *t, const void *at, text_buffer *b)
{
    switch (t->kind) {
    case V_U8: append(b, "%u", *(const uint8_t *)at); break;
    case V_BYTE: append(b, "0x%02x", *(const uint8_t *)at); break;
    case V_U16: append(b, "%u", read_u16(at)); break;
    case V_I16: append(b, "%d", (int16_t)read_u16(at)); break;
    case V_U32: append(b, "%luu", (unsigned long)read_u32(at)); break;
    case V_RGB: append(b, "0x%06lxu", (unsigned long)read_u32(at)); break;
    case V_Q16: format_q16(b, (int32_t)read_u32(at)); break;
    case V_FEATURES: format_features(b, read_u32(at)); break;
    case V_REF: format_ref(e, read_pointer(at), b); break;
    case V_MATRIX: format_matrix(at, b); break;
    case V_STRUCT: format_one_line_struct(e, t, at, b); break;
    }
}

static void indent(FILE *out, int depth)
{
    for (int i = 0; i < depth; i++) fputs(INDENT, out);
}

static void print_value(emitter *e, const bake_type *t, const void *at, int depth);

/* Designated members, one per line: the baked file reads like the struct. */
static void print_struct(emitter *e, const bake_type *t, const void *at, int depth)
{
    fputs("{\n", e->out);
    for (size_t i = 0; i < t->field_count; i++) {
        indent(e->out, depth + 1);
        fprintf(e->out, ".%s = ", t->fields[i].name);
        print_value(e, t->fields[i].type, (const char *)at + t->fields[i].offset, depth + 1);
        fputs(i + 1 < t->field_count ? ",\n" : "\n", e->out);
    }
    indent(e->out, depth);
    fputc('}', e->out);
}

static void print_value(emitter *e, const bake_type *t, const void *at, int depth)
{
    if (t->kind == V_STRUCT && !t->one_line) {
        print_struct(e, t, at, depth);
        return;
    }
    text_buffer b = {"", 0};
    format_value(e, t, at, &b);
    fputs(b.text, e->out);
}

/* Small elements fill lines up to LINE_WIDTH; structs take a block each. */
static void print_elements(emitter *e, const bake_item *item)
{
    const bake_type *t = item->type;
    const char *data = item->data;
    size_t column = 0;
    for (size_t i = 0; i < item->count; i++) {
        const char *separator = i + 1 < item->count ? "," : "";
        if (t->kind == V_STRUCT && !t->one_line) {
            indent(e->out, 1);
            print_struct(e, t, data + i * t->host_size, 1);
            fprintf(e->out, "%s\n", separator);
            continue;
        }
        text_buffer b = {"", 0};
        format_value(e, t, data + i * t->host_size, &b);
        append(&b, "%s", separator);
        if (column == 0 || column + 1 + b.length > LINE_WIDTH) {
            fprintf(e->out, "%s" INDENT, column ? "\n" : "");
            column = strlen(INDENT);
        } else {
            fputc(' ', e->out);
            column++;
        }
        fputs(b.text, e->out);
        column += b.length;
    }
    if (column) fputc('\n', e->out);
}

/* Text inside a C comment: never closing or opening one, nor forming a trigraph,
 * whatever a path or an argument holds. */
static void comment_text(FILE *out, const char *text)
{
    char previous = '\0';
    for (const char *c = text; *c; c++) {
        char shown = *c >= 0x20 && *c < 0x7f ? *c : '?';
        if ((previous == '/' && shown == '*') || (previous == '*' && shown == '/') ||
            (previous == '?' && shown == '?'))
            fputc(' ', out);
        fputc(shown, out);
        previous = shown;
    }
}

static void print_item(emitter *e, const bake_item *item)
{
    if (item->note[0]) {
        fputs("/* ", e->out);
        comment_text(e->out, item->note);
        fputs(" */\n", e->out);
    }
    fprintf(e->out, "%sconst %s %s", item->exported ? "" : "static ", item->type->c_name, item->symbol);
    if (item->count) {
        fprintf(e->out, "[%zu] = {\n", item->count);
        print_elements(e, item);
        fputs("};\n\n", e->out);
    } else {
        fputs(" = ", e->out);
        print_struct(e, item->type, item->data, 0);
        fputs(";\n\n", e->out);
    }
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* An argument as a shell would need it: quoted unless plainly safe. */
static void print_argument(FILE *out, const char *arg)
{
    int plain = *arg != '\0';
    for (const char *c = arg; *c; c++)
        if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./:=,+-", *c)) plain = 0;
    if (plain) {
        comment_text(out, arg);
        return;
    }
    fputc('\'', out);
    for (const char *c = arg; *c; c++) {
        char one[2] = {*c, '\0'};
        comment_text(out, *c == '\'' ? "'\\''" : one);
    }
    fputc('\'', out);
}

static void print_command(FILE *out, const tarn_bake_options *o)
{
    fputs(" *   tarn", out);
    for (int i = 1; i < o->argc; i++) {
        fputc(' ', out);
        print_argument(out, o->argv[i]);
    }
    fputc('\n', out);
}

static void macro_name(const char *name, char out[TARN_BAKE_NAME_MAX + 1])
{
    size_t n = 0;
    for (; name[n]; n++) out[n] = name[n] >= 'a' && name[n] <= 'z' ? (char)(name[n] - 'a' + 'A') : name[n];
    out[n] = '\0';
}

typedef struct {
    const char *header_path;
    const char *link_path;
    size_t bytes[BYTES_KINDS];
    size_t const_bytes;
    size_t memory_bytes;
    unsigned piece_width, piece_rows; /* the largest tile or strip the sink takes */
} bake_totals;

/* What moves in the scene, for messages and the header: "the camera, 2 objects". */
static const char *motion_summary(const tarn_scene *scene)
{
    static char text[96];
    size_t objects = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) objects += scene->objects[i].motion != NULL;
    snprintf(text, sizeof text, "%s%s%s%s", scene->camera_path ? "the camera" : "",
             scene->camera_path && scene->light_motion ? ", " : "", scene->light_motion ? "the light" : "",
             (scene->camera_path || scene->light_motion) && objects ? ", " : "");
    if (objects) snprintf(text + strlen(text), sizeof text - strlen(text), "%zu object%s", objects, objects > 1 ? "s" : "");
    return text;
}

static void print_source_comment(FILE *out, const bake_plan *p, const tarn_bake_options *o,
                                 const bake_totals *totals)
{
    char macro[TARN_BAKE_NAME_MAX + 1];
    macro_name(p->name, macro);
    fputs("/* ", out);
    comment_text(out, base_name(o->output_path));
    fputs(": the scene ", out);
    comment_text(out, o->scene_path);
    fputs(" as const data for the tarn renderer.\n * Generated; do not edit. Made by\n", out);
    print_command(out, o);
    fputs(" *\n * Const bytes as a 32-bit target lays them out:\n", out);
    for (int k = 0; k < BYTES_KINDS; k++)
        fprintf(out, " *   %-15s %9zu\n", byte_kind_names[k], totals->bytes[k]);
    fprintf(out, " *   %-15s %9zu\n *\n", "total", totals->const_bytes);
    if (tarn_scene_moves(&p->scene->scene))
        fprintf(out, " * The scene moves (%s): nothing is frozen; each frame poses it for its time\n"
                " * and transforms, lights and projects every vertex.\n *\n", motion_summary(&p->scene->scene));
    else if (p->scene->scene.static_view != NULL)
        fputs(" * Nothing in the scene moves: its static view holds every vertex as the camera sees it.\n *\n", out);
    fprintf(out, " * A %ux%u frame at the baked quality%s needs %zu bytes of working memory:\n * %s_MEMORY_BYTES in ",
            p->config.width, p->config.height, p->points->count ? " or any of the points" : "",
            totals->memory_bytes, macro);
    comment_text(out, base_name(totals->header_path));
    fputs(". */\n#include \"tarn/tarn_motion.h\"\n#include \"tarn/tarn_render.h\"\n\n", out);
}

static void print_header(FILE *out, const bake_plan *p, const tarn_bake_options *o,
                         const bake_totals *totals)
{
    char macro[TARN_BAKE_NAME_MAX + 1];
    macro_name(p->name, macro);
    fputs("/* ", out);
    comment_text(out, base_name(totals->header_path));
    fputs(": the objects of ", out);
    comment_text(out, base_name(o->output_path));
    fputs(", the scene ", out);
    comment_text(out, o->scene_path);
    fputs(" baked by tarn.\n * Generated; do not edit. */\n", out);
    fprintf(out, "#ifndef %s_BAKED_H\n#define %s_BAKED_H\n\n#include \"tarn/tarn_render.h\"\n\n", macro, macro);
    if (p->points->count)
        fprintf(out, "/* The largest tarn_frame_memory_bytes(&config, &%s_scene) of %s_config and of %s_config\n"
                " * with the quality of each of %s_points: a frame's working memory at any of them. */\n",
                p->name, p->name, p->name, p->name);
    else
        fprintf(out, "/* tarn_frame_memory_bytes(&%s_config, &%s_scene): a frame's working memory. */\n",
                p->name, p->name);
    fprintf(out, "#define %s_MEMORY_BYTES %zu\n\n", macro, totals->memory_bytes);
    if (p->config.quality.frame_shape == TARN_FRAME_STRIPS && !p->points->count)
        fprintf(out, "/* tarn_strip_pipeline_memory_bytes(&%s_config, &%s_scene): the frame's working memory\n"
                " * when two workers share its ring of strips (tarn_strip_pipeline_begin). */\n"
                "#define %s_PIPELINE_MEMORY_BYTES %zu\n\n",
                p->name, p->name, macro, tarn_strip_pipeline_memory_bytes(&p->config, &p->scene->scene));
    fprintf(out, "/* The widest and tallest piece (tile or strip, tarn_tile) the frame hands its sink%s. */\n"
            "#define %s_PIECE_WIDTH %u\n#define %s_PIECE_ROWS %u\n\n",
            p->points->count ? " at any of them" : "", macro, totals->piece_width, macro, totals->piece_rows);
    fprintf(out, "extern const tarn_scene %s_scene;\nextern const tarn_frame_config %s_config;\n\n", p->name,
            p->name);
    if (p->points->count)
        fprintf(out, "/* --points: the qualities to measure, in the order of the file's lines. */\n"
                "#define %s_POINT_COUNT %zu\nextern const tarn_quality %s_points[];\n\n",
                macro, p->points->count, p->name);
    fputs("#endif\n", out);
}

/* 1 if some object's material is water; `features`: the TARN_WATER_* bits they use. */
/* Whether the scene has water, the effects some water material has (`features`)
 * and those every one has (`every`). */
static int used_water(const tarn_scene *scene, uint32_t *features, uint32_t *every)
{
    int water = 0;
    *features = 0;
    *every = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_material *m = scene->objects[i].material;
        if (m == NULL || m->water == NULL) continue;
        *every = water ? *every & m->water->features : m->water->features;
        water = 1;
        *features |= m->water->features;
    }
    return water;
}

/* 1 if some object's material is opaque: a backdrop holds none of them. */
static int has_opaque_objects(const tarn_scene *scene)
{
    for (uint32_t i = 0; i < scene->object_count; i++)
        if (scene->objects[i].material == NULL || scene->objects[i].material->water == NULL) return 1;
    return 0;
}

/* The link switches a baked quality decides, as bits: a build links a part when
 * some quality it bakes (the main one or a point) uses it. */
enum {
    USES_PERSPECTIVE_AFFINE = 1u << 0, /* affine, and span for its narrow triangles */
    USES_PERSPECTIVE_SPAN = 1u << 1,
    USES_PERSPECTIVE_PIXEL = 1u << 2,
    USES_APRON = 1u << 3,
    USES_WATER_BLOCKS = 1u << 4,
    USES_DEPTH16 = 1u << 5,
    USES_DEPTH32 = 1u << 6,
    USES_EXACT_DEPTH = 1u << 7,
    USES_FOUND_BINS = 1u << 8, /* bins on, and the static view holds none for its grid */
    USES_REFRACTION_EXACT = 1u << 9,
    USES_STRIPS = 1u << 10,
    USES_VERTEX_PASS = 1u << 11,
    USES_LIT_LINE = 1u << 12,
    USES_WATER_PLANE = 1u << 13 /* plane coordinates, and a water mesh has a plane */
};

static const struct {
    const char *name; /* TARN_LINK_NAME */
    unsigned bit;
} quality_switches[] = {
    {"PERSPECTIVE_AFFINE", USES_PERSPECTIVE_AFFINE}, {"PERSPECTIVE_SPAN", USES_PERSPECTIVE_SPAN},
    {"PERSPECTIVE_PIXEL", USES_PERSPECTIVE_PIXEL},   {"APRON", USES_APRON},
    {"WATER_BLOCKS", USES_WATER_BLOCKS},             {"DEPTH16", USES_DEPTH16},
    {"DEPTH32", USES_DEPTH32},                       {"EXACT_DEPTH", USES_EXACT_DEPTH},
    {"FOUND_BINS", USES_FOUND_BINS},                 {"REFRACTION_EXACT", USES_REFRACTION_EXACT},
    {"STRIPS", USES_STRIPS},                         {"VERTEX_PASS", USES_VERTEX_PASS},
    {"LIT_LINE", USES_LIT_LINE},                     {"WATER_PLANE", USES_WATER_PLANE}};

static unsigned quality_uses(const tarn_scene *scene, const tarn_quality *q)
{
    /* a build that shades water links the plane's code for a quality that takes the
     * plane's coordinates, or refuses that quality */
    uint32_t features, every;
    const int water = used_water(scene, &features, &every);
    const tarn_static_view *view = scene->static_view;
    const int finds_bins =
        q->cluster_bins && (view == NULL || view->bins == NULL || view->subpixel_bits != q->subpixel_bits);
    return (q->perspective != TARN_PERSPECTIVE_PIXEL ? USES_PERSPECTIVE_AFFINE : 0u) |
           (q->perspective == TARN_PERSPECTIVE_SPAN ? USES_PERSPECTIVE_SPAN : 0u) |
           (q->perspective == TARN_PERSPECTIVE_PIXEL ? USES_PERSPECTIVE_PIXEL : 0u) |
           (q->refraction_apron != 0 ? USES_APRON : 0u) | (q->water_block > 1 ? USES_WATER_BLOCKS : 0u) |
           (q->depth_bits == 16 ? USES_DEPTH16 : 0u) | (q->depth_bits == 32 ? USES_DEPTH32 : 0u) |
           (q->depth_interpolation == TARN_DEPTH_EXACT ? USES_EXACT_DEPTH : 0u) |
           (finds_bins ? USES_FOUND_BINS : 0u) |
           (q->refraction_normal == TARN_REFRACTION_NORMAL_EXACT ? USES_REFRACTION_EXACT : 0u) |
           (q->frame_shape == TARN_FRAME_STRIPS ? USES_STRIPS : 0u) |
           (q->vertex_pass != TARN_VERTICES_PER_TILE ? USES_VERTEX_PASS : 0u) |
           (q->perspective == TARN_PERSPECTIVE_PIXEL && q->lit_colour == TARN_LIT_LINE &&
                    (view == NULL || view->backdrop == NULL)
                ? USES_LIT_LINE : 0u) |
           (q->water_coordinates == TARN_WATER_UV_PLANE && water &&
                    (view == NULL || view->backdrop == NULL || !view->backdrop->still_water)
                ? USES_WATER_PLANE : 0u);
}

static void print_link_header(FILE *out, const bake_plan *p, const tarn_bake_options *o,
                              const bake_totals *totals)
{
    uint32_t features, every;
    const int water = used_water(&p->scene->scene, &features, &every);
    text_buffer names = {{0}, 0}, every_names = {{0}, 0};
    format_features(&names, features);
    format_features(&every_names, every);
    fputs("/* ", out);
    comment_text(out, base_name(totals->link_path));
    fputs(": the parts of the renderer the scene ", out);
    comment_text(out, o->scene_path);
    fputs(" uses.\n * Generated; do not edit. Compile core/ with  -include ", out);
    comment_text(out, base_name(totals->link_path));
    fputs("  and the code of\n * every effect the scene does not use is left out of the image (tarn_water.h). */\n",
          out);
    fprintf(out, "#define TARN_LINK_WATER %d\n", water);
    fprintf(out, "#define TARN_LINK_WATER_FEATURES (%s)\n", names.text);
    fprintf(out, "#define TARN_LINK_WATER_FEATURES_ALL (%s)\n", every_names.text);
    fprintf(out, "#define TARN_LINK_UNDERWATER %d\n", p->scene->scene.underwater != NULL);
    unsigned uses = quality_uses(&p->scene->scene, &p->config.quality);
    for (size_t i = 0; i < p->points->count; i++) uses |= quality_uses(&p->scene->scene, &p->points->qualities[i]);
    for (size_t k = 0; k < sizeof quality_switches / sizeof quality_switches[0]; k++)
        fprintf(out, "#define TARN_LINK_%s %d\n", quality_switches[k].name, (uses & quality_switches[k].bit) != 0);
    fprintf(out, "#define TARN_LINK_OPAQUE_OBJECTS %d\n", has_opaque_objects(&p->scene->scene));
    fprintf(out, "#define TARN_LINK_COMPUTED_VERTICES %d\n", p->scene->scene.static_view == NULL);
    /* the vertex pass reads the vertices it finds as static ones */
    fprintf(out, "#define TARN_LINK_STATIC_VERTICES %d\n",
            p->scene->scene.static_view != NULL || (uses & USES_VERTEX_PASS) != 0);
    const tarn_backdrop *backdrop = p->scene->scene.static_view != NULL ? p->scene->scene.static_view->backdrop : NULL;
    const int still = backdrop != NULL && backdrop->still_water;
    fprintf(out, "#define TARN_LINK_BACKDROP %d\n", backdrop != NULL);
    fprintf(out, "#define TARN_LINK_STILL_WATER %d\n", still);
    fprintf(out, "#define TARN_LINK_MOTION %d\n", tarn_scene_moves(&p->scene->scene));
    fprintf(out, "#define TARN_LINK_WATER_SHADING %d\n", !still);
}

/* The three files to temporaries, then renamed into place; a failure removes all. */
static int write_outputs(const bake_plan *p, const tarn_bake_options *o, const bake_totals *totals,
                         tarn_error *err)
{
    const char *paths[3] = {o->output_path, totals->header_path, totals->link_path};
    tarn_atomic_file files[3];
    if (tarn_atomic_open_all(files, paths, 3, err) != 0) return -1;
    emitter e = {files[0].file, p, 0};
    print_source_comment(files[0].file, p, o, totals);
    /* a scene near the budget is millions of triangles, and seconds of text */
    tarn_progress progress;
    tarn_progress_start(&progress, "tarn bake: tables written", p->item_count, o->quiet);
    for (size_t k = 0; k < p->item_count; k++) {
        print_item(&e, &p->items[k]);
        tarn_progress_step(&progress, k + 1u);
    }
    tarn_progress_end(&progress);
    print_header(files[1].file, p, o, totals);
    print_link_header(files[2].file, p, o, totals);
    if (e.unresolved) {
        tarn_atomic_abandon_all(files, 3);
        return tarn_fail(err, "%s: internal error: the scene points to data the baker did not plan", o->output_path);
    }
    return tarn_atomic_commit_all(files, 3, err);
}

/* ---- names and the whole bake --------------------------------------------------- */

static int is_identifier_char(char c, int first)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (!first && c >= '0' && c <= '9');
}

/* "tarn", "tarn_..." in any case: NAME_scene could be tarn_scene, a core type. */
static int in_tarn_namespace(const char *name)
{
    static const char prefix[] = "tarn_";
    size_t k = 0;
    for (; k < 5 && name[k]; k++) {
        char lower = name[k] >= 'A' && name[k] <= 'Z' ? (char)(name[k] - 'A' + 'a') : name[k];
        if (lower != prefix[k]) return 0;
    }
    return k == 5 || (k == 4 && name[4] == '\0');
}

int tarn_bake_check_name(const char *name, tarn_error *err)
{
    size_t length = strlen(name);
    int identifier = length > 0;
    for (size_t k = 0; k < length; k++) identifier = identifier && is_identifier_char(name[k], k == 0);
    char shown[TARN_BAKE_NAME_MAX + 4];
    size_t n = 0;
    for (; name[n] && n < TARN_BAKE_NAME_MAX; n++) shown[n] = name[n] >= 0x20 && name[n] < 0x7f ? name[n] : '?';
    snprintf(shown + n, sizeof shown - n, "%s", name[n] ? "..." : "");
    if (!identifier)
        return tarn_fail(err, "--name: expected a C identifier (letters, digits and _, not starting with a "
                         "digit), got '%s'", shown);
    if (length > TARN_BAKE_NAME_MAX)
        return tarn_fail(err, "--name: expected at most %u characters, got %zu ('%s')", TARN_BAKE_NAME_MAX,
                         length, shown);
    if (in_tarn_namespace(name))
        return tarn_fail(err, "--name: '%s' would clash with the renderer's own tarn_ names", shown);
    return 0;
}

void tarn_bake_default_name(const char *stem, char out[TARN_BAKE_NAME_MAX + 1])
{
    size_t n = 0;
    for (; stem[n] && n < TARN_BAKE_NAME_MAX; n++) out[n] = is_identifier_char(stem[n], 0) ? stem[n] : '_';
    out[n] = '\0';
    if (tarn_bake_check_name(out, NULL) == 0) return;
    char fixed[TARN_BAKE_NAME_MAX + 1];
    snprintf(fixed, sizeof fixed, "scene_%s", out);
    memcpy(out, fixed, sizeof fixed);
}

/* "out/pond.c" -> "out/pond" + suffix ("out/pond.h", "out/pond_link.h"), malloc'd;
 * NULL with `err` set unless the output ends in .c. */
static char *path_beside(const char *output_path, const char *suffix, tarn_error *err)
{
    size_t length = strlen(output_path);
    const char *base = base_name(output_path);
    if (strlen(base) < 3 || strcmp(output_path + length - 2, ".c") != 0) {
        tarn_fail(err, "-o: expected a C file name ending in .c, got '%s'", output_path);
        return NULL;
    }
    char *path = malloc(length - 2 + strlen(suffix) + 1);
    if (!path) {
        tarn_fail(err, "%s: out of memory", output_path);
        return NULL;
    }
    memcpy(path, output_path, length - 2);
    strcpy(path + length - 2, suffix);
    return path;
}

static int choose_name(const tarn_loaded_scene *scene, const tarn_bake_options *o,
                       char name[TARN_BAKE_NAME_MAX + 1], tarn_error *err)
{
    if (o->name == NULL) {
        tarn_bake_default_name(scene->name, name);
        return 0;
    }
    if (tarn_bake_check_name(o->name, err) != 0) return -1;
    snprintf(name, TARN_BAKE_NAME_MAX + 1, "%s", o->name);
    return 0;
}

/* The loaded scene as baked with its static view (static_view.h), and with
 * --backdrop on, only its water over the backdrop (backdrop.h). */
typedef struct {
    tarn_loaded_scene loaded;
    tarn_static_scene with_view;
    tarn_backdrop_scene over_backdrop;
    int backdrop;
} static_scene;

static int static_scene_make(const tarn_loaded_scene *scene, const tarn_frame_config *config,
                             tarn_backdrop_request backdrop, static_scene *out, tarn_error *err)
{
    out->backdrop = backdrop.kind != TARN_BACKDROP_NONE;
    if (out->backdrop && tarn_backdrop_scene_make(&scene->scene, config, backdrop, 0, &out->over_backdrop, err) != 0)
        return -1;
    if (!out->backdrop && tarn_static_scene_make(&scene->scene, config, 0, &out->with_view, err) != 0) return -1;
    out->loaded = *scene;
    out->loaded.scene = out->backdrop ? out->over_backdrop.water.scene : out->with_view.scene;
    return 0;
}

static uint32_t static_bin_count(const static_scene *s)
{
    return s->backdrop ? s->over_backdrop.water.vertices.bin_count : s->with_view.vertices.bin_count;
}

static void static_scene_free(static_scene *s)
{
    if (s->backdrop) tarn_backdrop_scene_free(&s->over_backdrop);
    else tarn_static_scene_free(&s->with_view);
}

/* The largest piece a frame at quality q hands its sink, into the totals. */
static void add_piece(bake_totals *totals, const tarn_frame_config *config, const tarn_quality *q)
{
    const unsigned tile = q->tile_size;
    const unsigned width = q->frame_shape == TARN_FRAME_STRIPS && config->width > tile ? config->width : tile;
    if (width > totals->piece_width) totals->piece_width = width;
    if (tile > totals->piece_rows) totals->piece_rows = tile;
}

/* The working memory of a frame of the scene as baked, at the config and at each
 * --points quality (loaded into `points`): the largest. 0, or -1 with `err` set. */
static int baked_memory(const bake_plan *p, const tarn_bake_options *o, tarn_bake_points *points,
                        size_t *memory_bytes, tarn_error *err)
{
    *memory_bytes = tarn_frame_memory_bytes(&p->config, &p->scene->scene);
    if (o->points_path == NULL) return 0;
    return tarn_bake_points_load(o->points_path, &p->config.quality, points, err) != 0 ||
                   tarn_bake_points_check(points, &p->config, &p->scene->scene, memory_bytes, err) != 0
               ? -1
               : 0;
}

int tarn_bake(const tarn_loaded_scene *scene, const tarn_bake_options *o, tarn_bake_result *result,
              tarn_error *err)
{
    bake_plan plan;
    memset(&plan, 0, sizeof plan);
    bake_totals totals;
    memset(&totals, 0, sizeof totals);
    if (check_tables(err) != 0 || choose_name(scene, o, result->name, err) != 0) return -1;
    plan.scene = scene;
    plan.name = result->name;
    plan.config = o->config;
    plan.config.time_ms = 0;
    if (tarn_frame_memory_bytes(&plan.config, &scene->scene) == 0)
        return tarn_fail(err, "%s: %ux%u with these quality settings: %s", o->scene_path, plan.config.width,
                         plan.config.height, tarn_status_text(TARN_ERR_CONFIG));
    static_scene with_static;
    /* a static view freezes the camera, the light and every object where they stand */
    const int freeze = o->static_view && !tarn_scene_moves(&scene->scene);
    if (o->backdrop.kind != TARN_BACKDROP_NONE && tarn_scene_moves(&scene->scene))
        return tarn_fail(err, "%s: --backdrop: the scene moves (%s), and a backdrop is one frame's picture; use "
                         "--backdrop off", o->scene_path, motion_summary(&scene->scene));
    if (freeze) {
        if (static_scene_make(scene, &plan.config, o->backdrop, &with_static, err) != 0)
            return tarn_fail_in(err, o->scene_path);
        plan.scene = &with_static.loaded;
        plan.static_bin_count = static_bin_count(&with_static);
        plan.backdrop_colour_words = with_static.backdrop ? with_static.over_backdrop.image.colour_words : 0u;
    }
    tarn_bake_points points = {NULL, NULL, NULL, 0};
    plan.points = &points;
    char *header_path = NULL, *link_path = NULL;
    int failed = baked_memory(&plan, o, &points, &totals.memory_bytes, err);
    add_piece(&totals, &plan.config, &plan.config.quality);
    for (size_t k = 0; !failed && k < points.count; k++) add_piece(&totals, &plan.config, &points.qualities[k]);
    if (!failed) {
        header_path = path_beside(o->output_path, ".h", err);
        link_path = header_path ? path_beside(o->output_path, "_link.h", err) : NULL;
        failed = link_path == NULL;
    }
    totals.header_path = header_path;
    totals.link_path = link_path;
    failed = failed || plan_build(&plan, err);
    if (!failed) {
        totals.const_bytes = plan_bytes(&plan, totals.bytes);
        failed = write_outputs(&plan, o, &totals, err);
    }
    result->const_bytes = totals.const_bytes;
    result->memory_bytes = totals.memory_bytes;
    plan_free(&plan);
    if (freeze) static_scene_free(&with_static);
    tarn_bake_points_free(&points);
    free(header_path);
    free(link_path);
    return failed ? -1 : 0;
}
