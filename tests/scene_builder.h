/* scene_builder.h: small scenes built in code for the rasterizer tests. */
#ifndef TARN_TEST_SCENE_BUILDER_H
#define TARN_TEST_SCENE_BUILDER_H

#include <stdint.h>
#include "tarn/tarn_render.h"

#define BUILDER_VERTICES_MAX 8192
#define BUILDER_OBJECTS_MAX 4

typedef struct {
    tarn_vec3 positions[BUILDER_VERTICES_MAX];
    tarn_vec3 normals[BUILDER_VERTICES_MAX];
    uint16_t indices[3 * BUILDER_VERTICES_MAX];
    tarn_mesh meshes[BUILDER_OBJECTS_MAX];
    tarn_material materials[BUILDER_OBJECTS_MAX];
    tarn_object objects[BUILDER_OBJECTS_MAX];
    tarn_scene scene;
    uint32_t vertex_count, index_count;
} scene_builder;

/* Camera at `eye` looking at `target`, fov 60, near 0.1, far 1000; white light. */
void builder_init(scene_builder *b, double eye_x, double eye_y, double eye_z,
                  double target_x, double target_y, double target_z);
/* Starts a new object (identity transform) with an unlit untextured material. */
void builder_begin_object(scene_builder *b, uint32_t colour_rgb, uint8_t cull);
uint16_t builder_vertex(scene_builder *b, double x, double y, double z);
void builder_triangle(scene_builder *b, uint16_t a, uint16_t c, uint16_t d);
/* A w x h rectangle in the plane z = `z` centred on (cx, cy), n x m quads. */
void builder_grid(scene_builder *b, double cx, double cy, double z, double w, double h, int n, int m);

tarn_q16 builder_q16(double v);

#endif
