#!/bin/sh
# stack_bound.sh: the deepest stack a firmware build can use, from its objects.
#
# Usage: firmware/stack_bound.sh CROSS OBJDIR ENTRY [HANDLER:EXTRA_BYTES | START:core ...]
#   CROSS    the toolchain prefix (arm-none-eabi-), for objdump and readelf
#   OBJDIR   where the objects and their .su files are (-fstack-usage)
#   ENTRY    the function the stack starts in (reset_handler, main)
#   HANDLER  an interrupt handler that can preempt at any depth, and the bytes the
#            hardware pushes before it runs (Cortex-M: 32, plus 4 of alignment)
#   START    where another core's stack starts (display_main.c's second_core_main,
#            or the reset handler seen from that core): its address is taken to
#            start the core, never to be called through a pointer on this stack
# Prints: stack_bytes=N, then the deepest path, one "bytes function" per line.
#
# Each function costs its own frame (its .su line) plus its deepest callee. The calls
# are the code's own: each call relocation in a function's section (-ffunction-sections),
# which is what the compiler left after inlining and folding, and each call through a
# register. Such an indirect call may reach any function whose address the program
# takes (a relocation from code or data to a function that is not a call or a branch)
# and that is not already on the chain: an over-estimate, since a tile sink is counted
# as reachable from the panel transport and the other way round, but one that needs no
# list of who calls which pointer. Functions without a frame (libgcc's and newlib's:
# memset, __aeabi_uldivmod...) are leaves costing LIBRARY_BYTES each; they are listed.
# Recursion, or a frame of dynamic size, makes the bound unknown: exit status 1.
set -eu
[ $# -ge 3 ] || { echo "usage: $0 CROSS OBJDIR ENTRY [HANDLER:BYTES...]" >&2; exit 2; }
cross=$1 objdir=$2 entry=$3
shift 3
LIBRARY_BYTES=${LIBRARY_BYTES:-64}

sus=$(find "$objdir" -name '*.su' | sort)
[ -n "$sus" ] || { echo "stack_bound: no .su files in $objdir (build with -fstack-usage)" >&2; exit 2; }
# the objects compiled from C, each beside its .su: the only ones whose frames are known
objs=$(for su in $sus; do [ -f "${su%.su}.o" ] && echo "${su%.su}.o"; done)

# A function's name as every graph below keys it: a section's (.text.NAME;
# .ram.text.NAME for code a board runs from RAM; .text.startup.main) and a
# relocation's (NAME+0x4) lose what is not the name, and a clone's (NAME.isra.0,
# .constprop.0, .part.0) its number, as GCC's .su gives it.
BARE='function bare(name) {
    sub(/\+0x[0-9a-f]+$/, "", name)
    sub(/^(\.ram)?\.text\.(startup\.|unlikely\.)?/, "", name)
    sub(/\.[0-9]+$/, "", name)
    return name
}'

