#include "scene_load.h"

#include "mesh_clusters.h"
#include "uv_plane.h"

#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_file.h"
#include "obj_load.h"
#include "motion_load.h"
#include "scene_fields.h"
#include "scene_textures.h"
#include "texel_span.h"
#include "water_load.h"

#define PI 3.14159265358979323846

/* The most textures one material loads: its own, two normal maps, foam and a ramp. */
#define TEXTURES_PER_MATERIAL 5u

/* ---- field rules ------------------------------------------------------------ */

static const tarn_rule FRAME_SIDE = { "an integer 1..1024", 1, 1024, TARN_INTEGER };
static const tarn_rule SEGMENTS = { "an integer 1..256", 1, 256, TARN_INTEGER };
static const tarn_rule SPHERE_SEGMENTS = { "an integer 3..256", 3, 256, TARN_INTEGER };
static const tarn_rule SPHERE_RINGS = { "an integer 2..256", 2, 256, TARN_INTEGER };


/* ---- frame, camera, light ----------------------------------------------------- */

static int load_frame(tarn_loader *l, const json_t *root)
{
    static const char *const fields[] = { "width", "height", NULL };
    static const double side = 240;
    json_t *frame;
    double width = side, height = side;
    if (tarn_get_object(l, root, "", "frame", "an object {\"width\", \"height\"}", 0, &frame)) {
        return -1;
    }
    if (frame && (tarn_check_fields(l, frame, "frame", fields, NULL, "") ||
                  tarn_get_number(l, frame, "frame", "width", &FRAME_SIDE, &side, &width) ||
                  tarn_get_number(l, frame, "frame", "height", &FRAME_SIDE, &side, &height))) {
        return -1;
    }
    l->out->width = (uint16_t)width;
    l->out->height = (uint16_t)height;
    return 0;
}

static int load_camera(tarn_loader *l, const json_t *root)
{
    static const char *const fields[] = { "position", "target", "fov", "near", "far", "path", NULL };
    static const double default_near = 0.1, default_far = 100, placed[3] = { 0, 0, 0 };
    json_t *c;
    int moves;
    double position[3], target[3], fov, near, far;
    if (tarn_get_object(l, root, "", "camera",
                        "an object {\"position\", \"target\", \"fov\"...}", 1, &c) ||
        tarn_check_fields(l, c, "camera", fields, NULL, "") ||
        tarn_camera_path_load(l, c, &l->out->camera_path, &moves)) {
        return -1;
    }
    if (moves) { /* the path places the camera (load_root puts it there at time 0) */
        const char *placed_field = json_object_get(c, "position") ? "camera.position"
                                   : json_object_get(c, "target") ? "camera.target" : NULL;
        if (placed_field) return tarn_fail_field(l, placed_field, "not with camera.path, which places the camera");
        l->out->scene.camera_path = &l->out->camera_path;
    }
    if (tarn_get_vec3(l, c, "camera", "position", moves ? placed : NULL, position) ||
        tarn_get_vec3(l, c, "camera", "target", moves ? placed : NULL, target) ||
        tarn_get_number(l, c, "camera", "fov", &TARN_FOV, NULL, &fov) ||
        tarn_get_number(l, c, "camera", "near", &TARN_POSITIVE, &default_near, &near) ||
        tarn_get_number(l, c, "camera", "far", &TARN_POSITIVE, &default_far, &far)) {
        return -1;
    }
    tarn_camera *camera = &l->out->scene.camera;
    camera->position = tarn_vec3_q16(position);
    camera->target = tarn_vec3_q16(target);
    camera->fov_y_degrees = tarn_q16_from_double(fov);
    camera->near = tarn_q16_from_double(near);
    camera->far = tarn_q16_from_double(far);
    if (camera->far <= camera->near) {
        return tarn_fail_field(l, "camera.far",
                               "expected a number greater than camera.near (%g), got %g",
                               near, far);
    }
    if (!moves && memcmp(&camera->position, &camera->target, sizeof camera->position) == 0) {
        return tarn_fail_field(l, "camera.target", "must differ from camera.position");
    }
    return 0;
}

