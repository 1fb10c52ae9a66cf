/* bad_scene_cases.h: bad scene inputs and the one-line error each must produce.
 *
 * Shared by tests/test_scene_load.c (the loader's message) and
 * tests/test_cli_bad_input.c (the CLI's exit status, stderr and lack of output).
 * Each case is a scene file "bad.json" plus up to two asset files, written into a
 * fresh directory; the error must contain "<dir>/<file><expect>": the file's full
 * path as the loader saw it, then the line or field and what was expected. */
#ifndef TARN_TESTS_BAD_SCENE_CASES_H
#define TARN_TESTS_BAD_SCENE_CASES_H

#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "png_io.h"

typedef enum {
    BAD_TEXT = 0,      /* `text` as is */
    BAD_PNG,           /* a valid width x height RGB PNG */
    BAD_PNG_TRUNCATED, /* the same, cut off half way */
    BAD_PNG_HEADER,    /* a PNG whose header claims width x height (0 or 65535 too), with an
                          empty IDAT: the size must be refused before anything is
                          allocated for the pixels */
    BAD_DEEP_JSON,     /* `width` nested arrays */
    BAD_SYMLINK,       /* a symbolic link to `text` */
    BAD_OVERSIZED,     /* a file of `width` MB (zeros, sparse) */
    BAD_DIRECTORY      /* a directory where a file should be */
} bad_file_kind;

typedef struct {
    const char *name; /* NULL: no file */
    bad_file_kind kind;
    const char *text;
    uint16_t width, height;
} bad_file;

typedef struct {
    const char *what;
    const char *scene; /* bad.json's contents; NULL: no bad.json at all */
    bad_file assets[2];
    const char *file;   /* the file the message names */
    const char *expect; /* what follows that file's path in the message */
} bad_scene_case;

#define BAD_CAMERA "\"camera\": {\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60}"
#define BAD_MATERIALS "\"materials\": {\"m\": {}}"
#define BAD_SCENE_WITH(objects) "{" BAD_CAMERA ", " BAD_MATERIALS ", \"objects\": [" objects "]}"
#define BAD_OBJECT(fields) "{\"material\": \"m\", " fields "}"
#define BAD_CAMERA_SCENE(camera) \
    "{\"camera\": {" camera "}, " BAD_MATERIALS ", \"objects\": []}"
#define BAD_MESH_SCENE BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"mesh\", \"file\": \"leaf.obj\""))
#define BAD_TEXTURE_SCENE \
    "{" BAD_CAMERA ", \"materials\": {\"m\": {\"texture\": \"tex.png\"}}, \"objects\": []}"
#define BAD_HEIGHTFIELD_SCENE                                                               \
    BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"heightfield\", \"image\": \"pit.png\", "         \
                              "\"size\": [4, 4], \"height\": 1"))
#define BAD_OBJ(text) { { "leaf.obj", BAD_TEXT, text, 0, 0 } }
#define BAD_QUAD "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
#define BAD_V_COUNT "'v' needs 3 numbers (x y z) or 6 (x y z r g b)"
/* A material "m" with a water block, and the message's field path up to it. */
#define BAD_WATER_SCENE(water) \
    "{" BAD_CAMERA ", \"materials\": {\"m\": {\"water\": {" water "}}}, \"objects\": []}"
#define BAD_WATER ": materials.m.water"
#define BAD_NORMALS "\"normal_maps\": [{\"image\": \"n.png\"}]"
#define BAD_NORMAL_PNG { { "n.png", BAD_PNG, NULL, 4, 4 } }
#define BAD_FOAM(fields) "\"foam\": {\"texture\": \"n.png\", \"distance\": 1, " fields "}"
#define BAD_UNDERWATER_SCENE(underwater) \
    "{" BAD_CAMERA ", " BAD_MATERIALS ", \"underwater\": {" underwater "}, \"objects\": []}"
#define BAD_MAPS_EXPECTED \
    "expected an array of 1 or 2 normal maps {\"image\", \"scale\", \"speed\"}"
#define BAD_UNDERWATER_MAP "\"normal_map\": {\"image\": \"n.png\"}"

