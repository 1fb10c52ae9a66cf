#!/usr/bin/env python3
"""Writes scenes/effects/*.json: one small scene per water feature, that feature alone.

    python3 scripts/gen_effect_scenes.py

Every scene is the same 120x120 pool, so that the effects compare side by side: a
sandy floor tilted from two units deep near the camera up through the surface
(a shore a third of the way from the back), a sphere floating half out of the
water, a post standing through it and a stone on the bottom. Only the water block (and, for
the underwater view, the camera) differs. The outputs are committed.
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "scenes", "effects")
ASSETS = "../assets/"

NORMAL_A = {"image": ASSETS + "water_normal_a.png", "scale": 3, "speed": [0.05, 0.02]}
NORMAL_B = {"image": ASSETS + "water_normal_b.png", "scale": 5, "speed": [-0.03, 0.04]}

# The water block of each scene: only the named feature (albedo and alpha are the
# surface itself, not a feature; most scenes leave the surface fully clear).
EFFECTS = {
    "fog": {"fog": {"colour": "#4e83a9", "density": 0.6}},
    "absorption": {"absorption": {"colour": "#3f8a7a", "strength": 0.5, "squared": True}},
    "depth_colour": {"alpha": 0.8,
                     "depth_colour": {"shallow": "#7fe0d0", "deep": "#123a78", "scale": 2}},
    "ramp": {"alpha": 0.8,
             "depth_colour": {"scale": 2, "ramp": ASSETS + "water_ramp.png"}},
    "refraction": {"normal_maps": [NORMAL_A, NORMAL_B], "normal_strength": 0.6,
                   "refraction": 0.1},
    "normals": {"normal_maps": [NORMAL_A, NORMAL_B],
                "specular": {"intensity": 0.5, "power": 32}},
    "fresnel": {"albedo": "#2f6f9f", "fresnel": 1},
    "foam": {"foam": {"texture": ASSETS + "foam.png", "scale": 6, "speed": [0.02, 0.01],
                      "distance": 0.8, "line_speed": 0.3, "lines": 3,
                      "colour": "#ffffff", "opacity": 0.9}},
    "sparkles": {"normal_maps": [NORMAL_A, NORMAL_B], "sparkles": {"amount": 25}},
}

FRONT_LIGHT = {"direction": [0.4, 1.0, 0.3], "colour": "#fffff0", "ambient": "#404850"}
# the sun beyond the pool, so that its reflection lies in view (the specular scene)
BACK_LIGHT = {"direction": [0.2, 0.6, -1.0], "colour": "#fffff0", "ambient": "#505860"}
LIGHTS = {"normals": BACK_LIGHT}

ABOVE = {"position": [0, 3.6, 5.2], "target": [0, -0.8, -0.6], "fov": 55, "near": 0.1,
         "far": 40}
BELOW = {"position": [0, -0.9, 4.6], "target": [0, -1.1, -1], "fov": 60, "near": 0.1,
         "far": 40}
UNDERWATER = {"level": 0,
              "normal_map": {"image": ASSETS + "water_normal_a.png", "scale": 2,
                             "speed": [0.03, 0.05]},
              "distortion": 0.02, "tint": {"colour": "#1d5f7a", "density": 0.35}}


def scene(water, camera, light, underwater=None):
    materials = {
        "sand": {"colour": "#ffffff", "texture": ASSETS + "ground.png"},
        "float": {"colour": "#d0452f"},
        "post": {"colour": "#8a6a44"},
        "stone": {"colour": "#7d8a90"},
    }
    if water is not None:
        materials["water"] = {"water": water}
    objects = [
        # tilted 16 degrees about x: y = -0.6 - 0.29 z, from -2.0 in front to +0.8 at
        # the back, through the surface at z = -2.1
        {"type": "plane", "material": "sand", "size": [10, 10], "segments": [4, 4],
         "uv_scale": [3, 3], "position": [0, -0.6, 0], "rotation": [16, 0, 0]},
        {"type": "sphere", "material": "float", "radius": 0.55, "segments": 16, "rings": 10,
         "position": [1.3, 0, 0.6]},
        {"type": "box", "material": "post", "size": [0.3, 3, 0.3], "position": [-1.4, 0, 0.2]},
        {"type": "box", "material": "stone", "size": [0.8, 0.6, 0.8], "position": [0.2, -1.2, 2],
         "rotation": [0, 30, 0]},
    ]
    if water is not None:
        # subdivided: a single quad's corners lie far off screen, and the whole
        # surface's texture coordinates would hang on those clipped vertices
        objects.append({"type": "plane", "material": "water", "size": [10, 10], "segments": [8, 8],
                        "position": [0, 0, 0]})
    out = {"frame": {"width": 120, "height": 120}, "background": "#87ceeb", "camera": camera,
           "light": light, "materials": materials}
    if underwater is not None:
        out["underwater"] = underwater
    out["objects"] = objects
    return out


def write(name, data):
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, water in EFFECTS.items():
        write(name, scene(water, ABOVE, LIGHTS.get(name, FRONT_LIGHT)))
    # the camera under the surface, which hides the surface itself (its back face)
    write("underwater", scene(None, BELOW, FRONT_LIGHT, UNDERWATER))
    # the same pool with no water at all: the baseline the effects' costs are read
    # against, and the proof that a scene without water does no water work
    write("none", scene(None, ABOVE, FRONT_LIGHT))


if __name__ == "__main__":
    main()