static int load_light(tarn_loader *l, const json_t *root)
{
    static const char *const fields[] = { "direction", "colour", "ambient", "motion", NULL };
    static const double from_above[3] = { 0, 1, 0 };
    json_t *light;
    int moves;
    double d[3];
    tarn_light *out = &l->out->scene.light;
    if (tarn_get_object(l, root, "", "light",
                        "an object {\"direction\", \"colour\", \"ambient\"}", 0, &light)) {
        return -1;
    }
    /* an absent light (NULL) has no fields, so every one takes its default */
    if (tarn_check_fields(l, light, "light", fields, NULL, "") ||
        tarn_get_vec3(l, light, "light", "direction", from_above, d) ||
        tarn_get_colour(l, light, "light", "colour", 0xFFFFFF, &out->colour_rgb) ||
        tarn_get_colour(l, light, "light", "ambient", 0x333333, &out->ambient_rgb) ||
        tarn_light_motion_load(l, light, &l->out->light_motion, &moves)) {
        return -1;
    }
    if (moves) l->out->scene.light_motion = &l->out->light_motion;
    double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(length > 1e-9)) {
        return tarn_fail_field(l, "light.direction", "expected a non-zero vector, got [%g, %g, %g]",
                               d[0], d[1], d[2]);
    }
    double unit[3] = { d[0] / length, d[1] / length, d[2] / length };
    out->direction = tarn_vec3_q16(unit);
    return 0;
}

/* ---- materials and textures --------------------------------------------------- */

static int parse_cull(tarn_loader *l, const json_t *m, const char *field, uint8_t *out)
{
    static const char *const modes[] = { "back", "none", "front", NULL }; /* tarn_cull order */
    static const char what[] = "one of \"back\", \"none\", \"front\"";
    const char *text;
    if (tarn_get_string(l, m, field, "cull", what, 0, &text)) return -1;
    *out = TARN_CULL_BACK;
    if (!text) return 0;
    for (uint8_t k = 0; modes[k]; k++) {
        if (strcmp(text, modes[k]) == 0) {
            *out = k;
            return 0;
        }
    }
    char cull_field[TARN_FIELD_PATH_MAX];
    tarn_join_path(cull_field, field, "cull");
    return tarn_fail_field(l, cull_field, "expected %s, got \"%s\"", what, text);
}

/* `water` is the material's slot in the scene's waters, used if it has a block. */
static int load_material(tarn_loader *l, const char *name, const json_t *m, tarn_material *out,
                         tarn_water *water)
{
    static const char *const fields[] = { "colour", "texture", "cull", "unlit", "water", NULL };
    char field[TARN_FIELD_PATH_MAX];
    tarn_join_path(field, "materials", name);
    if (!json_is_object(m)) {
        return tarn_fail_field(l, field, "expected an object {\"colour\", \"texture\", "
                                         "\"cull\", \"unlit\", \"water\"}, got %s",
                               tarn_json_type(m));
    }
    int unlit;
    if (tarn_check_fields(l, m, field, fields, NULL, "") ||
        tarn_get_colour(l, m, field, "colour", 0xFFFFFF, &out->colour_rgb) ||
        parse_cull(l, m, field, &out->cull) || tarn_get_bool(l, m, field, "unlit", 0, &unlit)) {
        return -1;
    }
    out->unlit = (uint8_t)unlit;
    out->texture = NULL;
    out->water = NULL;
    if (json_object_get(m, "texture") && tarn_get_texture(l, m, field, "texture", &out->texture)) {
        return -1;
    }
    int present;
    if (tarn_water_load(l, m, field, l->out->width, water, &present)) return -1;
    if (present) out->water = water;
    return 0;
}

static int load_materials(tarn_loader *l, const json_t *root)
{
    tarn_loaded_scene *s = l->out;
    json_t *materials;
    if (tarn_get_object(l, root, "", "materials", "an object of named materials", 1, &materials)) {
        return -1;
    }
    size_t n = json_object_size(materials);
    s->texture_capacity = TEXTURES_PER_MATERIAL * n + 1; /* + the underwater normal map */
    s->materials = calloc(n + 1, sizeof *s->materials);
    s->material_names = calloc(n + 1, sizeof *s->material_names);
    s->waters = calloc(n + 1, sizeof *s->waters);
    s->textures = calloc(s->texture_capacity, sizeof *s->textures);
    s->texture_images = calloc(s->texture_capacity, sizeof *s->texture_images);
    s->texture_paths = calloc(s->texture_capacity, sizeof *s->texture_paths);
    if (!s->materials || !s->material_names || !s->waters || !s->textures ||
        !s->texture_images || !s->texture_paths) {
        return tarn_fail(l->err, "%s: out of memory", l->file);
    }
    const char *name;
    const json_t *m;
    json_object_foreach(materials, name, m) {
        size_t k = s->material_count++;
        s->material_names[k] = strdup(name);
        if (!s->material_names[k]) return tarn_fail(l->err, "%s: out of memory", l->file);
        if (load_material(l, name, m, &s->materials[k], &s->waters[k])) return -1;
    }
    return 0;
}