# Address-taken functions: non-call relocations in code and data sections that name
# a function's section (.text.NAME, -ffunction-sections; .ram.text.NAME for code a
# board runs from RAM) or a function symbol.
taken=$(for o in $objs; do "${cross}readelf" -rW "$o"; done | awk "$BARE"'
    /^Relocation section/ {
        s = $3; gsub(/\047/, "", s)
        use = (s ~ /^\.rela?(\.ram)?\.(text|rodata|data|sdata|srodata)/)
        next
    }
    use && NF >= 5 && $3 !~ /(CALL|JUMP|JAL|BRANCH|RELAX|ALIGN|PCREL_LO12|V4BX|TLS)/ {
        print bare($5)
    }' | sort -u)

# The call graph: "frame NAME BYTES dynamic|static" from each .su line, and "call
# FROM TO" for each call or tail call in the code (a call relocation: bl, b.w, call,
# tail, jal) and each indirect one (blx/bx through a register on Arm, jalr/jr through
# a register but ra's own return on RISC-V: TO is __indirect_call).
graph() {
    cat $sus | awk -F '\t' "$BARE"'
        { name = $1; sub(/^.*:/, "", name); print "frame", bare(name), $2, ($3 ~ /dynamic/ && $3 !~ /bounded/) ? "dynamic" : "static" }'
    for o in $objs; do "${cross}objdump" -dr --no-show-raw-insn "$o"; done | awk "$BARE"'
        /^Disassembly of section/ { fn = ""; next }
        /^[0-9a-f]+ <[^.][^>]*>:$/ { fn = $2; gsub(/[<>:]/, "", fn); fn = bare(fn); next }
        fn == "" { next }
        /R_(ARM_(THM_CALL|THM_JUMP24|CALL|JUMP24)|RISCV_(CALL|CALL_PLT|JAL|RVC_JUMP))[ \t]/ {
            to = bare($NF)
            if (to !~ /^\./ && to != fn) print "call", fn, to
            next
        }
        /\t(blx|bx)\tr([0-9]|1[0-2])$/ || /\t(jalr|jr)\t[a-z0-9]+$/ { print "call", fn, "__indirect_call" }'
}

graph | awk -v entry="$entry" -v handlers="$*" -v taken="$taken" -v library="$LIBRARY_BYTES" '
$1 == "frame" {
    if ($4 == "dynamic") dynamic[$2] = 1
    if (!($2 in frame) || $3 + 0 > frame[$2]) frame[$2] = $3 + 0
    next
}
$1 == "call" {
    if (!(($2, $3) in seen)) { seen[$2, $3] = 1; calls[$2] = calls[$2] " " $3 }
}
# deepest(f): bytes from entering f to the bottom of its deepest call chain. An
# indirect call skips the targets already on the chain (a function pointer that
# leads back into its own caller is not how this firmware works); a result that
# skipped something depends on the chain, so it is not memoised.
function deepest(f,    list, n, i, c, d, best, via, k, own, was_tainted, mine) {
    if (f in memo) return memo[f]
    if (f in active) { recursive = recursive " " f; return 0 }
    active[f] = 1
    was_tainted = tainted; tainted = 0
    best = 0; via = ""
    n = split(calls[f], list, " ")
    for (i = 1; i <= n; i++) {
        c = list[i]
        if (c == "__indirect_call") {
            for (k in address_taken) {
                if (k in active) { tainted = 1; continue }
                d = deepest(k)
                if (d > best) { best = d; via = k }
            }
            continue
        }
        d = deepest(c)
        if (d > best) { best = d; via = c }
    }
    delete active[f]
    if (f in frame) own = frame[f]
    else { own = library; unknown[f] = 1 }
    if (f in dynamic) dynamics = dynamics " " f
    mine = tainted
    tainted = was_tainted || mine
    if (!mine) memo[f] = own + best
    next_of[f] = via
    return own + best
}
END {
    n = split(taken, list, "\n")
    for (i = 1; i <= n; i++) if (list[i] in frame || list[i] in calls) address_taken[list[i]] = 1
    n = split(handlers, hl, " ")
    for (i = 1; i <= n; i++) if (hl[i] ~ /:core$/) { sub(/:core$/, "", hl[i]); delete address_taken[hl[i]] }
    if (!(entry in frame)) { print "stack_bound: no function " entry " in the call graph" > "/dev/stderr"; exit 2 }
    total = deepest(entry)
    worst_handler = 0; worst_name = ""
    n = split(handlers, hl, " ")
    for (i = 1; i <= n; i++) {
        if (hl[i] ~ /:core$/) continue
        split(hl[i], part, ":")
        d = deepest(part[1]) + part[2]
        if (d > worst_handler) { worst_handler = d; worst_name = hl[i] }
    }
    printf "stack_bytes=%d\n", total + worst_handler
    for (f = entry; f != ""; f = next_of[f]) printf "%6d %s\n", (f in frame) ? frame[f] : library, f
    if (worst_name != "") printf "%6d interrupt %s (its chain and the pushed bytes)\n", worst_handler, worst_name
    for (f in unknown) u = u " " f
    if (u != "") print "library leaves counted as " library " bytes:" u
    if (recursive != "") { print "recursion through:" recursive; bad = 1 }
    if (dynamics != "") { print "frames of dynamic size:" dynamics; bad = 1 }
    exit bad
}'
