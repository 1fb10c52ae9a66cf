/* test_scene_load.c: the host's scene loading: primitives, OBJ meshes, PNG reading
 * and writing, the demo scene, and the error for every kind of bad input. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bad_scene_cases.h"
#include "core_render.h"
#include "mesh_gen.h"
#include "obj_load.h"
#include "atomic_file.h"
#include "png_io.h"
#include "scene_load.h"
#include "water_load.h"

/* ---- helpers ------------------------------------------------------------------ */

typedef struct {
    double x, y, z;
} dvec;

static dvec dvec_of(tarn_vec3 v)
{
    dvec d = { v.x / 65536.0, v.y / 65536.0, v.z / 65536.0 };
    return d;
}

static dvec sub(dvec a, dvec b)
{
    dvec d = { a.x - b.x, a.y - b.y, a.z - b.z };
    return d;
}

static dvec cross3(dvec a, dvec b)
{
    dvec d = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return d;
}

static double dot3(dvec a, dvec b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static dvec face_normal(const tarn_mesh *m, uint32_t t)
{
    const uint16_t *i = m->indices + 3 * t;
    dvec a = dvec_of(m->positions[i[0]]), b = dvec_of(m->positions[i[1]]),
         c = dvec_of(m->positions[i[2]]);
    return cross3(sub(b, a), sub(c, a));
}

static dvec face_centroid(const tarn_mesh *m, uint32_t t)
{
    const uint16_t *i = m->indices + 3 * t;
    dvec a = dvec_of(m->positions[i[0]]), b = dvec_of(m->positions[i[1]]),
         c = dvec_of(m->positions[i[2]]);
    dvec d = { (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3 };
    return d;
}

/* Indices in range, unit normals, no zero-area triangles. */
static void check_mesh_consistent(const tarn_mesh *m)
{
    assert_non_null(m->positions);
    assert_non_null(m->normals);
    assert_non_null(m->indices);
    assert_true(m->vertex_count > 0);
    assert_true(m->triangle_count > 0);
    for (uint32_t k = 0; k < 3u * m->triangle_count; k++) {
        assert_true(m->indices[k] < m->vertex_count);
    }
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        dvec n = dvec_of(m->normals[v]);
        assert_true(fabs(sqrt(dot3(n, n)) - 1.0) < 1e-3);
    }
    for (uint32_t t = 0; t < m->triangle_count; t++) {
        dvec n = face_normal(m, t);
        assert_true(dot3(n, n) > 0.0);
    }
}

/* Each triangle faces away from `centre`, and its vertices' normals agree with it. */
static void check_faces_outward(const tarn_mesh *m, dvec centre)
{
    for (uint32_t t = 0; t < m->triangle_count; t++) {
        dvec n = face_normal(m, t);
        assert_true(dot3(n, sub(face_centroid(m, t), centre)) > 0.0);
        for (int k = 0; k < 3; k++) {
            assert_true(dot3(n, dvec_of(m->normals[m->indices[3 * t + k]])) > 0.0);
        }
    }
}

static int same_position(const tarn_mesh *m, uint16_t a, uint16_t b)
{
    return memcmp(&m->positions[a], &m->positions[b], sizeof(tarn_vec3)) == 0;
}

/* Closed and consistently wound: every edge a->b (by position) is matched by
 * exactly one edge b->a in another triangle. */
static void check_closed(const tarn_mesh *m)
{
    for (uint32_t t = 0; t < m->triangle_count; t++) {
        for (int e = 0; e < 3; e++) {
            uint16_t a = m->indices[3 * t + e], b = m->indices[3 * t + (e + 1) % 3];
            int matches = 0;
            for (uint32_t u = 0; u < m->triangle_count; u++) {
                for (int f = 0; f < 3; f++) {
                    uint16_t c = m->indices[3 * u + f], d = m->indices[3 * u + (f + 1) % 3];
                    if (same_position(m, a, d) && same_position(m, b, c)) matches++;
                }
            }
            assert_int_equal(matches, 1);
        }
    }
}

static void check_faces_up(const tarn_mesh *m)
{
    for (uint32_t t = 0; t < m->triangle_count; t++) assert_true(face_normal(m, t).y > 0.0);
    for (uint32_t v = 0; v < m->vertex_count; v++) assert_true(m->normals[v].y > 0);
}

static char *make_temp_dir(void)
{
    char *dir = strdup("/tmp/tarn_scene_test_XXXXXX");
    assert_non_null(dir);
    assert_non_null(mkdtemp(dir));
    return dir;
}

static void remove_temp_dir(char *dir)
{
    bad_case_remove_dir(dir);
    free(dir);
}

/* Writes `text` to dir/name and returns the path (static buffer). */
/* Writes a width x height PNG of one repeated texel to dir/name. */
static void write_flat_png(const char *dir, const char *name, uint16_t width, uint16_t height,
                           const uint8_t texel[3])
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    uint8_t rgb[8 * 8 * 3];
    assert_true((size_t)width * height * 3 <= sizeof rgb);
    for (size_t k = 0; k < (size_t)width * height; k++) memcpy(rgb + 3 * k, texel, 3);
    tarn_error err;
    if (tarn_png_write_rgb(path, rgb, width, height, &err)) fail_msg("%s", err.message);
}

static const char *write_temp(const char *dir, const char *name, const char *text)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    assert_int_equal(bad_write_text(path, text), 0);
    return path;
}

static size_t files_in(const char *dir)
{
    size_t n = 0;
    DIR *d = opendir(dir);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0) n++;
    }
    closedir(d);
    return n;
}

/* ---- Q16.16 conversion -------------------------------------------------------- */

static void test_q16_from_double(void **state)
{
    (void)state;
    assert_int_equal(tarn_q16_from_double(1.0), 65536);
    assert_int_equal(tarn_q16_from_double(-2.5), -163840);
    assert_int_equal(tarn_q16_from_double(0.1), 6554);  /* 6553.6 rounds up */
    assert_int_equal(tarn_q16_from_double(0.5 / 65536), 1);   /* ties away from zero */
    assert_int_equal(tarn_q16_from_double(-0.5 / 65536), -1);
    assert_int_equal(tarn_q16_from_double(40000.0), INT32_MAX); /* saturates */
    assert_int_equal(tarn_q16_from_double(-40000.0), INT32_MIN);
    assert_int_equal(tarn_q16_from_double(NAN), INT32_MIN);
}

/* ---- primitives --------------------------------------------------------------- */

static void test_plane(void **state)
{
    (void)state;
    tarn_error err;
    tarn_mesh_buffer b;
    assert_int_equal(tarn_mesh_plane(&b, 4, 2, 4, 2, 3, 0.5, "plane", &err), 0);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 5 * 3);
    assert_int_equal(m->triangle_count, 4 * 2 * 2);
    check_mesh_consistent(m);
    check_faces_up(m);
    assert_non_null(m->uvs);
    /* corners: (-2, 0, -1) with uv (0, 0) first, (2, 0, 1) with uv (3, 0.5) last */
    assert_int_equal(m->positions[0].x, -2 * 65536);
    assert_int_equal(m->positions[0].z, -65536);
    assert_int_equal(m->positions[14].x, 2 * 65536);
    assert_int_equal(m->positions[14].z, 65536);
    assert_int_equal(m->uvs[14].u, 3 * 65536);
    assert_int_equal(m->uvs[14].v, 32768);
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        assert_int_equal(m->positions[v].y, 0);
        assert_int_equal(m->normals[v].y, 65536);
    }
    tarn_mesh_buffer_free(&b);
}

static void test_box(void **state)
{
    (void)state;
    tarn_error err;
    tarn_mesh_buffer b;
    assert_int_equal(tarn_mesh_box(&b, 2, 4, 6, "box", &err), 0);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 24);
    assert_int_equal(m->triangle_count, 12);
    check_mesh_consistent(m);
    check_faces_outward(m, (dvec){ 0, 0, 0 });
    check_closed(m);
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        assert_int_equal(abs(m->positions[v].x), 65536);
        assert_int_equal(abs(m->positions[v].y), 2 * 65536);
        assert_int_equal(abs(m->positions[v].z), 3 * 65536);
        /* flat faces: normals along one axis */
        tarn_vec3 n = m->normals[v];
        assert_int_equal(abs(n.x) + abs(n.y) + abs(n.z), 65536);
        assert_true(m->uvs[v].u == 0 || m->uvs[v].u == 65536);
    }
    tarn_mesh_buffer_free(&b);
}

