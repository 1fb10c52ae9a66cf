#!/bin/sh
# core/ must be integer-only, freestanding C99: compiled for a Cortex-M0 with a
# soft-float ABI, no object may reference a soft-float helper, and the sources may
# name no float type, libm, allocator or stdio, nor include anything but the
# freestanding headers (and core's own).
set -u
BUILD=${BUILD:-build/m0}
mkdir -p "$BUILD"
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

for src in core/*/*.c; do
    obj="$BUILD/$(basename "$src" .c).o"
    if ! arm-none-eabi-gcc -std=c99 -pedantic -Wall -Wextra -Werror -mcpu=cortex-m0 -mthumb \
            -mfloat-abi=soft -ffreestanding -O2 -Icore -Icore/include -c "$src" -o "$obj"; then
        fail "$src does not compile for Cortex-M0"
        continue
    fi
    helpers=$(arm-none-eabi-nm -u "$obj" | grep -E '__aeabi_(f|d)|__aeabi_[a-z0-9]+2(f|d)$' || true)
    if [ -n "$helpers" ]; then fail "$src references soft-float helpers: $helpers"; else pass; fi
done

# Code that runs per pixel on a Cortex-M0 (no divider, no 32x32->64 multiply)
# must not call the library's division or 64-bit multiply helpers.
for unit in exp2 recip raster water_span water_pixel water_common water_normals water_refraction water_fog \
    water_surface water_highlights water_foam water_still underwater; do
    slow=$(arm-none-eabi-nm -u "$BUILD/$unit.o" | grep -E '__aeabi_(l|ul|i|ui)div|__aeabi_lmul|__aeabi_.*divmod|__divdi3|__muldi3' || true)
    if [ -n "$slow" ]; then fail "$(find core -name "$unit.c") calls division or 64-bit multiply helpers: $slow"; else pass; fi
done

# Comments may mention these words; code may not. Strip comments before looking.
for src in $(find core -name '*.[ch]'); do
    code=$(sed -e 's://.*$::' "$src" | perl -0pe 's:/\*.*?\*/::gs')
    bad=$(printf '%s\n' "$code" | grep -nwE 'float|double|malloc|calloc|realloc|free|printf|FILE|long double' || true)
    if [ -n "$bad" ]; then fail "$src uses a forbidden word: $bad"; else pass; fi
    includes=$(printf '%s\n' "$code" | grep -E '^\s*#\s*include' |
        grep -vE '<(stdint|stddef|limits|string)\.h>|"[a-z0-9_/]+\.h"' || true)
    if [ -n "$includes" ]; then fail "$src includes a non-freestanding header: $includes"; else pass; fi
done

# The checks must be able to fail: a float expression pulls in a soft-float
# helper, and a 64-bit product a multiply helper.
probe="$BUILD/probe_float.o"
printf 'float tarn_probe(float a, int b) { return a * (float)b; }\n' |
    arm-none-eabi-gcc -x c -std=c99 -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -O2 -c - -o "$probe"
if arm-none-eabi-nm -u "$probe" | grep -qE '__aeabi_(f|d)|__aeabi_[a-z0-9]+2(f|d)$'; then pass; else
    fail "the soft-float probe found no helper: the check itself is broken"; fi
printf 'long long tarn_probe(long long a, long long b) { return a * b / 3; }\n' |
    arm-none-eabi-gcc -x c -std=c99 -mcpu=cortex-m0 -mthumb -O2 -c - -o "$probe"
if arm-none-eabi-nm -u "$probe" | grep -qE '__aeabi_lmul' && arm-none-eabi-nm -u "$probe" | grep -qE '__aeabi_ldivmod'; then pass; else
    fail "the 64-bit probe found no helper: the check itself is broken"; fi

echo "purity: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
