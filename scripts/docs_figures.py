#!/usr/bin/env python3
"""Every measured figure of README.md and docs/, from the command that measures it.

    scripts/docs_figures.py write [--reuse]   measure, then rewrite the docs in place
    scripts/docs_figures.py check [--reuse]   measure, then name every figure that differs
    scripts/docs_figures.py list              every block, key and image, and what makes it

`make docs-figures` runs `write` (after `make sweep-docs` and `make firmware-run`);
tests/check_doc_figures.sh (in `make test`) runs `check --reuse`.

A document marks its figures three ways:

  * a block, rewritten whole:       <!-- figures:NAME -->  ...  <!-- /figures -->
  * a number in prose, with a key:  1286<!-- fig:board.qemu-m0.insn_per_pixel -->
    (an optional format after a colon: fig:KEY:comma gives 1,286, fig:KEY:kB 15.6)
  * an image: docs/images/NAME.png (or an animation, NAME.gif), rendered by tarn
    (IMAGES in the catalogue).

What each block, key and image is, and the command behind it, is
scripts/docs_figures_catalogue.py. Every figure has a kind, which says how `check`
compares it: exact (errors, bytes, counts: the same text), instructions (within
0.5%), derived from instructions (within what 0.5% of its inputs can move it), or a
wall time (never compared: the machine's load moves it). `write` leaves a figure
whose measurement this run did not make (a wall time, when sweep-docs did not run)
as it is. Numbers that are not measurements (sizes, formats, limits) stay typed;
a limit quoted from the code has a key that reads the code.

--reuse takes what `make test` has already measured instead of measuring it again:
the emulated boards' runs (build/firmware/*/report.txt, by make bench-target, which
rebuilds nothing that is up to date) and the water cost of tests/check_water_cost.sh
(build/release/water-cost.txt). Measurements go to build/figures/ (values.txt: every
key's and block figure's value as measured).
"""

import concurrent.futures
import difflib
import hashlib
import os
import re
import shlex
import struct
import subprocess
import sys
import threading
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARN = os.environ.get("TARN_BIN", "build/release/tarn")
OUT = "build/figures"
DOCS = ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(ROOT, "docs")) if f.endswith(".md")) + \
    sorted("boards/%s/README.md" % b for b in os.listdir(os.path.join(ROOT, "boards"))
           if os.path.exists(os.path.join(ROOT, "boards", b, "README.md")))

# a block may be indented (inside a list item): its lines all are, by its marker's indent
BLOCK_RE = re.compile(r"^([ \t]*)<!-- figures:([\w.-]+) -->\n(.*?)^[ \t]*<!-- /figures -->", re.S | re.M)
# the value is the run of number-like characters right before the key's comment (or
# digits grouped by single spaces, as 115 211)
KEY_RE = re.compile(r"(\d{1,3}(?: \d{3})+|[\w.,%+-]*)<!-- fig:([\w.-]+)(?::(\w+))? -->")


# The frame times (FW_TIMES, ms) of a profiled run: one streamed frame (make
# profile-target draws nothing else) is enough for the shares, and QEMU's execution
# log, which the profile reads line by line, costs a minute a frame.
PROFILE_TIMES = "1000"


class MeasureError(Exception):
    pass


# ---- figures -----------------------------------------------------------------------

class Fig:
    """One measured figure: its text as published, its number, and the tolerance a
    check allows (0: the text must be the same). text None: not measured this run."""

    def __init__(self, text, num=None, tol=0.0, label=""):
        self.text = text
        self.num = num
        self.tol = tol
        self.label = label

    def __repr__(self):
        return "Fig(%r)" % self.text

    def fmt(self, style):
        """The same figure in another format: comma (1,286), kB (15.6 for 15,576
        bytes), int (rounded)."""
        if self.text is None or style in (None, "plain"):
            return self
        n = self.num
        if style == "comma":
            text = "{:,}".format(int(round(n))) if float(n).is_integer() or self.tol else "{:,}".format(n)
            return Fig(text, n, self.tol, self.label)
        if style == "kB":
            return Fig("%.1f" % (n / 1000.0), n / 1000.0, max(self.tol / 1000.0, 0.05 if self.tol else 0),
                       self.label)
        if style == "int":
            return Fig("%d" % round(n), n, self.tol, self.label)
        raise MeasureError("unknown format '%s'" % style)


