#!/usr/bin/env python3
"""Where an emulated board spends its instructions: a statistical profiler.

Runs the firmware under QEMU with its gdbstub, stops it at random moments, reads
the program counter and maps the samples to functions and source lines of the ELF
(arm-none-eabi-nm and -addr2line, -g builds). Under -icount shift=0 virtual time is
instruction count, and it stands still while the guest is stopped, so the samples
are uniform over executed instructions whatever the host's load; a few thousand
give each entry to about a percent. Inlined code counts where it was inlined.

Usage: scripts/profile-target.py [--samples N] [--top N] ELF -- QEMU_COMMAND...
  e.g. scripts/profile-target.py build/firmware/qemu-m0/firmware.elf -- \\
         qemu-system-arm -M microbit -nographic -monitor none -serial none -icount shift=0 \\
         -semihosting-config enable=on,target=native,arg=firmware,arg=/tmp/s,arg=/tmp/r \\
         -kernel build/firmware/qemu-m0/firmware.elf
(make profile-target BOARD=qemu-m0 builds that command line from the board's.)
Cortex-M only: the register layout is QEMU's for Arm (r0..r15).
"""
import argparse
import bisect
import collections
import random
import socket
import subprocess
import sys
import time


class GdbStub:
    """Just enough of the GDB remote protocol: continue, interrupt, read registers."""

    def __init__(self, port):
        for _ in range(200):
            try:
                self.sock = socket.create_connection(('127.0.0.1', port))
                break
            except OSError:
                time.sleep(0.05)
        else:
            sys.exit('profile-target: QEMU did not open its gdbstub on port %d' % port)
        self.stream = self.sock.makefile('rb')

    def send(self, data):
        self.sock.sendall(b'$' + data + b'#' + b'%02x' % (sum(data) & 255))
        if self.stream.read(1) != b'+':
            raise OSError('no acknowledgement')

    def receive(self):
        while self.stream.read(1) != b'$':
            pass
        data = b''
        c = self.stream.read(1)
        while c != b'#':
            if not c:
                raise OSError('connection closed')
            data += c
            c = self.stream.read(1)
        self.stream.read(2)
        self.sock.sendall(b'+')
        return data

    def sample_pc(self, run_seconds):
        """Lets the guest run, stops it, returns its pc (None when it has exited)."""
        self.send(b'c')
        time.sleep(run_seconds)
        self.sock.sendall(b'\x03')
        reply = self.receive()
        if reply[:1] in (b'W', b'X'):
            return None
        self.send(b'g')
        registers = bytes.fromhex(self.receive()[:128].decode())
        return int.from_bytes(registers[60:64], 'little')


def symbols(elf):
    table = []
    out = subprocess.run(['arm-none-eabi-nm', '-n', elf], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        fields = line.split()
        if len(fields) == 3 and fields[1] in 'tTwW':
            table.append((int(fields[0], 16), fields[2]))
    return table


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument('--samples', type=int, default=3000)
    parser.add_argument('--top', type=int, default=30)
    parser.add_argument('elf')
    parser.add_argument('qemu', nargs=argparse.REMAINDER)
    args = parser.parse_args()
    qemu = args.qemu[1:] if args.qemu[:1] == ['--'] else args.qemu
    if not qemu:
        parser.error('the QEMU command line follows --')
    port = random.randint(20000, 40000)
    guest = subprocess.Popen(qemu + ['-gdb', 'tcp::%d' % port, '-S'],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    pcs = []
    try:
        stub = GdbStub(port)
        while len(pcs) < args.samples:
            pc = stub.sample_pc(random.uniform(0.0005, 0.003))
            if pc is None:
                break
            pcs.append(pc)
    except OSError:
        pass  # the guest exited while stopped or running
    finally:
        guest.kill()
    if not pcs:
        sys.exit('profile-target: no samples (did the firmware start?)')
    table = symbols(args.elf)
    starts = [address for address, _ in table]

    def function(pc):
        k = bisect.bisect_right(starts, pc & ~1) - 1
        return table[k][1] if k >= 0 else '?'

    lines = subprocess.run(['arm-none-eabi-addr2line', '-e', args.elf] + ['%#x' % pc for pc in pcs],
                           capture_output=True, text=True, check=True).stdout.splitlines()
    n = len(pcs)
    print('profile elf=%s samples=%d' % (args.elf, n))
    print('functions:')
    for name, count in collections.Counter(function(pc) for pc in pcs).most_common(args.top):
        print('%6.2f%% %s' % (100.0 * count / n, name))
    print('lines:')
    places = collections.Counter(line.split('/')[-1].split(' (')[0] for line in lines)
    for place, count in places.most_common(args.top):
        print('%6.2f%% %s' % (100.0 * count / n, place))


if __name__ == '__main__':
    main()