static void test_sphere(void **state)
{
    (void)state;
    tarn_error err;
    tarn_mesh_buffer b;
    assert_int_equal(tarn_mesh_sphere(&b, 1.5, 12, 6, "sphere", &err), 0);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 7 * 13);
    assert_int_equal(m->triangle_count, 2 * 12 * 5);
    check_mesh_consistent(m);
    check_faces_outward(m, (dvec){ 0, 0, 0 });
    check_closed(m);
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        dvec p = dvec_of(m->positions[v]);
        assert_true(fabs(sqrt(dot3(p, p)) - 1.5) < 1e-4);
        /* smooth: the normal is the direction from the centre */
        dvec n = dvec_of(m->normals[v]);
        assert_true(dot3(n, p) / 1.5 > 0.9999);
    }
    tarn_mesh_buffer_free(&b);

    /* the smallest closed sphere */
    assert_int_equal(tarn_mesh_sphere(&b, 1, 3, 2, "sphere", &err), 0);
    check_mesh_consistent(&b.mesh);
    check_faces_outward(&b.mesh, (dvec){ 0, 0, 0 });
    check_closed(&b.mesh);
    tarn_mesh_buffer_free(&b);
}

static void test_heightfield(void **state)
{
    (void)state;
    /* a 5x5 image with a peak in the middle */
    uint8_t gray[25] = { 0 };
    gray[2 * 5 + 2] = 255;
    gray[1 * 5 + 2] = gray[3 * 5 + 2] = gray[2 * 5 + 1] = gray[2 * 5 + 3] = 128;
    tarn_image image = { 5, 5, 1, gray };
    tarn_error err;
    tarn_mesh_buffer b;
    assert_int_equal(tarn_mesh_heightfield(&b, &image, 8, 4, 2, 1, 1, 0, "hf", &err), 0);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 25);
    assert_int_equal(m->triangle_count, 32);
    check_mesh_consistent(m);
    check_faces_up(m);
    /* the peak: centre of the field, height 2, normal straight up by symmetry */
    const uint32_t peak = 2 * 5 + 2;
    assert_int_equal(m->positions[peak].x, 0);
    assert_int_equal(m->positions[peak].z, 0);
    assert_int_equal(m->positions[peak].y, 2 * 65536);
    assert_int_equal(m->normals[peak].x, 0);
    assert_int_equal(m->normals[peak].z, 0);
    /* left of the peak the ground rises toward +x, so the normal leans to -x;
     * the image's top row lies toward -z, and a slope there leans to -z */
    assert_true(m->normals[2 * 5 + 1].x < 0);
    assert_true(m->normals[1 * 5 + 2].z < 0);
    assert_int_equal(m->positions[0].x, -4 * 65536);
    assert_int_equal(m->positions[0].z, -2 * 65536);
    assert_int_equal(m->uvs[24].u, 65536);
    assert_int_equal(m->uvs[24].v, 65536);
    tarn_mesh_buffer_free(&b);
}

/* No crack: every edge of the mesh meets the opposite edge of exactly one other
 * triangle, unless it lies on the border of the width x depth grid. */
static void check_no_cracks(const tarn_mesh *m, tarn_q16 half_width, tarn_q16 half_depth)
{
    for (uint32_t t = 0; t < m->triangle_count; t++) {
        for (int e = 0; e < 3; e++) {
            uint16_t a = m->indices[3 * t + e], b = m->indices[3 * t + (e + 1) % 3];
            const tarn_vec3 *pa = &m->positions[a], *pb = &m->positions[b];
            int on_border = (pa->x == pb->x && (pa->x == half_width || pa->x == -half_width)) ||
                            (pa->z == pb->z && (pa->z == half_depth || pa->z == -half_depth));
            int matches = 0;
            for (uint32_t u = 0; u < m->triangle_count; u++) {
                for (int f = 0; f < 3; f++) {
                    uint16_t c = m->indices[3 * u + f], d = m->indices[3 * u + (f + 1) % 3];
                    if (same_position(m, a, d) && same_position(m, b, c)) matches++;
                }
            }
            assert_int_equal(matches, on_border ? 0 : 1);
        }
    }
}

/* Twice the area the mesh covers seen from above, in Q16.16 units squared. */
static double covered_area2_xz(const tarn_mesh *m)
{
    double sum = 0;
    for (uint32_t t = 0; t < m->triangle_count; t++) {
        const tarn_vec3 *p = &m->positions[m->indices[3 * t]], *q = &m->positions[m->indices[3 * t + 1]],
                        *r = &m->positions[m->indices[3 * t + 2]];
        sum += fabs((double)(q->x - p->x) * (r->z - p->z) - (double)(q->z - p->z) * (r->x - p->x));
    }
    return sum;
}

/* The largest heightfields a mesh holds are read; one row more is refused. */
static void test_heightfield_size_limit(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    char path[1100];
    snprintf(path, sizeof path, "%s/hf.png", dir);
    static uint8_t rgb[3 * 256 * 256];
    static const struct {
        unsigned width, height;
        int accepted;
    } sizes[] = {{182, 182, 1}, {2, 256, 1}, {256, 129, 1}, {183, 182, 0}, {256, 130, 0}};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        tarn_error err;
        tarn_image image;
        assert_int_equal(tarn_png_write_rgb(path, rgb, sizes[k].width, sizes[k].height, &err), 0);
        const int read = tarn_png_read_heightfield(path, &image, &err) == 0;
        if (read != sizes[k].accepted)
            fail_msg("a %ux%u heightfield was %s", sizes[k].width, sizes[k].height, read ? "read" : err.message);
        if (read) tarn_image_free(&image);
    }
    unlink(path);
    remove_temp_dir(dir);
}

static void test_heightfield_merges_level_squares(void **state)
{
    (void)state;
    /* 17x17 at one height but for a bump near one corner */
    uint8_t gray[17 * 17];
    memset(gray, 200, sizeof gray);
    gray[4 * 17 + 12] = 250;
    tarn_image image = { 17, 17, 1, gray };
    tarn_error err;
    tarn_mesh_buffer whole, merged;
    assert_int_equal(tarn_mesh_heightfield(&whole, &image, 16, 16, 2, 1, 1, 0, "hf", &err), 0);
    assert_int_equal(tarn_mesh_heightfield(&merged, &image, 16, 16, 2, 1, 1, 1, "hf", &err), 0);
    assert_int_equal(whole.mesh.triangle_count, 2 * 16 * 16);
    /* the bump and its four neighbours lean (9 cells around it stay whole) while
     * the 8x8 and 4x4 squares clear of it merge */
    assert_true(merged.mesh.triangle_count < whole.mesh.triangle_count / 4);
    assert_true(merged.mesh.vertex_count < whole.mesh.vertex_count / 2);
    check_mesh_consistent(&merged.mesh);
    check_faces_up(&merged.mesh);
    check_no_cracks(&merged.mesh, 8 * 65536, 8 * 65536);
    assert_true(covered_area2_xz(&merged.mesh) == covered_area2_xz(&whole.mesh));
    /* the bump keeps its vertex, height and normal */
    int found = 0;
    for (uint32_t v = 0; v < merged.mesh.vertex_count; v++) {
        if (merged.mesh.positions[v].x != whole.mesh.positions[4 * 17 + 12].x ||
            merged.mesh.positions[v].z != whole.mesh.positions[4 * 17 + 12].z)
            continue;
        assert_memory_equal(&merged.mesh.positions[v], &whole.mesh.positions[4 * 17 + 12], sizeof(tarn_vec3));
        assert_memory_equal(&merged.mesh.normals[v], &whole.mesh.normals[4 * 17 + 12], sizeof(tarn_vec3));
        found++;
    }
    assert_int_equal(found, 1);
    tarn_mesh_buffer_free(&whole);
    tarn_mesh_buffer_free(&merged);

    /* a field with no level square is drawn cell by cell, as without merging */
    for (size_t k = 0; k < sizeof gray; k++) gray[k] = (uint8_t)(k * 7 % 251);
    assert_int_equal(tarn_mesh_heightfield(&whole, &image, 16, 16, 2, 1, 1, 0, "hf", &err), 0);
    assert_int_equal(tarn_mesh_heightfield(&merged, &image, 16, 16, 2, 1, 1, 1, "hf", &err), 0);
    assert_int_equal(merged.mesh.triangle_count, whole.mesh.triangle_count);
    assert_memory_equal(merged.mesh.indices, whole.mesh.indices, 6u * whole.mesh.triangle_count);
    tarn_mesh_buffer_free(&whole);
    tarn_mesh_buffer_free(&merged);
}

/* Random fields of two heights in patches, any size: level squares of every size
 * sit beside leaning cells, and the merged mesh stays watertight and covers the
 * whole field, facing up. */
