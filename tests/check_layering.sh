#!/bin/sh
# The code's dependencies form no circle, so each file and each folder can be read
# before the ones that use it.
#
# From the objects of a build (BUILD, build/release by default): file A depends on
# file B when A's object refers to a global symbol B's object defines. Then:
#  - no circle of files, in core/ or in host/ (a file may call itself);
#  - no circle of folders in host/;
#  - core/'s folders are the stages of a frame in order (core/README.md): a file
#    calls only its own folder and the folders before it;
#  - a core/ source includes the public headers (core/include/tarn/), its own
#    folder's headers and the *_internal.h headers of the folders before it;
#    host/, tests/ and firmware/ include the public headers and core/tarn_internal.h,
#    never a stage's own header.
# Static inline functions leave no symbol; the include rule covers them.
set -u
BUILD=${BUILD:-build/release}
CORE_STAGES="math scene geometry tile raster water frame panel"
status=0
passed=0
failed=0
fail() { echo "FAIL: $*"; status=1; failed=$((failed + 1)); }
ok() { passed=$((passed + 1)); } # ok WHAT: a check passed (said only in the count)

# "caller callee" pairs of source files (without .o) below $BUILD/$1
file_edges() {
    find "$BUILD/$1" -name '*.o' | sort | while read -r o; do
        f=${o#"$BUILD"/}
        [ -f "${f%.o}.c" ] || continue # left by a source that moved
        nm "$o" | awk -v f="${f%.o}" '$2 ~ /^[TDBR]$/ {print "def", $3, f} $1 == "U" {print "use", $2, f}'
    done | awk '$1 == "def" {def[$2] = $3} $1 == "use" {n++; sym[n] = $2; file[n] = $3}
        END {for (k = 1; k <= n; k++) if ((sym[k] in def) && def[sym[k]] != file[k]) print file[k], def[sym[k]]}' | sort -u
}

# Fails naming the circle when the pairs ("caller callee" lines) hold one. Takes
# them as an argument, not from a pipe: a function at a pipe's end runs in a
# subshell, where fail's status would be lost.
no_circle() { # WHAT PAIRS
    loop=$(printf '%s\n' "$2" | grep . | tsort 2>&1 >/dev/null | sed -n 's/^tsort: //p' |
        grep -v 'input contains a loop' | tr '\n' ' ')
    if [ -n "$loop" ]; then fail "$1 call each other in a circle: $loop"; return; fi
    ok "no circle of $1"
}

[ -d "$BUILD/core" ] || { echo "FAIL: no objects in $BUILD/core: build first"; exit 1; }

core=$(file_edges core)
host=$(file_edges host)
no_circle "core/ files" "$core"
no_circle "host/ files" "$host"
no_circle "host/ folders" "$(printf '%s\n' "$host" |
    awk '{split($1, a, "/"); split($2, b, "/"); if (a[2] != b[2]) print a[2], b[2]}' | sort -u)"

stage_of() { # core/FOLDER/file -> the folder's place in the order, 0 when it is none
    folder=$(echo "$1" | cut -d/ -f2)
    k=1
    for s in $CORE_STAGES; do [ "$s" = "$folder" ] && { echo $k; return; }; k=$((k + 1)); done
    echo 0
}

backward=0
for pair in $(printf '%s\n' "$core" | tr ' ' ':'); do
    caller=${pair%%:*} callee=${pair#*:}
    a=$(stage_of "$caller") b=$(stage_of "$callee")
    if [ "$a" -eq 0 ]; then fail "$caller.c is in no stage folder of core/ ($CORE_STAGES)"; backward=1
    elif [ "$b" -gt "$a" ]; then fail "$caller.c calls $callee.c, a later stage"; backward=1; fi
done
[ $backward -eq 0 ] && ok "each core/ stage calls only itself and the stages before it"

# The include rule: every #include "..." of core/, resolved as the compiler does.
bad=0
for src in $(find core -name '*.c' -o -name '*.h' | grep -v '^core/include/'); do
    own=$(dirname "$src")
    here=$(stage_of "$src")
    for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$src"); do
        # the door for host/ and tests/ may open onto every stage
        [ "$src" = core/tarn_internal.h ] && [ -f "core/$inc" ] && continue
        case $inc in
        tarn/*) [ -f "core/include/$inc" ] && continue ;;
        */*_internal.h)
            [ -f "core/$inc" ] || { fail "$src includes $inc, which is not there"; bad=1; continue; }
            there=$(stage_of "core/$inc")
            [ "$(dirname "core/$inc")" = "$own" ] || [ "$there" -lt "$here" ] && continue ;;
        *) [ -f "$own/$inc" ] && continue ;;
        esac
        fail "$src includes $inc: expected a public header (tarn/...), one of its own folder or an earlier stage's *_internal.h"
        bad=1
    done
done
for src in $(find host tests firmware boards -name '*.c' -o -name '*.h' 2>/dev/null); do
    for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$src"); do
        case $inc in
        tarn/* | tarn_internal.h) continue ;;
        esac
        base=$(basename "$inc")
        if find core -name "$base" | grep -v '^core/include/' | grep -q .; then
            fail "$src includes core's $inc: expected tarn/... or tarn_internal.h"
            bad=1
        fi
    done
done
[ $bad -eq 0 ] && ok "core/ includes follow the stages; host/, tests/ and firmware/ include only tarn/ and tarn_internal.h"

# The API line: a global symbol of the core is declared in a public header, or is
# marked internal with two underscores (tarn__); no public header names one.
public=$(cat core/include/tarn/*.h | perl -0pe 's:/\*.*?\*/::gs' | grep -oE '\btarn_[a-z0-9_]+' | sort -u)
unmarked=$(find "$BUILD/core" -name '*.o' | while read -r o; do
        f=${o#"$BUILD"/}; [ -f "${f%.o}.c" ] && nm -g "$o"; done |
    awk '$2 ~ /^[TDBR]$/ {print $3}' | sort -u | grep -v '^tarn__' | grep -vxF "$public" | tr '\n' ' ')
if [ -n "$unmarked" ]; then fail "core/ defines symbols neither public nor marked tarn__: $unmarked"
else ok "every symbol of core/ is declared in core/include/tarn/ or named tarn__"; fi
leaked=$(for h in core/include/tarn/*.h; do perl -0pe 's:/\*.*?\*/::gs' "$h" | grep -q 'tarn__' && echo "$h"; done |
    tr '\n' ' ')
if [ -n "$leaked" ]; then fail "public headers name internal tarn__ functions: $leaked"
else ok "no public header names an internal function"; fi
echo "layering: $passed passed, $failed failed (circles of files and folders; stages, includes and symbols as core/README.md says)"
exit $status
