#!/bin/sh
# check_packages.sh: the core as others take it (docs/packages.md), each way built and
# run as a user would, with tests/consumer/consumer.c as the program:
#  (a) make install into a temporary DESTDIR: exactly libtarn.a (the core's objects),
#      tarn.pc and the public headers, no internal header; the consumer compiled with
#      pkg-config's flags alone runs and prints the version line;
#  (b) CMake: the consumer adding core/ as a subdirectory and linking tarn::core prints
#      the same checksum; every TARN_LINK_* switch of tarn_config.h is an option; core/
#      built and installed on its own serves find_package(tarn) and pkg-config alike;
#  (c) the switches reach the compile: with -DTARN_LINK_UNDERWATER=OFF, and with a
#      TARN_LINK_HEADER that sets it to 0, the underwater tile function is no longer
#      linked and the frame is the same; a Cortex-M0 toolchain file builds the library
#      and the consumer as Thumb-1 ARMv6-M code with tarn_render_frame and no
#      soft-float helper;
#  (d) each public header compiles alone, as C99 (-pedantic) and as C++11;
#  (e) core/library.json is valid JSON naming what PlatformIO needs, and its version,
#      tarn.pc's and the program's are TARN_VERSION_STRING.
# A FAIL: line for each check that fails (with the end of its log), then the totals;
# exits non-zero on any failure. PACKAGES_VERBOSE=1 prints an ok: line for each
# check that passes too. Writes only to a temporary directory and to build/release
# (make install's library).
set -u
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tarn-packages.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' INT TERM
failed=0
passed=0
ok() { passed=$((passed + 1)); [ "${PACKAGES_VERBOSE:-0}" = 1 ] && echo "ok: $*"; return 0; }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
# quiet NAME COMMAND...: runs COMMAND with its output in $tmp/NAME.log, shown on failure
quiet() {
    quiet_log=$tmp/$1.log
    shift
    if "$@" > "$quiet_log" 2>&1; then return 0; fi
    sed 's/^/    /' "$quiet_log" | tail -n 20
    return 1
}
# The builds below are builds of their own: none takes a calling make's flags,
# variables or jobserver (make test runs this script), each is given its jobs.
unset MAKEFLAGS MFLAGS MAKELEVEL MAKEOVERRIDES
jobs=--parallel=2
for tool in make gcc g++ pkg-config cmake python3 arm-none-eabi-gcc arm-none-eabi-nm arm-none-eabi-readelf; do
    command -v $tool > /dev/null 2>&1 || { fail "$tool is not installed (make deps-test installs it)"; exit 1; }
done