def exact(text):
    """A figure the code gives to the digit: an error, a byte count."""
    text = str(text)
    return Fig(text, number(text), 0.0)


def insn(n, style="plain"):
    """An instruction count: the same code gives the same count, but a neighbour's
    change moves code and data by a few instructions; checked within 0.5%."""
    return Fig(str(int(round(n))), float(n), 0.005 * abs(n)).fmt(style)


def wall(text):
    """A wall time: measured and published, never compared."""
    return Fig(text, None, None)


def derived(value, tol, digits=0, sign=False, suffix=""):
    """A figure computed from others (a share, a difference) with the tolerance its
    inputs' tolerances give it."""
    text = ("%+.*f" if sign else "%.*f") % (digits, value) + suffix
    return Fig(text, round(value, digits), tol)


def number(text):
    if text is None:
        return None
    t = text.replace(",", "").replace("%", "").replace(" ", "").replace("+", "")
    try:
        return float(t)
    except ValueError:
        return None


def pct_less(a, b, digits=0):
    """How much less a is than b, in percent of b (instruction counts)."""
    v = 100.0 * (1.0 - a.num / b.num)
    tol = 100.0 * (a.num / b.num) * ((a.tol or 0) / a.num + (b.tol or 0) / b.num) if a.num and b.num else 0
    return derived(v, tol, digits, suffix="%")


def pct_more(a, b, digits=0):
    """How much more a is than b, in percent of b (instruction counts)."""
    v = 100.0 * (a.num / b.num - 1.0)
    tol = 100.0 * (a.num / b.num) * ((a.tol or 0) / a.num + (b.tol or 0) / b.num) if a.num and b.num else 0
    return derived(v, tol, digits, suffix="%")


def diff(a, b, digits=0, sign=False):
    """a - b, with both tolerances."""
    return derived(a.num - b.num, (a.tol or 0) + (b.tol or 0), digits, sign)


def ratio(a, b, digits=1):
    v = a.num / b.num if b.num else 0.0
    tol = v * ((a.tol or 0) / a.num + (b.tol or 0) / b.num) if a.num and b.num else 0
    return derived(v, tol, digits)


def same(a, b):
    """Compares a published text with a measured figure: None, or why they differ."""
    if b.text is None or b.tol is None:
        return None
    if b.tol == 0:
        return None if a == b.text else "differs"
    p = number(a)
    if p is None:
        return "is not a number"
    # the published number was rounded to its last digit: half of that is slack too
    digits = a.replace(",", "").rstrip("%").split(".")
    slack = 0.5 * 10 ** -len(digits[1]) if len(digits) > 1 else 0.5
    return None if abs(p - b.num) <= b.tol + slack else "differs by more than %.3g" % b.tol


# ---- measurements ---------------------------------------------------------------------

class Placeholder(dict):
    """What a measurement returns while the catalogue is only being read for what it
    needs: a figure of 1, whose every field is a figure of 1 too."""
    text, num, tol, label = "1", 1.0, 0.0, ""

    def __missing__(self, key):
        return Fig("1", 1.0, 0.0)

    def fmt(self, style):
        return Fig("1", 1.0, 0.0)


def run(argv, **kw):
    """Runs a command from the repository root; its stdout, or MeasureError naming it."""
    try:
        p = subprocess.run(argv, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)
    except OSError as e:
        raise MeasureError("%s: %s" % (" ".join(argv), e))
    if p.returncode != 0:
        raise MeasureError("%s exited with status %d:\n%s%s" % (" ".join(shlex.quote(a) for a in argv),
                                                                p.returncode, p.stdout[-2000:], p.stderr[-2000:]))
    return p.stdout


def fields(line):
    """NAME=value words of a line."""
    return dict(w.split("=", 1) for w in line.split() if "=" in w)


def scene_path(scene):
    return scene if scene.endswith(".json") else "scenes/%s.json" % scene


