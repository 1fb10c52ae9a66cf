#include "obj_load.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input_file.h"

/* v, vt and vn lines beyond this are refused whatever the scene's limits
 * (scene_budget.h, which stop a file far sooner), so that every index stays an
 * int32_t; far more than a tarn mesh can use (TARN_MESH_VERTICES_MAX). */
#define OBJ_ELEMENTS_MAX (1u << 24)

#define NO_INDEX (-1)

#define Q16_COORDINATE_LIMIT 32768.0 /* Q16.16 holds |v| < 32768 */
#define ELEMENT_NUMBERS_MAX 3        /* the most a vt or vn line takes */
#define VERTEX_NUMBERS_COLOURED 6    /* v x y z r g b */

typedef struct {
    double *values; /* `width` per element */
    size_t count, capacity;
    unsigned width;
    const char *noun;  /* "vertices": used in range errors */
    const char *index; /* "index": "face index 7 is out of range" */
} element_list;

typedef struct {
    int32_t position, texcoord, normal; /* 0-based, NO_INDEX when absent */
} corner;

typedef struct {
    const char *path;
    unsigned long line;
    tarn_error *err;
    const tarn_scene_cost *scene; /* what the rest of the scene holds */
    element_list positions, texcoords, normals;
    corner *corners; /* 3 per triangle, in file order */
    size_t triangle_count, corner_capacity;
    int any_texcoords;
    uint32_t *position_colours; /* 0xRRGGBB per position, white where the file gave none */
    size_t position_colour_capacity;
    int any_colours; /* some v line had a colour: the mesh gets colours */
} obj_parser;

/* Makes room for `needed` elements of `size` bytes, doubling. 0 ok, -1 no memory. */
static int ensure_capacity(void **data, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity) return 0;
    size_t grown = *capacity ? *capacity : 64;
    while (grown < needed) grown *= 2;
    void *bigger = realloc(*data, grown * size);
    if (!bigger) return -1;
    *data = bigger;
    *capacity = grown;
    return 0;
}

/* "file:LINE: message". The message quotes the file's own text, so control
 * characters in it become '?': the error must stay one printable line. */
