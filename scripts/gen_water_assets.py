#!/usr/bin/env python3
"""Generates the water textures of the water scenes into scenes/assets/.

    python3 scripts/gen_water_assets.py

Like gen_pond_assets.py (whose PNG writer and hash it reuses): deterministic,
standard library only, outputs committed.

  water_normal_a.png  64x64 tangent-space normal map of broad swells (gradient noise,
                      4 and 8 cells across); RGB = (n * 0.5 + 0.5) * 255, x along u
                      (columns), y along v (rows, downward), z up.
  water_normal_b.png  64x64, the same from finer ripples (8 and 16 cells across).
  foam.png            64x64 gray noise (R = G = B; the core reads red), values spread
                      over 0..255 so a foam threshold anywhere in 0..1 finds texels.
  water_ramp.png      32x1 colour ramp: shallow turquoise to deep blue.

All three noises tile: the lattice wraps with the texture, and slopes are taken
with wrap-around finite differences, so no seam shows when a map repeats.
"""
import math
import os

from gen_pond_assets import OUT, hash01, smoothstep, write_png

SIZE = 64


def fade(t):
    return t * t * t * (t * (t * 6 - 15) + 10)


def gradient_noise(x, y, cells, seed):
    """Perlin-style gradient noise over [0, 1)^2 with `cells` lattice cells per side,
    wrapping at 1. Returns roughly -0.7..0.7."""
    gx, gy = x * cells, y * cells
    x0, y0 = int(math.floor(gx)), int(math.floor(gy))
    fx, fy = gx - x0, gy - y0

    def corner(i, j):
        angle = 2 * math.pi * hash01((x0 + i) % cells, (y0 + j) % cells, seed)
        return math.cos(angle) * (fx - i) + math.sin(angle) * (fy - j)

    sx, sy = fade(fx), fade(fy)
    top = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * sx
    bottom = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * sx
    return top + (bottom - top) * sy


def heightfield(octaves, seed):
    """SIZE x SIZE heights: the sum of (cells, weight) octaves of gradient noise."""
    return [[sum(w * gradient_noise((x + 0.5) / SIZE, (y + 0.5) / SIZE, cells, seed + k)
                 for k, (cells, w) in enumerate(octaves))
             for x in range(SIZE)] for y in range(SIZE)]


def normal_rows(height, max_slope):
    """Normals of a wrapping heightfield, scaled so the steepest texel leans to
    |x| or |y| = max_slope (before the 8-bit rounding)."""
    def slope(x, y):
        dx = (height[y][(x + 1) % SIZE] - height[y][(x - 1) % SIZE]) / 2
        dy = (height[(y + 1) % SIZE][x] - height[(y - 1) % SIZE][x]) / 2
        return dx, dy

    slopes = [[slope(x, y) for x in range(SIZE)] for y in range(SIZE)]

    def steepest(k):
        return max(k * max(abs(dx), abs(dy)) / math.sqrt(k * k * (dx * dx + dy * dy) + 1)
                   for row in slopes for dx, dy in row)

    low, high = 0.0, 1.0
    while steepest(high) < max_slope:
        high *= 2
    for _ in range(50):  # steepest() grows with k: bisect for the bump scale
        low, high = ((low + high) / 2, high) if steepest((low + high) / 2) < max_slope \
            else (low, (low + high) / 2)
    k = low

    def encode(v):
        return max(0, min(255, round((v * 0.5 + 0.5) * 255)))

    rows = []
    for row in slopes:
        out = bytearray()
        for dx, dy in row:
            nx, ny, nz = -k * dx, -k * dy, 1.0
            length = math.sqrt(nx * nx + ny * ny + nz * nz)
            out += bytes(encode(c / length) for c in (nx, ny, nz))
        rows.append(bytes(out))
    return rows


def make_normal_map(path, octaves, seed, max_slope):
    write_png(path, SIZE, SIZE, normal_rows(heightfield(octaves, seed), max_slope), 2)


def make_foam(path):
    height = heightfield(((8, 0.6), (16, 0.3), (32, 0.15)), 41)
    low = min(min(row) for row in height)
    high = max(max(row) for row in height)
    rows = []
    for row in height:
        # stretched to 0..1, then a smoothstep to push values toward the ends: foam
        # breaks into blobs and gaps instead of a soft haze
        grays = (round(255 * smoothstep(0.15, 0.85, (h - low) / (high - low))) for h in row)
        rows.append(bytes(g for v in grays for g in (v, v, v)))
    write_png(path, SIZE, SIZE, rows, 2)


def make_ramp(path, width=32):
    stops = ((0.0, (92, 226, 214)), (0.35, (38, 170, 190)), (0.7, (22, 96, 160)),
             (1.0, (12, 40, 104)))
    row = bytearray()
    for x in range(width):
        t = x / (width - 1)
        for (t0, c0), (t1, c1) in zip(stops, stops[1:]):
            if t0 <= t <= t1:
                s = (t - t0) / (t1 - t0)
                row += bytes(round(a + (b - a) * s) for a, b in zip(c0, c1))
                break
    write_png(path, width, 1, [bytes(row)], 2)


def main():
    os.makedirs(OUT, exist_ok=True)
    make_normal_map(os.path.join(OUT, "water_normal_a.png"), ((4, 1.0), (8, 0.35)), 21, 0.45)
    make_normal_map(os.path.join(OUT, "water_normal_b.png"), ((8, 1.0), (16, 0.4)), 31, 0.35)
    make_foam(os.path.join(OUT, "foam.png"))
    make_ramp(os.path.join(OUT, "water_ramp.png"))


if __name__ == "__main__":
    main()