def png_pixels(path):
    """(width, height, colour type, raw rows) of an 8-bit non-interlaced PNG."""
    with open(os.path.join(ROOT, path), "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise MeasureError("%s is not a PNG" % path)
    pos, idat, head = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            head = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = head
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or interlace or channels is None:
        raise MeasureError("%s: only 8-bit, non-interlaced grey or RGB(A) PNGs are read here" % path)
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, prev, at = [], bytearray(stride), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


class Measurer:
    """Every measurement the catalogue asks for. First the catalogue is read with
    `recording` on: each call notes what it needs and returns placeholders. Then
    `measure_all` makes the measurements (the slow ones two at a time), and the
    catalogue is read again with the real values."""

    def __init__(self, reuse=False, log=None):
        self.reuse = reuse
        self.recording = False
        self.pending = []
        self.cache = {}
        self.lock = threading.RLock()
        self.log = log or (lambda s: None)
        os.makedirs(os.path.join(ROOT, OUT), exist_ok=True)

    # each public method: a request, measured once
    def _get(self, req):
        if req in self.cache:
            return self.cache[req]
        if self.recording:
            if req not in self.pending:
                self.pending.append(req)
            return Placeholder() if req[0] != "output" else None
        with self.lock:  # one at a time: two tools may ask for the same board's build
            if req not in self.cache:
                self.cache[req] = self._measure(req)
        return self.cache[req]

    def compare(self, scene, args="", time=None):
        """tarn compare's line: psnr maxerr over2 over8 shading_psnr shading_over2
        panel_psnr coverage, each to the digit."""
        return self._get(("compare", scene, args, time))

    def host(self, scene, args=""):
        """Host instructions of tarn render's frames (callgrind, tarn_render_frame
        inclusive): insn_per_pixel (one frame), total."""
        return self._get(("host", scene, args))

    def sweep_cost(self, scene, args=""):
        """A sweep point's host instructions per pixel, as tarn sweep counts them
        (its cost worker under callgrind, 1000 ms, a sink that keeps nothing)."""
        return self._get(("sweep_cost", scene, args))

    def sweep_point(self, scene, args=""):
        """A sweep point as tarn sweep measures it: the yardstick at 1000 ms, and
        host = its host cost."""
        d = dict(self.compare(scene, args, 1000))
        d["host"] = self.sweep_cost(scene, args)
        return Placeholder(d) if self.recording else d

    def bench(self, board, scene=None, flags=None, may_fail=False, own_scene=None, make_vars=()):
        """make bench-target's line for a board's own build (scene None), for the
        build of another of the board's own scenes (own_scene: one of its
        BOARD_SCENES but the first), or for a build of another scene or bake flags
        in a directory of its own, with the board's variables `make_vars`
        ("NAME=value" each: another BOARD_CORE_SPLIT, BOARD_RAM_CODE) where given;
        the run's report fields too (frame_insn, counter_check). may_fail: a build
        that fails gives {"failed": its output} instead of stopping the
        measurement."""
        value = self._get(("bench", board, scene, flags, own_scene, tuple(make_vars)))
        if isinstance(value, MeasureError):
            if may_fail:
                return {"failed": str(value)}
            raise value
        return value

    def profile(self, board):
        """make profile-target's stages for a board's own build: each stage's
        instructions a pixel over the run's frames (stage name -> Fig), and
        "frames", the frames they were counted over."""
        return self._get(("profile", board))

    def memory(self, scene, args=""):
        return self._get(("memory", scene, args))

    def build(self, board):
        """A board's own build, sized without running it (the real boards): text,
        data, bss, flash_bytes, ram_bytes, scene_bytes and code_bytes as
        firmware/image_sizes.sh gives them, stack_bytes (the static bound), memory_bytes (its scene's, as
        baked), piece_width and piece_rows (the largest tile or strip it sends), pipeline_memory_bytes
        where it is baked in strips (a strip pipeline's), and uf2_bytes where the build makes a UF2
        file."""
        return self._get(("build", board))

    def bake(self, scene, args=""):
        """tarn bake's line (const_bytes, memory_bytes), its header's byte table
        (bytes.mesh ...), and each array's element count (count.SYMBOL)."""
        return self._get(("bake", scene, args))

    def code(self, path, pattern):
        """A limit quoted from the code: the first group of `pattern` in `path`."""
        return self._get(("code", path, pattern))

    def output(self, name):
        """A tool's whole output (TOOLS in the catalogue)."""
        return self._get(("output", name))

    # ---- making them ----
    def measure_all(self, tools):
        """Every pending measurement: the firmware builds two at a time (each build is
        mostly serial), then callgrind runs and tools two at a time, the quick ones
        meanwhile."""
        self.tools = tools
        pending, self.pending = self.pending, []
        sweeps = {}
        for r in pending:
            if r[0] == "sweep_cost":
                sweeps.setdefault(r[1], []).append(r[2])
        # a board's own builds share its directories (bench-target of a board runs each
        # of its scenes, profile-target its first): one at a time, each board's in turn
        boards = {}
        for r in pending:
            if r[0] in ("bench", "build", "profile"):
                own = r[0] != "bench" or r[2] is None or r[4] is not None
                boards.setdefault(("board", r[1]) if own else r, []).append(r)
        # the tools first in the second phase: one of them profiles a board, the longest
        # job there, which started last would end the phase on one core
        phases = [[("serial", tuple(jobs)) for jobs in boards.values()],
                  [r for r in pending if r[0] == "output"] +
                  [("sweep_batch", scene, tuple(args)) for scene, args in sweeps.items()] +
                  [r for r in pending if r[0] == "host"]]
        quick = [r for r in pending if r[0] not in ("bench", "build", "profile", "host", "output", "sweep_cost")]
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            for k, jobs in enumerate(phases):
                futures = {pool.submit(self._measure, j): j for j in jobs}
                if k == 1:
                    for r in quick:
                        self._get(r)
                for f in concurrent.futures.as_completed(futures):
                    j = futures[f]
                    if j[0] == "sweep_batch":
                        for args, value in zip(j[2], f.result()):
                            self.cache[("sweep_cost", j[1], args)] = value
                    elif j[0] == "serial":
                        for one, value in zip(j[1], f.result()):
                            self.cache[one] = value
                    else:
                        self.cache[j] = f.result()

    def _m_serial(self, jobs):
        """Measurements that must not run beside each other, in turn."""
        return [self._measure(j) for j in jobs]

    def _measure(self, req):
        kind = req[0]
        if kind == "serial":
            return self._m_serial(req[1])
        self.log("measure: %s" % " ".join(str(x) for x in req if x is not None))
        try:
            return getattr(self, "_m_" + kind)(*req[1:])
        except MeasureError as e:
            if kind == "bench":  # kept, for bench(may_fail=True) to see
                return e
            raise

    def _m_compare(self, scene, args, time):
        argv = [TARN, "compare", scene_path(scene)] + shlex.split(args)
        if time is not None:
            argv += ["--time", str(time)]
        line = [ln for ln in run(argv).splitlines() if ln.startswith("compare ")][-1]
        return {k: exact(v) for k, v in fields(line).items()}

    def _callgrind(self, argv, tag):
        """Runs argv under callgrind, counting inside tarn_render_frame; the profile's
        path (a dump at each CALLGRIND_DUMP_STATS goes beside it, PATH.1 onward)."""
        folder = os.path.join(ROOT, OUT, "callgrind")
        os.makedirs(folder, exist_ok=True)
        out = os.path.join(folder, tag + ".cg")
        for f in os.listdir(folder):
            if f.startswith(tag + ".cg"):
                os.remove(os.path.join(folder, f))
        run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, "--collect-atstart=no",
             "--toggle-collect=tarn_render_frame", "--dump-instr=no"] + argv)
        return out

    def _m_host(self, scene, args):
        tag = "host-" + hashlib.sha1((scene + "\0" + args).encode()).hexdigest()[:12]
        png = os.path.join(OUT, "callgrind", tag + ".png")
        argv = shlex.split(args)
        out = self._callgrind([TARN, "render", scene_path(scene), "-o", png] + argv, tag)
        with open(out) as f:
            total = int(re.search(r"^summary: (\d+)", f.read(), re.M).group(1))
        frames = int(argv[argv.index("--frames") + 1]) if "--frames" in argv else 1
        first = png if frames == 1 else png[:-4] + "-0000.png"
        w, h, _, _ = png_pixels(first)
        return {"insn_per_pixel": insn(total / (w * h * frames)), "total": insn(total), "pixels": exact(w * h)}

    def _m_sweep_batch(self, scene, args_list):
        tag = "sweep-" + hashlib.sha1((scene + "\0" + "\0".join(args_list)).encode()).hexdigest()[:12]
        points = os.path.join(ROOT, OUT, "callgrind", tag + ".txt")
        os.makedirs(os.path.dirname(points), exist_ok=True)
        with open(points, "w") as f:
            f.write("".join((a or "--quality balanced") + "\n" for a in args_list))
        out = self._callgrind([os.path.join(ROOT, TARN), "sweep-cost-worker", scene_path(scene), points], tag)
        size = run([TARN, "memory", scene_path(scene)])
        w, h = map(int, fields(size)["size"].split("x"))
        costs = [None] * len(args_list)
        for f in os.listdir(os.path.dirname(out)):
            if not f.startswith(tag + ".cg"):
                continue
            with open(os.path.join(os.path.dirname(out), f)) as fh:
                text = fh.read()
            m = re.search(r"^desc: Trigger: Client Request: point (\d+)", text, re.M)
            if m:
                costs[int(m.group(1))] = insn(int(re.search(r"^summary: (\d+)", text, re.M).group(1)) / (w * h))
        if None in costs:
            raise MeasureError("the sweep's cost worker measured %d of %d points of %s" %
                               (len(costs) - costs.count(None), len(costs), scene))
        return costs

    def _m_bench(self, board, scene, flags, own_scene, make_vars):
        argv = ["make", "--no-print-directory", "-s", "bench-target", "BOARD=" + board] + list(make_vars)
        if own_scene is not None:
            # where firmware/firmware.mk builds a board's scene after its first
            argv.append("FW_BOARD_SCENE=" + scene_path(own_scene))
            fw_dir = "build/firmware/%s@%s" % (board, os.path.basename(scene_path(own_scene))[:-len(".json")])
        elif scene is not None:
            # short: the emulator's semihosting takes the stream's path, and long ones fail
            slug = "%s-%s" % (board, hashlib.sha1("\0".join((scene, flags or "") + make_vars).encode()).hexdigest()[:10])
            fw_dir = os.path.join(OUT, "fw", slug)
            argv += ["SCENE=" + scene_path(scene), "BAKE_FLAGS=" + (flags or ""), "FW_BUILD_DIR=" + fw_dir]
        else:
            fw_dir = os.path.join("build/firmware", board)
        out = run(argv)
        with open(os.path.join(ROOT, fw_dir, "report.txt")) as f:
            report = fields(f.read().strip())
        # a board of several scenes prints a line for each: this build's is its scene's
        lines = [ln for ln in out.splitlines() if ln.startswith("target ") and fields(ln).get("scene") ==
                 report.get("scene")]
        if not lines:
            raise MeasureError("make bench-target BOARD=%s printed no target line for scene %s" %
                               (board, report.get("scene")))
        values = {}
        for k, v in list(report.items()) + list(fields(lines[-1]).items()):
            if k in ("insn_per_pixel", "render_insn_per_pixel", "parts_insn_per_pixel"):
                values[k] = insn(int(v))
            elif k == "frame_insn":
                values[k] = [insn(int(x)) for x in v.split(",")]
            elif k == "counter_check":  # a loop of `want` instructions, within 0.01%
                got, want = v.split("/")
                values[k] = Fig(got, float(got), 0.0001 * float(want))
                values[k + "_loop"] = exact(want)
            else:
                values[k] = exact(v)
        return values

    def _m_profile(self, board):
        # make profile-target runs the streamed frame alone, on one core
        fw_dir = os.path.join(OUT, "profile", board)
        out = run(["make", "--no-print-directory", "-s", "profile-target", "BOARD=" + board, "TOP=20",
                   "FW_TIMES=" + PROFILE_TIMES, "FW_BUILD_DIR=" + fw_dir])
        with open(os.path.join(ROOT, fw_dir, "profile.report")) as f:
            report = fields(f.read().strip())
        frames = len(report["frame_insn"].split(","))
        width, height = map(int, report["size"].split("x"))
        stages, inside = {}, False
        for line in out.splitlines():
            if line.startswith("stages:"):
                inside = True
            elif inside and line.startswith(" "):
                count, _, name = line.split(None, 2)
                stages[name.strip()] = insn(int(count) / (frames * width * height))
            elif inside:
                break
        if not stages:
            raise MeasureError("make profile-target BOARD=%s printed no stages" % board)
        stages["frames"] = exact(frames)
        return stages

    def _m_build(self, board):
        run(["make", "--no-print-directory", "-s", "firmware", "BOARD=" + board])
        fw_dir = os.path.join("build/firmware", board)
        with open(os.path.join(ROOT, fw_dir, "firmware.conf")) as f:
            conf = dict(line.rstrip("\n").split("=", 1) for line in f if "=" in line)
        elf = os.path.join(fw_dir, "firmware.elf")
        sizes = {k: int(v) for k, v in fields(run(["firmware/image_sizes.sh", conf["cross"], elf])).items()}
        bound = run(["firmware/stack_bound.sh", conf["cross"], os.path.join(fw_dir, "obj")] +
                    conf["stack_entry"].split())
        with open(os.path.join(ROOT, fw_dir, "scene.h")) as f:
            header = f.read()
        memory = re.search(r"^#define SCENE_MEMORY_BYTES (\d+)", header, re.M).group(1)
        values = dict(sizes, stack_bytes=int(fields(bound.splitlines()[0])["stack_bytes"]), memory_bytes=int(memory))
        for name in ("PIECE_WIDTH", "PIECE_ROWS"):
            values[name.lower()] = int(re.search(r"^#define SCENE_%s (\d+)" % name, header, re.M).group(1))
        pipeline = re.search(r"^#define SCENE_PIPELINE_MEMORY_BYTES (\d+)", header, re.M)
        if pipeline:  # a frame in strips: two workers' shared memory too
            values["pipeline_memory_bytes"] = int(pipeline.group(1))
        uf2 = os.path.join(ROOT, fw_dir, "firmware.uf2")
        if os.path.exists(uf2):
            values["uf2_bytes"] = os.path.getsize(uf2)
        return {k: exact(str(v)) for k, v in values.items()}

    def _m_memory(self, scene, args):
        line = run([TARN, "memory", scene_path(scene)] + shlex.split(args)).strip().splitlines()[-1]
        return {k: exact(v) for k, v in fields(line).items()}

    def _m_bake(self, scene, args):
        tag = hashlib.sha1((scene + "\0" + args).encode()).hexdigest()[:12]
        path = os.path.join(OUT, "bake", "b%s.c" % tag)
        os.makedirs(os.path.join(ROOT, os.path.dirname(path)), exist_ok=True)
        line = run([TARN, "bake", scene_path(scene), "-o", path] + shlex.split(args)).strip().splitlines()[-1]
        values = {k: exact(v) for k, v in fields(line).items()}
        with open(os.path.join(ROOT, path)) as f:
            text = f.read()
        head = text[:text.index("*/")]
        for m in re.finditer(r"^ \*   ([a-z ]+?) +(\d+)$", head, re.M):
            values["bytes." + m.group(1).replace(" ", "_")] = exact(m.group(2))
        sizes = {"uint8_t": 1, "uint16_t": 2, "uint32_t": 4}
        for m in re.finditer(r"^(?:static )?const (\w+) %s_(\w+)\[(\d+)\]" % re.escape(values["scene"].text),
                             text, re.M):
            values["count." + m.group(2)] = exact(m.group(3))
            if m.group(1) in sizes:
                values["bytes." + m.group(2)] = exact(sizes[m.group(1)] * int(m.group(3)))
        for m in re.finditer(r"^/\* backdrop: the (\d+) colours .*? each named by a (\d+)-bit index", text, re.M):
            values["backdrop.colours"], values["backdrop.bits"] = map(exact, m.groups())
        return values

    def _m_code(self, path, pattern):
        with open(os.path.join(ROOT, path)) as f:
            m = re.search(pattern, f.read(), re.M)
        if not m:
            raise MeasureError("%s: no match for %s" % (path, pattern))
        return exact(m.group(1))

    def _m_output(self, name):
        return self.tools[name](self)