# TARN_VERSION_STRING as the compiler reads it
version=$(printf '#include "tarn/tarn_version.h"\nTARN_VERSION_STRING\n' | gcc -E -P -Icore/include -x c - | tail -n 1 | tr -d '" ')
case $version in
[0-9]*.[0-9]*.[0-9]*) ;;
*) fail "TARN_VERSION_STRING reads as '$version', not MAJOR.MINOR.PATCH"; exit 1 ;;
esac
public_headers=$(for h in core/include/tarn/*.h; do basename "$h"; done | sort)
header_count=$(printf '%s\n' "$public_headers" | wc -l)
line_re="^consumer version=$(printf '%s' "$version" | sed 's/\./\\./g') checksum=[0-9a-f]{8}$"

# consumer_checksum OUTPUT: the checksum of a version line
consumer_checksum() { printf '%s\n' "$1" | sed -n 's/^consumer version=.* checksum=\([0-9a-f]*\)$/\1/p'; }

# ---- (a) make install, pkg-config -------------------------------------------------
dest=$tmp/dest
checksum=
if quiet install make -s -j2 --no-print-directory install DESTDIR="$dest" PREFIX=/usr; then
    expected=$( (echo usr/lib/libtarn.a; echo usr/lib/pkgconfig/tarn.pc
        printf '%s\n' "$public_headers" | sed 's|^|usr/include/tarn/|') | sort)
    installed=$(cd "$dest" && find . -type f | sed 's|^\./||' | sort)
    if [ "$installed" = "$expected" ]; then
        ok "make install put libtarn.a, tarn.pc and the $header_count public headers, nothing else"
    else
        fail "make install's files differ from libtarn.a, tarn.pc and the public headers:" \
            "$(printf '%s\n' "$installed" | tr '\n' ' ')"
    fi
    internal=$(find "$dest" -name '*internal*' | sed "s|^$dest/||")
    if [ -z "$internal" ]; then ok "make install installed no internal header"; else
        fail "make install installed internal headers: $internal"; fi
    members=$(ar t "$dest/usr/lib/libtarn.a" | sort)
    objects=$(for src in core/*/*.c; do basename "$src" .c; done | sed 's/$/.o/' | sort)
    if [ "$members" = "$objects" ]; then ok "libtarn.a holds the core's $(echo "$objects" | wc -l) objects and nothing else"; else
        fail "libtarn.a's members are not the objects of core/*/*.c: $(echo "$members" | tr '\n' ' ')"; fi

    pc() { PKG_CONFIG_PATH=$dest/usr/lib/pkgconfig PKG_CONFIG_SYSROOT_DIR=$dest pkg-config "$@"; }
    pc_version=$(pc --modversion tarn 2> /dev/null)
    if [ "$pc_version" = "$version" ]; then ok "tarn.pc's version is TARN_VERSION_STRING, $version"; else
        fail "tarn.pc's version is '$pc_version', TARN_VERSION_STRING is $version"; fi
    cflags=$(pc --cflags tarn 2> /dev/null | sed 's/ *$//')
    libs=$(pc --libs tarn 2> /dev/null)
    if [ "$cflags" = "-I$dest/usr/include" ]; then ok "pkg-config --cflags tarn gives the include directory alone"; else
        fail "pkg-config --cflags tarn gives '$cflags', expected -I$dest/usr/include"; fi
    # shellcheck disable=SC2086 # the flags are words
    if quiet cc-pc gcc -std=c99 -pedantic -Wall -Wextra -Werror tests/consumer/consumer.c $cflags $libs -o "$tmp/consumer-pc"; then
        out=$("$tmp/consumer-pc")
        status=$?
        if [ $status -eq 0 ] && printf '%s\n' "$out" | grep -Eqx "$line_re"; then
            checksum=$(consumer_checksum "$out")
            ok "the consumer built with pkg-config's flags alone prints: $out"
        else
            fail "the consumer built with pkg-config's flags printed '$out' (status $status)"
        fi
    else
        fail "the consumer does not compile and link with pkg-config --cflags --libs tarn"
    fi
else
    fail "make install DESTDIR=$dest PREFIX=/usr failed"
fi

# ---- (b), (c) CMake ---------------------------------------------------------------
# cmake_consumer NAME ARGS...: configures and builds the consumer in $tmp/NAME
cmake_consumer() {
    consumer_dir=$1
    shift
    quiet "$consumer_dir-configure" cmake -S tests/consumer -B "$tmp/$consumer_dir" "$@" &&
        quiet "$consumer_dir-build" cmake --build "$tmp/$consumer_dir" $jobs
}
# run_same NAME WHAT: runs $tmp/NAME/consumer; ok when it prints the checksum of (a)
run_same() {
    out=$("$tmp/$1/consumer")
    status=$?
    if [ $status -ne 0 ] || ! printf '%s\n' "$out" | grep -Eqx "$line_re"; then
        fail "$2: the consumer printed '$out' (status $status)"
        return 1
    fi
    [ -n "$checksum" ] || checksum=$(consumer_checksum "$out")
    if [ "$(consumer_checksum "$out")" = "$checksum" ]; then ok "$2: the consumer prints the same frame, $checksum"; else
        fail "$2: the consumer's checksum is $(consumer_checksum "$out"), make install's $checksum"; fi
}
# underwater_tile NAME: the underwater tile function's name in the linked consumer
underwater_tile() { nm "$tmp/$1/consumer" | awk '$3 ~ /^tarn__?underwater_tile$/ {print $3}'; }