static const bad_scene_case BAD_SCENE_CASES[] = {
    /* JSON syntax: jansson's text, at line:column */
    { "syntax error", "{\n  \"camera\": {\n    \"fov\": 60,,\n", { { 0 } }, "bad.json",
      ":3:15: string or '}' expected near ','" },
    { "duplicate key", "{\"camera\": {}, \"camera\": {}}", { { 0 } }, "bad.json",
      ":1:23: duplicate object key near '\"camera\"'" },
    { "empty file", "", { { 0 } }, "bad.json", ":1:0: '[' or '{' expected near end of file" },
    { "no scene file", NULL, { { 0 } }, "bad.json", ": cannot open: No such file or directory" },
    { "top level array", "[1, 2]", { { 0 } }, "bad.json",
      ": expected a JSON object at the top level, got array" },
    /* fields */
    { "unknown top-level field", "{\"cameras\": {}}", { { 0 } }, "bad.json",
      ": cameras: unknown field (expected frame, background, camera, light, materials, "
      "underwater, objects)" },
    { "control character in a field name", "{\"fo\\no\": 1}", { { 0 } }, "bad.json",
      ": fo\\x0ao: unknown field (expected frame, background, camera, light, materials, underwater, "
      "objects)" },
    { "unknown camera field", BAD_CAMERA_SCENE("\"fob\": 1"), { { 0 } }, "bad.json",
      ": camera.fob: unknown field (expected position, target, fov, near, far, path)" },
    { "field of another object type",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"sphere\", \"radius\": 1, \"size\": [1, 1, 1]")),
      { { 0 } }, "bad.json",
      ": objects[0].size: unknown field for a sphere (expected type, material, position, "
      "rotation, scale, motion, radius, segments, rings)" },
    { "wrong type", BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"size\": [1, 1, 1]") ", "
                                   BAD_OBJECT("\"type\": \"sphere\", \"radius\": \"big\"")),
      { { 0 } }, "bad.json", ": objects[1].radius: expected a number, got string" },
    { "missing fov", BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"target\": [0, 0, 0]"),
      { { 0 } }, "bad.json", ": camera.fov: missing (expected a number of degrees, 1..179)" },
    { "fov out of range",
      BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 180"),
      { { 0 } }, "bad.json", ": camera.fov: expected a number of degrees, 1..179, got 180" },
    { "near zero",
      BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60, \"near\": 0"),
      { { 0 } }, "bad.json", ": camera.near: expected a number > 0 and < 32768, got 0" },
    { "near below Q16.16",
      BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60, "
                       "\"near\": 0.000001"),
      { { 0 } }, "bad.json",
      ": camera.near: expected a number > 0 and < 32768, got 1e-06 (0 in Q16.16)" },
    { "far before near",
      BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"target\": [0, 0, 0], \"fov\": 60, "
                       "\"near\": 5, \"far\": 2"),
      { { 0 } }, "bad.json", ": camera.far: expected a number greater than camera.near (5), got 2" },
    { "coordinate too large",
      BAD_CAMERA_SCENE("\"position\": [0, 40000, 6], \"target\": [0, 0, 0], \"fov\": 60"),
      { { 0 } }, "bad.json",
      ": camera.position[1]: expected a number, -32768 < v < 32768, got 40000" },
    { "vector too short", BAD_CAMERA_SCENE("\"position\": [0, 2], \"target\": [0, 0, 0], \"fov\": 60"),
      { { 0 } }, "bad.json", ": camera.position: expected an array of 3 numbers, got 2" },
    { "camera on its target",
      BAD_CAMERA_SCENE("\"position\": [1, 2, 3], \"target\": [1, 2, 3], \"fov\": 60"),
      { { 0 } }, "bad.json", ": camera.target: must differ from camera.position" },
    /* motion (host/scene/motion_load.c) */
    { "orbit and keys", BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"orbit\": {\"centre\": [0, 0, 0], "
                                         "\"radius\": 5, \"period\": 8000}, \"keys\": []}"),
      { { 0 } }, "bad.json", ": camera.path: expected either \"orbit\" or \"keys\", not both" },
    { "path with a position", BAD_CAMERA_SCENE("\"position\": [0, 2, 6], \"fov\": 60, \"path\": {\"orbit\": "
                                               "{\"centre\": [0, 0, 0], \"radius\": 5, \"period\": 8000}}"),
      { { 0 } }, "bad.json", ": camera.position: not with camera.path, which places the camera" },
    { "orbit period not whole", BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"orbit\": {\"centre\": [0, 0, 0], "
                                                 "\"radius\": 5, \"period\": 80.5}}"),
      { { 0 } }, "bad.json",
      ": camera.path.orbit.period: expected a whole number of milliseconds, 1..2147483647, got 80.5" },
    { "orbit without radius", BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"orbit\": {\"centre\": [0, 0, 0], "
                                               "\"period\": 8000}}"),
      { { 0 } }, "bad.json", ": camera.path.orbit.radius: missing (expected a number > 0 and < 32768)" },
    { "orbit target on the orbit",
      BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"orbit\": {\"centre\": [0, 0, 0], \"radius\": 5, "
                       "\"period\": 8000, \"target\": [5, 0, 0]}}"),
      { { 0 } }, "bad.json", ": camera.path.orbit.target: lies on the orbit, where the camera would stand on it" },
    { "orbit direction", BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"orbit\": {\"centre\": [0, 0, 0], "
                                          "\"radius\": 5, \"period\": 8000, \"direction\": \"left\"}}"),
      { { 0 } }, "bad.json", ": camera.path.orbit.direction: expected \"counterclockwise\" or \"clockwise\", got \"left\"" },
    { "keys out of order",
      BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"keys\": [{\"time\": 500, \"position\": [0, 2, 6], \"target\": [0, 0, 0]}, "
                       "{\"time\": 500, \"position\": [0, 3, 6], \"target\": [0, 0, 0]}]}"),
      { { 0 } }, "bad.json", ": camera.path.keys[1].time: expected a time after the key before's (500 ms), got 500" },
    { "loop before the last key",
      BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"keys\": [{\"time\": 0, \"position\": [0, 2, 6], \"target\": [0, 0, 0]}, "
                       "{\"time\": 900, \"position\": [0, 3, 6], \"target\": [0, 0, 0]}], \"loop\": 900}"),
      { { 0 } }, "bad.json", ": camera.path.loop: expected a period after the last key's time (900 ms), got 900" },
    { "fov in some keys",
      BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"keys\": [{\"time\": 0, \"position\": [0, 2, 6], \"target\": [0, 0, 0], "
                       "\"fov\": 50}, {\"time\": 900, \"position\": [0, 3, 6], \"target\": [0, 0, 0]}]}"),
      { { 0 } }, "bad.json", ": camera.path.keys[1]: lacks \"fov\": give it in every key or in none" },
    { "key target at its position",
      BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"keys\": [{\"time\": 0, \"position\": [0, 2, 6], \"target\": [0, 2, 6]}]}"),
      { { 0 } }, "bad.json", ": camera.path.keys[0].target: must differ from the key's position" },
    { "no keys", BAD_CAMERA_SCENE("\"fov\": 60, \"path\": {\"keys\": []}"),
      { { 0 } }, "bad.json", ": camera.path.keys: expected an array of 1..256 keys, got none" },
    { "bob without axis", BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"motion\": {\"bob\": {\"amplitude\": 1, \"period\": 900}}")),
      { { 0 } }, "bad.json", ": objects[0].motion.bob.axis: missing (expected an array of 3 numbers)" },
    { "spin about nothing",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"motion\": {\"spin\": {\"axis\": [0, 0, 0], \"period\": 900}}")),
      { { 0 } }, "bad.json", ": objects[0].motion.spin.axis: expected a non-zero vector, got [0, 0, 0]" },
    { "unknown motion", BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"motion\": {\"wobble\": {}}")),
      { { 0 } }, "bad.json", ": objects[0].motion.wobble: unknown field (expected bob, spin, path)" },
    { "light spin period zero",
      "{" BAD_CAMERA ", \"light\": {\"motion\": {\"spin\": {\"axis\": [0, 1, 0], \"period\": 0}}}, " BAD_MATERIALS
      ", \"objects\": []}",
      { { 0 } }, "bad.json", ": light.motion.spin.period: expected a whole number of milliseconds, 1..2147483647, got 0" },
    { "bad colour", "{\"background\": \"#12345\"}", { { 0 } }, "bad.json",
      ": background: expected a colour \"#rrggbb\", got \"#12345\"" },
    { "colour not a string", "{\"background\": 255}", { { 0 } }, "bad.json",
      ": background: expected a colour \"#rrggbb\", got number" },
    { "frame too wide", "{\"frame\": {\"width\": 2000}}", { { 0 } }, "bad.json",
      ": frame.width: expected an integer 1..1024, got 2000" },
    { "zero light direction",
      "{" BAD_CAMERA ", \"light\": {\"direction\": [0, 0, 0]}, " BAD_MATERIALS ", \"objects\": []}",
      { { 0 } }, "bad.json", ": light.direction: expected a non-zero vector, got [0, 0, 0]" },
    { "bad cull", "{" BAD_CAMERA ", \"materials\": {\"m\": {\"cull\": \"both\"}}, \"objects\": []}",
      { { 0 } }, "bad.json",
      ": materials.m.cull: expected one of \"back\", \"none\", \"front\", got \"both\"" },
    { "bad unlit", "{" BAD_CAMERA ", \"materials\": {\"m\": {\"unlit\": \"yes\"}}, \"objects\": []}",
      { { 0 } }, "bad.json", ": materials.m.unlit: expected true or false, got string" },
    { "material not an object", "{" BAD_CAMERA ", \"materials\": {\"m\": 3}, \"objects\": []}",
      { { 0 } }, "bad.json",
      ": materials.m: expected an object {\"colour\", \"texture\", \"cull\", \"unlit\", "
      "\"water\"}, got number" },
    { "missing objects", "{" BAD_CAMERA ", " BAD_MATERIALS "}", { { 0 } }, "bad.json",
      ": objects: missing (expected an array of objects)" },
    { "unknown material",
      BAD_SCENE_WITH("{\"type\": \"box\", \"material\": \"lava\", \"size\": [1, 1, 1]}"),
      { { 0 } }, "bad.json", ": objects[0].material: no material named \"lava\" in materials" },
    { "unknown object type", BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"cone\"")), { { 0 } },
      "bad.json",
      ": objects[0].type: expected one of \"plane\", \"box\", \"sphere\", \"heightfield\", "
      "\"mesh\", got \"cone\"" },
    { "zero segments",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"plane\", \"size\": [1, 1], \"segments\": [0, 1]")),
      { { 0 } }, "bad.json", ": objects[0].segments[0]: expected an integer 1..256, got 0" },
    { "fractional segments",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"sphere\", \"radius\": 1, \"segments\": 2.5")),
      { { 0 } }, "bad.json", ": objects[0].segments: expected an integer 3..256, got 2.5" },
    { "zero scale",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"size\": [1, 1, 1], \"scale\": 0")),
      { { 0 } }, "bad.json", ": objects[0].scale: expected a number > 0 and < 32768, got 0" },
    { "sphere over the vertex limit",
      BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"sphere\", \"radius\": 1, \"segments\": 256, "
                                "\"rings\": 256")),
      { { 0 } }, "bad.json", ": objects[0]: needs 66049 vertices; a tarn mesh holds at most 65535" },
    /* textures and heightfields */
    { "texture not a power of two", BAD_TEXTURE_SCENE, { { "tex.png", BAD_PNG, NULL, 300, 200 } },
      "tex.png", ": texture is 300x200; expected power-of-two sides up to 1024" },
    { "texture not a PNG", BAD_TEXTURE_SCENE, { { "tex.png", BAD_TEXT, "GIF89a...", 0, 0 } },
      "tex.png", ": not a PNG file" },
    { "texture truncated", BAD_TEXTURE_SCENE,
      { { "tex.png", BAD_PNG_TRUNCATED, NULL, 64, 64 } }, "tex.png",
      ": bad PNG: file is truncated" },
    { "texture missing", BAD_TEXTURE_SCENE, { { 0 } }, "tex.png",
      ": cannot open: No such file or directory" },
    { "heightfield too large", BAD_HEIGHTFIELD_SCENE, { { "pit.png", BAD_PNG, NULL, 300, 300 } },
      "pit.png", ": heightfield image is 300x300; expected sides 2..256" },
    { "heightfield over the triangle limit", BAD_HEIGHTFIELD_SCENE,
      { { "pit.png", BAD_PNG, NULL, 200, 200 } }, "pit.png",
      ": heightfield image is 200x200, whose grid needs 79202 triangles; a tarn mesh holds at most 65535 "
      "(a square image up to 182x182)" },
    { "heightfield one past the triangle limit", BAD_HEIGHTFIELD_SCENE,
      { { "pit.png", BAD_PNG, NULL, 183, 183 } }, "pit.png",
      ": heightfield image is 183x183, whose grid needs 66248 triangles; a tarn mesh holds at most 65535 "
      "(a square image up to 182x182)" },
    /* a triangle spanning more texels than the core interpolates precisely enough */
    { "texture spanned too far",
      "{" BAD_CAMERA ", \"materials\": {\"m\": {\"texture\": \"tex.png\"}}, \"objects\": ["
      BAD_OBJECT("\"type\": \"plane\", \"size\": [4, 4], \"uv_scale\": [65, 1]") "]}",
      { { "tex.png", BAD_PNG, NULL, 64, 64 } }, "bad.json",
      ": objects[0].uv_scale: a triangle of objects[0] spans 4160 texels of its texture; the core interpolates "
      "at most 4096 precisely enough (use smaller triangles or a smaller scale)" },
    { "normal map scaled too far",
      "{" BAD_CAMERA ", \"materials\": {\"m\": {\"water\": {\"normal_maps\": [{\"image\": \"n.png\", "
      "\"scale\": 1025}]}}}, \"objects\": [" BAD_OBJECT("\"type\": \"plane\", \"size\": [4, 4]") "]}",
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".normal_maps[0].scale: a triangle of objects[0] spans 4100 texels of the map; the core "
      "interpolates at most 4096 precisely enough (use smaller triangles or a smaller scale)" },
    /* water: each feature's block, its ranges and its files */
    { "water not an object",
      "{" BAD_CAMERA ", \"materials\": {\"m\": {\"water\": 3}}, \"objects\": []}", { { 0 } },
      "bad.json", BAD_WATER ": expected an object of water features {\"fog\", \"refraction\"...}, "
      "got number" },
    { "unknown water field", BAD_WATER_SCENE("\"fgo\": {}"), { { 0 } }, "bad.json",
      BAD_WATER ".fgo: unknown field (expected albedo, alpha, normal_strength, fog, absorption, "
      "depth_colour, normal_maps, refraction, fresnel, specular, foam, sparkles)" },
    { "bad albedo", BAD_WATER_SCENE("\"albedo\": \"blue\""), { { 0 } }, "bad.json",
      BAD_WATER ".albedo: expected a colour \"#rrggbb\", got \"blue\"" },
    { "alpha above 1", BAD_WATER_SCENE("\"alpha\": 1.5"), { { 0 } }, "bad.json",
      BAD_WATER ".alpha: expected a number 0..1, got 1.5" },
    { "fog not an object", BAD_WATER_SCENE("\"fog\": 0.5"), { { 0 } }, "bad.json",
      BAD_WATER ".fog: expected an object {\"colour\", \"density\"}, got number" },
    { "negative fog density",
      BAD_WATER_SCENE("\"fog\": {\"colour\": \"#4e83a9\", \"density\": -1}"), { { 0 } },
      "bad.json", BAD_WATER ".fog.density: expected a number 0..64, got -1" },
    { "fog without colour", BAD_WATER_SCENE("\"fog\": {\"density\": 1}"), { { 0 } }, "bad.json",
      BAD_WATER ".fog.colour: missing (expected a colour \"#rrggbb\")" },
    { "unknown fog field", BAD_WATER_SCENE("\"fog\": {\"color\": \"#000000\", \"density\": 1}"),
      { { 0 } }, "bad.json", BAD_WATER ".fog.color: unknown field (expected colour, density)" },
    { "absorption without strength", BAD_WATER_SCENE("\"absorption\": {\"colour\": \"#808080\"}"),
      { { 0 } }, "bad.json", BAD_WATER ".absorption.strength: missing (expected a number 0..64)" },
    { "absorption strength above 64",
      BAD_WATER_SCENE("\"absorption\": {\"colour\": \"#808080\", \"strength\": 65}"), { { 0 } },
      "bad.json", BAD_WATER ".absorption.strength: expected a number 0..64, got 65" },
    { "absorption squared not a boolean",
      BAD_WATER_SCENE("\"absorption\": {\"colour\": \"#808080\", \"strength\": 1, \"squared\": 2}"),
      { { 0 } }, "bad.json", BAD_WATER ".absorption.squared: expected true or false, got number" },
    { "depth colour scale zero",
      BAD_WATER_SCENE("\"depth_colour\": {\"shallow\": \"#00ffff\", \"deep\": \"#000080\", "
                      "\"scale\": 0}"),
      { { 0 } }, "bad.json",
      BAD_WATER ".depth_colour.scale: expected a number > 0 and < 32768, got 0" },
    { "depth colour without deep",
      BAD_WATER_SCENE("\"depth_colour\": {\"shallow\": \"#00ffff\", \"scale\": 1}"), { { 0 } },
      "bad.json", BAD_WATER ".depth_colour.deep: missing (expected a colour \"#rrggbb\")" },
    { "ramp missing", BAD_WATER_SCENE("\"depth_colour\": {\"scale\": 1, \"ramp\": \"ramp.png\"}"),
      { { 0 } }, "ramp.png", ": cannot open: No such file or directory" },
    { "ramp not a power of two",
      BAD_WATER_SCENE("\"depth_colour\": {\"scale\": 1, \"ramp\": \"ramp.png\"}"),
      { { "ramp.png", BAD_PNG, NULL, 30, 1 } }, "ramp.png",
      ": texture is 30x1; expected power-of-two sides up to 1024" },
    { "normal maps not an array", BAD_WATER_SCENE("\"normal_maps\": {\"image\": \"n.png\"}"),
      { { 0 } }, "bad.json", BAD_WATER ".normal_maps: " BAD_MAPS_EXPECTED ", got object" },
    { "three normal maps", BAD_WATER_SCENE("\"normal_maps\": [{}, {}, {}]"), { { 0 } },
      "bad.json", BAD_WATER ".normal_maps: " BAD_MAPS_EXPECTED ", got 3" },
    { "no normal maps", BAD_WATER_SCENE("\"normal_maps\": []"), { { 0 } }, "bad.json",
      BAD_WATER ".normal_maps: " BAD_MAPS_EXPECTED ", got 0" },
    { "normal map not an object", BAD_WATER_SCENE("\"normal_maps\": [\"n.png\"]"), { { 0 } },
      "bad.json",
      BAD_WATER ".normal_maps[0]: expected an object {\"image\", \"scale\", \"speed\"}, "
      "got string" },
    { "normal map without image", BAD_WATER_SCENE("\"normal_maps\": [{\"scale\": 2}]"), { { 0 } },
      "bad.json", BAD_WATER ".normal_maps[0].image: missing (expected a PNG file name)" },
    { "normal map missing", BAD_WATER_SCENE(BAD_NORMALS), { { 0 } }, "n.png",
      ": cannot open: No such file or directory" },
    { "normal map speed above 16",
      BAD_WATER_SCENE("\"normal_maps\": [{\"image\": \"n.png\", \"speed\": [20, 0]}]"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".normal_maps[0].speed[0]: expected a number -16..16, got 20" },
    { "normal map scale zero",
      BAD_WATER_SCENE("\"normal_maps\": [{\"image\": \"n.png\", \"scale\": 0}]"), BAD_NORMAL_PNG,
      "bad.json", BAD_WATER ".normal_maps[0].scale: expected a number > 0 and < 32768, got 0" },
    { "unknown normal map field",
      BAD_WATER_SCENE("\"normal_maps\": [{\"image\": \"n.png\", \"scroll\": 1}]"), BAD_NORMAL_PNG,
      "bad.json",
      BAD_WATER ".normal_maps[0].scroll: unknown field (expected image, scale, speed)" },
    { "bad second normal map",
      BAD_WATER_SCENE("\"normal_maps\": [{\"image\": \"n.png\"}, {\"image\": \"n.png\", "
                      "\"scale\": -1}]"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".normal_maps[1].scale: expected a number > 0 and < 32768, got -1" },
    { "normal strength above 8", BAD_WATER_SCENE(BAD_NORMALS ", \"normal_strength\": 9"),
      BAD_NORMAL_PNG, "bad.json", BAD_WATER ".normal_strength: expected a number 0..8, got 9" },
    { "normal strength without normal maps", BAD_WATER_SCENE("\"normal_strength\": 1"),
      { { 0 } }, "bad.json", BAD_WATER ".normal_strength: needs normal_maps (it scales them)" },
    { "refraction without normal maps", BAD_WATER_SCENE("\"refraction\": 0.1"), { { 0 } },
      "bad.json", BAD_WATER ".refraction: needs normal_maps (the offset comes from the normals)" },
    { "refraction above 1", BAD_WATER_SCENE(BAD_NORMALS ", \"refraction\": 2"), BAD_NORMAL_PNG,
      "bad.json", BAD_WATER ".refraction: expected a number 0..1, got 2" },
    { "refraction past the apron", BAD_WATER_SCENE(BAD_NORMALS ", \"refraction\": 0.5"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".refraction: expected at most 0.1642 at width 240 (normal_xy_max 0.7863; the "
      "apron holds 32 pixels), got 0.5 (96 pixels)" },
    { "fresnel not a number", BAD_WATER_SCENE("\"fresnel\": \"high\""), { { 0 } }, "bad.json",
      BAD_WATER ".fresnel: expected a number, got string" },
    { "specular power zero", BAD_WATER_SCENE("\"specular\": {\"power\": 0}"), { { 0 } },
      "bad.json", BAD_WATER ".specular.power: expected an integer 1..256, got 0" },
    { "fractional specular power", BAD_WATER_SCENE("\"specular\": {\"power\": 2.5}"), { { 0 } },
      "bad.json", BAD_WATER ".specular.power: expected an integer 1..256, got 2.5" },
    { "specular intensity above 4", BAD_WATER_SCENE("\"specular\": {\"intensity\": 5}"),
      { { 0 } }, "bad.json", BAD_WATER ".specular.intensity: expected a number 0..4, got 5" },
    { "foam without texture", BAD_WATER_SCENE("\"foam\": {\"distance\": 1}"), { { 0 } },
      "bad.json", BAD_WATER ".foam.texture: missing (expected a PNG file name)" },
    { "foam without distance", BAD_WATER_SCENE("\"foam\": {\"texture\": \"n.png\"}"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".foam.distance: missing (expected a number > 0 and < 32768)" },
    { "foam lines above 16", BAD_WATER_SCENE(BAD_FOAM("\"lines\": 17")), BAD_NORMAL_PNG,
      "bad.json", BAD_WATER ".foam.lines: expected an integer 0..16, got 17" },
    { "foam line speed below -16", BAD_WATER_SCENE(BAD_FOAM("\"line_speed\": -17")),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".foam.line_speed: expected a number -16..16, got -17" },
    { "foam opacity above 1", BAD_WATER_SCENE(BAD_FOAM("\"opacity\": 1.01")), BAD_NORMAL_PNG,
      "bad.json", BAD_WATER ".foam.opacity: expected a number 0..1, got 1.01" },
    { "foam texture truncated", BAD_WATER_SCENE(BAD_FOAM("\"scale\": 2")),
      { { "n.png", BAD_PNG_TRUNCATED, NULL, 64, 64 } }, "n.png", ": bad PNG: file is truncated" },
    { "sparkles without normal maps", BAD_WATER_SCENE("\"sparkles\": {\"amount\": 10}"),
      { { 0 } }, "bad.json",
      BAD_WATER ".sparkles: needs normal_maps (sparkles come from the normal maps' x)" },
    { "sparkle amount zero", BAD_WATER_SCENE(BAD_NORMALS ", \"sparkles\": {\"amount\": 0}"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".sparkles.amount: expected a number > 0 and < 32768, got 0" },
    { "unknown sparkles field",
      BAD_WATER_SCENE(BAD_NORMALS ", \"sparkles\": {\"amount\": 10, \"size\": 2}"),
      BAD_NORMAL_PNG, "bad.json",
      BAD_WATER ".sparkles.size: unknown field (expected amount, colour)" },
    /* underwater */
    { "underwater not an object",
      "{" BAD_CAMERA ", " BAD_MATERIALS ", \"underwater\": true, \"objects\": []}", { { 0 } },
      "bad.json",
      ": underwater: expected an object {\"level\", \"normal_map\", \"distortion\", \"tint\"}, "
      "got boolean" },
    { "underwater without level", BAD_UNDERWATER_SCENE(BAD_UNDERWATER_MAP), BAD_NORMAL_PNG,
      "bad.json", ": underwater.level: missing (expected a number, -32768 < v < 32768)" },
    { "underwater level too high", BAD_UNDERWATER_SCENE("\"level\": 40000, " BAD_UNDERWATER_MAP),
      BAD_NORMAL_PNG, "bad.json",
      ": underwater.level: expected a number, -32768 < v < 32768, got 40000" },
    { "underwater without normal map", BAD_UNDERWATER_SCENE("\"level\": 0"), { { 0 } },
      "bad.json",
      ": underwater.normal_map: missing (expected an object {\"image\", \"scale\", \"speed\"})" },
    { "underwater normal map missing", BAD_UNDERWATER_SCENE("\"level\": 0, " BAD_UNDERWATER_MAP),
      { { 0 } }, "n.png", ": cannot open: No such file or directory" },
    { "underwater normal map speed above 16",
      BAD_UNDERWATER_SCENE("\"level\": 0, \"normal_map\": {\"image\": \"n.png\", "
                           "\"speed\": [0, 99]}"),
      BAD_NORMAL_PNG, "bad.json",
      ": underwater.normal_map.speed[1]: expected a number -16..16, got 99" },
    { "underwater distortion above 1",
      BAD_UNDERWATER_SCENE("\"level\": 0, " BAD_UNDERWATER_MAP ", \"distortion\": 1.5"),
      BAD_NORMAL_PNG, "bad.json", ": underwater.distortion: expected a number 0..1, got 1.5" },
    { "underwater tint density above 64",
      BAD_UNDERWATER_SCENE("\"level\": 0, " BAD_UNDERWATER_MAP
                           ", \"tint\": {\"colour\": \"#204060\", \"density\": 100}"),
      BAD_NORMAL_PNG, "bad.json", ": underwater.tint.density: expected a number 0..64, got 100" },
    { "underwater tint without colour",
      BAD_UNDERWATER_SCENE("\"level\": 0, " BAD_UNDERWATER_MAP ", \"tint\": {\"density\": 1}"),
      BAD_NORMAL_PNG, "bad.json",
      ": underwater.tint.colour: missing (expected a colour \"#rrggbb\")" },
    { "unknown underwater field",
      BAD_UNDERWATER_SCENE("\"level\": 0, " BAD_UNDERWATER_MAP ", \"fog\": 1"), BAD_NORMAL_PNG,
      "bad.json",
      ": underwater.fog: unknown field (expected level, normal_map, distortion, tint)" },
    /* OBJ meshes */
    { "OBJ index out of range", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "s off\nf 1 2 7\n"), "leaf.obj",
      ":6: face index 7 is out of range (1..4)" },
    { "OBJ negative index out of range", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "f -1 -2 -5\n"),
      "leaf.obj", ":5: face index -5 is out of range (-4..-1)" },
    { "OBJ texture index with no texture coordinates", BAD_MESH_SCENE,
      BAD_OBJ(BAD_QUAD "f 1/1 2/2 3/3\n"), "leaf.obj",
      ":5: face texture index 1 is out of range (no texture coordinates before this line)" },
    { "OBJ unknown statement", BAD_MESH_SCENE, BAD_OBJ("# a leaf\nxyz 1 2\n"), "leaf.obj",
      ":2: unknown statement 'xyz' (expected v, vt, vn, f, o, g, s, usemtl or mtllib)" },
    { "OBJ control character", BAD_MESH_SCENE, BAD_OBJ("x\033y 1\n"), "leaf.obj",
      ":1: unknown statement 'x?y' (expected v, vt, vn, f, o, g, s, usemtl or mtllib)" },
    { "OBJ bad number", BAD_MESH_SCENE, BAD_OBJ("v 0 abc 0\n"), "leaf.obj",
      ":1: 'abc' is not a number" },
    { "OBJ coordinate too large", BAD_MESH_SCENE, BAD_OBJ("v 0 1e6 0\n"), "leaf.obj",
      ":1: 1e6 is out of range (|v| < 32768)" },
    { "OBJ too few coordinates", BAD_MESH_SCENE, BAD_OBJ("v 0 1\n"), "leaf.obj",
      ":1: " BAD_V_COUNT },
    { "OBJ homogeneous w", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 1\n"), "leaf.obj",
      ":5: " BAD_V_COUNT },
    { "OBJ colour missing b", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 1 1\n"), "leaf.obj",
      ":5: " BAD_V_COUNT },
    { "OBJ colour with alpha", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 1 1 1 1\n"),
      "leaf.obj", ":5: " BAD_V_COUNT },
    { "OBJ colour above 1", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 0.5 1.5 0\n"),
      "leaf.obj", ":5: colour component 1.5 is out of range (0..1)" },
    { "OBJ negative colour", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 0 0 -0.1\n"),
      "leaf.obj", ":5: colour component -0.1 is out of range (0..1)" },
    { "OBJ NaN colour", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 nan 0 0\n"), "leaf.obj",
      ":5: colour component nan is out of range (0..1)" },
    { "OBJ infinite colour", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "v 0 0 0 0 inf 0\n"), "leaf.obj",
      ":5: colour component inf is out of range (0..1)" },
    { "OBJ two-corner face", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "f 1 2\n"), "leaf.obj",
      ":5: a face needs at least 3 corners" },
    { "OBJ bad corner", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD "f 1 2 3/1/1/1\n"), "leaf.obj",
      ":5: bad face corner; expected v, v/vt, v//vn or v/vt/vn" },
    { "OBJ without faces", BAD_MESH_SCENE, BAD_OBJ(BAD_QUAD), "leaf.obj",
      ": no faces; a mesh needs at least one" },
    /* hostile input: what an attacker or a broken tool would write */
    { "JSON nested 60000 deep", NULL, { { "bad.json", BAD_DEEP_JSON, NULL, 60000, 0 } }, "bad.json",
      ":1:2049: maximum parsing depth reached near '['" },
    { "coordinate 1e308", BAD_CAMERA_SCENE("\"position\": [1e308, 2, 6], \"target\": [0, 0, 0], \"fov\": 60"),
      { { 0 } }, "bad.json", ": camera.position[0]: expected a number, -32768 < v < 32768, got 1e+308" },
    { "coordinate -1e308", BAD_CAMERA_SCENE("\"position\": [0, -1e308, 6], \"target\": [0, 0, 0], \"fov\": 60"),
      { { 0 } }, "bad.json", ": camera.position[1]: expected a number, -32768 < v < 32768, got -1e+308" },
    { "negative size", BAD_SCENE_WITH(BAD_OBJECT("\"type\": \"box\", \"size\": [-1, 1, 1]")), { { 0 } },
      "bad.json", ": objects[0].size[0]: expected a number > 0 and < 32768, got -1" },
    { "texture 65535x65535", BAD_TEXTURE_SCENE, { { "tex.png", BAD_PNG_HEADER, NULL, 65535, 65535 } }, "tex.png",
      ": texture is 65535x65535; expected power-of-two sides up to 1024" },
    { "texture 0x0", BAD_TEXTURE_SCENE, { { "tex.png", BAD_PNG_HEADER, NULL, 0, 0 } }, "tex.png", ": bad PNG: Invalid IHDR data" },
    { "heightfield 65535x65535", BAD_HEIGHTFIELD_SCENE, { { "pit.png", BAD_PNG_HEADER, NULL, 65535, 65535 } },
      "pit.png", ": heightfield image is 65535x65535; expected sides 2..256" },
    { "texture a directory", BAD_TEXTURE_SCENE, { { "tex.png", BAD_DIRECTORY, NULL, 0, 0 } }, "tex.png",
      ": is a directory; a PNG file must be a regular file" },
    { "texture name with a newline",
      "{" BAD_CAMERA ", \"materials\": {\"m\": {\"texture\": \"water\\nmap.png\"}}, \"objects\": []}", { { 0 } },
      "water\\x0amap.png", ": cannot open: No such file or directory" },
    { "texture a dangling link", BAD_TEXTURE_SCENE, { { "tex.png", BAD_SYMLINK, "nowhere.png", 0, 0 } },
      "tex.png", ": cannot open: No such file or directory" },
    { "scene file of 5 MB", NULL, { { "bad.json", BAD_OVERSIZED, NULL, 5, 0 } }, "bad.json",
      ": is 5242880 bytes; a scene file holds at most 4194304" },
    { "mesh file of 65 MB", BAD_MESH_SCENE, { { "leaf.obj", BAD_OVERSIZED, NULL, 65, 0 } }, "leaf.obj",
      ": is 68157440 bytes; an OBJ file holds at most 67108864" },
    { "texture file of 65 MB", BAD_TEXTURE_SCENE, { { "tex.png", BAD_OVERSIZED, NULL, 65, 0 } }, "tex.png",
      ": is 68157440 bytes; a PNG file holds at most 67108864" },
    { "scene a directory", NULL, { { "bad.json", BAD_DIRECTORY, NULL, 0, 0 } }, "bad.json",
      ": is a directory; a scene file must be a regular file" },
    { "mesh a link to itself", BAD_MESH_SCENE, { { "leaf.obj", BAD_SYMLINK, "leaf.obj", 0, 0 } }, "leaf.obj",
      ": cannot open: Too many levels of symbolic links" },
};