/* ---- objects ------------------------------------------------------------------ */

/* Builds an object's mesh from its type-specific fields; its material decides what
 * a heightfield may merge. */
typedef int (*mesh_builder)(tarn_loader *l, const json_t *o, const char *field,
                            const tarn_material *material, tarn_mesh_buffer *mesh);

/* Words for an object in the budget's messages: "sphere, segments 64, rings 64". */
#define OBJECT_WORDS_MAX 96

static const double ONE_BY_ONE[2] = { 1, 1 };

static int get_plane_segments(tarn_loader *l, const json_t *o, const char *field, double segments[2])
{
    return tarn_get_numbers(l, o, field, "segments", 2, &SEGMENTS, ONE_BY_ONE, segments);
}

static int get_sphere_segments(tarn_loader *l, const json_t *o, const char *field, double *segments,
                               double *rings)
{
    static const double default_segments = 16, default_rings = 8;
    return tarn_get_number(l, o, field, "segments", &SPHERE_SEGMENTS, &default_segments, segments) ||
           tarn_get_number(l, o, field, "rings", &SPHERE_RINGS, &default_rings, rings);
}

/* The mesh of a plane, box or sphere weighed from its fields, and the words that
 * name it; for the other types the files they name decide. */
typedef int (*mesh_sizer)(tarn_loader *l, const json_t *o, const char *field, tarn_mesh_size *size,
                          char words[OBJECT_WORDS_MAX]);

static int size_plane(tarn_loader *l, const json_t *o, const char *field, tarn_mesh_size *size,
                      char words[OBJECT_WORDS_MAX])
{
    double segments[2];
    if (get_plane_segments(l, o, field, segments)) return -1;
    *size = tarn_mesh_plane_size((uint32_t)segments[0], (uint32_t)segments[1]);
    snprintf(words, OBJECT_WORDS_MAX, "plane, segments [%g, %g]", segments[0], segments[1]);
    return 0;
}

static int size_box(tarn_loader *l, const json_t *o, const char *field, tarn_mesh_size *size,
                    char words[OBJECT_WORDS_MAX])
{
    (void)l, (void)o, (void)field;
    *size = tarn_mesh_box_size();
    snprintf(words, OBJECT_WORDS_MAX, "box");
    return 0;
}

static int size_sphere(tarn_loader *l, const json_t *o, const char *field, tarn_mesh_size *size,
                       char words[OBJECT_WORDS_MAX])
{
    double segments, rings;
    if (get_sphere_segments(l, o, field, &segments, &rings)) return -1;
    *size = tarn_mesh_sphere_size((uint32_t)segments, (uint32_t)rings);
    snprintf(words, OBJECT_WORDS_MAX, "sphere, segments %g, rings %g", segments, rings);
    return 0;
}

/* Adds an object's mesh to the scene's weight, or refuses the object that would
 * cross a limit: "FILE: objects[3] (WORDS): the scene would hold...". */
static int weigh_mesh(tarn_loader *l, const char *field, const char *words, tarn_mesh_size size)
{
    const tarn_scene_cost mesh = { 0, size.vertices, size.triangles, 0 };
    char what[sizeof l->err->message];
    snprintf(what, sizeof what, "%s: %s (%s)", l->file, field, words);
    return tarn_scene_cost_charge(&l->out->cost, &mesh, what, l->err);
}

static int build_plane(tarn_loader *l, const json_t *o, const char *field,
                       const tarn_material *material, tarn_mesh_buffer *mesh)
{
    (void)material;
    double size[2], segments[2], uv_scale[2];
    char what[TARN_FIELD_PATH_MAX + 64];
    snprintf(what, sizeof what, "%s: %s", l->file, field);
    if (tarn_get_numbers(l, o, field, "size", 2, &TARN_POSITIVE, NULL, size) ||
        get_plane_segments(l, o, field, segments) ||
        tarn_get_numbers(l, o, field, "uv_scale", 2, &TARN_COORDINATE, ONE_BY_ONE, uv_scale)) {
        return -1;
    }
    return tarn_mesh_plane(mesh, size[0], size[1], (uint32_t)segments[0], (uint32_t)segments[1],
                           uv_scale[0], uv_scale[1], what, l->err);
}

