#!/usr/bin/env python3
"""Where an emulated board spends its instructions, counted exactly.

Runs the firmware under QEMU with its execution log (-d in_asm,exec,nochain) sent
through a pipe: each translated block is listed once with its instructions, and
each execution of a block is one line. Counting executions times the block's
instructions gives every instruction the guest ran, so the figures are exact and
add up to the firmware's own SysTick count (the report's frame_insn), whatever the
host's load. The counts are mapped to functions, source files and source lines of
the ELF (its -g build); code inlined into a function counts in that function and
at the inlined line. `calls` counts entries at a function's first instruction.

Stages follow the calls: a shadow stack pushed at each call instruction (bl, blx;
jal, jalr) and popped when execution reaches a pushed return address gives every
instruction to the innermost stage function it runs under (STAGES below), helpers
such as the reciprocal counting in the stage that called them.

With --annotate NAME (repeatable), each such function's disassembly follows, each instruction with
the times it ran: where inside one function the instructions go.

Usage: scripts/profile-target.py [--top N] [--tools PREFIX] [--annotate NAME] ELF -- QEMU_COMMAND...
  e.g. scripts/profile-target.py build/firmware/qemu-m0/firmware.elf -- \\
         qemu-system-arm -M microbit -nographic -monitor none -serial none -icount shift=0 \\
         -semihosting-config enable=on,target=native,arg=firmware,arg=/tmp/s,arg=/tmp/r \\
         -kernel build/firmware/qemu-m0/firmware.elf
(make profile-target BOARD=qemu-m0 builds that command line from the board's.)
PREFIX is the toolchain's (arm-none-eabi- by default) for nm and addr2line.
"""
import argparse
import re
import bisect
import collections
import os
import subprocess
import sys
import tempfile


# The stage of each function that starts one: an instruction counts in the stage of
# the innermost of these on the call stack, 'other' outside all of them.
STAGES = {
    'tarn__walk_triangles': 'geometry: transform, clip, project, vertex cache',
    'tarn__raster_triangle': 'raster: coverage, depth, interpolation, texels',
    'tarn__triangle_next_span': 'raster: coverage, depth, interpolation, texels',
    'tarn__span_attributes': 'raster: coverage, depth, interpolation, texels',
    'tarn__triangle_enters_tile': 'triangle setup: edges, planes, exact depth',
    'tarn__triangle_rows_begin': 'triangle setup: edges, planes, exact depth',
    'tarn__orient_triangle': 'triangle setup: edges, planes, exact depth',
    'tarn__triangle_pixels': 'triangle setup: edges, planes, exact depth',
    'tarn__setup_attributes': 'triangle setup: edges, planes, exact depth',
    'tarn__exact_depth_at': 'triangle setup: edges, planes, exact depth',
    'tarn__water_draw_triangle': 'water shading',
    'tarn__water_context_setup': 'water shading',
    'tarn__water_shade': 'water shading',
    'tarn__water_effects_at': 'water shading',
    'tarn__water_apply': 'water shading',
    'tarn__water_sharp_features': 'water shading',
    'tarn__water_still_tile': 'water shading',
    'tarn__underwater_tile': 'water shading',
    'tarn__vertex_pass': 'geometry: transform, clip, project, vertex cache',
    'tarn__scene_pose': 'frame: pose, tiles or strips, clears, copies',
    'tarn__bin_clusters': 'cluster bins',
    'tarn_render_frame': 'frame: pose, tiles or strips, clears, copies',
    'tarn_panel_send_tile': 'panel: RGB565 and the stream',
    'tarn_panel_band_add': 'panel: RGB565 and the stream',
}
CALL = re.compile(r'^(bl|blx|jal|jalr|c\.jal|c\.jalr)\b')


class Block:
    """A translated block: its addresses, and the return address when it ends in a call."""
    __slots__ = ('addresses', 'returns_to')

    def __init__(self, listing):
        self.addresses = [address for address, _, _ in listing]
        address, size, mnemonic = listing[-1]
        calls = CALL.match(mnemonic) and not mnemonic.startswith(('jal zero', 'jalr zero'))
        self.returns_to = address + size if calls else None


def parse_instruction(line):
    """(address, size in bytes, the rest) of a listing line '0x...:  hex hex  mnemonic ...'."""
    head, rest = line.split(':', 1)
    fields = rest.split()
    size = 0
    while fields and re.fullmatch(r'[0-9a-f]{4}|[0-9a-f]{8}', fields[0]):
        size += len(fields.pop(0)) // 2
    return int(head, 16), size, ' '.join(fields)


class Counter:
    """Counts a log's executions into addresses, entries and stages as it streams."""

    def __init__(self, stage_of_address):
        self.stage_of_address = stage_of_address
        self.blocks = {}
        self.executions = collections.Counter()
        self.stages = collections.Counter()
        self.stack = []  # (return address, stage inside the call); the stage is set on entry
        self.pending = False

    def execute(self, block):
        start = block.addresses[0]
        if self.pending:  # the first block of a call: its function's stage, or the caller's
            caller_stage = self.stack[-2][1] if len(self.stack) > 1 else 'other'
            self.stack[-1] = (self.stack[-1][0], self.stage_of_address(start) or caller_stage)
            self.pending = False
        else:
            for depth in range(len(self.stack) - 1, max(len(self.stack) - 8, -1), -1):
                if self.stack[depth][0] == start:
                    del self.stack[depth:]
                    break
        self.stages[self.stack[-1][1] if self.stack else 'other'] += len(block.addresses)
        if block.returns_to is not None:
            self.stack.append((block.returns_to, None))
            self.pending = True