static void test_random_heightfields_merge_watertight(void **state)
{
    (void)state;
    uint32_t seed = 99, triangles_whole = 0, triangles_merged = 0;
    for (int n = 0; n < 40; n++) {
        seed = seed * 1664525u + 1013904223u;
        const uint16_t width = (uint16_t)(2 + (seed >> 8) % 23), height = (uint16_t)(2 + (seed >> 16) % 23);
        uint8_t gray[24 * 24];
        for (uint16_t y = 0; y < height; y++) {
            for (uint16_t x = 0; x < width; x++) {
                seed = seed * 1664525u + 1013904223u;
                /* 8x8 patches, most of them level, with a bump now and then */
                const uint32_t patch = ((uint32_t)(x / 8) * 7u + (uint32_t)(y / 8) * 13u + (uint32_t)n) % 4u;
                gray[y * width + x] = (uint8_t)(patch == 0 ? 60 : 200) + ((seed >> 24) % 150 == 0 ? 30 : 0);
            }
        }
        tarn_image image = { width, height, 1, gray };
        tarn_error err;
        tarn_mesh_buffer whole, merged;
        assert_int_equal(tarn_mesh_heightfield(&whole, &image, 10, 10, 3, 1, 1, 0, "hf", &err), 0);
        assert_int_equal(tarn_mesh_heightfield(&merged, &image, 10, 10, 3, 1, 1, 1, "hf", &err), 0);
        assert_true(merged.mesh.triangle_count <= whole.mesh.triangle_count);
        check_mesh_consistent(&merged.mesh);
        check_faces_up(&merged.mesh);
        check_no_cracks(&merged.mesh, 5 * 65536, 5 * 65536);
        assert_true(covered_area2_xz(&merged.mesh) == covered_area2_xz(&whole.mesh));
        triangles_whole += whole.mesh.triangle_count;
        triangles_merged += merged.mesh.triangle_count;
        tarn_mesh_buffer_free(&whole);
        tarn_mesh_buffer_free(&merged);
    }
    print_message("random heightfields: %u triangles merged into %u\n", (unsigned)triangles_whole,
                  (unsigned)triangles_merged);
    /* the merge ran, not only the whole cells: 11,360 become 7,863 */
    assert_true(triangles_merged < triangles_whole - triangles_whole / 4);
}

/* A level heightfield merges under an opaque material, not under water, whose
 * vertices carry a fresnel term that depends on where they are. */
static void test_water_heightfield_stays_whole(void **state)
{
    (void)state;
    static const uint8_t level[3] = { 100, 100, 100 };
    char *dir = make_temp_dir();
    write_flat_png(dir, "flat.png", 8, 8, level);
    const char *path = write_temp(
        dir, "hf.json",
        "{\"frame\": {\"width\": 64, \"height\": 64},"
        " \"camera\": {\"position\": [0, 4, 6], \"target\": [0, 0, 0], \"fov\": 60},"
        " \"materials\": {\"sand\": {}, \"sea\": {\"water\": {\"albedo\": \"#102030\"}}},"
        " \"objects\": [{\"type\": \"heightfield\", \"material\": \"sand\", \"image\": \"flat.png\","
        "                \"size\": [4, 4], \"height\": 1},"
        "               {\"type\": \"heightfield\", \"material\": \"sea\", \"image\": \"flat.png\","
        "                \"size\": [4, 4], \"height\": 1}]}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    assert_true(s.objects[0].mesh->triangle_count < 2 * 7 * 7);
    assert_int_equal(s.objects[1].mesh->triangle_count, 2 * 7 * 7);
    tarn_scene_free(&s);
    remove_temp_dir(dir);
}

static void test_primitive_limits(void **state)
{
    (void)state;
    tarn_error err;
    tarn_mesh_buffer b;
    assert_int_equal(tarn_mesh_plane(&b, 1, 1, 256, 256, 1, 1, "big plane", &err), -1);
    assert_string_equal(err.message, "big plane: needs 66049 vertices; a tarn mesh holds at most 65535");
    assert_null(b.positions);
    assert_int_equal(tarn_mesh_sphere(&b, 1, 256, 200, "big sphere", &err), -1);
    assert_string_equal(err.message,
                        "big sphere: needs 101888 triangles; a tarn mesh holds at most 65535");
    /* the largest plane that fits */
    assert_int_equal(tarn_mesh_plane(&b, 1, 1, 180, 180, 1, 1, "plane", &err), 0);
    assert_int_equal(b.mesh.triangle_count, 64800);
    tarn_mesh_buffer_free(&b);
}

/* ---- OBJ ------------------------------------------------------------------------ */

static void load_obj_text(const char *text, tarn_mesh_buffer *out)
{
    char *dir = make_temp_dir();
    tarn_error err = { "" };
    int result = tarn_obj_load(write_temp(dir, "t.obj", text), NULL, out, &err);
    remove_temp_dir(dir);
    if (result) fail_msg("%s", err.message);
}

static void test_obj_polygons(void **state)
{
    (void)state;
    /* a quad and a convex pentagon in the XY plane, facing +z; comments, blank
     * lines and the ignored statements on the way */
    tarn_mesh_buffer b;
    load_obj_text("# two polygons\nmtllib x.mtl\no thing\ng group\n\nv 0 0 0\nv 1 0 0\n"
                  "v 1 1 0\nv 0 1 0\nusemtl green\ns 1\nf 1 2 3 4\n"
                  "v 3 0 0\nv 4 0 0\nv 4.5 1 0\nv 3.5 2 0\nv 2.5 1 0\nf 5 6 7 8 9\n",
                  &b);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 9);
    assert_int_equal(m->triangle_count, 2 + 3);
    check_mesh_consistent(m);
    /* fans from the first corner, winding kept */
    static const uint16_t expected[] = { 0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 4, 7, 8 };
    assert_memory_equal(m->indices, expected, sizeof expected);
    for (uint32_t t = 0; t < m->triangle_count; t++) assert_true(face_normal(m, t).z > 0);
    /* no normals in the file: smooth ones, here all +z */
    for (uint32_t v = 0; v < m->vertex_count; v++) assert_int_equal(m->normals[v].z, 65536);
    assert_null(m->uvs);     /* no vt anywhere */
    assert_null(m->colours); /* nor a coloured v */
    tarn_mesh_buffer_free(&b);
}

static void test_obj_negative_indices(void **state)
{
    (void)state;
    tarn_mesh_buffer absolute, relative;
    load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n", &absolute);
    load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2 -1\n", &relative);
    assert_int_equal(relative.mesh.vertex_count, absolute.mesh.vertex_count);
    assert_int_equal(relative.mesh.triangle_count, absolute.mesh.triangle_count);
    assert_memory_equal(relative.indices, absolute.indices, 6 * sizeof(uint16_t));
    assert_memory_equal(relative.positions, absolute.positions, 4 * sizeof(tarn_vec3));
    tarn_mesh_buffer_free(&absolute);
    tarn_mesh_buffer_free(&relative);
}

static void test_obj_missing_normals(void **state)
{
    (void)state;
    /* a closed square pyramid without normals: smooth normals point outward */
    tarn_mesh_buffer b;
    load_obj_text("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 2 0\n"
                  "f 1 2 3 4\nf 4 3 5\nf 3 2 5\nf 2 1 5\nf 1 4 5\n",
                  &b);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 5);
    assert_int_equal(m->triangle_count, 6);
    check_mesh_consistent(m);
    dvec centre = { 0, 0.5, 0 };
    check_closed(m);
    /* every face is wound to face out, so each smooth normal leans away from the centre */
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        assert_true(dot3(dvec_of(m->normals[v]), sub(dvec_of(m->positions[v]), centre)) > 0);
    }
    assert_int_equal(m->normals[4].x, 0); /* the apex: straight up by symmetry */
    assert_int_equal(m->normals[4].z, 0);
    assert_int_equal(m->normals[4].y, 65536);
    tarn_mesh_buffer_free(&b);
}

static void test_obj_texcoords_and_normals(void **state)
{
    (void)state;
    /* v/vt/vn, v//vn and v/vt corners; a corner repeated with the same triple is
     * one vertex, with a different normal it is another */
    tarn_mesh_buffer b;
    load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nvt 1 1 0\nvn 0 0 2\nvn 0 1 0\n"
                  "f 1/1/1 2/2/1 3/1/1\nf 1/1/1 3/1/1 2//2\nf 3/2 1/1 2/2\n",
                  &b);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->triangle_count, 3);
    assert_int_equal(m->vertex_count, 3 + 1 + 3);
    check_mesh_consistent(m);
    assert_non_null(m->uvs);
    /* vertex 0: uv (0.25, 1 - 0.75), normal (0, 0, 2) normalised */
    assert_int_equal(m->uvs[0].u, 16384);
    assert_int_equal(m->uvs[0].v, 16384);
    assert_int_equal(m->normals[0].z, 65536);
    /* 2//2: no texture coordinate -> (0, 0); normal +y as given */
    assert_int_equal(m->uvs[3].u, 0);
    assert_int_equal(m->uvs[3].v, 0);
    assert_int_equal(m->normals[3].y, 65536);
    assert_int_equal(m->uvs[1].v, 0); /* vt 1 1 -> v = 0 */
    tarn_mesh_buffer_free(&b);
}

