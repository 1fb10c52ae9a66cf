#!/bin/sh
# Installs the Debian packages the build and tests need, or says exactly how to.
# Usage: scripts/ensure-deps.sh [demo|test]
set -eu
need=""
want() { # want PACKAGE CHECK...: queue PACKAGE when the check fails
    pkg=$1; shift
    if ! "$@" >/dev/null 2>&1; then need="$need $pkg"; fi
}
want pkg-config command -v pkg-config
want make command -v make
want gcc command -v gcc
want libpng-dev pkg-config --exists libpng
want libjansson-dev pkg-config --exists jansson
want libgif-dev pkg-config --exists libgif           # tarn render -o NAME.gif
want libgpiod-dev pkg-config --exists libgpiod       # tarn show: DC/reset lines, GPIO bit-bang
want libhidapi-dev pkg-config --exists hidapi-hidraw # tarn show: the MCP2210 bridge
want libsdl2-dev pkg-config --exists sdl2            # tarn view: the window
want valgrind test -e /usr/include/valgrind/callgrind.h # tarn sweep: host instruction counts
want gnuplot-nox command -v gnuplot                  # tarn sweep: the plot
if [ "${1:-demo}" = test ]; then
    want libcmocka-dev pkg-config --exists cmocka
    want xvfb command -v Xvfb                            # tests/test_view.c: a display server
    want cmake command -v cmake                          # tests/check_packages.sh: core/CMakeLists.txt
    want g++ command -v g++                              # tests/check_packages.sh: the headers as C++
    want python3 command -v python3                      # tests/check_packages.sh: core/library.json
    want ccache command -v ccache                        # firmware builds of other scenes share objects
    want gcc-arm-none-eabi command -v arm-none-eabi-gcc
    want libnewlib-arm-none-eabi test -e /usr/lib/arm-none-eabi/newlib
    want binutils-arm-none-eabi command -v arm-none-eabi-nm
    want gcc-riscv64-unknown-elf command -v riscv64-unknown-elf-gcc
    want qemu-system-arm command -v qemu-system-arm
    want qemu-system-misc command -v qemu-system-riscv32
    want clang command -v clang                          # make fuzz, make fuzz-replay
    want libclang-rt-14-dev sh -c 'ls /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a' 
fi
[ -z "$need" ] && exit 0

cmd="apt-get install -y --no-install-recommends$need"
echo "tarn: installing missing packages:$need" >&2
if [ "$(id -u)" = 0 ]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive $cmd
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive $cmd
else
    echo "tarn: cannot install as this user; run:  sudo apt-get update && sudo $cmd" >&2
    exit 1
fi