# ---- documents -------------------------------------------------------------------------

def render(parts):
    return "".join(p if isinstance(p, str) else p.text for p in parts)


def indented(parts, indent):
    """The parts with every line started by indent (the block's marker's)."""
    if not indent:
        return parts
    out, at_start = [], True
    for p in parts:
        if isinstance(p, str):
            out.append("\n".join(indent + line if line and (i > 0 or at_start) else line
                                 for i, line in enumerate(p.split("\n"))))
            if p:
                at_start = p.endswith("\n")
        else:
            if at_start:
                out.append(indent)
            out.append(p)
            at_start = False
    return out


def fill_keys(text, keys, m, problems, doc):
    """The text with every key's value measured; problems for unknown keys."""
    def one(match):
        value, key, style = match.groups()
        fig = key_fig(keys, key, style, m, problems, doc)
        if fig is None or fig.text is None:
            return match.group(0)
        return "%s<!-- fig:%s%s -->" % (fig.text, key, ":" + style if style else "")
    return KEY_RE.sub(one, text)


def key_fig(keys, key, style, m, problems, doc):
    fn = keys.get(key)
    if fn is None:
        problems.append("%s: fig:%s: no such key in scripts/docs_figures_catalogue.py" % (doc, key))
        return None
    fig = fn(m)
    if isinstance(fig, Placeholder):
        return Fig("1", 1.0)
    return fig.fmt(style)