static int build_box(tarn_loader *l, const json_t *o, const char *field,
                     const tarn_material *material, tarn_mesh_buffer *mesh)
{
    (void)material;
    double size[3];
    char what[TARN_FIELD_PATH_MAX + 64];
    snprintf(what, sizeof what, "%s: %s", l->file, field);
    if (tarn_get_numbers(l, o, field, "size", 3, &TARN_POSITIVE, NULL, size)) return -1;
    return tarn_mesh_box(mesh, size[0], size[1], size[2], what, l->err);
}

static int build_sphere(tarn_loader *l, const json_t *o, const char *field,
                        const tarn_material *material, tarn_mesh_buffer *mesh)
{
    (void)material;
    double radius, segments, rings;
    char what[TARN_FIELD_PATH_MAX + 64];
    snprintf(what, sizeof what, "%s: %s", l->file, field);
    if (tarn_get_number(l, o, field, "radius", &TARN_POSITIVE, NULL, &radius) ||
        get_sphere_segments(l, o, field, &segments, &rings)) {
        return -1;
    }
    return tarn_mesh_sphere(mesh, radius, (uint32_t)segments, (uint32_t)rings, what, l->err);
}

static int build_heightfield(tarn_loader *l, const json_t *o, const char *field,
                             const tarn_material *material, tarn_mesh_buffer *mesh)
{
    double size[2], height, uv_scale[2];
    char *path;
    if (tarn_get_numbers(l, o, field, "size", 2, &TARN_POSITIVE, NULL, size) ||
        tarn_get_number(l, o, field, "height", &TARN_POSITIVE, NULL, &height) ||
        tarn_get_numbers(l, o, field, "uv_scale", 2, &TARN_COORDINATE, ONE_BY_ONE, uv_scale) ||
        tarn_get_asset_path(l, o, field, "image", "a PNG file name", &path)) {
        return -1;
    }
    tarn_image image;
    char words[OBJECT_WORDS_MAX];
    int result = tarn_png_read_heightfield(path, &image, l->err);
    if (result == 0) {
        snprintf(words, sizeof words, "heightfield, image %ux%u", image.width, image.height);
        result = weigh_mesh(l, field, words, tarn_mesh_heightfield_size(image.width, image.height));
    }
    if (result == 0) {
        result = tarn_mesh_heightfield(mesh, &image, size[0], size[1], height, uv_scale[0],
                                       uv_scale[1], material->water == NULL, path, l->err);
    }
    tarn_image_free(&image);
    free(path);
    return result;
}

static int build_obj_mesh(tarn_loader *l, const json_t *o, const char *field,
                          const tarn_material *material, tarn_mesh_buffer *mesh)
{
    (void)material;
    char *path;
    if (tarn_get_asset_path(l, o, field, "file", "an OBJ file name", &path)) return -1;
    /* the file stops at the line that would cross a limit; the mesh is then weighed
     * as built, since a position split by its texture coordinates or normals makes
     * more vertices than the file has lines */
    char words[OBJECT_WORDS_MAX];
    snprintf(words, sizeof words, "mesh, %s", path);
    int result = tarn_obj_load(path, &l->out->cost, mesh, l->err);
    if (result == 0) {
        const tarn_mesh_size size = { mesh->mesh.vertex_count, mesh->mesh.triangle_count };
        result = weigh_mesh(l, field, words, size);
    }
    free(path);
    return result;
}

typedef struct {
    const char *type;
    const char *kind;            /* " for a sphere": in unknown-field messages */
    const char *const fields[5]; /* the type's own fields, NULL-terminated */
    mesh_sizer size;             /* NULL: the files it names decide, as it is built */
    mesh_builder build;
    const char *uv_field;        /* the field that sets its texture coordinates, or NULL */
} object_type;

static const object_type OBJECT_TYPES[] = {
    { "plane", " for a plane", { "size", "segments", "uv_scale", NULL }, size_plane, build_plane,
      "uv_scale" },
    { "box", " for a box", { "size", NULL }, size_box, build_box, NULL },
    { "sphere", " for a sphere", { "radius", "segments", "rings", NULL }, size_sphere, build_sphere,
      NULL },
    { "heightfield", " for a heightfield", { "image", "size", "height", "uv_scale", NULL }, NULL,
      build_heightfield, "uv_scale" },
    { "mesh", " for a mesh", { "file", NULL }, NULL, build_obj_mesh, "file" },
};
#define OBJECT_TYPE_COUNT (sizeof OBJECT_TYPES / sizeof OBJECT_TYPES[0])

