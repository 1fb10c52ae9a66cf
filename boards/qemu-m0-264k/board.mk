# qemu-m0-264k: Cortex-M0 code on QEMU's mps2-an385 (whose CPU is a Cortex-M3:
# ARMv6-M code runs on it unchanged), held by its link.ld to the RP2040's 2 MB of
# flash and 264 KB of RAM. It renders the moving pond (scenes/pond-orbit.json: the
# camera circling, the balls bobbing; each frame poses the scene, nothing frozen)
# and the same scene without its water, at the balanced preset (core/scene/presets.c:
# refraction, 32-bit depth, per-pixel perspective) with its depth stepped on a
# plane (--depth-interpolation plane: three divisions less a triangle, and the
# panel as close to the reference as the exact depth's; the exact preset costs more
# for dBs the board does not need over its 40: docs/firmware.md gives the figures), in strips
# of the whole width (--frame strips): each strip's opaque pass is drawn once into
# a ring deep enough for the water's refracted samples, where 64-pixel tiles drew
# about four times the frame's opaque pixels for their aprons; the same image.
# Every vertex is found once a frame (--vertices frame, 16 bytes each), where each
# strip's walk found its own again; to keep that, the ring (12-row strips and a
# 24-pixel apron above and below, five strips) and the water's strip within 200
# KB, refraction reaches 24 pixels instead of 32 (1.6 dB of panel PSNR, for about
# a twentieth of the frame: docs/firmware.md). The 8 KB stack holds the 4.6 KB
# bound with room to spare. Variables read by firmware/firmware.mk; the rest, as for every
# emulated Cortex-M board, from boards/common/qemu_cortex_m.mk.
BOARD_DIR := boards/qemu-m0-264k
BOARD_CPU := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
BOARD_QEMU_MACHINE := mps2-an385
BOARD_STACK_BYTES := 8192
# the walk keeps 64 vertices transformed, projected and lit (tarn_config.h's
# TARN_VERTEX_CACHE_SLOTS; 16 elsewhere): each strip of the moving pond finds its
# vertices again, and 16 slots lost most of a grid row's; 1.5 KB more stack
BOARD_VERTEX_CACHE_SLOTS := 64
# the RP2040's two cores: the measured run also draws the frame in two parts
# (tarn_render_frame_part) and reports the slower, the frame's time on both cores
BOARD_CORES := 2
# the scenes make bench-target measures, a line each; the first is the board's own
# build (build/firmware/qemu-m0-264k), each other one builds in
# build/firmware/qemu-m0-264k@NAME
BOARD_SCENES := scenes/pond-orbit.json scenes/pond-opaque.json
# water interpolates its texture coordinates on its triangles (--water-uv
# triangles): the balanced preset's plane costs each water pixel a reciprocal of
# its own, and the frame is the board's to make fast; the panel shows the pond
# well above issue 22's 40 dB without it (docs/firmware.md gives both)
BOARD_BAKE_FLAGS := --quality balanced --depth-interpolation plane --frame strips --tile 12 --apron 24 --vertices frame --water-uv triangles
# without water nothing refracts: one strip is the ring, and taller strips cut
# fewer triangles in two; the room left keeps each vertex's view position too
# (--vertices frame-view), which the triangles clipped at the guard band read
# instead of transforming their vertices again
BOARD_BAKE_FLAGS.pond-opaque := --quality balanced --depth-interpolation plane --frame strips --tile 64 --vertices frame-view
include boards/common/qemu_cortex_m.mk
