/* scene_load.h: scene files (JSON) into tarn_scene structs and the storage they view.
 *
 * The format (every field is checked; unknown fields are errors):
 *   { "frame": {"width": 240, "height": 240},            optional, integers 1..1024
 *     "background": "#87ceeb",                            optional, default black
 *     "camera": {"position": [x,y,z], "target": [x,y,z], "fov": 60,
 *                "near": 0.1, "far": 100,                 near and far optional
 *                "path": {...}},                          optional (motion_load.h); with
 *                                                         it, no position or target
 *     "light": {"direction": [x,y,z], "colour": "#fffff0", "ambient": "#404850",
 *               "motion": {...}},                         motion optional (motion_load.h)
 *                                                         optional; direction points
 *                                                         toward the light, any length
 *     "materials": { "NAME": {"colour": "#rrggbb", "texture": "file.png",
 *                             "cull": "back"|"none"|"front", "unlit": false,
 *                             "water": {...} (water_load.h)} },
 *     "underwater": {...},                                optional (water_load.h)
 *     "objects": [ {"type": "plane"|"box"|"sphere"|"heightfield"|"mesh",
 *                   "material": "NAME", "position": [x,y,z],
 *                   "rotation": [rx,ry,rz] (degrees; R = Rz * Ry * Rx), "scale": 1,
 *                   "motion": {...} (optional, motion_load.h),
 *                   plane:       "size": [w,d], "segments": [n,m], "uv_scale": [su,sv]
 *                   box:         "size": [w,h,d]
 *                   sphere:      "radius": r, "segments": 16, "rings": 8
 *                   heightfield: "image": "file.png", "size": [w,d], "height": h,
 *                                "uv_scale": [su,sv]
 *                   mesh:        "file": "file.obj" } ] }
 * Numbers become Q16.16 (rounded), so every one must satisfy |v| < 32768. Asset
 * paths are relative to the scene file's directory. Errors name the file and the
 * field path, e.g. "pond.json: objects[2].radius: expected a number, got string". */
#ifndef TARN_HOST_SCENE_LOAD_H
#define TARN_HOST_SCENE_LOAD_H

#include <stddef.h>
#include <stdint.h>
#include "error.h"
#include "mesh_gen.h"
#include "png_io.h"
#include "scene_budget.h"
#include "tarn/tarn_motion.h"
#include "tarn/tarn_scene.h"
#include "tarn/tarn_water.h"

typedef struct tarn_loaded_scene {
    tarn_scene scene;       /* views the storage below */
    char name[64];          /* the file's stem: "pond" for scenes/pond.json */
    uint16_t width, height; /* default frame size ("frame"), 240x240 if not given */

    /* Owned storage. Objects, and their meshes, in file order; materials in file
     * order with their names, and waters[k] for materials[k] when it has a "water"
     * block; textures once per distinct image file. */
    tarn_object *objects;
    tarn_mesh_buffer *meshes; /* meshes[i] is objects[i]'s */
    size_t object_count;
    tarn_material *materials;
    char **material_names;
    tarn_water *waters;
    size_t material_count;
    tarn_underwater underwater; /* scene.underwater points here when the file has one */
    tarn_camera_path camera_path;   /* scene.camera_path points here when the camera moves */
    tarn_light_motion light_motion; /* scene.light_motion, when the light moves */
    tarn_object_motion *motions;    /* motions[i] for objects[i], which points to it if it moves */
    tarn_texture *textures;     /* fixed capacity: materials point into it as it fills */
    tarn_image *texture_images;
    char **texture_paths; /* as resolved against the scene's directory */
    size_t texture_count, texture_capacity;
    tarn_scene_cost cost; /* what it holds, weighed against the limits as it loads
                             (scene_budget.h) */
} tarn_loaded_scene;

/* The largest scene file the loader parses (meshes and images are files of their
 * own): the scenes of scenes/ take 3 KB; a file this large is not a scene, and
 * parsing it whole would take memory in proportion. Checked before it is read. */
#define TARN_SCENE_FILE_BYTES_MAX (4u * 1024u * 1024u)

/* 0, or -1 with `err` set and `out` left empty (nothing to free). A scene file, and
 * every file it names, must be a regular file (input_file.h), and the scene must stay
 * within the limits of scene_budget.h. */
int tarn_scene_load(const char *path, tarn_loaded_scene *out, tarn_error *err);

/* Frees everything the scene owns; safe on an emptied or zeroed scene. */
void tarn_scene_free(tarn_loaded_scene *s);

#endif