static const char TYPE_CHOICES[] =
    "one of \"plane\", \"box\", \"sphere\", \"heightfield\", \"mesh\"";

/* The type named `type`, or NULL (also for a NULL name). */
static const object_type *object_type_named(const char *type)
{
    for (size_t k = 0; type && k < OBJECT_TYPE_COUNT; k++) {
        if (strcmp(type, OBJECT_TYPES[k].type) == 0) return &OBJECT_TYPES[k];
    }
    return NULL;
}

static int find_object_type(tarn_loader *l, const json_t *o, const char *field,
                            const object_type **out)
{
    const char *type;
    if (tarn_get_string(l, o, field, "type", TYPE_CHOICES, 1, &type)) return -1;
    *out = object_type_named(type);
    if (*out) return 0;
    char type_field[TARN_FIELD_PATH_MAX];
    tarn_join_path(type_field, field, "type");
    return tarn_fail_field(l, type_field, "expected %s, got \"%s\"", TYPE_CHOICES, type);
}

static int find_material(tarn_loader *l, const json_t *o, const char *field,
                         const tarn_material **out)
{
    const char *name;
    if (tarn_get_string(l, o, field, "material", "a material name", 1, &name)) return -1;
    for (size_t k = 0; k < l->out->material_count; k++) {
        if (strcmp(name, l->out->material_names[k]) == 0) {
            *out = &l->out->materials[k];
            return 0;
        }
    }
    char material_field[TARN_FIELD_PATH_MAX];
    tarn_join_path(material_field, field, "material");
    return tarn_fail_field(l, material_field, "no material named \"%s\" in materials", name);
}

/* R = Rz * Ry * Rx from degrees, in double, each entry then rounded to Q16.16. */
static void rotation_matrix(const double degrees[3], tarn_q16 out[3][3])
{
    double c[3], s[3];
    for (int k = 0; k < 3; k++) {
        c[k] = cos(degrees[k] * PI / 180);
        s[k] = sin(degrees[k] * PI / 180);
    }
    const double rx[3][3] = { { 1, 0, 0 }, { 0, c[0], -s[0] }, { 0, s[0], c[0] } };
    const double ry[3][3] = { { c[1], 0, s[1] }, { 0, 1, 0 }, { -s[1], 0, c[1] } };
    const double rz[3][3] = { { c[2], -s[2], 0 }, { s[2], c[2], 0 }, { 0, 0, 1 } };
    double ryx[3][3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            ryx[i][j] = ry[i][0] * rx[0][j] + ry[i][1] * rx[1][j] + ry[i][2] * rx[2][j];
        }
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            out[i][j] = tarn_q16_from_double(rz[i][0] * ryx[0][j] + rz[i][1] * ryx[1][j] +
                                             rz[i][2] * ryx[2][j]);
        }
    }
}

/* The mesh's clusters (mesh_clusters.h) and, under water, its plane (uv_plane.h):
 * their one failure, memory, is named after the object, as the orderer knows
 * only the mesh. */
static int finish_mesh(tarn_loader *l, const char *field, const tarn_material *material, tarn_mesh_buffer *mesh)
{
    if (material->water != NULL && tarn_mesh_find_plane(mesh, material->water) != 0) {
        tarn_fail(l->err, "out of memory");
    } else if (tarn_mesh_build_clusters(mesh, l->err) == 0) {
        return 0;
    }
    char what[TARN_FIELD_PATH_MAX + 64];
    snprintf(what, sizeof what, "%s: %s", l->file, field);
    return tarn_fail_in(l->err, what);
}