static int fail_at_line(obj_parser *p, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

static int fail_at_line(obj_parser *p, const char *format, ...)
{
    char message[sizeof p->err->message];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    for (char *c = message; *c; c++) {
        if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
    }
    return tarn_fail(p->err, "%s:%lu: %s", p->path, p->line, message);
}

/* strtod's syntax, which includes nan and inf: callers check the range. errno is
 * ERANGE afterwards when the value over- or underflowed. */
static int read_number(obj_parser *p, const char *token, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(token, &end);
    if (end == token || *end != '\0') return fail_at_line(p, "'%s' is not a number", token);
    return 0;
}

/* `count` coordinates, each finite with |v| < limit. */
static int parse_coordinates(obj_parser *p, char *const tokens[], unsigned count, double limit,
                             double *out)
{
    for (unsigned k = 0; k < count; k++) {
        if (read_number(p, tokens[k], &out[k])) return -1;
        if (!isfinite(out[k]) || errno == ERANGE || fabs(out[k]) >= limit) {
            return fail_at_line(p, "%s is out of range (|v| < %g)", tokens[k], limit);
        }
    }
    return 0;
}

/* r g b, each 0..1, as 0xRRGGBB rounded to nearest. */
static int parse_colour(obj_parser *p, char *const tokens[3], uint32_t *rgb)
{
    *rgb = 0;
    for (unsigned k = 0; k < 3; k++) {
        double c;
        if (read_number(p, tokens[k], &c)) return -1;
        if (!(c >= 0.0 && c <= 1.0)) { /* NaN fails both */
            return fail_at_line(p, "colour component %s is out of range (0..1)", tokens[k]);
        }
        *rgb = (*rgb << 8) | (uint32_t)(c * 255.0 + 0.5);
    }
    return 0;
}

/* The rest of the line's tokens, up to `max` + 1 of them so that one too many shows. */
static unsigned split_tokens(char **save, char *tokens[], unsigned max)
{
    unsigned n = 0;
    while (n <= max && (tokens[n] = strtok_r(NULL, " \t\r\n", save)) != NULL) n++;
    return n;
}

/* The file so far, beside the rest of the scene, within the scene's limits
 * (scene_budget.h): checked at every element and triangle, so that a file that
 * would cross one stops at the line that does, before it takes the memory. A mesh
 * vertex takes at most one v, one vt and one vn, so the most lines of any of them
 * is as few vertices as the file can make. */
static int check_scene_limits(obj_parser *p)
{
    size_t most = p->positions.count;
    if (p->texcoords.count > most) most = p->texcoords.count;
    if (p->normals.count > most) most = p->normals.count;
    const tarn_scene_cost so_far = { 0, most, p->triangle_count, 0 };
    char why[sizeof p->err->message];
    if (tarn_scene_cost_over(p->scene, &so_far, why, sizeof why)) return fail_at_line(p, "%s", why);
    return 0;
}

/* Room for one more element at the end of `list`; NULL with the error set. */
static double *append_element(obj_parser *p, element_list *list, const char *keyword)
{
    if (list->count >= OBJ_ELEMENTS_MAX) {
        fail_at_line(p, "more than %u '%s' lines", OBJ_ELEMENTS_MAX, keyword);
        return NULL;
    }
    if (ensure_capacity((void **)&list->values, &list->capacity,
                        (list->count + 1) * list->width, sizeof(double))) {
        fail_at_line(p, "out of memory");
        return NULL;
    }
    list->count++;
    if (check_scene_limits(p)) return NULL;
    return list->values + (list->count - 1) * list->width;
}

/* vt u [v [w]], vn x y z: `min`..`max` numbers of which the first list->width are
 * kept (missing ones are 0). */
static int parse_element(obj_parser *p, element_list *list, const char *keyword, unsigned min,
                         unsigned max, char **save)
{
    char *tokens[ELEMENT_NUMBERS_MAX + 1];
    unsigned n = split_tokens(save, tokens, max);
    if (n < min || n > max) {
        return fail_at_line(p, "'%s' needs %u to %u numbers", keyword, min, max);
    }
    double numbers[ELEMENT_NUMBERS_MAX] = { 0.0 };
    /* normals are normalised later, so any size goes */
    double limit = list == &p->normals ? HUGE_VAL : Q16_COORDINATE_LIMIT;
    double *element = append_element(p, list, keyword);
    if (!element || parse_coordinates(p, tokens, n, limit, numbers)) return -1;
    memcpy(element, numbers, list->width * sizeof *element);
    return 0;
}

/* v x y z, or v x y z r g b: the vertex-colour extension MeshLab and Blender write.
 * Every position gets a colour, white when its line has none. */
static int parse_vertex(obj_parser *p, char **save)
{
    char *tokens[VERTEX_NUMBERS_COLOURED + 1];
    unsigned n = split_tokens(save, tokens, VERTEX_NUMBERS_COLOURED);
    if (n != 3 && n != VERTEX_NUMBERS_COLOURED) {
        return fail_at_line(p, "'v' needs 3 numbers (x y z) or 6 (x y z r g b)");
    }
    double *position = append_element(p, &p->positions, "v");
    if (!position || parse_coordinates(p, tokens, 3, Q16_COORDINATE_LIMIT, position)) return -1;
    uint32_t rgb = 0xFFFFFFu;
    if (n == VERTEX_NUMBERS_COLOURED && parse_colour(p, tokens + 3, &rgb)) return -1;
    if (ensure_capacity((void **)&p->position_colours, &p->position_colour_capacity,
                        p->positions.count, sizeof *p->position_colours)) {
        return fail_at_line(p, "out of memory");
    }
    p->position_colours[p->positions.count - 1] = rgb;
    if (n == VERTEX_NUMBERS_COLOURED) p->any_colours = 1;
    return 0;
}

/* One face index: 1..count, or -count..-1 counting back from the latest element. */
static int parse_index(obj_parser *p, const char *text, const element_list *list, int32_t *out)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0') {
        return fail_at_line(p, "face %s '%s' is not a whole number", list->index, text);
    }
    long count = (long)list->count;
    if (errno != ERANGE && v >= 1 && v <= count) {
        *out = (int32_t)(v - 1);
        return 0;
    }
    if (errno != ERANGE && v < 0 && -v <= count) {
        *out = (int32_t)(count + v);
        return 0;
    }
    if (count == 0) {
        return fail_at_line(p, "face %s %s is out of range (no %s before this line)", list->index,
                            text, list->noun);
    }
    if (v < 0) {
        return fail_at_line(p, "face %s %s is out of range (-%ld..-1)", list->index, text, count);
    }
    return fail_at_line(p, "face %s %s is out of range (1..%ld)", list->index, text, count);
}

/* A face corner: v, v/vt, v//vn or v/vt/vn. */
static int parse_corner(obj_parser *p, char *token, corner *out)
{
    char *fields[3] = { token, NULL, NULL };
    for (int k = 1; k < 3 && fields[k - 1]; k++) {
        char *slash = strchr(fields[k - 1], '/');
        if (slash) {
            *slash = '\0';
            fields[k] = slash + 1;
        }
    }
    if (fields[2] && strchr(fields[2], '/')) {
        return fail_at_line(p, "bad face corner; expected v, v/vt, v//vn or v/vt/vn");
    }
    out->texcoord = out->normal = NO_INDEX;
    if (parse_index(p, fields[0], &p->positions, &out->position)) return -1;
    if (fields[1] && fields[1][0] && parse_index(p, fields[1], &p->texcoords, &out->texcoord)) {
        return -1;
    }
    if (fields[2] && fields[2][0] && parse_index(p, fields[2], &p->normals, &out->normal)) {
        return -1;
    }
    if (out->texcoord != NO_INDEX) p->any_texcoords = 1;
    return 0;
}

