#include "scene_builder.h"

#include <string.h>

tarn_q16 builder_q16(double v)
{
    double scaled = v * 65536.0;
    return (tarn_q16)(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
}

static tarn_vec3 vec(double x, double y, double z)
{
    tarn_vec3 v = {builder_q16(x), builder_q16(y), builder_q16(z)};
    return v;
}

void builder_init(scene_builder *b, double eye_x, double eye_y, double eye_z,
                  double target_x, double target_y, double target_z)
{
    memset(b, 0, sizeof *b);
    b->scene.objects = b->objects;
    b->scene.camera.position = vec(eye_x, eye_y, eye_z);
    b->scene.camera.target = vec(target_x, target_y, target_z);
    b->scene.camera.fov_y_degrees = builder_q16(60);
    b->scene.camera.near = builder_q16(0.1);
    b->scene.camera.far = builder_q16(1000);
    b->scene.light.direction = vec(0, 1, 0);
    b->scene.light.colour_rgb = 0xFFFFFF;
    b->scene.light.ambient_rgb = 0x404040;
    b->scene.background_rgb = 0x000000;
}

void builder_begin_object(scene_builder *b, uint32_t colour_rgb, uint8_t cull)
{
    int n = b->scene.object_count++;
    tarn_material *m = &b->materials[n];
    m->colour_rgb = colour_rgb;
    m->cull = cull;
    m->unlit = 1;
    tarn_mesh *mesh = &b->meshes[n];
    mesh->positions = b->positions;
    mesh->normals = b->normals;
    mesh->indices = b->indices + b->index_count;
    tarn_object *o = &b->objects[n];
    o->mesh = mesh;
    o->material = m;
    o->scale = TARN_Q16_ONE;
    for (int i = 0; i < 3; i++) o->rotation[i][i] = TARN_Q16_ONE;
}

uint16_t builder_vertex(scene_builder *b, double x, double y, double z)
{
    uint16_t index = (uint16_t)b->vertex_count++;
    b->positions[index] = vec(x, y, z);
    b->normals[index] = vec(0, 0, 1);
    b->meshes[b->scene.object_count - 1].vertex_count = (uint16_t)b->vertex_count;
    return index;
}

void builder_triangle(scene_builder *b, uint16_t a, uint16_t c, uint16_t d)
{
    b->indices[b->index_count++] = a;
    b->indices[b->index_count++] = c;
    b->indices[b->index_count++] = d;
    b->meshes[b->scene.object_count - 1].triangle_count++;
}

void builder_grid(scene_builder *b, double cx, double cy, double z, double w, double h, int n, int m)
{
    uint16_t first = (uint16_t)b->vertex_count;
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++)
            builder_vertex(b, cx - w / 2 + w * i / n, cy - h / 2 + h * j / m, z);
    for (int j = 0; j < m; j++) {
        for (int i = 0; i < n; i++) {
            uint16_t v00 = (uint16_t)(first + j * (n + 1) + i), v10 = (uint16_t)(v00 + 1);
            uint16_t v01 = (uint16_t)(v00 + n + 1), v11 = (uint16_t)(v01 + 1);
            builder_triangle(b, v00, v10, v11); /* counter-clockwise seen from +z */
            builder_triangle(b, v00, v11, v01);
        }
    }
}