static void test_obj_crlf(void **state)
{
    (void)state;
    tarn_mesh_buffer b;
    load_obj_text("v 0 0 0\r\nv 1 0 0 0 0 1\r\nv 0 1 0\r\nf 1 2 3\r\n", &b);
    assert_int_equal(b.mesh.triangle_count, 1);
    assert_int_equal(b.mesh.positions[1].x, 65536);
    assert_non_null(b.mesh.colours);
    assert_int_equal(b.mesh.colours[1], 0x0000FF); /* the \r is not part of the blue */
    tarn_mesh_buffer_free(&b);
}

static void test_obj_vertex_colours(void **state)
{
    (void)state;
    /* position 1 is used with two normals, so it splits into two vertices: both
     * keep its colour. 0.5 -> 128 and 0.2 -> 51 show rounding to nearest. */
    tarn_mesh_buffer b;
    load_obj_text("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 0.5 0.25 0.2\n"
                  "vn 0 0 1\nvn 0 1 0\nf 1//1 2//1 3//1\nf 2//1 4//1 3//1\nf 1//2 3//1 4//1\n",
                  &b);
    const tarn_mesh *m = &b.mesh;
    assert_int_equal(m->vertex_count, 5);
    check_mesh_consistent(m);
    assert_non_null(m->colours);
    static const uint32_t expected[] = { 0xFF0000, 0x00FF00, 0x0000FF, 0x804033, 0xFF0000 };
    assert_memory_equal(m->colours, expected, sizeof expected);
    assert_int_equal(m->positions[4].x, m->positions[0].x); /* the split: same position */
    tarn_mesh_buffer_free(&b);
}

static void test_obj_mixed_colours(void **state)
{
    (void)state;
    /* one coloured v line gives the whole mesh colours; the others are white */
    tarn_mesh_buffer b;
    load_obj_text("v 0 0 0\nv 1 0 0 0.2 0.4 0.6\nv 0 1 0\nf 1 2 3\n", &b);
    static const uint32_t expected[] = { 0xFFFFFF, 0x336699, 0xFFFFFF };
    assert_non_null(b.mesh.colours);
    assert_memory_equal(b.mesh.colours, expected, sizeof expected);
    tarn_mesh_buffer_free(&b);
}

static void test_obj_triangle_limit(void **state)
{
    (void)state;
    /* 65536 triangles over three vertices: the face that crosses the limit is named */
    size_t size = 64 + 65536 * 8;
    char *text = malloc(size);
    assert_non_null(text);
    size_t used = (size_t)snprintf(text, size, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for (int k = 0; k < 65536; k++) used += (size_t)snprintf(text + used, size - used, "f 1 2 3\n");
    char *dir = make_temp_dir();
    tarn_error err;
    tarn_mesh_buffer b;
    const char *path = write_temp(dir, "t.obj", text);
    char expected[1200];
    snprintf(expected, sizeof expected,
             "%s:65539: more than 65535 triangles; a tarn mesh holds at most 65535", path);
    assert_int_equal(tarn_obj_load(path, NULL, &b, &err), -1);
    assert_string_equal(err.message, expected);
    remove_temp_dir(dir);
    free(text);
}

/* An OBJ file stops at the line that takes the scene past a limit of
 * scene_budget.h, counting what the rest of the scene holds: a v line for the
 * vertices (and a vt or vn line, each a vertex's at most), a face for the
 * triangles. */
static void test_obj_stops_at_the_scene_limits(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        tarn_scene_cost held;
        const char *expect;
    } cases[] = {
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", { 0, TARN_SCENE_VERTICES_MAX - 2, 0, 0 },
          ":3: the scene would hold 3,000,001 vertices; the limit is 3,000,000" },
        { "vt 0 0\nvt 1 0\nvt 0 1\n", { 0, TARN_SCENE_VERTICES_MAX - 2, 0, 0 },
          ":3: the scene would hold 3,000,001 vertices; the limit is 3,000,000" },
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 1 2\n", { 0, 0, TARN_SCENE_TRIANGLES_MAX - 2, 0 },
          ":5: the scene would hold 4,000,001 triangles; the limit is 4,000,000" },
    };
    assert_int_equal(TARN_SCENE_VERTICES_MAX, 3000000);
    assert_int_equal(TARN_SCENE_TRIANGLES_MAX, 4000000);
    char *dir = make_temp_dir();
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const char *path = write_temp(dir, "t.obj", cases[k].text);
        char expected[1200];
        snprintf(expected, sizeof expected, "%s%s", path, cases[k].expect);
        tarn_error err;
        tarn_mesh_buffer b;
        assert_int_equal(tarn_obj_load(path, &cases[k].held, &b, &err), -1);
        assert_string_equal(err.message, expected);
        /* the same file alone loads, or fails for its own reasons */
        if (tarn_obj_load(path, NULL, &b, &err) == 0) tarn_mesh_buffer_free(&b);
        else assert_null(strstr(err.message, "the scene would"));
    }
    remove_temp_dir(dir);
}

/* ---- PNG ------------------------------------------------------------------------ */

/* Writes a PNG of any colour type and depth through libpng directly (test data). */
static void write_png_raw(const char *path, uint32_t width, uint32_t height, int bit_depth,
                          int colour_type, int interlace, const png_color *palette,
                          int palette_size, const uint8_t *rows, size_t stride)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, width, height, bit_depth, colour_type, interlace,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (palette) png_set_PLTE(png, info, palette, palette_size);
    png_write_info(png, info);
    int passes = png_set_interlace_handling(png);
    for (int pass = 0; pass < passes; pass++) {
        for (uint32_t y = 0; y < height; y++) png_write_row(png, (png_bytep)(rows + y * stride));
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

static void test_png_round_trip(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    char path[1024];
    snprintf(path, sizeof path, "%s/out.png", dir);
    uint8_t rgb[4 * 2 * 3];
    for (size_t k = 0; k < sizeof rgb; k++) rgb[k] = (uint8_t)(k * 11);
    tarn_error err;
    assert_int_equal(tarn_png_write_rgb(path, rgb, 4, 2, &err), 0);
    assert_int_equal(files_in(dir), 1); /* the temporary file was renamed, not left */
    struct stat info;
    assert_int_equal(stat(path, &info), 0);
    assert_true(info.st_mode & S_IRUSR);

    tarn_image image;
    assert_int_equal(tarn_png_read_texture(path, &image, &err), 0);
    assert_int_equal(image.width, 4);
    assert_int_equal(image.height, 2);
    assert_int_equal(image.channels, 3);
    assert_memory_equal(image.pixels, rgb, sizeof rgb);
    tarn_image_free(&image);

    /* gray pixels come back unchanged as a heightfield */
    for (size_t k = 0; k < 8; k++) rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = (uint8_t)(k * 30);
    assert_int_equal(tarn_png_write_rgb(path, rgb, 4, 2, &err), 0); /* replaces the file */
    assert_int_equal(tarn_png_read_heightfield(path, &image, &err), 0);
    assert_int_equal(image.channels, 1);
    for (size_t k = 0; k < 8; k++) assert_int_equal(image.pixels[k], k * 30);
    tarn_image_free(&image);
    remove_temp_dir(dir);
}

static void test_png_formats(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    char path[1024];
    snprintf(path, sizeof path, "%s/in.png", dir);
    tarn_error err;
    tarn_image image;

    /* palette, 2 bits per pixel */
    static const png_color palette[3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };
    const uint8_t indices[2] = { 0x18, 0x90 }; /* rows: 0 1 2 0 / 2 1 0 0 */
    write_png_raw(path, 4, 2, 2, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, palette, 3, indices, 1);
    assert_int_equal(tarn_png_read_texture(path, &image, &err), 0);
    static const uint8_t expected_palette[24] = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 0, 0,
                                                  0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 0, 0 };
    assert_memory_equal(image.pixels, expected_palette, 24);
    tarn_image_free(&image);

    /* 1-bit gray */
    const uint8_t bits[2] = { 0xA0, 0x50 }; /* rows: 1 0 1 0 / 0 1 0 1 */
    write_png_raw(path, 4, 2, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, NULL, 0, bits, 1);
    assert_int_equal(tarn_png_read_heightfield(path, &image, &err), 0);
    static const uint8_t expected_bits[8] = { 255, 0, 255, 0, 0, 255, 0, 255 };
    assert_memory_equal(image.pixels, expected_bits, 8);
    tarn_image_free(&image);

    /* 16-bit gray + alpha: alpha dropped, high byte kept, expanded to RGB */
    const uint8_t gray_alpha[2 * 4] = { 0x12, 0x00, 0x00, 0x00, 0xAB, 0xFF, 0xFF, 0xFF };
    write_png_raw(path, 2, 1, 16, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_INTERLACE_NONE, NULL, 0,
                  gray_alpha, 8);
    assert_int_equal(tarn_png_read_texture(path, &image, &err), 0);
    static const uint8_t expected_gray[6] = { 0x12, 0x12, 0x12, 0xAB, 0xAB, 0xAB };
    assert_memory_equal(image.pixels, expected_gray, 6);
    tarn_image_free(&image);

    /* RGBA: alpha stripped */
    const uint8_t rgba[8] = { 1, 2, 3, 0, 4, 5, 6, 128 };
    write_png_raw(path, 2, 1, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, NULL, 0, rgba, 8);
    assert_int_equal(tarn_png_read_texture(path, &image, &err), 0);
    static const uint8_t expected_rgb[6] = { 1, 2, 3, 4, 5, 6 };
    assert_memory_equal(image.pixels, expected_rgb, 6);
    tarn_image_free(&image);

    /* Adam7 interlacing */
    uint8_t pattern[8 * 8 * 3];
    for (size_t k = 0; k < sizeof pattern; k++) pattern[k] = (uint8_t)(k * 37 + 5);
    write_png_raw(path, 8, 8, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7, NULL, 0, pattern, 24);
    assert_int_equal(tarn_png_read_texture(path, &image, &err), 0);
    assert_memory_equal(image.pixels, pattern, sizeof pattern);
    tarn_image_free(&image);
    remove_temp_dir(dir);
}