static int add_triangle(obj_parser *p, corner a, corner b, corner c)
{
    if (p->triangle_count >= TARN_MESH_TRIANGLES_MAX) {
        return fail_at_line(p, "more than %u triangles; a tarn mesh holds at most %u",
                            TARN_MESH_TRIANGLES_MAX, TARN_MESH_TRIANGLES_MAX);
    }
    if (ensure_capacity((void **)&p->corners, &p->corner_capacity, 3 * (p->triangle_count + 1),
                        sizeof *p->corners)) {
        return fail_at_line(p, "out of memory");
    }
    corner *tri = p->corners + 3 * p->triangle_count++;
    tri[0] = a;
    tri[1] = b;
    tri[2] = c;
    return check_scene_limits(p);
}

/* f c1 c2 c3 ...: a convex polygon, fanned from its first corner. */
static int parse_face(obj_parser *p, char **save)
{
    corner first = { 0, NO_INDEX, NO_INDEX }, previous = first, current = first;
    unsigned n = 0;
    for (char *token; (token = strtok_r(NULL, " \t\r\n", save)) != NULL; n++) {
        if (parse_corner(p, token, &current)) return -1;
        if (n == 0) first = current;
        if (n >= 2 && add_triangle(p, first, previous, current)) return -1;
        previous = current;
    }
    if (n < 3) return fail_at_line(p, "a face needs at least 3 corners");
    return 0;
}

static int parse_line(obj_parser *p, char *line)
{
    char *save = NULL;
    char *keyword = strtok_r(line, " \t\r\n", &save);
    if (!keyword || keyword[0] == '#') return 0;
    if (strcmp(keyword, "v") == 0) return parse_vertex(p, &save);
    if (strcmp(keyword, "vt") == 0) return parse_element(p, &p->texcoords, keyword, 1, 3, &save);
    if (strcmp(keyword, "vn") == 0) return parse_element(p, &p->normals, keyword, 3, 3, &save);
    if (strcmp(keyword, "f") == 0) return parse_face(p, &save);
    static const char *const ignored[] = { "o", "g", "s", "usemtl", "mtllib" };
    for (size_t k = 0; k < sizeof ignored / sizeof ignored[0]; k++) {
        if (strcmp(keyword, ignored[k]) == 0) return 0;
    }
    return fail_at_line(p, "unknown statement '%s' (expected v, vt, vn, f, o, g, s, usemtl "
                           "or mtllib)", keyword);
}

static int parse_file(obj_parser *p)
{
    FILE *file = tarn_open_input(p->path, "an OBJ file", TARN_OBJ_FILE_BYTES_MAX, p->err);
    if (!file) return -1;
    char *line = NULL;
    size_t size = 0;
    int result = 0;
    errno = 0;
    while (result == 0 && getline(&line, &size, file) >= 0) {
        p->line++;
        result = parse_line(p, line);
    }
    if (result == 0 && ferror(file)) {
        result = tarn_fail(p->err, "%s: cannot read: %s", p->path, strerror(errno));
    }
    free(line);
    fclose(file);
    return result;
}

/* ---- from corners to a tarn mesh ---------------------------------------------- */

static const double *position_of(const obj_parser *p, corner c)
{
    return p->positions.values + 3 * (size_t)c.position;
}

/* Area-weighted face normals summed per position, for corners the file gave no
 * normal: a smooth normal shared by every face around the position. */
static double *smooth_normals(const obj_parser *p)
{
    double *sums = calloc(p->positions.count * 3 + 1, sizeof *sums);
    if (!sums) return NULL;
    for (size_t t = 0; t < p->triangle_count; t++) {
        const corner *tri = p->corners + 3 * t;
        const double *a = position_of(p, tri[0]), *b = position_of(p, tri[1]),
                     *c = position_of(p, tri[2]);
        double ab[3], ac[3];
        for (int k = 0; k < 3; k++) {
            ab[k] = b[k] - a[k];
            ac[k] = c[k] - a[k];
        }
        double n[3] = { ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                        ab[0] * ac[1] - ab[1] * ac[0] };
        for (int v = 0; v < 3; v++) {
            for (int k = 0; k < 3; k++) sums[3 * (size_t)tri[v].position + k] += n[k];
        }
    }
    return sums;
}

