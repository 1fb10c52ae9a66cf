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

Usage: scripts/profile-target.py [--top N] [--tools PREFIX] ELF -- QEMU_COMMAND...
  e.g. scripts/profile-target.py build/firmware/qemu-m0/firmware.elf -- \\
         qemu-system-arm -M microbit -nographic -monitor none -serial none -icount shift=0 \\
         -semihosting-config enable=on,target=native,arg=firmware,arg=/tmp/s,arg=/tmp/r \\
         -kernel build/firmware/qemu-m0/firmware.elf
(make profile-target BOARD=qemu-m0 builds that command line from the board's.)
PREFIX is the toolchain's (arm-none-eabi- by default) for nm and addr2line.
"""
import argparse
import bisect
import collections
import os
import subprocess
import sys
import tempfile


def count_blocks(log):
    """Instructions executed at each guest address, from QEMU's log lines."""
    block_addresses = {}  # translated block (host pointer) -> its guest addresses
    executions = collections.Counter()
    listing = None
    for line in log:
        if line.startswith('Trace'):
            block = line.split(' ', 3)[2]
            if listing is not None:  # the first execution follows the block's listing
                block_addresses[block] = listing
                listing = None
            executions[block] += 1
        elif line.startswith('0x') and listing is not None:
            listing.append(int(line[:line.index(':')], 16))
        elif line.startswith('IN:'):
            listing = []
    per_address = collections.Counter()
    entries = collections.Counter()
    for block, n in executions.items():
        addresses = block_addresses.get(block, ())
        for address in addresses:
            per_address[address] += n
        if addresses:
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


def run_logged(qemu):
    """Runs QEMU with its log into a pipe and counts it as it comes."""
    with tempfile.TemporaryDirectory() as scratch:
        fifo = os.path.join(scratch, 'log')
        os.mkfifo(fifo)
        guest = subprocess.Popen(qemu + ['-d', 'in_asm,exec,nochain', '-D', fifo],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(fifo, errors='replace') as log:
            counts = count_blocks(log)
        if guest.wait() != 0:
            sys.exit('profile-target: QEMU exited with status %d' % guest.returncode)
    return counts


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument('--top', type=int, default=30)
    parser.add_argument('--tools', default='arm-none-eabi-')
    parser.add_argument('elf')
    parser.add_argument('qemu', nargs=argparse.REMAINDER)
    args = parser.parse_args()
    qemu = args.qemu[1:] if args.qemu[:1] == ['--'] else args.qemu
    if not qemu:
        parser.error('the QEMU command line follows --')
    per_address, entries = run_logged(qemu)
    total = sum(per_address.values())
    if total == 0:
        sys.exit('profile-target: no instructions logged (did the firmware start?)')
    table = symbols(args.tools, args.elf)
    starts = [start for start, _, _ in table]
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
    print_table('functions', functions, total, args.top, calls)
    print_table('files', files, total, args.top)
    print_table('lines', lines, total, args.top)


if __name__ == '__main__':
    main()