/* An output of two files whose second cannot be renamed into place (a folder took
 * its name after it was opened): the first, already in place, is taken back, and
 * no temporary file stays. */
static void test_a_failed_rename_takes_back_the_whole_output(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    char first[1100], second[1100], inner[1200];
    snprintf(first, sizeof first, "%s/out.c", dir);
    snprintf(second, sizeof second, "%s/out.h", dir);
    const char *const paths[] = {first, second};
    tarn_atomic_file files[2];
    tarn_error err;
    assert_int_equal(tarn_atomic_open_all(files, paths, 2, &err), 0);
    fputs("source", files[0].file);
    fputs("header", files[1].file);
    assert_int_equal(mkdir(second, 0755), 0);
    snprintf(inner, sizeof inner, "%s/x", second);
    assert_int_equal(bad_write_text(inner, "x"), 0); /* non-empty: rename cannot replace it */
    assert_int_equal(tarn_atomic_commit_all(files, 2, &err), -1);
    assert_non_null(strstr(err.message, "cannot rename"));
    assert_int_equal(files_in(dir), 1); /* the folder alone */
    assert_int_equal(unlink(inner), 0);
    assert_int_equal(rmdir(second), 0);
    remove_temp_dir(dir);
}

static void test_png_write_failure_leaves_nothing(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    char path[1024];
    uint8_t rgb[3] = { 1, 2, 3 };
    tarn_error err;
    /* a missing directory: no temporary file can even be made */
    snprintf(path, sizeof path, "%s/missing/out.png", dir);
    assert_int_equal(tarn_png_write_rgb(path, rgb, 1, 1, &err), -1);
    assert_non_null(strstr(err.message, path));
    /* the target is a directory: refused before anything is written */
    snprintf(path, sizeof path, "%s/taken", dir);
    assert_int_equal(mkdir(path, 0755), 0);
    assert_int_equal(tarn_png_write_rgb(path, rgb, 1, 1, &err), -1);
    assert_non_null(strstr(err.message, "is a directory"));
    assert_int_equal(files_in(dir), 1);
    assert_int_equal(rmdir(path), 0);
    /* an empty image is refused before anything is created */
    snprintf(path, sizeof path, "%s/empty.png", dir);
    assert_int_equal(tarn_png_write_rgb(path, rgb, 0, 1, &err), -1);
    assert_int_equal(files_in(dir), 0);
    remove_temp_dir(dir);
}

/* ---- scenes --------------------------------------------------------------------- */

static void test_pond(void **state)
{
    (void)state;
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load("scenes/pond.json", &s, &err)) fail_msg("%s", err.message);
    assert_string_equal(s.name, "pond");
    assert_int_equal(s.width, 240);
    assert_int_equal(s.height, 240);
    assert_int_equal(s.scene.background_rgb, 0x87CEEB);
    assert_int_equal(s.scene.camera.fov_y_degrees, 60 * 65536);
    assert_int_equal(s.scene.camera.near, 6554);
    assert_int_equal(s.scene.camera.far, 100 * 65536);
    assert_int_equal(s.scene.light.colour_rgb, 0xFFFFF0);
    assert_int_equal(s.scene.light.ambient_rgb, 0x404850);
    dvec l = dvec_of(s.scene.light.direction);
    assert_true(fabs(sqrt(dot3(l, l)) - 1) < 1e-4);
    assert_true(l.y > 0);
    /* the camera looks down into the pit at 30..40 degrees */
    dvec view = sub(dvec_of(s.scene.camera.target), dvec_of(s.scene.camera.position));
    double down = atan2(-view.y, sqrt(view.x * view.x + view.z * view.z)) * 180 / 3.14159265358979;
    assert_true(down >= 30 && down <= 40);

    assert_int_equal(s.material_count, 6);
    assert_int_equal(s.texture_count, 4); /* ground, two normal maps, foam */
    assert_int_equal(s.textures[0].width, 64);
    assert_int_equal(s.textures[0].height, 64);
    assert_ptr_equal(s.materials[0].texture, &s.textures[0]);
    assert_string_equal(s.material_names[1], "plant");
    assert_int_equal(s.materials[1].cull, TARN_CULL_NONE);

    assert_int_equal(s.scene.object_count, 12);
    assert_ptr_equal(s.scene.objects, s.objects);
    unsigned triangles = 0, spheres = 0, plants = 0;
    for (size_t k = 0; k < s.object_count; k++) {
        const tarn_object *o = &s.objects[k];
        check_mesh_consistent(o->mesh);
        assert_true(o->scale > 0);
        triangles += o->mesh->triangle_count;
        if (o->material == &s.materials[1]) plants++;
        if (o->material == &s.materials[3] || o->material == &s.materials[4]) {
            spheres++;
            check_faces_outward(o->mesh, (dvec){ 0, 0, 0 });
            check_closed(o->mesh);
        }
    }
    assert_int_equal(spheres, 2);
    assert_true(plants >= 4);
    /* the pit: 48x48 samples, so that the pond fits the Cortex-M0 board's flash, less
     * what its level rim merges (1704 vertices and 3288 triangles are left); the
     * water: a 12 x 12 grid at the end of the list */
    assert_int_equal(s.objects[0].mesh->vertex_count, 1704);
    assert_int_equal(s.objects[0].mesh->triangle_count, 3288);
    check_faces_up(s.objects[11].mesh);
    assert_int_equal(s.objects[11].mesh->triangle_count, 12 * 12 * 2);
    /* the seeds' water: fog #4E83A9 at 0.15, refraction 0.25 within the apron at 240 */
    const tarn_water *water = s.objects[11].material->water;
    assert_ptr_equal(water, &s.waters[5]);
    assert_int_equal(water->fog_rgb, 0x4E83A9);
    assert_int_equal(water->fog_density, 9830);
    assert_int_equal(water->refraction, 16384);
    assert_true(tarn_water_reach_pixels(water, 240) <= (int32_t)TARN_WATER_APRON_MAX);
    assert_ptr_equal(water->normal_a, &s.textures[1]);
    assert_ptr_equal(water->normal_b, &s.textures[2]);
    assert_ptr_equal(water->foam_texture, &s.textures[3]);
    print_message("pond: %zu objects, %u triangles\n", s.object_count, triangles);
    tarn_scene_free(&s);
    assert_null(s.objects);
}