def count_blocks(log, counter):
    """Instructions executed at each guest address, from QEMU's log lines."""
    listing = None
    for line in log:
        if line.startswith('Trace'):
            key = line.split(' ', 3)[2]
            if listing:  # the first execution follows the block's listing
                counter.blocks[key] = Block(listing)
            listing = None
            block = counter.blocks.get(key)
            if block is not None:
                counter.executions[key] += 1
                counter.execute(block)
        elif line.startswith('0x') and listing is not None:
            listing.append(parse_instruction(line))
        elif line.startswith('IN:'):
            listing = []
    per_address = collections.Counter()
    entries = collections.Counter()
    for key, n in counter.executions.items():
        addresses = counter.blocks[key].addresses
        for address in addresses:
            per_address[address] += n
        entries[addresses[0]] += n
    return per_address, entries


def symbols(tools, elf):
    table = []
    out = subprocess.run([tools + 'nm', '-n', '-S', '--defined-only', elf],
                         capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        fields = line.split()
        if len(fields) == 4 and fields[2] in 'tTwW':
            table.append((int(fields[0], 16), int(fields[1], 16), fields[3]))
    return table


def source_lines(tools, elf, addresses):
    out = subprocess.run([tools + 'addr2line', '-e', elf] + ['%#x' % a for a in addresses],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    return [line.split('/')[-1].split(' (')[0] for line in out]


def print_table(title, counter, total, top, calls=None):
    print(title + ':')
    for name, n in counter.most_common(top):
        extra = ' calls=%d' % calls[name] if calls is not None else ''
        print('%12d %6.2f%% %s%s' % (n, 100.0 * n / total, name, extra))


def annotate(tools, elf, table, name, per_address):
    """The disassembly of function `name`, each instruction led by its executions."""
    found = [(start, size) for start, size, symbol in table if symbol == name]
    if not found:
        sys.exit('profile-target: no function %s in %s' % (name, elf))
    start, size = found[0]
    out = subprocess.run([tools + 'objdump', '-d', '--no-show-raw-insn', '--start-address=%#x' % start,
                          '--stop-address=%#x' % (start + size), elf],
                         capture_output=True, text=True, check=True).stdout
    print('annotate %s:' % name)
    for line in out.splitlines():
        match = re.match(r'\s*([0-9a-f]+):\s', line)
        if match:
            print('%12d %s' % (per_address.get(int(match.group(1), 16), 0), line.strip()))


def run_logged(qemu, counter):
    """Runs QEMU with its log into a pipe and counts it as it comes."""
    with tempfile.TemporaryDirectory() as scratch:
        fifo = os.path.join(scratch, 'log')
        os.mkfifo(fifo)
        guest = subprocess.Popen(qemu + ['-d', 'in_asm,exec,nochain', '-D', fifo],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(fifo, errors='replace') as log:
            counts = count_blocks(log, counter)
        if guest.wait() != 0:
            sys.exit('profile-target: QEMU exited with status %d' % guest.returncode)
    return counts


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument('--top', type=int, default=30)
    parser.add_argument('--tools', default='arm-none-eabi-')
    parser.add_argument('--annotate', metavar='NAME', action='append', default=[])
    parser.add_argument('elf')
    parser.add_argument('qemu', nargs=argparse.REMAINDER)
    args = parser.parse_args()
    qemu = args.qemu[1:] if args.qemu[:1] == ['--'] else args.qemu
    if not qemu:
        parser.error('the QEMU command line follows --')
    table = symbols(args.tools, args.elf)
    starts = [start for start, _, _ in table]
    stage_starts = {start: STAGES[name] for start, _, name in table if name in STAGES}
    counter = Counter(lambda address: stage_starts.get(address & ~1))
    per_address, entries = run_logged(qemu, counter)
    total = sum(per_address.values())
    if total == 0:
        sys.exit('profile-target: no instructions logged (did the firmware start?)')
    functions, calls = collections.Counter(), collections.Counter()
    for address, n in per_address.items():
        k = bisect.bisect_right(starts, address & ~1) - 1
        name = table[k][2] if k >= 0 and address < table[k][0] + max(table[k][1], 2) else '?'
        functions[name] += n
        calls[name] += entries[address] if k >= 0 and address == table[k][0] else 0
    addresses = sorted(per_address)
    lines, files = collections.Counter(), collections.Counter()
    for address, place in zip(addresses, source_lines(args.tools, args.elf, addresses)):
        lines[place] += per_address[address]
        files[place.split(':')[0]] += per_address[address]
    print('profile elf=%s instructions=%d' % (args.elf, total))
    print_table('stages', counter.stages, total, args.top)
    print_table('functions', functions, total, args.top, calls)
    print_table('files', files, total, args.top)
    print_table('lines', lines, total, args.top)
    for name in args.annotate:
        annotate(args.tools, args.elf, table, name, per_address)


if __name__ == '__main__':
    main()