def block_parts(blocks, name, m, problems, doc):
    fn = blocks.get(name)
    if fn is None:
        problems.append("%s: figures:%s: no such block in scripts/docs_figures_catalogue.py" % (doc, name))
        return None
    parts = fn(m)
    return [parts] if isinstance(parts, (str, Fig)) else list(parts)


def read_docs():
    docs = {}
    for d in DOCS:
        with open(os.path.join(ROOT, d)) as f:
            docs[d] = f.read()
    return docs


def walk(docs, cat, m, problems):
    """Reads every block and key of every doc through `m`."""
    for doc, text in docs.items():
        for match in BLOCK_RE.finditer(text):
            block_parts(cat.BLOCKS, match.group(2), m, problems, doc)
        for match in KEY_RE.finditer(text):
            key_fig(cat.KEYS, match.group(2), match.group(3), m, problems, doc)


def measure(cat, reuse, log):
    m = Measurer(reuse, log)
    docs = read_docs()
    problems = []
    m.recording = True
    walk(docs, cat, m, problems)
    m.recording = False
    m.measure_all(cat.TOOLS)
    return m, docs, problems


def write_values(m, docs, cat):
    """build/figures/values.txt: each key's and block figure's value, as measured."""
    lines = []
    for doc, text in docs.items():
        for match in KEY_RE.finditer(text):
            fig = key_fig(cat.KEYS, match.group(2), match.group(3), m, [], doc)
            if fig is not None:
                lines.append("%s\tfig:%s\t%s" % (doc, match.group(2), fig.text))
        for match in BLOCK_RE.finditer(text):
            for p in block_parts(cat.BLOCKS, match.group(2), m, [], doc) or []:
                if isinstance(p, Fig):
                    lines.append("%s\tfigures:%s\t%s\t%s" % (doc, match.group(2), p.label, p.text))
    with open(os.path.join(ROOT, OUT, "values.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")


def cmd_write(cat, reuse, log):
    m, docs, problems = measure(cat, reuse, log)
    for doc, text in docs.items():
        def block(match):
            indent, name = match.group(1), match.group(2)
            parts = block_parts(cat.BLOCKS, name, m, problems, doc)
            if parts is None:
                return match.group(0)
            body = render(indented(parts, indent))
            return "%s<!-- figures:%s -->\n%s%s%s<!-- /figures -->" % (indent, name, body,
                                                                       "" if body.endswith("\n") else "\n", indent)
        new = BLOCK_RE.sub(block, text)
        new = fill_keys(new, cat.KEYS, m, problems, doc)
        if new != text:
            with open(os.path.join(ROOT, doc), "w") as f:
                f.write(new)
            log("wrote %s" % doc)
    for path, argv in cat.IMAGES.items():
        run([TARN] + argv + ["-o", path])
        log("wrote %s" % path)
    write_values(m, docs, cat)
    for p in problems:
        print("docs-figures: " + p, file=sys.stderr)
    return 1 if problems else 0


def check_block(doc, name, published, parts):
    """Problems of one block: its text beyond the figures, then each figure."""
    pattern = "".join(re.escape(p) if isinstance(p, str) else "(.*?)" for p in parts)
    match = re.fullmatch(pattern, published, re.S)
    if match is None:
        fresh = render(parts).splitlines()
        for line in difflib.unified_diff(published.splitlines(), fresh, "published", "measured", n=0, lineterm=""):
            if line.startswith(("-", "+")) and not line.startswith(("---", "+++")):
                return ["%s: figures:%s: the block's text differs from what its command gives: %s" %
                        (doc, name, line)]
        return ["%s: figures:%s: the block differs from what its command gives" % (doc, name)]
    out = []
    figs, before = [], ""
    for p in parts:  # a figure without a label is named by the text before it (name=)
        if isinstance(p, str):
            before = p
        else:
            if not p.label:
                p = Fig(p.text, p.num, p.tol, before.split()[-1] if before.split() else "figure")
            figs.append(p)
    for got, fig in zip(match.groups(), figs):
        why = same(got, fig)
        if why:
            out.append("%s: figures:%s: %s: published %s, measured %s" % (doc, name, fig.label or "figure", got,
                                                                         fig.text))
    return out


def cmd_check(cat, reuse, log):
    m, docs, problems = measure(cat, reuse, log)
    for doc, text in docs.items():
        for match in BLOCK_RE.finditer(text):
            indent, name, body = match.groups()
            parts = block_parts(cat.BLOCKS, name, m, problems, doc)
            if parts is not None:
                parts = indented(parts, indent)
                if not render(parts).endswith("\n"):
                    parts.append("\n")
                problems += check_block(doc, name, body, parts)
        for match in KEY_RE.finditer(text):
            value, key, style = match.groups()
            fig = key_fig(cat.KEYS, key, style, m, problems, doc)
            if fig is None:
                continue
            why = same(value, fig)
            if why:
                line = text.count("\n", 0, match.start()) + 1
                problems.append("%s:%d: fig:%s: published %s, measured %s" % (doc, line, key, value or "nothing",
                                                                            fig.text))
    for path, argv in cat.IMAGES.items():
        fresh = os.path.join(OUT, "images", os.path.basename(path))
        os.makedirs(os.path.join(ROOT, os.path.dirname(fresh)), exist_ok=True)
        run([TARN] + argv + ["-o", fresh])
        if path.endswith(".gif"):  # one palette, chosen the same way each run: the same bytes
            if open(os.path.join(ROOT, path), "rb").read() != open(os.path.join(ROOT, fresh), "rb").read():
                problems.append("%s: differs from what `tarn %s` writes" % (path, " ".join(argv)))
            continue
        a, b = png_pixels(path), png_pixels(fresh)
        if a[:3] != b[:3]:
            problems.append("%s: %dx%d (%d channels), but `tarn %s` renders %dx%d (%d channels)" %
                            ((path,) + a[:3] + (" ".join(argv),) + b[:3]))
            continue
        bad = [(x, y) for y in range(a[1]) if a[3][y] != b[3][y]
               for x in range(a[0]) if a[3][y][x * a[2]:(x + 1) * a[2]] != b[3][y][x * b[2]:(x + 1) * b[2]]]
        if bad:
            x, y = bad[0]
            problems.append("%s: %d of %d pixels differ from `tarn %s` (the first at %d,%d: published %s, "
                            "rendered %s)" % (path, len(bad), a[0] * a[1], " ".join(argv), x, y,
                                              a[3][y][x * a[2]:(x + 1) * a[2]].hex(),
                                              b[3][y][x * b[2]:(x + 1) * b[2]].hex()))
    write_values(m, docs, cat)
    for p in problems:
        print("FAIL: " + p)
    keys = sum(len(KEY_RE.findall(t)) for t in docs.values())
    blocks = sum(len(BLOCK_RE.findall(t)) for t in docs.values())
    print("docs-figures: %d blocks, %d keyed figures, %d images: %d problems" %
          (blocks, keys, len(cat.IMAGES), len(problems)))
    return 1 if problems else 0


def cmd_list(cat):
    for name in sorted(cat.BLOCKS):
        print("block  %s: %s" % (name, (cat.BLOCKS[name].__doc__ or "").strip().splitlines()[0]))
    for key in sorted(cat.KEYS):
        print("key    %s" % key)
    for path, argv in sorted(cat.IMAGES.items()):
        print("image  %s: tarn %s" % (path, " ".join(argv)))
    return 0


def main(argv):
    sys.modules.setdefault("docs_figures", sys.modules[__name__])  # one module, run or imported
    import docs_figures_catalogue as cat
    os.chdir(ROOT)
    # The makes run below are makes of their own, each with the Makefile's jobs: a
    # calling make's jobserver (MAKEFLAGS) would not reach them through subprocess,
    # which closes its descriptors.
    for var in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL"):
        os.environ.pop(var, None)
    reuse = "--reuse" in argv
    quiet = "--quiet" in argv
    args = [a for a in argv if not a.startswith("--")]
    log = (lambda s: None) if quiet else (lambda s: print("docs-figures: " + s, file=sys.stderr, flush=True))
    try:
        if args == ["write"]:
            return cmd_write(cat, reuse, log)
        if args == ["check"]:
            return cmd_check(cat, reuse, log)
        if args == ["list"]:
            return cmd_list(cat)
    except MeasureError as e:
        print("docs-figures: %s" % e, file=sys.stderr)
        return 1
    print(__doc__.strip().split("\n\n")[1], file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
