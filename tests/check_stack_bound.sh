#!/bin/sh
# check_stack_bound.sh: firmware/stack_bound.sh against call chains of known shape
# (tests/stack_bound/chains.c), compiled as the firmware is for a Cortex-M0, a
# Cortex-M3 and a RISC-V core: each entry's bound must be the sum of the frames GCC
# reports along the chain it must take (a direct call, a call through a pointer, a
# tail call), and recursion and a frame of dynamic size must leave it unknown.
# Prints a FAIL line for each check that fails, then "stack bound: N passed, F failed".
set -u
out=build/stack-bound-check
passed=0 failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

# frame NAME: its frame in the .su of the current build
frame() { awk -F '\t' -v name="$1" '{ n = $1; sub(/^.*:/, "", n); sub(/\.[0-9]+$/, "", n); if (n == name) print $2 }' "$dir/chains.su"; }
# bound ENTRY: the script's output in $report, its exit status in $status and its
# stack_bytes in $got
bound() {
    report=$(firmware/stack_bound.sh "$cross" "$dir" "$1" 2>&1)
    status=$?
    got=$(printf '%s\n' "$report" | sed -n 's/^stack_bytes=//p')
}
# expect ENTRY FUNCTION...: the bound from ENTRY is the sum of the functions' frames
expect() {
    entry=$1
    want=0
    for f in "$@"; do
        bytes=$(frame "$f")
        [ -n "$bytes" ] || { fail "$target: no frame for $f in chains.su"; return; }
        want=$((want + bytes))
    done
    bound "$entry"
    if [ "$status" -eq 0 ] && [ "$got" = "$want" ]; then pass; else
        fail "$target: the bound from $entry is ${got:-none} (status $status), the frames of $* sum to $want"; fi
}
# unknown ENTRY WHY: the script exits 1 and names WHY
unknown() {
    bound "$1"
    if [ "$status" -eq 1 ] && printf '%s\n' "$report" | grep -q "$2"; then pass; else
        fail "$target: from $1 the script exited $status without '$2': $report"; fi
}

for target in "arm-none-eabi- -mcpu=cortex-m0 -mthumb" "arm-none-eabi- -mcpu=cortex-m3 -mthumb" \
              "riscv64-unknown-elf- -march=rv32imac -mabi=ilp32"; do
    set -- $target
    cross=$1
    shift
    dir=$out/$(echo "$*" | tr -c 'a-z0-9\n' '_')
    mkdir -p "$dir"
    if ! "${cross}gcc" "$@" -std=c99 -O2 -ffreestanding -ffunction-sections -fdata-sections -fstack-usage \
        -c -o "$dir/chains.o" tests/stack_bound/chains.c; then
        fail "$target: tests/stack_bound/chains.c does not compile"
        continue
    fi
    target="$cross $*"
    expect entry_indirect through_pointer leaf_large
    expect entry_tail tail_caller leaf_large
    unknown entry_recursive "recursion through"
    unknown entry_dynamic "frames of dynamic size"
done

echo "stack bound: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