static void test_scene_defaults_and_rotation(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    const char *path = write_temp(
        dir, "min.scene.json",
        "{\"camera\": {\"position\": [0, 0, 5], \"target\": [0, 0, 0], \"fov\": 45.5},"
        " \"materials\": {\"m\": {}},"
        " \"objects\": [{\"type\": \"box\", \"material\": \"m\", \"size\": [1, 1, 1],"
        "                \"rotation\": [90, 0, 0]},"
        "               {\"type\": \"box\", \"material\": \"m\", \"size\": [1, 1, 1],"
        "                \"rotation\": [90, 90, 0], \"scale\": 0.5, \"position\": [1, -2, 3.25]}]}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    assert_string_equal(s.name, "min.scene");
    assert_int_equal(s.width, 240);
    assert_int_equal(s.height, 240);
    assert_int_equal(s.scene.background_rgb, 0);
    assert_int_equal(s.scene.camera.fov_y_degrees, 45 * 65536 + 32768);
    assert_int_equal(s.scene.camera.near, 6554);
    assert_int_equal(s.scene.camera.far, 100 * 65536);
    assert_int_equal(s.scene.light.direction.y, 65536);
    assert_int_equal(s.scene.light.colour_rgb, 0xFFFFFF);
    assert_int_equal(s.materials[0].colour_rgb, 0xFFFFFF);
    assert_int_equal(s.materials[0].cull, TARN_CULL_BACK);
    assert_int_equal(s.materials[0].unlit, 0);
    assert_null(s.materials[0].texture);
    /* Rx(90): y -> z, z -> -y */
    static const tarn_q16 rx90[3][3] = { { 65536, 0, 0 }, { 0, 0, -65536 }, { 0, 65536, 0 } };
    assert_memory_equal(s.objects[0].rotation, rx90, sizeof rx90);
    /* Ry(90) * Rx(90): X first, then Y. x -> -z; y -> z -> x; z -> -y */
    static const tarn_q16 ryrx[3][3] = { { 0, 65536, 0 }, { 0, 0, -65536 }, { -65536, 0, 0 } };
    assert_memory_equal(s.objects[1].rotation, ryrx, sizeof ryrx);
    assert_int_equal(s.objects[1].scale, 32768);
    assert_int_equal(s.objects[1].position.z, 3 * 65536 + 16384);
    assert_int_equal(s.objects[0].scale, 65536);
    tarn_scene_free(&s);
    tarn_scene_free(&s); /* twice is harmless */
    remove_temp_dir(dir);
}

static void test_asset_paths(void **state)
{
    (void)state;
    /* relative to the scene's directory; absolute paths as they are */
    char *dir = make_temp_dir();
    char sub_dir[1024], obj_path[1100], scene[2600];
    snprintf(sub_dir, sizeof sub_dir, "%s/meshes", dir);
    assert_int_equal(mkdir(sub_dir, 0755), 0);
    snprintf(obj_path, sizeof obj_path, "%s/tri.obj", sub_dir);
    assert_int_equal(bad_write_text(obj_path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), 0);
    snprintf(scene, sizeof scene,
             "{\"frame\": {\"width\": 320, \"height\": 200},"
             " \"camera\": {\"position\": [0, 0, 5], \"target\": [0, 0, 0], \"fov\": 60},"
             " \"materials\": {\"m\": {}}, \"objects\": ["
             "  {\"type\": \"mesh\", \"material\": \"m\", \"file\": \"meshes/tri.obj\"},"
             "  {\"type\": \"mesh\", \"material\": \"m\", \"file\": \"%s\"}]}",
             obj_path);
    const char *path = write_temp(dir, "s.json", scene);
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    assert_int_equal(s.width, 320);
    assert_int_equal(s.height, 200);
    assert_int_equal(s.scene.object_count, 2);
    assert_int_equal(s.objects[1].mesh->triangle_count, 1);
    tarn_scene_free(&s);
    assert_int_equal(unlink(obj_path), 0);
    assert_int_equal(rmdir(sub_dir), 0);
    remove_temp_dir(dir);
}

/* ---- water ---------------------------------------------------------------------- */

/* The one material of `s` with a water block. */
static const tarn_water *only_water(const tarn_loaded_scene *s)
{
    const tarn_water *found = NULL;
    for (size_t k = 0; k < s->material_count; k++) {
        if (!s->materials[k].water) continue;
        assert_null(found);
        assert_ptr_equal(s->materials[k].water, &s->waters[k]);
        found = s->materials[k].water;
    }
    return found;
}

/* A foam map another field reads too keeps its three channels: a normal map reads
 * green and blue. */
static void test_a_foam_map_read_otherwise_keeps_rgb(void **state)
{
    (void)state;
    static const uint8_t up[3] = { 128, 128, 255 };
    char *dir = make_temp_dir();
    write_flat_png(dir, "a.png", 4, 4, up);
    write_flat_png(dir, "foam.png", 8, 8, up);
    const char *path = write_temp(
        dir, "w.json",
        "{\"frame\": {\"width\": 100, \"height\": 80},"
        " \"camera\": {\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60},"
        " \"materials\": {\"shared\": {\"water\": {"
        "   \"normal_maps\": [{\"image\": \"a.png\", \"scale\": 4}],"
        "   \"foam\": {\"texture\": \"a.png\", \"distance\": 0.4}}},"
        "   \"own\": {\"water\": {\"foam\": {\"texture\": \"foam.png\", \"distance\": 0.4}}}},"
        " \"objects\": []}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    assert_ptr_equal(s.materials[0].water->foam_texture, s.materials[0].water->normal_a);
    assert_int_equal(s.materials[0].water->foam_texture->red_only, 0);
    assert_int_equal(s.materials[1].water->foam_texture->red_only, 1);
    tarn_scene_free(&s);
    remove_temp_dir(dir);
}

static void test_water_fields(void **state)
{
    (void)state;
    static const uint8_t up[3] = { 128, 128, 255 }, grey[3] = { 90, 90, 90 };
    char *dir = make_temp_dir();
    write_flat_png(dir, "a.png", 4, 4, up);
    write_flat_png(dir, "b.png", 2, 2, up);
    write_flat_png(dir, "foam.png", 8, 8, grey);
    write_flat_png(dir, "ramp.png", 4, 1, grey);
    const char *path = write_temp(
        dir, "w.json",
        "{\"frame\": {\"width\": 100, \"height\": 80},"
        " \"camera\": {\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60},"
        " \"materials\": {\"w\": {\"water\": {"
        "   \"albedo\": \"#102030\", \"alpha\": 0.25,"
        "   \"fog\": {\"colour\": \"#4e83a9\", \"density\": 0.15},"
        "   \"absorption\": {\"colour\": \"#406080\", \"strength\": 1.5, \"squared\": true},"
        "   \"depth_colour\": {\"shallow\": \"#00ffff\", \"deep\": \"#000080\", \"scale\": 2.5,"
        "                      \"ramp\": \"ramp.png\"},"
        "   \"normal_maps\": [{\"image\": \"a.png\", \"scale\": 4, \"speed\": [0.05, -0.02]},"
        "                     {\"image\": \"b.png\", \"scale\": 0.5}],"
        "   \"normal_strength\": 2, \"refraction\": 0.125, \"fresnel\": 0.75,"
        "   \"specular\": {\"intensity\": 0.5, \"power\": 64},"
        "   \"foam\": {\"texture\": \"foam.png\", \"scale\": 3, \"speed\": [0.01, 0.02],"
        "              \"distance\": 0.4, \"line_speed\": -0.5, \"lines\": 3,"
        "              \"colour\": \"#f0f0e0\", \"opacity\": 0.8},"
        "   \"sparkles\": {\"amount\": 12.5, \"colour\": \"#fffff0\"}}},"
        "   \"plain\": {}},"
        " \"underwater\": {\"level\": -1.5, \"distortion\": 0.01,"
        "   \"normal_map\": {\"image\": \"a.png\", \"scale\": 2, \"speed\": [0.03, 0.05]},"
        "   \"tint\": {\"colour\": \"#1f6478\", \"density\": 0.2}},"
        " \"objects\": []}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    const tarn_water *w = only_water(&s);
    assert_ptr_equal(w, s.materials[0].water);
    assert_null(s.materials[1].water);
    assert_int_equal(w->features, 0x1FF); /* every TARN_WATER_* */
    assert_int_equal(w->albedo_rgb, 0x102030);
    assert_int_equal(w->alpha, 16384);
    assert_int_equal(w->fog_rgb, 0x4E83A9);
    assert_int_equal(w->fog_density, 9830); /* 0.15 * 65536 = 9830.4 */
    assert_int_equal(w->absorb_rgb, 0x406080);
    assert_int_equal(w->absorption, 98304);
    assert_int_equal(w->absorption_squared, 1);
    assert_int_equal(w->shallow_rgb, 0x00FFFF);
    assert_int_equal(w->deep_rgb, 0x000080);
    assert_int_equal(w->depth_scale, 163840);
    assert_non_null(w->colour_ramp);
    assert_int_equal(w->colour_ramp->width, 4);
    assert_int_equal(w->colour_ramp->height, 1);
    assert_int_equal(w->normal_a->width, 4);
    assert_int_equal(w->normal_b->width, 2);
    assert_int_equal(w->pan_a.scale, 4 * 65536);
    assert_int_equal(w->pan_a.speed_u, 3277);  /* 3276.8 */
    assert_int_equal(w->pan_a.speed_v, -1311); /* -1310.72 */
    assert_int_equal(w->pan_b.scale, 32768);
    assert_int_equal(w->pan_b.speed_u, 0);
    assert_int_equal(w->normal_strength, 2 * 65536);
    /* flat maps: x = y = 1/255, z = 1 each, so N.x = 2 (2/255) / sqrt((4/255)^2 + 1) */
    assert_int_equal(w->normal_xy_max, 1028);
    assert_int_equal(w->refraction, 8192);
    assert_int_equal(w->fresnel, 49152);
    assert_int_equal(w->specular, 32768);
    assert_int_equal(w->specular_power, 64);
    assert_int_equal(w->foam_texture->width, 8);
    assert_int_equal(w->foam_texture->red_only, 1); /* read as foam alone: its red bytes */
    for (int k = 0; k < 64; k++) assert_int_equal(w->foam_texture->rgb[k], 90);
    assert_int_equal(w->normal_a->red_only, 0);
    assert_int_equal(w->colour_ramp->red_only, 0);
    assert_int_equal(w->foam_pan.scale, 3 * 65536);
    assert_int_equal(w->foam_pan.speed_u, 655);  /* 655.36 */
    assert_int_equal(w->foam_pan.speed_v, 1311); /* 1310.72 */
    assert_int_equal(w->foam_distance, 26214);   /* 26214.4 */
    assert_int_equal(w->foam_line_speed, -32768);
    assert_int_equal(w->foam_line_count, 3);
    assert_int_equal(w->foam_rgb, 0xF0F0E0);
    assert_int_equal(w->foam_opacity, 52429); /* 52428.8 */
    assert_int_equal(w->sparkle_amount, 819200);
    assert_int_equal(w->sparkle_rgb, 0xFFFFF0);

    const tarn_underwater *u = s.scene.underwater;
    assert_ptr_equal(u, &s.underwater);
    assert_int_equal(u->level, -98304);
    assert_ptr_equal(u->normal_map, w->normal_a); /* a.png is loaded once */
    assert_int_equal(u->pan.scale, 2 * 65536);
    assert_int_equal(u->pan.speed_u, 1966); /* 1966.08 */
    assert_int_equal(u->pan.speed_v, 3277);
    assert_int_equal(u->distortion, 655);
    assert_int_equal(u->tint_rgb, 0x1F6478);
    assert_int_equal(u->tint_density, 13107); /* 13107.2 */
    assert_int_equal(s.texture_count, 4);
    tarn_scene_free(&s);
    remove_temp_dir(dir);
}

/* An empty block is clear water: no features, every field at its default. */
static void test_water_defaults(void **state)
{
    (void)state;
    char *dir = make_temp_dir();
    const char *path = write_temp(
        dir, "w.json",
        "{\"camera\": {\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60},"
        " \"materials\": {\"clear\": {\"water\": {}},"
        "                 \"foggy\": {\"water\": {\"fog\": {\"colour\": \"#000000\","
        "                                                  \"density\": 0}}}},"
        " \"objects\": []}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(path, &s, &err)) fail_msg("%s", err.message);
    const tarn_water *clear = s.materials[0].water, *foggy = s.materials[1].water;
    assert_non_null(clear);
    assert_int_equal(clear->features, 0);
    assert_int_equal(clear->albedo_rgb, 0xFFFFFF);
    assert_int_equal(clear->alpha, 0);
    assert_int_equal(clear->normal_strength, 65536);
    assert_int_equal(clear->normal_xy_max, 0);
    assert_int_equal(clear->specular, 65536);
    assert_int_equal(clear->specular_power, 32);
    assert_int_equal(clear->pan_a.scale, 65536);
    assert_int_equal(clear->foam_pan.scale, 65536);
    assert_int_equal(clear->foam_opacity, 65536);
    assert_int_equal(clear->foam_line_count, 0);
    assert_null(clear->normal_a);
    assert_null(clear->colour_ramp);
    assert_int_equal(foggy->features, TARN_WATER_FOG); /* a block present, its flag set */
    assert_int_equal(foggy->fog_density, 0);
    assert_null(s.scene.underwater);
    tarn_scene_free(&s);
    remove_temp_dir(dir);
}

typedef struct {
    const char *path;
    uint32_t features;
    int ramp, underwater; /* a colour ramp; an underwater view */
} water_scene;

static const water_scene WATER_SCENES[] = {
    { "scenes/pond.json",
      TARN_WATER_FOG | TARN_WATER_NORMALS | TARN_WATER_REFRACTION | TARN_WATER_FRESNEL |
          TARN_WATER_SPECULAR | TARN_WATER_FOAM, 0, 0 },
    { "scenes/beach.json",
      TARN_WATER_DEPTH_COLOUR | TARN_WATER_NORMALS | TARN_WATER_FRESNEL | TARN_WATER_FOAM |
          TARN_WATER_SPARKLES, 1, 0 },
    { "scenes/murky.json",
      TARN_WATER_ABSORPTION | TARN_WATER_NORMALS | TARN_WATER_FRESNEL | TARN_WATER_SPECULAR |
          TARN_WATER_FOAM, 0, 0 },
    { "scenes/lake.json",
      TARN_WATER_FOG | TARN_WATER_NORMALS | TARN_WATER_FRESNEL | TARN_WATER_SPECULAR, 0, 0 },
    { "scenes/underwater.json", TARN_WATER_FOG, 0, 1 },
    { "scenes/effects/fog.json", TARN_WATER_FOG, 0, 0 },
    { "scenes/effects/absorption.json", TARN_WATER_ABSORPTION, 0, 0 },
    { "scenes/effects/depth_colour.json", TARN_WATER_DEPTH_COLOUR, 0, 0 },
    { "scenes/effects/ramp.json", TARN_WATER_DEPTH_COLOUR, 1, 0 },
    { "scenes/effects/refraction.json", TARN_WATER_NORMALS | TARN_WATER_REFRACTION, 0, 0 },
    { "scenes/effects/normals.json", TARN_WATER_NORMALS | TARN_WATER_SPECULAR, 0, 0 },
    { "scenes/effects/fresnel.json", TARN_WATER_FRESNEL, 0, 0 },
    { "scenes/effects/foam.json", TARN_WATER_FOAM, 0, 0 },
    { "scenes/effects/sparkles.json", TARN_WATER_NORMALS | TARN_WATER_SPARKLES, 0, 0 },
    { "scenes/effects/underwater.json", 0, 0, 1 },
};

/* Each water scene loads with exactly its features, and its refraction fits the apron. */
static void test_water_scenes(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof WATER_SCENES / sizeof WATER_SCENES[0]; k++) {
        const water_scene *c = &WATER_SCENES[k];
        tarn_loaded_scene s;
        tarn_error err = { "" };
        if (tarn_scene_load(c->path, &s, &err)) fail_msg("%s", err.message);
        const tarn_water *w = only_water(&s);
        if (c->features) {
            assert_non_null(w);
            if (w->features != c->features) {
                fail_msg("%s: features 0x%x, expected 0x%x", c->path, w->features, c->features);
            }
            assert_true((w->colour_ramp != NULL) == c->ramp);
            int32_t reach = tarn_water_reach_pixels(w, s.width);
            assert_true(reach <= (int32_t)TARN_WATER_APRON_MAX);
            print_message("%s: normal_xy_max %.4f, refraction %.4f, reach %d pixels at width %u\n",
                          c->path, w->normal_xy_max / 65536.0, w->refraction / 65536.0, reach,
                          s.width);
        } else {
            assert_null(w);
        }
        assert_true((s.scene.underwater != NULL) == c->underwater);
        if (c->underwater) assert_true(s.scene.camera.position.y < s.scene.underwater->level);
        tarn_scene_free(&s);
    }
}

/* ---- the normals' bound --------------------------------------------------------- */

static double decoded(uint8_t c)
{
    return (2.0 * c - 255.0) / 255.0;
}

/* max(|N.x|, |N.y|) of step 1 of tarn_water.h for one texel of each map (b may be NULL). */
static double exact_lean(const uint8_t *a, const uint8_t *b, double s)
{
    double x = decoded(a[0]), y = decoded(a[1]), z = decoded(a[2]);
    if (b) {
        x += decoded(b[0]);
        y += decoded(b[1]);
        z *= decoded(b[2]);
    }
    x *= s;
    y *= s;
    return fmax(fabs(x), fabs(y)) / sqrt(x * x + y * y + z * z);
}

/* A map of leaning normals, z the larger the flatter, from a small hash. */
static void make_normal_texels(uint8_t *rgb, size_t texels, uint32_t seed)
{
    for (size_t k = 0; k < texels; k++) {
        seed = seed * 1664525u + 1013904223u;
        double x = ((seed >> 8) & 255) / 255.0 - 0.5, y = ((seed >> 16) & 255) / 255.0 - 0.5;
        double z = sqrt(fmax(0.0, 1 - x * x - y * y));
        rgb[3 * k] = (uint8_t)lround((x * 0.5 + 0.5) * 255);
        rgb[3 * k + 1] = (uint8_t)lround((y * 0.5 + 0.5) * 255);
        rgb[3 * k + 2] = (uint8_t)lround((z * 0.5 + 0.5) * 255);
    }
}

static void test_normal_xy_max(void **state)
{
    (void)state;
    enum { SIDE = 8, TEXELS = SIDE * SIDE };
    uint8_t a_rgb[TEXELS * 3], b_rgb[TEXELS * 3];
    make_normal_texels(a_rgb, TEXELS, 1);
    make_normal_texels(b_rgb, TEXELS, 2);
    const tarn_texture a = { SIDE, SIDE, a_rgb, 0 }, b = { SIDE, SIDE, b_rgb, 0 };
    static const double strengths[] = { 0, 0.25, 0.6, 1, 2.5, 8 };
    tarn_q16 previous_one = -1, previous_two = -1;
    for (size_t k = 0; k < sizeof strengths / sizeof strengths[0]; k++) {
        tarn_q16 strength = tarn_q16_from_double(strengths[k]);
        double s = strength / 65536.0, one = 0, two = 0;
        for (int i = 0; i < TEXELS; i++) {
            one = fmax(one, exact_lean(a_rgb + 3 * i, NULL, s));
            for (int j = 0; j < TEXELS; j++) {
                two = fmax(two, exact_lean(a_rgb + 3 * i, b_rgb + 3 * j, s));
            }
        }
        tarn_q16 bound_one = tarn_water_normal_xy_max(&a, NULL, strength);
        tarn_q16 bound_two = tarn_water_normal_xy_max(&a, &b, strength);
        /* one map: the exact maximum, rounded up; two: an upper bound on every pair */
        assert_int_equal(bound_one, (tarn_q16)ceil(one * 65536));
        assert_true(bound_two >= ceil(two * 65536) && bound_two <= 65536);
        assert_true(bound_one >= previous_one && bound_two >= previous_two);
        print_message("strength %.2f: one map %.4f (exact %.4f), two %.4f (pairs %.4f)\n", s,
                      bound_one / 65536.0, one, bound_two / 65536.0, two);
        previous_one = bound_one;
        previous_two = bound_two;
    }
    assert_int_equal(tarn_water_normal_xy_max(&a, &b, 0), 0);
}

/* Index of the covered pixel whose centre is nearest (sx, sy). */
static size_t nearest_covered_pixel(const uint8_t *covered, int width, int height, double sx,
                                    double sy)
{
    size_t best = SIZE_MAX;
    double best_distance = HUGE_VAL;
    for (int j = 0; j < height; j++) {
        for (int i = 0; i < width; i++) {
            double dx = i + 0.5 - sx, dy = j + 0.5 - sy, distance = dx * dx + dy * dy;
            if (covered[j * width + i] && distance < best_distance) {
                best = (size_t)(j * width + i);
                best_distance = distance;
            }
        }
    }
    assert_true(best_distance < 2.0 * 2.0);
    return best;
}

static void test_vertex_colours_render(void **state)
{
    (void)state;
    /* loader to core: an unlit white triangle with a red, a green and a blue corner,
     * seen head on. fov 90 from z = 1 maps x, y in -1..1 onto the 64 pixels. */
    enum { SIDE = 64 };
    static const double corners[3][2] = { { -0.9, -0.9 }, { 0.9, -0.9 }, { 0.0, 0.9 } };
    static const uint8_t corner_rgb[3][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };
    char *dir = make_temp_dir();
    write_temp(dir, "tri.obj", "v -0.9 -0.9 0 1 0 0\nv 0.9 -0.9 0 0 1 0\nv 0 0.9 0 0 0 1\n"
                               "f 1 2 3\n");
    const char *scene_path = write_temp(
        dir, "tri.json",
        "{\"frame\": {\"width\": 64, \"height\": 64},"
        " \"camera\": {\"position\": [0, 0, 1], \"target\": [0, 0, 0], \"fov\": 90},"
        " \"materials\": {\"paint\": {\"colour\": \"#ffffff\", \"unlit\": true}},"
        " \"objects\": [{\"type\": \"mesh\", \"material\": \"paint\", \"file\": \"tri.obj\"}]}");
    tarn_loaded_scene s;
    tarn_error err = { "" };
    if (tarn_scene_load(scene_path, &s, &err)) fail_msg("%s", err.message);
    tarn_frame_config config = { SIDE, SIDE, tarn_quality_default(), 0 };
    static uint8_t rgb[SIDE * SIDE * 3], covered[SIDE * SIDE];
    if (tarn_core_render(&s.scene, &config, rgb, covered, &err)) fail_msg("%s", err.message);
    for (int k = 0; k < 3; k++) {
        double sx = SIDE / 2.0 * (1.0 + corners[k][0]), sy = SIDE / 2.0 * (1.0 - corners[k][1]);
        const uint8_t *pixel = rgb + 3 * nearest_covered_pixel(covered, SIDE, SIDE, sx, sy);
        for (int c = 0; c < 3; c++) {
            if (abs(pixel[c] - corner_rgb[k][c]) > 8) {
                fail_msg("corner %d: pixel #%02x%02x%02x, expected #%02x%02x%02x", k, pixel[0],
                         pixel[1], pixel[2], corner_rgb[k][0], corner_rgb[k][1], corner_rgb[k][2]);
            }
        }
    }
    tarn_scene_free(&s);
    remove_temp_dir(dir);
}

static void test_bad_inputs(void **state)
{
    (void)state;
    int failures = 0; /* every case runs, so one run shows every wrong message */
    for (size_t k = 0; k < BAD_SCENE_CASE_COUNT; k++) {
        const bad_scene_case *c = &BAD_SCENE_CASES[k];
        char *dir = make_temp_dir();
        char scene_path[1100], expected[1600];
        assert_int_equal(bad_case_write(c, dir, scene_path, sizeof scene_path), 0);
        snprintf(expected, sizeof expected, "%s/%s%s", dir, c->file, c->expect);
        tarn_loaded_scene s;
        tarn_error err = { "" };
        int result = tarn_scene_load(scene_path, &s, &err);
        if (result != -1 || strcmp(err.message, expected) != 0) {
            print_error("case \"%s\":\n  got      %s\n  expected %s\n", c->what,
                        result ? err.message : "(loaded)", expected);
            failures++;
        }
        assert_null(strchr(err.message, '\n'));
        assert_null(s.objects); /* nothing left to free */
        assert_int_equal(s.material_count, 0);
        remove_temp_dir(dir);
    }
    assert_int_equal(failures, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_q16_from_double),
        cmocka_unit_test(test_plane),
        cmocka_unit_test(test_box),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_heightfield),
        cmocka_unit_test(test_heightfield_size_limit),
        cmocka_unit_test(test_heightfield_merges_level_squares),
        cmocka_unit_test(test_random_heightfields_merge_watertight),
        cmocka_unit_test(test_water_heightfield_stays_whole),
        cmocka_unit_test(test_primitive_limits),
        cmocka_unit_test(test_obj_polygons),
        cmocka_unit_test(test_obj_negative_indices),
        cmocka_unit_test(test_obj_missing_normals),
        cmocka_unit_test(test_obj_texcoords_and_normals),
        cmocka_unit_test(test_obj_crlf),
        cmocka_unit_test(test_obj_vertex_colours),
        cmocka_unit_test(test_obj_mixed_colours),
        cmocka_unit_test(test_obj_triangle_limit),
        cmocka_unit_test(test_obj_stops_at_the_scene_limits),
        cmocka_unit_test(test_png_round_trip),
        cmocka_unit_test(test_png_formats),
        cmocka_unit_test(test_png_write_failure_leaves_nothing),
        cmocka_unit_test(test_a_failed_rename_takes_back_the_whole_output),
        cmocka_unit_test(test_pond),
        cmocka_unit_test(test_scene_defaults_and_rotation),
        cmocka_unit_test(test_asset_paths),
        cmocka_unit_test(test_water_fields),
        cmocka_unit_test(test_a_foam_map_read_otherwise_keeps_rgb),
        cmocka_unit_test(test_water_defaults),
        cmocka_unit_test(test_water_scenes),
        cmocka_unit_test(test_normal_xy_max),
        cmocka_unit_test(test_vertex_colours_render),
        cmocka_unit_test(test_bad_inputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
