#!/bin/sh
# check_firmware.sh: the built and emulated firmware, build by build.
#
#   tests/check_firmware.sh DIR...          checks (make test, after make firmware-run)
#   tests/check_firmware.sh --bench DIR...  one line per build (make bench-target):
#     target board=B scene=S size=WxH insn_per_pixel=N ram_bytes=N flash_bytes=N
#            stack_bytes=N render_insn_per_pixel=N
#            [parts=N [split=pipeline] parts_insn_per_pixel=N]
#            scene_bytes=N code_bytes=N
#            stack_peak_bytes=N stack_reserved_bytes=N panel_psnr=NN.NN
#
# ram_bytes, flash_bytes, scene_bytes, code_bytes: as firmware/image_sizes.sh finds
# them (RAM: .data, .bss and the stack reserved by the linker script; flash: the
# image; the baked scene's const data and the rest of the image); stack_bytes: the deepest call chain
# the objects' calls and frames allow (firmware/stack_bound.sh), stack_peak_bytes what the run
# really used (startup paints the stack); panel_psnr the board's frame on the
# yardstick (tarn compare: the panel error, RGB565 with the ordered dither).
#
# Each DIR is a firmware build (firmware/firmware.mk): build/firmware/BOARD, a
# board's other scenes in build/firmware/BOARD@SCENE, or a build of FW_BUILD_DIR=;
# its firmware.conf names the board and the scene.
#
# Prints a line of figures a build (flash, RAM, stack), a FAIL line for each check
# that fails, and the totals; make firmware-run has printed the runs' own figures.
#
# Checks, per build: the run finished and reported; the board's counter measured a
# loop of known length within 0.01%; the stack bound and the measured peak fit the
# reserved stack; the image links no floating-point helper, allocator or stdio; the
# code (the image less the scene) fits the board's BOARD_CODE_BYTES_MAX, if it has one.
# A real board (firmware.conf: emulated=0) is never run: it gets the stack bound
# and the link checks only (tests/test_real_boards.c checks its image).
# The byte-for-byte comparison with the host is tests/test_firmware.c.
set -u
bench=0
if [ "${1:-}" = --bench ]; then bench=1; shift; fi
[ $# -gt 0 ] || { echo "usage: $0 [--bench] DIR..." >&2; exit 2; }

passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }
field() { # field NAME TEXT: the value of NAME=value in a line of words
    printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p" | head -1
}
conf() { sed -n "s/^$1=//p" "$dir/firmware.conf"; }
# The board's own frame (its scene and bake's quality, at its second frame's time:
# the panel stream is the host's frame byte for byte, tests/test_firmware.c) on the
# yardstick's panel error: what the board's user sees of the arithmetic.
board_panel_psnr() {
    flags=$(conf bake_flags | sed 's/--static-view [a-z]*//')
    second=$(conf times | cut -d, -f2)
    # shellcheck disable=SC2086
    line=$("${TARN_BIN:-build/release/tarn}" compare "$(conf scene)" $flags --time "$second") || { echo none; return; }
    field panel_psnr "$line"
}

for dir in "$@"; do
    elf=$dir/firmware.elf
    if [ ! -f "$dir/firmware.conf" ] || [ ! -f "$elf" ]; then
        fail "$dir: not built: no firmware.conf and firmware.elf there (make firmware)"
        continue
    fi
    # the board, and in what failures say, its scene too
    board=$(conf board)
    what="$board $(conf label)"
    cross=$(conf cross)
    reserved=$(conf stack_bytes)
    sizes=$(firmware/image_sizes.sh "$cross" "$elf")
    flash=$(field flash_bytes "$sizes") ram=$(field ram_bytes "$sizes")
    scene_bytes=$(field scene_bytes "$sizes") code=$(field code_bytes "$sizes")
    bound_out=$(firmware/stack_bound.sh "$cross" "$dir/obj" $(conf stack_entry))
    bound_status=$?
    stack=$(field stack_bytes "$(printf '%s\n' "$bound_out" | head -1)")

    emulated=$(conf emulated)
    if [ "$emulated" = 0 ]; then
        [ $bench = 1 ] && continue
        report="" peak="" parts="" split=""
    else
        report=$(cat "$dir/report.txt" 2>/dev/null || true)
        case $report in
        "target board=$board scene=$(conf label) "*) ;;
        *)
            fail "$what: no report from a finished run in $dir/report.txt (make firmware-run BOARD=$board): $report"
            continue
            ;;
        esac
        peak=$(field stack_peak_bytes "$report")
        parts=$(field parts "$report")
        split=$(field split "$report")
    fi

    if [ $bench = 1 ]; then
        echo "target board=$board scene=$(field scene "$report") size=$(field size "$report")" \
            "insn_per_pixel=$(field insn_per_pixel "$report") ram_bytes=$ram flash_bytes=$flash" \
            "stack_bytes=$stack render_insn_per_pixel=$(field render_insn_per_pixel "$report")" \
            ${parts:+"parts=$parts${split:+ split=$split} parts_insn_per_pixel=$(field parts_insn_per_pixel "$report")"} \
            "scene_bytes=$scene_bytes code_bytes=$code stack_peak_bytes=$peak stack_reserved_bytes=$reserved" \
            "panel_psnr=$(board_panel_psnr)"
        continue
    fi

    if [ "$emulated" != 0 ]; then
        counter=$(field counter_check "$report")
        measured=${counter%/*} expected=${counter#*/}
        if [ -n "$counter" ] && [ $((measured - expected)) -le $((expected / 10000)) ] &&
            [ $((expected - measured)) -le $((expected / 10000)) ]; then pass; else
            fail "$what: the counter measured $measured instructions for a loop of $expected"; fi
    fi

    if [ $bound_status -eq 0 ] && [ -n "$stack" ]; then pass; else
        fail "$what: no stack bound: $bound_out"; fi
    if [ -n "$stack" ] && [ "$stack" -le "$reserved" ]; then pass; else
        fail "$what: the deepest call chain needs $stack bytes of stack, the board reserves $reserved (BOARD_STACK_BYTES):"
        printf '%s\n' "$bound_out"; fi
    if [ "$emulated" = 0 ]; then :
    elif [ -n "$peak" ] && [ "$peak" -lt "$reserved" ] && [ "$peak" -le "${stack:-0}" ]; then pass; else
        fail "$what: the run used $peak bytes of stack; reserved $reserved, bound ${stack:-?}"; fi

    forbidden=$("${cross}nm" "$elf" | awk '{print $NF}' |
        grep -E '^(__aeabi_[fd][a-z0-9]*|__aeabi_[a-z0-9]+2[fd]|__(add|sub|mul|div)[sd]f3|__float[a-z]*|__fix[a-z]*|malloc|free|calloc|realloc|printf|puts|_sbrk)$' || true)
    if [ -z "$forbidden" ]; then pass; else
        fail "$what: the image links $(echo $forbidden)"; fi

    code_max=$(conf code_bytes_max)
    if [ -z "$code_max" ] || [ "$code" -le "$code_max" ]; then pass; else
        fail "$what: the code takes $code bytes of flash besides the scene, over the board's $code_max"; fi

    echo "$what: flash $flash bytes ($scene_bytes scene, $code code), RAM $ram bytes, stack bound $stack, peak ${peak:-(a real board, not run)}, reserved $reserved"
done

[ $bench = 1 ] && exit $((failed > 0))
echo "firmware: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
