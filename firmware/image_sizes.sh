#!/bin/sh
# image_sizes.sh: a firmware image's sizes, as every figure of the firmware states
# them (tests/check_firmware.sh, tests/check_firmware_link.sh, make firmware,
# scripts/docs_figures.py).
#
# Usage: firmware/image_sizes.sh CROSS ELF   (CROSS: the toolchain prefix, arm-none-eabi-)
# Prints one line: text=N data=N bss=N flash_bytes=N ram_bytes=N scene_bytes=N code_bytes=N
#   scratch_bytes=N
#   text         what only flash holds: boot2, .text (the vector table, code, const
#                data), .ARM.exidx
#   data         .data: its image in flash, copied to RAM at reset, with the code a
#                board runs from RAM (BOARD_RAM_CODE)
#   bss          .bss and the stack: RAM only
#   flash_bytes  text + data; ram_bytes: data + bss
#   scene_bytes  the baked scene's const data (the symbols scene_*); code_bytes: the
#                rest of the flash image
#   scratch_bytes .scratch: RAM of a region apart from RAM (the RP2040's SRAM4-5,
#                core 1's stack), 0 on a board without one
# By section name, as the link scripts (boards/common/*_sections.ld) name them: size's
# Berkeley format counts an executable .data, the code run from RAM, as text.
set -eu
[ $# -eq 2 ] || { echo "usage: $0 CROSS ELF" >&2; exit 2; }
cross=$1 elf=$2
scene=$("${cross}nm" -S -t d --defined-only "$elf" | awk '
    NF == 4 && $4 ~ /^scene_/ && $3 ~ /^[rRtT]$/ { n += $2 } END { print n + 0 }')
"${cross}size" -A "$elf" | awk -v scene="$scene" '
    $1 == ".boot2" || $1 == ".text" || $1 ~ /^\.ARM\.exidx/ { text += $2 }
    $1 == ".data" { data += $2 }
    $1 == ".bss" || $1 == ".stack" { bss += $2 }
    $1 == ".scratch" { scratch += $2 }
    END {
        printf "text=%d data=%d bss=%d flash_bytes=%d ram_bytes=%d scene_bytes=%d code_bytes=%d scratch_bytes=%d\n",
            text, data, bss, text + data, data + bss, scene, text + data - scene, scratch
    }'
