#!/bin/sh
# Every path of this repository that the docs, the READMEs and the code's comments
# name exists, so a file that moves takes its mentions with it.
#
# A path is a word starting with one of the top folders (core/, host/, ...), not
# inside another path (build/firmware/... is a build output). Placeholders in
# capitals (scenes/NAME.json, boards/BOARD/) and a glob that matches something
# pass; so do the examples of bad input that the docs name on purpose.
set -u
cd "$(dirname "$0")/.."
examples="scenes/missing.json scenes/bad.json scenes/nope.json scenes/assets/rock.obj"
missing=$(git ls-files '*.md' '*.c' '*.h' '*.sh' '*.py' |
    grep -v '^tests/fuzz/corpus/' |
    xargs grep -oHP '(?<![\w/.-])(core|host|tests|firmware|boards|scripts|docs|scenes)/[\w./*-]*[\w*]' |
    while IFS=: read -r file path; do
        case $path in *[A-Z][A-Z]*) continue ;; esac
        case " $examples " in *" $path "*) continue ;; esac
        # shellcheck disable=SC2086
        if [ -e "$path" ] || { case $path in *'*'*) ls -d $path >/dev/null 2>&1 ;; *) false ;; esac; }; then
            continue
        fi
        echo "$file: $path"
    done | sort -u)
if [ -n "$missing" ]; then
    printf '%s\n' "$missing" | sed 's/^/FAIL: names a path that does not exist: /'
    exit 1
fi
echo "ok: every path the docs and comments name exists"
