#!/bin/sh
# check_firmware_link.sh: an effect a scene does not use is not linked, nor the span
# perspective mode when the baked quality does not use it, nor refraction when the
# quality has no apron for a refracted sample to move in, nor vertex lighting when
# every object carries static vertices (the bake's default, --static-view on), nor
# the water blocks' code (tarn__water_sharp_features) when no baked quality has water_block 2,
# nor exact depth (tarn__exact_depth_at) when every baked quality steps depth on a plane,
# nor the backdrop's reader (tarn__backdrop_fill) unless the scene is baked with one,
# nor the water over still water (tarn__water_still_tile) unless that backdrop is baked
# with still water, and then none of the shading it holds (tarn__water_shade, fog) and,
# since no triangle is drawn at all, no depth interpolation (tarn__exact_depth_at);
# refraction over still water (an apron) finds the normal and reads the picture, but
# links no refracted read of the opaque pass (tarn__water_refract).
#
# Builds the qemu-m0 firmware for several scenes (each in its own directory under
# build/firmware-link/, the board's own build untouched) and reads the images' symbols
# with arm-none-eabi-nm: each effect's function (core/water/water_*.c, core/water/underwater.c)
# must be in the image exactly when the scene uses that effect. The expectations are
# written out here, not read from the baked scene_link.h, so that a bake that links
# too much (or too little) fails. Writes the code bytes of each image (flash minus
# the baked scene's const data), which is what each effect costs in flash, to
# build/firmware-link/code-bytes.txt, a line an image; prints a FAIL line for each
# symbol linked or left out against the expectation, then the totals.
set -u
board=qemu-m0
# the flags every image is baked with, and --apron off unless the image's own give an apron;
# water interpolates its coordinates on its triangles, as the board's own fast preset does
# (the plane's code and context do not fit its 32 KB and its stack), but over still water,
# whose coordinates are always its plane's
flags="--tile 16 --depth 16"
effects="tarn__water_shade tarn__water_sharp_features tarn__water_surface_normal tarn__water_refract tarn__water_fog tarn__water_absorb
tarn__water_depth_colour tarn__water_fresnel_alpha tarn__water_specular tarn__water_foam tarn__water_sparkles
tarn__underwater_tile span_end tarn__vertex_shade tarn__exact_depth_at tarn__backdrop_fill tarn__water_still_tile"
passed=0
failed=0
sizes=build/firmware-link/code-bytes.txt
mkdir -p build/firmware-link
: > "$sizes"

# check SCENE EXPECTED...: build, then compare the effect symbols with EXPECTED
check() {
    scene=$1
    shift
    dir=build/firmware-link/$(basename "$scene" .json)$extra_name
    mkdir -p "$dir"
    case "$extra_flags" in *--apron*) apron= ;; *) apron=" --apron off" ;; esac
    case "$extra_flags" in *"--backdrop still"*) uv= ;; *) uv=" --water-uv triangles" ;; esac
    if ! make --no-print-directory -s firmware BOARD=$board FW_BUILD_DIR="$dir" SCENE="$scene" \
        BAKE_FLAGS="$flags$apron$uv$extra_flags" > "$dir.log" 2>&1; then
        cat "$dir.log"
        echo "FAIL: $scene: the $board build failed"
        failed=$((failed + 1))
        return
    fi
    linked=$(arm-none-eabi-nm --defined-only "$dir/firmware.elf" | awk '{print $3}' | sort)
    for symbol in $effects; do
        want=0
        for expected in "$@"; do [ "$expected" = "$symbol" ] && want=1; done
        have=0
        printf '%s\n' "$linked" | grep -qx "$symbol" && have=1
        if [ $want -ne $have ]; then
            echo "FAIL: $scene: $symbol is $( [ $have -eq 1 ] && echo linked || echo missing)," \
                "expected $( [ $want -eq 1 ] && echo linked || echo 'left out')"
            failed=$((failed + 1))
        else
            passed=$((passed + 1))
        fi
    done
    code_bytes=$(firmware/image_sizes.sh arm-none-eabi- "$dir/firmware.elf" | sed -n 's/.* code_bytes=\([0-9]*\).*/\1/p')
    echo "firmware-link board=$board scene=$(basename "$scene" .json)$extra_name code_bytes=$code_bytes" >> "$sizes"
}

extra_name= extra_flags=
check scenes/effects/none.json tarn__exact_depth_at
check scenes/effects/fog.json tarn__water_shade tarn__water_fog tarn__exact_depth_at
check scenes/effects/foam.json tarn__water_shade tarn__water_foam tarn__exact_depth_at
check scenes/effects/sparkles.json tarn__water_shade tarn__water_surface_normal tarn__water_sparkles tarn__exact_depth_at
check scenes/effects/refraction.json tarn__water_shade tarn__water_surface_normal tarn__exact_depth_at
check scenes/effects/underwater.json tarn__underwater_tile tarn__exact_depth_at
extra_name=-span extra_flags=" --perspective span:16"
check scenes/effects/fog.json tarn__water_shade tarn__water_fog span_end tarn__exact_depth_at
extra_name=-apron extra_flags=" --apron 4"
check scenes/effects/refraction.json tarn__water_shade tarn__water_surface_normal tarn__water_refract tarn__exact_depth_at
extra_name=-blocks extra_flags=" --water-block 2"
check scenes/effects/fog.json tarn__water_shade tarn__water_sharp_features tarn__water_fog tarn__exact_depth_at
extra_name=-plane extra_flags=" --depth-interpolation plane"
check scenes/effects/fog.json tarn__water_shade tarn__water_fog
extra_name=-moving extra_flags=" --static-view off"
check scenes/effects/fog.json tarn__water_shade tarn__water_fog tarn__vertex_shade tarn__exact_depth_at
extra_name=-backdrop extra_flags=" --backdrop on"
check scenes/effects/fog.json tarn__water_shade tarn__water_fog tarn__exact_depth_at tarn__backdrop_fill
extra_name=-still extra_flags=" --backdrop still"
check scenes/effects/fog.json tarn__backdrop_fill tarn__water_still_tile
check scenes/effects/foam.json tarn__water_foam tarn__backdrop_fill tarn__water_still_tile
extra_name=-still-apron extra_flags=" --backdrop still --apron 4"
check scenes/effects/refraction.json tarn__water_surface_normal tarn__backdrop_fill tarn__water_still_tile
# The fog image's directory baked again with water blocks: its core objects take the
# new bake's switches (scene_link.opts follows scene_link.h), not the last bake's.
# (The next make test bakes it back, the other way round.)
dir=build/firmware-link/fog
if ! make --no-print-directory -s firmware BOARD=$board FW_BUILD_DIR="$dir" SCENE=scenes/effects/fog.json \
    BAKE_FLAGS="$flags --apron off --water-block 2 --water-uv triangles" > "$dir-again.log" 2>&1; then
    cat "$dir-again.log"
    echo "FAIL: $dir baked again: the build failed"
    failed=$((failed + 1))
elif ! arm-none-eabi-nm --defined-only "$dir/firmware.elf" | awk '{print $3}' | grep -qx tarn__water_sharp_features; then
    echo "FAIL: $dir baked again with --water-block 2: tarn__water_sharp_features is missing," \
        "the core kept the last bake's switches ($(grep -c . "$dir/scene_link.opts") in scene_link.opts)"
    failed=$((failed + 1))
else
    passed=$((passed + 1))
fi
echo "firmware-link: $passed passed, $failed failed (each image's code bytes: $sizes)"
[ $failed -eq 0 ]