static int load_object(tarn_loader *l, const json_t *o, size_t index)
{
    static const char *const common[] = { "type",  "material", "position", "rotation",
                                          "scale", "motion",   NULL };
    static const double origin[3] = { 0, 0, 0 }, unit_scale = 1;
    char field[TARN_FIELD_PATH_MAX];
    snprintf(field, sizeof field, "objects[%zu]", index);
    if (!json_is_object(o)) {
        return tarn_fail_field(l, field, "expected an object {\"type\", \"material\"...}, got %s",
                               tarn_json_type(o));
    }
    tarn_object *object = &l->out->objects[index];
    tarn_mesh_buffer *mesh = &l->out->meshes[index];
    const object_type *type = NULL;
    double position[3], rotation[3], scale;
    int moves;
    if (find_object_type(l, o, field, &type) ||
        tarn_check_fields(l, o, field, common, type->fields, type->kind) ||
        find_material(l, o, field, &object->material) ||
        tarn_get_vec3(l, o, field, "position", origin, position) ||
        tarn_get_vec3(l, o, field, "rotation", origin, rotation) ||
        tarn_get_number(l, o, field, "scale", &TARN_POSITIVE, &unit_scale, &scale) ||
        tarn_object_motion_load(l, o, field, &l->out->motions[index], &moves) ||
        type->build(l, o, field, object->material, mesh) || finish_mesh(l, field, object->material, mesh)) {
        return -1;
    }
    object->mesh = &mesh->mesh;
    if (moves) object->motion = &l->out->motions[index];
    object->position = tarn_vec3_q16(position);
    rotation_matrix(rotation, object->rotation);
    object->scale = tarn_q16_from_double(scale);
    char uv_field[TARN_FIELD_PATH_MAX];
    if (type->uv_field != NULL)
        tarn_join_path(uv_field, field, type->uv_field);
    else
        snprintf(uv_field, sizeof uv_field, "%s", field);
    return tarn_check_texel_spans(l, object, index, uv_field);
}

/* The object arrays, and every plane, box and sphere weighed from its fields, before
 * any object is built: a scene that asks for too much is refused at once, naming
 * the object that crosses a limit. An object whose fields cannot be weighed (a bad
 * type or segment count) is left to its own load, which refuses it in file order. */
static int weigh_objects(tarn_loader *l, const json_t *objects)
{
    const tarn_scene_cost arrays = { json_array_size(objects), 0, 0, 0 };
    char what[sizeof l->err->message];
    snprintf(what, sizeof what, "%s: objects", l->file);
    if (tarn_scene_cost_charge(&l->out->cost, &arrays, what, l->err)) return -1;
    tarn_error unread;
    tarn_loader quiet = *l;
    quiet.err = &unread;
    for (size_t k = 0; k < json_array_size(objects); k++) {
        const json_t *o = json_array_get(objects, k);
        const object_type *type = object_type_named(json_string_value(json_object_get(o, "type")));
        char field[TARN_FIELD_PATH_MAX], words[OBJECT_WORDS_MAX];
        tarn_mesh_size size;
        snprintf(field, sizeof field, "objects[%zu]", k);
        if (!type || !type->size || type->size(&quiet, o, field, &size, words)) continue;
        if (weigh_mesh(l, field, words, size)) return -1;
    }
    return 0;
}

static int load_objects(tarn_loader *l, const json_t *root)
{
    tarn_loaded_scene *s = l->out;
    const json_t *objects = json_object_get(root, "objects");
    if (!objects) return tarn_fail_field(l, "objects", "missing (expected an array of objects)");
    if (!json_is_array(objects)) {
        return tarn_fail_field(l, "objects", "expected an array of objects, got %s",
                               tarn_json_type(objects));
    }
    size_t n = json_array_size(objects);
    if (n > UINT16_MAX) {
        return tarn_fail_field(l, "objects", "expected at most %u objects, got %zu", UINT16_MAX, n);
    }
    if (weigh_objects(l, objects)) return -1;
    s->objects = calloc(n + 1, sizeof *s->objects);
    s->meshes = calloc(n + 1, sizeof *s->meshes);
    s->motions = calloc(n + 1, sizeof *s->motions);
    if (!s->objects || !s->meshes || !s->motions) return tarn_fail(l->err, "%s: out of memory", l->file);
    s->object_count = n;
    for (size_t k = 0; k < n; k++) {
        if (load_object(l, json_array_get(objects, k), k)) return -1;
    }
    s->scene.objects = s->objects;
    s->scene.object_count = (uint16_t)n;
    return 0;
}

/* ---- the file ----------------------------------------------------------------- */