#define BAD_SCENE_CASE_COUNT (sizeof BAD_SCENE_CASES / sizeof BAD_SCENE_CASES[0])

static inline void bad_put_u32_be(uint8_t *out, uint32_t v)
{
    out[0] = (uint8_t)(v >> 24);
    out[1] = (uint8_t)(v >> 16);
    out[2] = (uint8_t)(v >> 8);
    out[3] = (uint8_t)v;
}

/* A chunk of no data: length, type, CRC. */
static inline void bad_put_empty_chunk(uint8_t *out, const char *type)
{
    bad_put_u32_be(out, 0);
    memcpy(out + 4, type, 4);
    bad_put_u32_be(out + 8, (uint32_t)crc32(0, out + 4, 4));
}

/* The PNG signature, an IHDR chunk claiming width x height RGB8, an empty IDAT and
 * IEND. */
static inline int bad_write_png_header(const char *path, uint32_t width, uint32_t height)
{
    uint8_t png[8 + 25 + 12 + 12] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    uint8_t *ihdr = png + 8;
    bad_put_u32_be(ihdr, 13);
    memcpy(ihdr + 4, "IHDR", 4);
    bad_put_u32_be(ihdr + 8, width);
    bad_put_u32_be(ihdr + 12, height);
    ihdr[16] = 8; /* bit depth */
    ihdr[17] = 2; /* RGB */
    bad_put_u32_be(ihdr + 21, (uint32_t)crc32(0, ihdr + 4, 17));
    bad_put_empty_chunk(ihdr + 25, "IDAT");
    bad_put_empty_chunk(ihdr + 37, "IEND");
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    int ok = fwrite(png, 1, sizeof png, f) == sizeof png;
    return (fclose(f) == 0 && ok) ? 0 : -1;
}