if cmake_consumer host -DCMAKE_BUILD_TYPE=Release; then
    run_same host "CMake, add_subdirectory(core) and tarn::core"
    switches=$(sed -n 's/^#ifndef \(TARN_LINK_[A-Z0-9_]*\)$/\1/p' core/include/tarn/tarn_config.h | grep -vx -e TARN_LINK_WATER_FEATURES -e TARN_LINK_WATER_FEATURES_ALL)
    cache=$(cmake -LA -N "$tmp/host")
    missing=$(for s in $switches; do printf '%s\n' "$cache" | grep -qx "$s:BOOL=ON" || printf '%s ' "$s"; done)
    printf '%s\n' "$cache" | grep -q '^TARN_LINK_WATER_FEATURES:STRING=' || missing="${missing}TARN_LINK_WATER_FEATURES "
    printf '%s\n' "$cache" | grep -qx 'TARN_LINK_WATER_FEATURES_ALL:STRING=0u' || missing="${missing}TARN_LINK_WATER_FEATURES_ALL=0u "
    printf '%s\n' "$cache" | grep -q '^TARN_LINK_HEADER:FILEPATH=' || missing="${missing}TARN_LINK_HEADER "
    printf '%s\n' "$cache" | grep -qx 'TARN_VERTEX_CACHE_SLOTS:STRING=16' || missing="${missing}TARN_VERTEX_CACHE_SLOTS=16 "
    if [ -z "$missing" ]; then
        ok "CMake has the $(printf '%s\n' "$switches" | wc -l) TARN_LINK_* switches of tarn_config.h as options, ON, and TARN_LINK_WATER_FEATURES, TARN_LINK_WATER_FEATURES_ALL (0u), TARN_LINK_HEADER, TARN_VERTEX_CACHE_SLOTS (16)"
    else
        fail "CMake's cache lacks: $missing"
    fi
    if [ -n "$(underwater_tile host)" ]; then ok "with every switch on, the consumer links $(underwater_tile host)"; else
        fail "with every switch on, the consumer links no tarn_underwater_tile or tarn__underwater_tile: the switch checks below prove nothing"; fi
else
    fail "CMake could not configure and build the consumer with add_subdirectory(core)"
fi

if cmake_consumer underwater-off -DCMAKE_BUILD_TYPE=Release -DTARN_LINK_UNDERWATER=OFF; then
    run_same underwater-off "CMake with TARN_LINK_UNDERWATER=OFF"
    if [ -z "$(underwater_tile underwater-off)" ]; then ok "-DTARN_LINK_UNDERWATER=OFF leaves the underwater tile function out"; else
        fail "-DTARN_LINK_UNDERWATER=OFF still links $(underwater_tile underwater-off)"; fi
else
    fail "CMake could not build the consumer with -DTARN_LINK_UNDERWATER=OFF"
fi

# the walk's vertex cache at a board with RAM's size: the same frame
if cmake_consumer cache-64 -DCMAKE_BUILD_TYPE=Release -DTARN_VERTEX_CACHE_SLOTS=64; then
    run_same cache-64 "CMake with TARN_VERTEX_CACHE_SLOTS=64"
    if grep -rqs 'TARN_VERTEX_CACHE_SLOTS=64u' "$tmp/cache-64/tarn"; then ok "-DTARN_VERTEX_CACHE_SLOTS=64 reaches the core's compile"; else
        fail "-DTARN_VERTEX_CACHE_SLOTS=64 is not on the core's compile lines"; fi
else
    fail "CMake could not build the consumer with -DTARN_VERTEX_CACHE_SLOTS=64"
fi

# a header as tarn bake writes one (NAME_link.h), of the switches this scene needs
printf '#define TARN_LINK_WATER 1\n#define TARN_LINK_WATER_FEATURES (TARN_WATER_FOG)\n#define TARN_LINK_UNDERWATER 0\n' > "$tmp/scene_link.h"
if cmake_consumer link-header -DCMAKE_BUILD_TYPE=Release -DTARN_LINK_HEADER="$tmp/scene_link.h"; then
    run_same link-header "CMake with TARN_LINK_HEADER"
    if [ -z "$(underwater_tile link-header)" ]; then ok "TARN_LINK_HEADER's TARN_LINK_UNDERWATER 0 leaves the underwater tile function out"; else
        fail "TARN_LINK_HEADER's TARN_LINK_UNDERWATER 0 did not reach the compile: $(underwater_tile link-header) is linked"; fi
