/* vertex_pass.c: every vertex of a scene as the frame's camera sees it, in the form
 * a baked static view keeps (tarn_static_vertex): what tarn bake stores in flash for
 * a still scene, and what a frame with the quality's vertex pass finds once into its
 * memory, so that every walk and the cluster bins read it instead of transforming,
 * projecting and lighting each vertex again. */
#include "geometry/geometry_internal.h"

/* docs/ and tarn_render.h say 16 bytes a vertex: the build holds them to it */
typedef char tarn_static_vertex_is_16_bytes[sizeof(tarn_static_vertex) == 16u ? 1 : -1];

tarn_static_vertex tarn__static_vertex_of(const tarn_view *view, const tarn_object_xform *xform,
                                          const tarn_mesh *mesh, uint16_t index, tarn_vec3 *position)
{
    tarn_static_vertex out = {0, 0, 0, {0, 0, 0}, 0};
    tarn_view_vertex v;
    tarn__vertex_position(xform, &mesh->positions[index], &v);
    if (position != NULL) {
        position->x = v.x;
        position->y = v.y;
        position->z = v.d;
    }
    const unsigned outcode = tarn__clip_outcode(view, &v);
    if (outcode == 0u) {
        tarn_screen_vertex screen;
        tarn__project_position(view, &v, &screen);
        out.screen_x = (int16_t)screen.x;
        out.screen_y = (int16_t)screen.y;
        out.inv_depth = screen.inv_depth;
    } else {
        out.screen_x = (int16_t)outcode; /* the planes it lies outside (tarn_static_vertex) */
    }
    tarn__vertex_shade(view, xform, mesh, index, &v);
    for (int c = 0; c < 3; c++) out.lit[c] = (uint16_t)v.lit[c];
    out.fresnel = (uint16_t)v.fresnel;
    return out;
}

uint32_t tarn__scene_vertex_count(const tarn_scene *scene)
{
    uint32_t count = 0;
    for (uint32_t i = 0; i < scene->object_count; i++) count += scene->objects[i].mesh->vertex_count;
    return count;
}

void tarn__vertex_pass(tarn_scene *scene, tarn_object *objects, const tarn_frame_config *config,
                       tarn_static_view *made, tarn_static_vertex *vertices, tarn_vec3 *positions)
{
    scene->static_view = NULL; /* the view of the camera itself */
    tarn_view view;
    tarn__view_setup(scene, config, &view);
    made->positions = positions;
    for (uint32_t i = 0; i < scene->object_count; i++) {
        const tarn_mesh *mesh = objects[i].mesh;
        /* every object's positions in scene order, as the walk steps through them */
        tarn_vec3 *position = positions;
        if (positions != NULL) positions += mesh->vertex_count;
        if (mesh->positions == NULL) continue; /* no triangles (tarn__scene_check): nothing read */
        tarn_object_xform xform;
        tarn__object_xform_setup(&view, &objects[i], &xform);
        for (uint32_t k = 0; k < mesh->vertex_count; k++)
            vertices[k] = tarn__static_vertex_of(&view, &xform, mesh, (uint16_t)k, position ? &position[k] : NULL);
        objects[i].static_vertices = vertices;
        vertices += mesh->vertex_count;
    }
    made->camera = scene->camera;
    made->light = scene->light;
    made->width = config->width;
    made->height = config->height;
    made->subpixel_bits = config->quality.subpixel_bits;
    made->bins = NULL; /* found in the frame's memory, from these vertices */
    made->backdrop = NULL;
    scene->static_view = made;
}