static inline int bad_write_deep_json(const char *path, unsigned depth)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    for (unsigned k = 0; k < depth; k++) fputc('[', f);
    for (unsigned k = 0; k < depth; k++) fputc(']', f);
    return fclose(f);
}

static inline int bad_write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    size_t length = strlen(text);
    int ok = fwrite(text, 1, length, f) == length;
    return (fclose(f) == 0 && ok) ? 0 : -1;
}

static inline int bad_write_file(const char *dir, const bad_file *file)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file->name);
    if (file->kind == BAD_TEXT) return bad_write_text(path, file->text);
    if (file->kind == BAD_PNG_HEADER) return bad_write_png_header(path, file->width, file->height);
    if (file->kind == BAD_DEEP_JSON) return bad_write_deep_json(path, file->width);
    if (file->kind == BAD_SYMLINK) return symlink(file->text, path);
    if (file->kind == BAD_OVERSIZED) /* sparse: no disk is spent on it */
        return bad_write_text(path, "") != 0 ? -1 : truncate(path, (off_t)file->width << 20);
    if (file->kind == BAD_DIRECTORY) return mkdir(path, 0700);
    size_t bytes = (size_t)file->width * file->height * 3;
    uint8_t *rgb = malloc(bytes);
    if (!rgb) return -1;
    for (size_t k = 0; k < bytes; k++) rgb[k] = (uint8_t)(k * 7 % 251); /* noise, so it compresses badly */
    tarn_error err;
    int result = tarn_png_write_rgb(path, rgb, file->width, file->height, &err);
    free(rgb);
    if (result == 0 && file->kind == BAD_PNG_TRUNCATED) {
        FILE *f = fopen(path, "rb");
        long size = -1;
        if (f && fseek(f, 0, SEEK_END) == 0) size = ftell(f);
        if (f) fclose(f);
        result = size > 0 ? truncate(path, size / 2) : -1;
    }
    return result;
}

/* Writes the case's files into `dir`; scene_path receives bad.json's path. */
static inline int bad_case_write(const bad_scene_case *c, const char *dir, char *scene_path,
                                 size_t size)
{
    snprintf(scene_path, size, "%s/bad.json", dir);
    if (c->scene && bad_write_text(scene_path, c->scene)) return -1;
    for (size_t k = 0; k < sizeof c->assets / sizeof c->assets[0]; k++) {
        if (c->assets[k].name && bad_write_file(dir, &c->assets[k])) return -1;
    }
    return 0;
}

/* Removes the files in `dir` (the case's, and anything a failing run left), then it. */
static inline void bad_case_remove_dir(const char *dir)
{
    DIR *d = opendir(dir);
    for (struct dirent *e; d && (e = readdir(d)) != NULL;) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (unlink(path) != 0) rmdir(path); /* a case's directory */
    }
    if (d) closedir(d);
    rmdir(dir);
}

#endif