/* Distinct (position, texcoord, normal) corners become the mesh's vertices.
 * Corners sharing a position are chained, so finding a match walks only those. */
typedef struct {
    int32_t *first_with_position; /* per position: a vertex using it, or NO_INDEX */
    int32_t *next_with_position;  /* per vertex: the next vertex with its position */
    corner *vertices;
    size_t vertex_count;
} vertex_table;

static int32_t find_or_add_vertex(vertex_table *t, corner c)
{
    for (int32_t v = t->first_with_position[c.position]; v != NO_INDEX;
         v = t->next_with_position[v]) {
        if (t->vertices[v].texcoord == c.texcoord && t->vertices[v].normal == c.normal) return v;
    }
    int32_t v = (int32_t)t->vertex_count++;
    t->vertices[v] = c;
    t->next_with_position[v] = t->first_with_position[c.position];
    t->first_with_position[c.position] = v;
    return v;
}

static void emit_vertex(const obj_parser *p, corner c, const double *smooth,
                        tarn_mesh_buffer *out)
{
    const double *normal = c.normal != NO_INDEX ? p->normals.values + 3 * (size_t)c.normal
                                                : smooth + 3 * (size_t)c.position;
    double uv[2] = { 0.0, 0.0 };
    if (c.texcoord != NO_INDEX) {
        const double *t = p->texcoords.values + 2 * (size_t)c.texcoord;
        uv[0] = t[0];
        uv[1] = 1.0 - t[1]; /* OBJ's v grows up the image, tarn's down */
    }
    uint16_t index = tarn_mesh_add_vertex(out, position_of(p, c), normal, uv);
    /* a colour belongs to the v line, so every split of a position shares it */
    if (out->colours) out->colours[index] = p->position_colours[c.position];
}

static int build_mesh(const obj_parser *p, tarn_mesh_buffer *out, tarn_error *err)
{
    if (p->triangle_count == 0) {
        return tarn_fail(err, "%s: no faces; a mesh needs at least one", p->path);
    }
    size_t corner_count = 3 * p->triangle_count;
    vertex_table t = { malloc((p->positions.count + 1) * sizeof(int32_t)),
                       malloc(corner_count * sizeof(int32_t)),
                       malloc(corner_count * sizeof(corner)), 0 };
    int32_t *triangle_vertices = malloc(corner_count * sizeof(int32_t));
    double *smooth = smooth_normals(p);
    int result = 0;
    if (!t.first_with_position || !t.next_with_position || !t.vertices || !triangle_vertices ||
        !smooth) {
        result = tarn_fail(err, "%s: out of memory", p->path);
    } else {
        for (size_t k = 0; k < p->positions.count; k++) t.first_with_position[k] = NO_INDEX;
        for (size_t k = 0; k < corner_count; k++) {
            triangle_vertices[k] = find_or_add_vertex(&t, p->corners[k]);
        }
        result = tarn_mesh_reserve(out, (uint32_t)t.vertex_count, (uint32_t)p->triangle_count,
                                   p->any_texcoords, p->path, err);
    }
    if (result == 0 && p->any_colours) result = tarn_mesh_reserve_colours(out, p->path, err);
    if (result == 0) {
        for (size_t v = 0; v < t.vertex_count; v++) emit_vertex(p, t.vertices[v], smooth, out);
        for (size_t k = 0; k < corner_count; k += 3) {
            tarn_mesh_add_triangle(out, (uint32_t)triangle_vertices[k],
                                   (uint32_t)triangle_vertices[k + 1],
                                   (uint32_t)triangle_vertices[k + 2]);
        }
    }
    free(t.first_with_position);
    free(t.next_with_position);
    free(t.vertices);
    free(triangle_vertices);
    free(smooth);
    return result;
}

int tarn_obj_load(const char *path, const tarn_scene_cost *scene, tarn_mesh_buffer *out, tarn_error *err)
{
    static const tarn_scene_cost nothing = { 0, 0, 0, 0 };
    memset(out, 0, sizeof *out);
    obj_parser p;
    memset(&p, 0, sizeof p);
    p.path = path;
    p.err = err;
    p.scene = scene ? scene : &nothing;
    p.positions = (element_list){ NULL, 0, 0, 3, "vertices", "index" };
    p.texcoords = (element_list){ NULL, 0, 0, 2, "texture coordinates", "texture index" };
    p.normals = (element_list){ NULL, 0, 0, 3, "normals", "normal index" };
    int result = parse_file(&p);
    if (result == 0) result = build_mesh(&p, out, err);
    free(p.positions.values);
    free(p.texcoords.values);
    free(p.normals.values);
    free(p.corners);
    free(p.position_colours);
    return result;
}