static json_t *parse_json(const char *path, tarn_error *err)
{
    FILE *file = tarn_open_input(path, "a scene file", TARN_SCENE_FILE_BYTES_MAX, err);
    if (!file) return NULL;
    json_error_t error;
    json_t *root = json_loadf(file, JSON_REJECT_DUPLICATES, &error);
    fclose(file);
    if (!root) {
        if (error.line > 0) {
            tarn_fail(err, "%s:%d:%d: %s", path, error.line, error.column, error.text);
        } else {
            tarn_fail(err, "%s: %s", path, error.text);
        }
        return NULL;
    }
    if (!json_is_object(root)) {
        tarn_fail(err, "%s: expected a JSON object at the top level, got %s", path,
                  tarn_json_type(root));
        json_decref(root);
        return NULL;
    }
    return root;
}

/* "scenes/pond.json" -> name "pond", directory "scenes/" */
static int split_path(const char *path, tarn_loaded_scene *out, char **dir)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t dir_length = (size_t)(base - path);
    *dir = malloc(dir_length + 1);
    if (!*dir) return -1;
    memcpy(*dir, path, dir_length);
    (*dir)[dir_length] = '\0';
    const char *dot = strrchr(base, '.');
    size_t stem = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    if (stem >= sizeof out->name) stem = sizeof out->name - 1;
    memcpy(out->name, base, stem);
    out->name[stem] = '\0';
    return 0;
}

static int load_underwater(tarn_loader *l, const json_t *root)
{
    int present;
    if (tarn_underwater_load(l, root, &l->out->underwater, &present)) return -1;
    if (present) l->out->scene.underwater = &l->out->underwater;
    return 0;
}

/* A camera on a path stands where the path has it at time 0: the scene's own
 * camera, which a frame that does not move (and the bake's header) describes. */
static int place_moving_camera(tarn_loader *l)
{
    tarn_scene *scene = &l->out->scene;
    if (scene->camera_path == NULL) return 0;
    tarn_object *objects = calloc(scene->object_count + 1u, sizeof *objects);
    tarn_scene posed;
    if (!objects) return tarn_fail(l->err, "%s: out of memory", l->file);
    const tarn_status status = tarn_scene_pose(scene, 0, &posed, objects);
    free(objects);
    if (status != TARN_OK) return tarn_fail_field(l, "camera.path", "cannot be posed: %s", tarn_status_text(status));
    scene->camera.position = posed.camera.position;
    scene->camera.target = posed.camera.target;
    return 0;
}

static int load_root(tarn_loader *l, const json_t *root)
{
    static const char *const fields[] = { "frame", "background", "camera", "light", "materials",
                                          "underwater", "objects", NULL };
    if (tarn_check_fields(l, root, "", fields, NULL, "") || load_frame(l, root) ||
        tarn_get_colour(l, root, "", "background", 0x000000, &l->out->scene.background_rgb) ||
        load_camera(l, root) || load_light(l, root) || load_materials(l, root) ||
        load_underwater(l, root) || load_objects(l, root) || place_moving_camera(l)) {
        return -1;
    }
    tarn_narrow_foam_maps(l->out);
    return 0;
}

int tarn_scene_load(const char *path, tarn_loaded_scene *out, tarn_error *err)
{
    memset(out, 0, sizeof *out);
    tarn_loader l = { path, NULL, err, out };
    if (split_path(path, out, &l.dir)) return tarn_fail(err, "%s: out of memory", path);
    json_t *root = parse_json(path, err);
    int result = root ? load_root(&l, root) : -1;
    json_decref(root);
    free(l.dir);
    if (result) tarn_scene_free(out);
    return result;
}

void tarn_scene_free(tarn_loaded_scene *s)
{
    if (!s) return;
    for (size_t k = 0; s->meshes && k < s->object_count; k++) tarn_mesh_buffer_free(&s->meshes[k]);
    for (size_t k = 0; s->material_names && k < s->material_count; k++) free(s->material_names[k]);
    for (size_t k = 0; k < s->texture_count; k++) {
        tarn_image_free(&s->texture_images[k]);
        free(s->texture_paths[k]);
    }
    for (size_t k = 0; s->motions && k < s->object_count; k++) tarn_key_curve_free(&s->motions[k].path);
    tarn_key_curve_free(&s->camera_path.keys);
    tarn_key_curve_free(&s->light_motion.direction);
    free(s->motions);
    free(s->objects);
    free(s->meshes);
    free(s->materials);
    free(s->material_names);
    free(s->waters);
    free(s->textures);
    free(s->texture_images);
    free(s->texture_paths);
    memset(s, 0, sizeof *s);
}