else
    fail "CMake could not build the consumer with TARN_LINK_HEADER"
fi

# core/ as a project of its own, installed: a CMake package and tarn.pc
prefix=$tmp/cmake-prefix
if quiet core-configure cmake -S core -B "$tmp/core" -DCMAKE_BUILD_TYPE=Release &&
    quiet core-build cmake --build "$tmp/core" $jobs && quiet core-install cmake --install "$tmp/core" --prefix "$prefix"; then
    headers=$(for h in "$prefix"/include/tarn/*; do basename "$h"; done | sort)
    pc_version=$(sed -n 's/^Version: //p' "$prefix/lib/pkgconfig/tarn.pc")
    if [ "$headers" = "$public_headers" ] && [ -f "$prefix/lib/libtarn.a" ] && [ "$pc_version" = "$version" ] &&
        [ -z "$(find "$prefix" -name '*internal*')" ]; then
        ok "cmake --install of core/ puts libtarn.a, the public headers alone and tarn.pc (version $pc_version)"
    else
        fail "cmake --install of core/: headers '$(printf '%s\n' "$headers" | tr '\n' ' ')', tarn.pc version '$pc_version'"
    fi
    if cmake_consumer find-package -DCMAKE_BUILD_TYPE=Release -DCONSUMER_FIND_PACKAGE=ON -DCMAKE_PREFIX_PATH="$prefix"; then
        run_same find-package "CMake, find_package(tarn) of the installed core"
    else
        fail "the consumer could not find_package(tarn) from cmake --install's prefix"
    fi
else
    fail "core/ does not configure, build and install as a CMake project of its own"
fi

# Cortex-M0: the library and the consumer, linked against newlib's nosys stubs
toolchain=$root/tests/consumer/arm-none-eabi-cortex-m0.cmake
if cmake_consumer m0 -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=MinSizeRel; then
    elf=$tmp/m0/consumer
    lib=$tmp/m0/tarn/libtarn.a
    units=$(arm-none-eabi-readelf -A "$elf" "$lib" | grep -c '^File Attributes')
    m0=$(arm-none-eabi-readelf -A "$elf" "$lib" | grep -c '^  Tag_CPU_arch: v6S-M$')
    thumb1=$(arm-none-eabi-readelf -A "$elf" "$lib" | grep -c '^  Tag_THUMB_ISA_use: Thumb-1$')
    arm_isa=$(arm-none-eabi-readelf -A "$elf" "$lib" | grep -c '^  Tag_ARM_ISA_use: Yes$')
    if [ "$units" -gt 1 ] && [ "$m0" -eq "$units" ] && [ "$thumb1" -eq "$units" ] && [ "$arm_isa" -eq 0 ]; then
        ok "Cortex-M0: the consumer and the library's $((units - 1)) objects are ARMv6-M Thumb-1 code"
    else
        fail "Cortex-M0: of $units files, $m0 say ARMv6-M (v6S-M), $thumb1 Thumb-1, $arm_isa ARM code"
    fi
    render=$(arm-none-eabi-readelf -sW "$elf" | awk '$8 == "tarn_render_frame" && $4 == "FUNC" {print $2}')
    case $render in
    *[13579bdf]) ok "Cortex-M0: the linked consumer holds tarn_render_frame, a Thumb function (0x$render)" ;;
    '') fail "Cortex-M0: the linked consumer has no tarn_render_frame" ;;
    *) fail "Cortex-M0: tarn_render_frame is at 0x$render, not a Thumb address" ;;
    esac
    helpers=$( (arm-none-eabi-nm "$elf"; arm-none-eabi-nm "$lib") 2> /dev/null |
        awk '{print $NF}' | grep -E '^__aeabi_(f|d)|^__aeabi_[a-z0-9]+2(f|d)$' | sort -u | tr '\n' ' ')
    if [ -z "$helpers" ]; then ok "Cortex-M0: no soft-float helper (__aeabi_f*, __aeabi_d*) in the library or the consumer"; else
        fail "Cortex-M0: soft-float helpers: $helpers"; fi
else
    fail "CMake with $toolchain could not build the library and the consumer"
fi

# ---- (d) the public headers alone -------------------------------------------------
c_bad=''
cxx_bad=''
for h in $public_headers; do
    # a declaration after it: a header of macros alone would leave ISO C an empty unit
    printf '#include "tarn/%s"\ntypedef int tarn_header_alone;\n' "$h" > "$tmp/alone.c"
    gcc -std=c99 -pedantic -Wall -Wextra -Werror -fsyntax-only -Icore/include "$tmp/alone.c" > "$tmp/alone-c.log" 2>&1 ||
        { c_bad="$c_bad $h"; sed 's/^/    /' "$tmp/alone-c.log" | head -n 5; }
    g++ -x c++ -std=c++11 -Wall -Wextra -Werror -fsyntax-only -Icore/include "$tmp/alone.c" > "$tmp/alone-cxx.log" 2>&1 ||
        { cxx_bad="$cxx_bad $h"; sed 's/^/    /' "$tmp/alone-cxx.log" | head -n 5; }
done
if [ -z "$c_bad" ]; then ok "each of the $header_count public headers compiles alone as C99 (gcc -pedantic -Wall -Wextra -Werror)"; else
    fail "public headers that do not compile alone as C99:$c_bad"; fi
if [ -z "$cxx_bad" ]; then ok "each of the $header_count public headers compiles alone as C++11 (g++ -Wall -Wextra -Werror)"; else
    fail "public headers that do not compile alone as C++11:$cxx_bad"; fi

# ---- (e) PlatformIO's library.json --------------------------------------------------
if python3 -m json.tool core/library.json > /dev/null 2> "$tmp/json.log"; then
    ok "core/library.json is valid JSON"
    problems=$(python3 - "$version" core/library.json << 'EOF'
import json, os, sys
version, path = sys.argv[1], sys.argv[2]
root = os.path.dirname(path)
m = json.load(open(path))
b = m.get("build", {})
problems = []
def want(cond, what):
    if not cond: problems.append(what)
want(m.get("name") == "tarn", "name is not tarn")
want(m.get("version") == version, "version %r is not TARN_VERSION_STRING %s" % (m.get("version"), version))
want(m.get("license") == "MIT", "license is not MIT")
want(m.get("description"), "no description")
want(m.get("keywords"), "no keywords")
want(m.get("platforms") == "*" and m.get("frameworks") == "*", "platforms and frameworks are not *")
want(b.get("includeDir") == "include" and os.path.isfile(os.path.join(root, "include/tarn/tarn.h")),
     "build.includeDir is not include (holding tarn/tarn.h)")
want(b.get("srcDir") == ".", "build.srcDir is not . (the stage folders hold the sources)")
want("+<*/*.c>" in b.get("srcFilter", []), "build.srcFilter does not take */*.c")
flags = b.get("flags", [])
flags = flags.split() if isinstance(flags, str) else " ".join(flags).split()
want(any(f in ("-I.", "-I./") for f in flags) or any(a == "-I" and c in (".", "./") for a, c in zip(flags, flags[1:])),
     "build.flags do not put the library root (core/) on the include path for the *_internal.h headers")
print("; ".join(problems))
EOF
    )
    if [ -z "$problems" ]; then ok "core/library.json names tarn $version, MIT, srcDir ., includeDir include, -I . and platforms and frameworks *"; else
        fail "core/library.json: $problems"; fi
else
    sed 's/^/    /' "$tmp/json.log"
    fail "core/library.json is not valid JSON"
fi

echo "packages: $passed passed, $failed failed (make install, CMake, the Cortex-M0 build, the headers alone, library.json)"
[ "$failed" -eq 0 ]
