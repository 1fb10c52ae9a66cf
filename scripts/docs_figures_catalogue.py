"""What every figure of README.md and docs/ is, and the command that measures it
(scripts/docs_figures.py reads and writes them).

BLOCKS: a block's name -> a function of the measurer giving the block's text, its
    figures as Fig parts (their kinds say how each is checked).
KEYS: a key -> a function of the measurer giving one figure.
IMAGES: a PNG (or an animated GIF) in docs/ -> the tarn command (without -o) that renders it.
TOOLS: a tool's name -> a function running it, whose output blocks and keys read.
"""

import os
import re
import subprocess

from docs_figures import (OUT, PROFILE_TIMES, ROOT, TARN, Fig, MeasureError, Placeholder, derived, diff, exact, insn,
                          pct_less, pct_more, ratio, run, wall)

BLOCKS = {}
KEYS = {}
TOOLS = {}

IMAGES = {"docs/images/%s.png" % s: ["render", "scenes/%s.json" % s]
          for s in ("pond", "beach", "murky", "lake", "underwater")}
# the README's first picture: the orbiting pond's whole 8-second circle, 10 frames a
# second, so that the loop meets itself
IMAGES["docs/images/pond-orbit.gif"] = ["render", "scenes/pond-orbit.json", "--frames", "80", "--fps", "10",
                                        "--quiet"]


def block(fn):
    BLOCKS[fn.__name__.replace("_", "-")] = fn
    return fn


def tool(fn):
    TOOLS[fn.__name__] = fn
    return fn


def labelled(fig, label):
    return Fig(fig.text, fig.num, fig.tol, label)


def table(header, rows, align=None):
    """A Markdown table; a cell is text, a Fig, or a list of both. Each Fig is
    labelled with its row's first cell and its column's header."""
    parts = ["| " + " | ".join(header) + " |\n",
             "| " + " | ".join(align or ["---"] * len(header)) + " |\n"]
    for row in rows:
        parts.append("|")
        for i, cell in enumerate(row):
            label = "%s / %s" % (re.sub(r"[`*]", "", str(row[0]) if isinstance(row[0], str) else row[0].text),
                                 header[i])
            parts.append(" ")
            for p in (cell if isinstance(cell, list) else [cell]):
                if isinstance(p, Fig):  # a figure already named (psnr) keeps its name after the cell's
                    p = labelled(p, "%s (%s)" % (label, p.label) if p.label else label)
                parts.append(p)
            parts.append(" |")
        parts.append("\n")
    return parts


def code_block(parts):
    return ["```\n"] + parts + ["```\n"]


# ---- the yardstick ---------------------------------------------------------------

def named(c, field):
    """A compare line's field, named by it in a failure."""
    return labelled(c[field], field)


def yard_whole(c):
    """PSNR / max error / >2 / >8 against the continuous reference."""
    return [named(c, "psnr"), " dB / ", named(c, "maxerr"), " / ", named(c, "over2"), " / ", named(c, "over8")]


def yard_shading(c):
    return [named(c, "shading_psnr"), " dB / ", named(c, "shading_over2")]


YARD_HEADER = ["whole: PSNR / max / >2 / >8", "shading: PSNR / >2", "panel PSNR", "coverage"]


def yard_cells(c):
    return [yard_whole(c), yard_shading(c), [c["panel_psnr"], " dB"], c["coverage"]]


# ---- README.md ----------------------------------------------------------------------

@block
def readme_compare(m):
    """tarn compare scenes/pond.json: the line it prints."""
    c = m.compare("pond")
    return code_block(["compare scene=pond size=240x240 time=0 psnr=", c["psnr"], " maxerr=", c["maxerr"],
                       " over2=", c["over2"], " over8=", c["over8"], " shading_psnr=", c["shading_psnr"],
                       " shading_over2=", c["shading_over2"], " panel_psnr=", c["panel_psnr"], " coverage=",
                       c["coverage"], "\n"])


def board_mk_value(board, name):
    """A variable's value in a board's board.mk (the last it sets), or in the board.mk
    it includes before it (qemu-m0-backdrop includes qemu-m0's); None if neither
    sets it."""
    value = None
    with open(os.path.join(ROOT, "boards/%s/board.mk" % board)) as f:
        for line in f:
            found = re.match(r"^%s\s*:?=\s*(.*)$" % re.escape(name), line)
            included = re.match(r"^include boards/([\w-]+)/board\.mk$", line)
            if found:
                value = found.group(1).strip()
            elif included and value is None:
                value = board_mk_value(included.group(1), name)
    return value


def board_scenes(board):
    """A board's scenes, by name (pond for scenes/pond.json), as its BOARD_SCENES
    lists them: make bench-target prints a line for each."""
    return [os.path.basename(s)[:-len(".json")] for s in board_mk_value(board, "BOARD_SCENES").split()]


def board_bench(m, board, scene):
    """make bench-target's line for one of a board's scenes."""
    return m.bench(board) if scene == board_scenes(board)[0] else m.bench(board, own_scene=scene)


def board_key(board, field, scene=None):
    return lambda m: board_bench(m, board, scene or board_scenes(board)[0])[field]


BOARDS = ("qemu-m0", "qemu-m0-backdrop", "qemu-m0-still", "qemu-m0-264k", "qemu-m3", "qemu-rv32", "qemu-rv32-400k")
BENCH_FIELDS = ("insn_per_pixel", "render_insn_per_pixel", "parts_insn_per_pixel", "ram_bytes", "flash_bytes", "stack_bytes",
                "scene_bytes", "code_bytes", "stack_peak_bytes", "stack_reserved_bytes", "panel_psnr")
# board.BOARD.FIELD: the board's first scene; board.BOARD.SCENE.FIELD: each of its scenes
for _b in BOARDS:
    for _f in BENCH_FIELDS:
        KEYS["board.%s.%s" % (_b, _f)] = board_key(_b, _f)
        for _s in board_scenes(_b):
            KEYS["board.%s.%s.%s" % (_b, _s, _f)] = board_key(_b, _f, _s)


def link_length(board, region):
    """A board's memory region in bytes, from its link.ld (LENGTH = 256K)."""
    def fn(m):
        v = m.code("boards/%s/link.ld" % board, r"^\s*%s\b.*LENGTH\s*=\s*(\d+K)" % region)
        if isinstance(v, Placeholder):
            return Fig("1", 1.0)
        return exact(int(v.text[:-1]) * 1024)
    return fn


# The real boards: their own build, sized as tests/check_firmware.sh sizes it (they
# do not run here), in their README.
REAL_BOARDS = ("rp2040-st7789", "stm32f411-st7789")
for _b in REAL_BOARDS:
    for _f in ("text", "data", "bss", "flash_bytes", "ram_bytes", "scene_bytes", "code_bytes", "stack_bytes",
               "memory_bytes"):
        KEYS["real.%s.%s" % (_b, _f)] = (lambda b, f: lambda m: comma(m.build(b)[f]))(_b, _f)
    for _r in ("FLASH", "RAM"):
        KEYS["limit.%s.%s" % (_b, _r.lower())] = (lambda f: lambda m: comma(f(m)))(link_length(_b, _r))
    KEYS["real.%s.ram_left" % _b] = (lambda b: lambda m: Fig("1", 1.0) if m.recording else comma(exact(
        link_length(b, "RAM")(m).num - m.build(b)["ram_bytes"].num)))(_b)
KEYS["real.rp2040-st7789.pipeline_memory_bytes"] = lambda m: comma(m.build("rp2040-st7789")["pipeline_memory_bytes"])
# SRAM4-5, apart from RAM: core 1's stack (boards/rp2040-st7789/link.ld's SCRATCH)
KEYS["real.rp2040-st7789.scratch_bytes"] = lambda m: comma(m.build("rp2040-st7789")["scratch_bytes"])
KEYS["limit.rp2040-st7789.scratch"] = (lambda f: lambda m: comma(f(m)))(link_length("rp2040-st7789", "SCRATCH"))


def piece_rgb565_bytes(m, board):
    """The RGB565 bytes of the largest tile or strip a board's build sends."""
    b = m.build(board)
    return 2 * b["piece_width"].num * b["piece_rows"].num


def rp2040_spi_hz(m):
    """SPI0's bit rate: clk_peri over the prescaler (boards/rp2040-st7789/panel_spi.c, SCR 0)."""
    peri = m.code("boards/rp2040-st7789/clock.h", r"^#define CLOCK_PERI_HZ (\d+)u").num
    return peri / m.code("boards/rp2040-st7789/panel_spi.c", r"^#define SPI_CPSDVSR (\d+)u").num


def stm32_spi_hz(m):
    """SPI1's bit rate: PCLK2 over the baud divider 2^(BR + 1) (boards/stm32f411-st7789/panel_spi.c)."""
    pclk2 = m.code("boards/stm32f411-st7789/clock.h", r"^#define CLOCK_PCLK2_HZ (\d+)u").num
    return pclk2 / 2 ** (m.code("boards/stm32f411-st7789/panel_spi.c", r"^#define SPI_BR_DIV4 (\d+)u").num + 1)


REAL_SPI_HZ = {"rp2040-st7789": rp2040_spi_hz, "stm32f411-st7789": stm32_spi_hz}
for _b, _spi in REAL_SPI_HZ.items():
    KEYS["real.%s.piece_bytes" % _b] = (lambda b: lambda m: Fig("1", 1.0) if m.recording else comma(exact(
        int(piece_rgb565_bytes(m, b)))))(_b)
    KEYS["real.%s.piece_ms" % _b] = (lambda b, spi: lambda m: Fig("1", 1.0) if m.recording else exact(
        "%.2f" % (1000.0 * 8 * piece_rgb565_bytes(m, b) / spi(m))))(_b, _spi)
    KEYS["real.%s.spi_mhz" % _b] = (lambda spi: lambda m: Fig("1", 1.0) if m.recording else exact(
        "%.2f" % (spi(m) / 1e6)))(_spi)
KEYS["real.stm32f411-st7789.piece_width"] = lambda m: m.build("stm32f411-st7789")["piece_width"]
KEYS["real.rp2040-st7789.uf2_bytes"] = lambda m: comma(m.build("rp2040-st7789")["uf2_bytes"])
KEYS["real.rp2040-st7789.uf2_blocks"] = lambda m: Fig("1", 1.0) if m.recording else exact(
    m.build("rp2040-st7789")["uf2_bytes"].num // 512)


KEYS["limit.qemu-m0.flash_bytes"] = link_length("qemu-m0", "FLASH")
KEYS["limit.qemu-m0.ram_bytes"] = link_length("qemu-m0", "RAM")
KEYS["limit.frame_size_max"] = lambda m: m.code("core/include/tarn/tarn_render.h",
                                                 r"#define TARN_FRAME_SIZE_MAX (\d+)u")


# ---- docs/figures.md -------------------------------------------------------------------

POND_KNOBS = ["", "--quality exact", "--quality fast", "--perspective span:4", "--perspective span:16",
              "--perspective affine", "--recip-steps 2", "--recip-steps 0", "--fog-bits 16", "--depth 16",
              "--subpixel 2", "--subpixel 5", "--subpixel 6", "--tile 16", "--tile 64", "--apron off",
              "--apron off --tile 16", "--bins off", "--water-block 2", "--quality fast --water-block 1",
              "--depth-interpolation plane", "--quality fast --depth-interpolation exact",
              "--frame strips --tile 16", "--vertices frame", "--frame strips --tile 16 --vertices frame"]


@block
def pond_knobs(m):
    """The pond under each knob: tarn compare, and callgrind on tarn render."""
    rows = [[k or "default"] + yard_cells(m.compare("pond", k)) + [m.host("pond", k)["insn_per_pixel"]]
            for k in POND_KNOBS]
    return table(["knob (default otherwise)"] + YARD_HEADER + ["host insn/px"], rows,
                 ["---", "---", "---", "---:", "---:", "---:"])


def knob_key(knob, field):
    return lambda m: m.compare("pond", knob)[field]


def host_key(knob, scene="pond"):
    return lambda m: m.host(scene, knob)["insn_per_pixel"]


for _k in POND_KNOBS:
    _n = (_k or "default").replace("--", "").replace(" ", "-").replace(":", "")
    for _f in ("psnr", "maxerr", "over2", "over8", "shading_psnr", "shading_over2", "panel_psnr", "coverage"):
        KEYS["pond.%s.%s" % (_n, _f)] = knob_key(_k, _f)
    KEYS["pond.%s.host" % _n] = host_key(_k)

WATER_SCENES = ["pond", "beach", "murky", "lake", "underwater", "effects/fog", "effects/absorption",
                "effects/depth_colour", "effects/ramp", "effects/refraction", "effects/normals", "effects/fresnel",
                "effects/foam", "effects/sparkles", "effects/underwater"]


@block
def water_scenes(m):
    """Every water scene at the default quality, time 0: tarn compare."""
    rows = [[s] + yard_cells(m.compare(s)) for s in WATER_SCENES]
    return table(["scene"] + YARD_HEADER, rows, ["---", "---", "---", "---:", "---:"])


for _s in WATER_SCENES:
    for _f in ("psnr", "shading_psnr", "panel_psnr", "coverage"):
        KEYS["scene.%s.%s" % (_s.replace("/", "."), _f)] = (lambda s, f: lambda m: m.compare(s)[f])(_s, _f)


@tool
def water_cost(m):
    """tests/check_water_cost.sh's lines; with --reuse, the ones make test wrote."""
    saved = os.path.join(ROOT, "build/release/water-cost.txt")
    if m.reuse and os.path.exists(saved) and os.path.getmtime(saved) >= os.path.getmtime(os.path.join(ROOT, TARN)):
        with open(saved) as f:
            return f.read()
    return run(["tests/check_water_cost.sh"], env=dict(os.environ, TARN_BIN=TARN))


def water_costs(m):
    text = m.output("water_cost")
    out = {}
    for line in (text if isinstance(text, str) else "").splitlines():
        if line.startswith("water-cost "):
            f = dict(w.split("=", 1) for w in line.split()[1:])
            out[f["scene"]] = (insn(int(f["insn_per_pixel"]), "comma"), insn(int(f["water_insn_per_pixel"]),
                                                                              "comma"))
    return out


EFFECT_ROWS = [("none", "none (no water)"), ("ramp", "ramp"), ("foam", "foam"), ("depth_colour", "depth colour"),
               ("fresnel", "fresnel"), ("fog", "fog"), ("absorption", "absorption"), ("sparkles", "sparkles"),
               ("normals", "normals (+ specular)"), ("refraction", "refraction"),
               ("underwater", "underwater (no water surface)")]


@block
def host_effect_cost(m):
    """What each effect costs the host: tests/check_water_cost.sh (callgrind)."""
    costs = water_costs(m)
    rows = [[label] + list(costs.get(scene, (Fig("?", 0), Fig("?", 0)))) for scene, label in EFFECT_ROWS]
    if not costs:
        rows = [[label, Fig("1", 1), Fig("1", 1)] for _, label in EFFECT_ROWS]
    return table(["scene", "frame", "water pixel"], rows, ["---", "---:", "---:"])


for _scene, _ in EFFECT_ROWS:
    KEYS["host.effect.%s.frame" % _scene] = (lambda s: lambda m: water_costs(m).get(s, (Fig("1", 1),) * 2)[0])(_scene)
    KEYS["host.effect.%s.water" % _scene] = (lambda s: lambda m: water_costs(m).get(s, (Fig("1", 1),) * 2)[1])(_scene)


@tool
def accuracy_math(m):
    return run([TARN, "accuracy", "--math"])


def sig(v, n=3):
    """v to n significant digits, integers from 100."""
    if v >= 100 or v == 0:
        return "%d" % round(v)
    digits = n - 1 - int(__import__("math").floor(__import__("math").log10(abs(v))))
    return "%.*f" % (max(digits, 0), v)


def math_rows(m):
    rows = {}
    for line in m.output("accuracy_math").splitlines() if isinstance(m.output("accuracy_math"), str) else []:
        mt = re.match(r"(tarn_\w+)\s+(.*?)\s+(\d+\.\d+)\s+(\d+\.\d+)\s+(\S+(?: \(2\^ *-?[\d.]+\))?|-)\s+\d+", line)
        if mt:
            rows[(mt.group(1), mt.group(2).strip())] = (float(mt.group(3)), float(mt.group(4)), mt.group(5))
    return rows


@block
def math_accuracy(m):
    """tarn accuracy --math: each function's error against libm."""
    r = math_rows(m)
    if not r:
        return [Fig("1", 1)]

    def cells(fn, configs, which, fmt=sig):
        return exact(" / ".join(fmt(r[(fn, c)][which]) for c in configs))

    sizes = ["8", "16", "32", "64", "128", "256"]
    near = ["%s nearest" % s for s in sizes]
    lin = ["%s linear" % s for s in sizes]
    steps = ["0 Newton steps", "1 Newton step", "2 Newton steps"]

    def rel(fn, c):
        return "2^" + re.search(r"2\^ *(-?[\d.]+)", r[(fn, c)][2]).group(1).rstrip("0").rstrip(".")

    rows = [
        ["`tarn_exp2_neg_q16` (Q0.16)", "8 / 16 / 32 / 64 / 128 / 256 entries, nearest", cells("tarn_exp2_neg_q16",
                                                                                               near, 0),
         cells("tarn_exp2_neg_q16", near, 1, lambda v: sig(v, 2))],
        ["", "same, linear", cells("tarn_exp2_neg_q16", lin, 0), cells("tarn_exp2_neg_q16", lin, 1,
                                                                       lambda v: sig(v, 2))],
        ["`tarn_recip_u32`", ["0 / 1 / 2 Newton steps, relative beyond rounding"],
         exact(" / ".join(rel("tarn_recip_u32", c) for c in steps)), ""],
        ["`tarn_recip_q30`", "2 Newton steps", exact(sig(r[("tarn_recip_q30", steps[2])][0])),
         exact(sig(r[("tarn_recip_q30", steps[2])][1], 2))],
        ["`tarn_sin_q15`, `tarn_cos_q15`", "every angle",
         exact(sig(max(r[("tarn_sin_q15", "")][0], r[("tarn_cos_q15", "")][0]), 4)),
         exact(sig(max(r[("tarn_sin_q15", "")][1], r[("tarn_cos_q15", "")][1]), 2))],
        ["`tarn_isqrt_u32`", "exact", exact(sig(r[("tarn_isqrt_u32", "")][0])),
         exact(sig(r[("tarn_isqrt_u32", "")][1]))],
        ["`tarn_rsqrt_q16`", ["relative beyond rounding ", exact(rel("tarn_rsqrt_q16", ""))],
         exact(sig(r[("tarn_rsqrt_q16", "")][0])), exact(sig(r[("tarn_rsqrt_q16", "")][1], 2))],
        ["`tarn_rsqrt15_q16`", ["one Newton step, relative beyond rounding ", exact(rel("tarn_rsqrt15_q16", ""))],
         exact(sig(r[("tarn_rsqrt15_q16", "")][0])), exact(sig(r[("tarn_rsqrt15_q16", "")][1], 2))],
        ["`tarn_sin_cos_q30`", "per frame, [-pi/2, pi/2]", "asserted <= 4 (2^-30 units)", ""],
    ]
    return table(["function", "configuration", "max error", "mean error"], rows)


@tool
def bench_math(m):
    return run(["scripts/bench-math.sh"])


def math_cost(fn, config):
    def get(m):
        text = m.output("bench_math")
        for line in text.splitlines() if isinstance(text, str) else []:
            mt = re.match(r"(tarn_\w+)\s+(.*?)\s+([\d.]+)$", line)
            if mt and mt.group(1) == fn and mt.group(2).strip() == config:
                return insn(float(mt.group(3)))
        if isinstance(text, str) and text:
            raise MeasureError("scripts/bench-math.sh gave no line for %s %s" % (fn, config))
        return Fig("1", 1.0)
    return get


def exp2_cost(which):
    def get(m):
        text = m.output("bench_math")
        costs = [float(x) for x in re.findall(r"^tarn_exp2_neg_q16 .*?([\d.]+)$", text, re.M)] \
            if isinstance(text, str) else []
        return insn(which(costs)) if costs else Fig("1", 1.0)
    return get


KEYS["math.exp2.least"] = exp2_cost(min)
KEYS["math.exp2.most"] = exp2_cost(max)
for _n, _c in (("0", "0 Newton steps"), ("1", "1 Newton step"), ("2", "2 Newton steps")):
    KEYS["math.recip_q30.%s" % _n] = math_cost("tarn_recip_q30", _c)
    KEYS["math.recip_u32.%s" % _n] = math_cost("tarn_recip_u32", _c)
KEYS["math.sin"] = math_cost("tarn_sin_q15", "")
KEYS["math.cos"] = math_cost("tarn_cos_q15", "")
KEYS["math.rsqrt"] = math_cost("tarn_rsqrt_q16", "")
KEYS["math.rsqrt15"] = math_cost("tarn_rsqrt15_q16", "")
KEYS["math.isqrt"] = math_cost("tarn_isqrt_u32", "")


@tool
def math_tables_m0(m):
    """The math tables' const bytes in the Cortex-M0 build (make firmware BOARD=qemu-m0)."""
    m.bench("qemu-m0")
    return run(["arm-none-eabi-size", "-A", "build/firmware/qemu-m0/obj/core/math/math_tables.o"])


def math_tables_bytes(m):
    text = m.output("math_tables_m0")
    if not isinstance(text, str):
        return Fig("1", 1.0)
    return exact(sum(int(x) for x in re.findall(r"^\.rodata\S*\s+(\d+)", text, re.M))).fmt("comma")


KEYS["math.tables_m0_bytes"] = math_tables_bytes


def memory_key(scene, args, field, style="comma"):
    return lambda m: m.memory(scene, args)[field].fmt(style)


KEYS["memory.pond.bytes"] = memory_key("pond", "", "bytes")
KEYS["memory.pond.baked_bytes"] = memory_key("pond", "", "baked_bytes")
KEYS["memory.pond.fast.bytes"] = memory_key("pond", "--quality fast", "bytes")
KEYS["memory.pond.fast.baked_bytes"] = memory_key("pond", "--quality fast", "baked_bytes")
KEYS["memory.pond-orbit.strips16.bytes"] = memory_key("pond-orbit", "--quality exact --frame strips --tile 16", "bytes")
KEYS["memory.pond-orbit.strips16-pass.bytes"] = memory_key(
    "pond-orbit", "--quality balanced --depth-interpolation plane --frame strips --tile 16 --vertices frame", "bytes")
KEYS["memory.pond-orbit.strips12-apron24-pass.bytes"] = memory_key(
    "pond-orbit", "--quality balanced --depth-interpolation plane --frame strips --tile 12 --apron 24 --vertices frame",
    "bytes")
KEYS["memory.pond-orbit.strips16.pipeline_bytes"] = memory_key("pond-orbit", "--quality exact --frame strips --tile 16",
                                                               "pipeline_bytes")
KEYS["memory.opaque.tile32"] = memory_key("effects/none", "--tile 32 --depth 32", "baked_bytes")
KEYS["memory.opaque.tile16_depth16"] = memory_key("effects/none", "--tile 16 --depth 16", "baked_bytes")


def pond_bins(m):
    """Bytes of the pond's cluster bins found in RAM: memory without the static view less with."""
    d = m.memory("pond")
    return diff(d["bytes"], d["baked_bytes"]).fmt("comma")


KEYS["memory.pond.bins_bytes"] = pond_bins
KEYS["memory.pond.clusters"] = lambda m: exact(int(pond_bins(m).num) // 4).fmt("comma")


@tool
def bench_panels(m):
    return run(["scripts/bench-panels.sh"], env=dict(os.environ, TARN_BIN=TARN))


def spaced(n):
    return "{:,}".format(int(n)).replace(",", " ")


@block
def panel_links(m):
    """scripts/bench-panels.sh: counted bytes of two frames of the pond on each link."""
    text = m.output("bench_panels")
    names = {"panel": "emulator direct", "mcp2210": "MCP2210"}
    rows = []
    for line in text.splitlines() if isinstance(text, str) else []:
        w = line.split()
        if len(w) < 8 or w[0] == "link":
            continue
        row = [names.get(w[0], w[0]), w[1], w[2], exact(spaced(int(w[3]))), exact(spaced(int(w[4])))]
        if w[6] == "sets/B":
            row += [[exact(w[5]), " line changes per byte"], "", ""]
        else:
            row += [exact(spaced(int(w[5]))), exact(w[6]), exact(w[7])]
        rows.append(row)
    if not rows:
        return [Fig("1", 1)]
    return table(["link", "send", "tile", "bytes, frame 1", "bytes, frame 2", "link bytes/s",
                  "link fps (2 frames)", "ceiling fps"], rows)


# ---- firmware builds of other scenes and bake flags --------------------------------------
# fw.NAME.FIELD: make bench-target BOARD=B SCENE=S BAKE_FLAGS=F FW_BUILD_DIR=build/figures/fw/...

FW_VARIANTS = {
    # the fast preset itself, the knobs' baseline: the board adds a refraction apron
    "m0-fast": ("qemu-m0", "pond", "--quality fast"),
    "m0-fast-bins-off": ("qemu-m0", "pond", "--quality fast --bins off"),
    "m0-fast-wb4": ("qemu-m0", "pond", "--quality fast --water-block 4"),
    "m0-fast-wb1": ("qemu-m0", "pond", "--quality fast --water-block 1"),
    "m0-fast-still-wb2": ("qemu-m0", "pond", "--quality fast --backdrop still"),
    "m0-fast-still-wb1": ("qemu-m0", "pond", "--quality fast --backdrop still --water-block 1"),
    "m0-fast-exact-depth": ("qemu-m0", "pond", "--quality fast --depth-interpolation exact"),
}


def fw(name):
    """A variant's bench line: FW_VARIANTS[name] is (board, scene, bake flags), and
    the board's variables it sets otherwise ("NAME=value" each) where it has them."""
    board, scene, flags = FW_VARIANTS[name][:3]
    make_vars = FW_VARIANTS[name][3] if len(FW_VARIANTS[name]) > 3 else ()
    return lambda m: m.bench(board, scene, flags, make_vars=make_vars)


def fw_key(name, field):
    return lambda m: fw(name)(m)[field]


def add_fw_keys():
    for name in FW_VARIANTS:
        for field in BENCH_FIELDS:
            KEYS["fw.%s.%s" % (name, field)] = fw_key(name, field)


add_fw_keys()


def share(a, b):
    """a as a percentage of b (instruction counts)."""
    return derived(100.0 * a.num / b.num, 100.0 * a.num / b.num * (a.tol / a.num + b.tol / b.num), 0, suffix="%")


def host_of(knob, scene="pond"):
    return lambda m: m.host(scene, knob)["insn_per_pixel"]


def cmp_of(knob, field, scene="pond", time=None):
    return lambda m: m.compare(scene, knob, time)[field]


KEYS["pond.apron-off.host_share"] = lambda m: share(host_of("--apron off")(m), host_of("")(m))
KEYS["pond.bins.host_saving"] = lambda m: pct_less(host_of("")(m), host_of("--bins off")(m))
KEYS["fw.m0-bins.saving"] = lambda m: pct_less(fw("m0-fast")(m)["insn_per_pixel"],
                                               fw("m0-fast-bins-off")(m)["insn_per_pixel"])
KEYS["pond.fast.blocks_host_saving"] = lambda m: pct_less(host_of("--quality fast")(m),
                                                          host_of("--quality fast --water-block 1")(m))
KEYS["pond.fast.blocks_psnr_cost"] = lambda m: diff(cmp_of("--quality fast --water-block 1", "psnr")(m),
                                                    cmp_of("--quality fast", "psnr")(m), 2)
KEYS["pond.water-block-2.shading_cost"] = lambda m: diff(cmp_of("", "shading_psnr")(m),
                                                         cmp_of("--water-block 2", "shading_psnr")(m), 2)
KEYS["pond.depth-16.shading_cost"] = lambda m: diff(cmp_of("", "shading_psnr")(m),
                                                    cmp_of("--depth 16", "shading_psnr")(m), 2)
STILL = "--quality fast --backdrop still"
KEYS["still.wb2.psnr"] = cmp_of(STILL, "psnr", time=1750)
KEYS["still.wb4.psnr"] = cmp_of(STILL + " --water-block 4", "psnr", time=1750)
STILL_REFRACTING = " --quality fast --water-block 4 --apron on --perspective pixel --depth 32"
KEYS["still.refracting.psnr"] = cmp_of("--backdrop still" + STILL_REFRACTING, "psnr", time=1750)
KEYS["still.refracting.whole_psnr"] = cmp_of(STILL_REFRACTING.strip(), "psnr", time=1750)
KEYS["still.wb4.psnr_cost"] = lambda m: diff(KEYS["still.wb2.psnr"](m), KEYS["still.wb4.psnr"](m), 2)
# flat water's texture coordinates, from its plane (the default) or its triangles
for _scene in ("pond", "effects/normals", "effects/foam"):
    for _preset in ("balanced", "exact"):
        for _mode in ("plane", "triangles"):
            for _f in ("psnr", "shading_psnr"):
                KEYS["uv.%s.%s.%s.%s" % (_scene, _preset, _mode, _f)] = cmp_of(
                    "--quality %s --water-uv %s" % (_preset, _mode), _f, scene=_scene)
KEYS["uv.pond.host_cost"] = lambda m: pct_more(host_of("")(m), host_of("--water-uv triangles")(m))
KEYS["pond.plane.host_saving"] = lambda m: pct_less(host_of("--depth-interpolation plane")(m), host_of("")(m))
KEYS["pond.fast.plane_host_saving"] = lambda m: pct_less(
    host_of("--quality fast")(m), host_of("--quality fast --depth-interpolation exact")(m))
KEYS["fw.m0-plane.saving"] = lambda m: pct_less(fw("m0-fast")(m)["insn_per_pixel"],
                                                fw("m0-fast-exact-depth")(m)["insn_per_pixel"])
KEYS["far.exact.shading_psnr"] = cmp_of("", "shading_psnr", "extremes/far")
KEYS["far.plane.shading_psnr"] = cmp_of("--depth-interpolation plane", "shading_psnr", "extremes/far")
KEYS["host.effect.normals_over_ramp"] = lambda m: diff(KEYS["host.effect.normals.water"](m),
                                                       KEYS["host.effect.ramp.water"](m))


@tool
def test_raster(m):
    """build/release/tests/test_raster's messages (make check builds it)."""
    run(["make", "--no-print-directory", "-s", "build/release/tests/test_raster"])
    return run(["build/release/tests/test_raster"])


def raster_opaque(field):
    def get(m):
        text = m.output("test_raster")
        if not isinstance(text, str):
            return Fig("1", 1.0)
        mt = re.search(r"opaque pond, snapped: ([\d.]+) dB, max error (\d+)", text)
        if not mt:
            raise MeasureError("build/release/tests/test_raster printed no 'opaque pond' line")
        return exact(mt.group(1 if field == "psnr" else 2))
    return get


KEYS["raster.opaque.psnr"] = raster_opaque("psnr")
KEYS["raster.opaque.maxerr"] = raster_opaque("maxerr")


# ---- docs/sweep.md -------------------------------------------------------------------------

@tool
def front_md(m):
    """docs/sweep/front.md, which make sweep-docs writes and tests/check_sweep.sh holds
    to a fresh measurement of its presets."""
    with open(os.path.join(ROOT, "docs/sweep/front.md")) as f:
        return f.read()


def front_section(m, scene):
    text = m.output("front_md")
    if not isinstance(text, str):
        return ""
    mt = re.search(r"^## %s \(.*?(?=^## |\Z)" % re.escape(scene), text, re.M | re.S)
    if not mt:
        raise MeasureError("docs/sweep/front.md has no section for %s" % scene)
    return mt.group(0)


def front_table(m, scene, first_header):
    """The header and rows of the table of a front.md section whose header starts so."""
    lines = front_section(m, scene).splitlines()
    for i, line in enumerate(lines):
        if line.startswith("| " + first_header):
            rows = []
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                rows.append([c.strip() for c in row.strip("|").split("|")])
            return [c.strip() for c in line.strip("|").split("|")], lines[i + 1], rows
    if front_section(m, scene):
        raise MeasureError("docs/sweep/front.md: %s has no table starting '%s'" % (scene, first_header))
    return [], "", []


def front_preset(m, scene, preset, column, table_first="preset | PSNR dB"):
    header, _, rows = front_table(m, scene, table_first)
    for row in rows:
        if row[0] == "`%s`" % preset:
            return row[header.index(column)]
    return "1"


def sweep_presets(scene):
    def fn(m):
        header, rule, rows = front_table(m, scene, "preset | PSNR dB")
        if not header:
            return [Fig("1", 1)]
        parts = ["| " + " | ".join(header) + " |\n", rule + "\n"]
        for row in rows:
            parts.append("| " + row[0] + " |")
            for i, cell in enumerate(row[1:], 1):
                parts += [" ", labelled(exact(cell), "%s / %s" % (row[0].strip("`"), header[i])), " |"]
            parts.append("\n")
        return parts
    fn.__doc__ = "The presets of docs/sweep/front.md's %s section, copied." % scene
    return fn


BLOCKS["sweep-presets-pond"] = sweep_presets("pond")
BLOCKS["sweep-presets-lake"] = sweep_presets("lake")

SWEEP_POINTS = {
    "balanced": "", "exact": "--quality exact", "fast": "--quality fast",
    "fast-wb1": "--quality fast --water-block 1", "fast-affine": "--quality fast --perspective affine",
    "apron-off": "--apron off", "apron-8": "--apron 8", "subpixel-5": "--subpixel 5", "subpixel-6": "--subpixel 6",
    "depth-16": "--depth 16", "recip-2-fog-16": "--recip-steps 2 --fog-bits 16",
    "plane": "--depth-interpolation plane", "water-block-2": "--water-block 2", "tile-64": "--tile 64",
    "affine": "--perspective affine",
}


def sp(scene, name):
    return lambda m: m.sweep_point(scene, SWEEP_POINTS[name])


for _scene in ("pond", "lake"):
    for _name in SWEEP_POINTS:
        for _f in ("psnr", "shading_psnr", "panel_psnr", "host"):
            KEYS["sweep.%s.%s.%s" % (_scene, _name, _f)] = (
                lambda s, n, f: lambda m: m.sweep_point(s, SWEEP_POINTS[n])[f])(_scene, _name, _f)


def psnr_diff(scene, a, b, field="psnr"):
    return lambda m: diff(sp(scene, a)(m)[field], sp(scene, b)(m)[field], 2)


KEYS["sweep.lake.preset_spread"] = psnr_diff("lake", "exact", "fast")
KEYS["sweep.lake.fast_to_balanced"] = psnr_diff("lake", "balanced", "fast")
KEYS["sweep.lake.blocks_cost"] = psnr_diff("lake", "fast-wb1", "fast")
KEYS["sweep.lake.fast_host_saving"] = lambda m: pct_less(sp("lake", "fast")(m)["host"], sp("lake", "balanced")(m)["host"])


def front_insn(scene, preset, column):
    def fn(m):
        text = front_preset(m, scene, preset, column)
        return insn(int(text.split()[0]))
    return fn


KEYS["sweep.lake.fast_m0_saving"] = lambda m: pct_less(front_insn("lake", "fast", "qemu-m0 insn/px")(m),
                                                       front_insn("lake", "balanced", "qemu-m0 insn/px")(m))
KEYS["sweep.pond.points"] = lambda m: exact(re.search(r"^## pond \(\S+, (\d+) points\)", front_section(m, "pond"),
                                                      re.M).group(1)) \
    if front_section(m, "pond") else Fig("1", 1.0)
KEYS["sweep.pond.depth-16.psnr_cost"] = psnr_diff("pond", "balanced", "depth-16")
KEYS["sweep.pond.recip-2-fog-16.psnr_gain"] = psnr_diff("pond", "recip-2-fog-16", "balanced")
KEYS["sweep.pond.recip-2-fog-16.host_more"] = lambda m: pct_more(sp("pond", "recip-2-fog-16")(m)["host"],
                                                                 sp("pond", "balanced")(m)["host"])
KEYS["sweep.pond.depth-16.host_more"] = lambda m: pct_more(sp("pond", "depth-16")(m)["host"],
                                                           sp("pond", "balanced")(m)["host"])
KEYS["sweep.pond.plane.host_saving"] = lambda m: pct_less(sp("pond", "plane")(m)["host"],
                                                          sp("pond", "balanced")(m)["host"])
KEYS["sweep.pond.balanced.host_saving"] = lambda m: pct_less(sp("pond", "balanced")(m)["host"],
                                                             sp("pond", "exact")(m)["host"])
KEYS["sweep.pond.fast.blocks_psnr_cost"] = psnr_diff("pond", "fast-wb1", "fast")
KEYS["sweep.pond.fast-affine.psnr_cost"] = psnr_diff("pond", "fast", "fast-affine")

PERSPECTIVES = ["pixel", "span:4", "span:16", "affine"]


@block
def sweep_pond_perspective(m):
    """The pond's perspective modes at balanced's other knobs: the sweep's points."""
    rows = []
    for p in PERSPECTIVES:
        d = m.sweep_point("pond", "--perspective %s" % p)
        rows.append(["`%s`" % p, d["psnr"], d["shading_psnr"], d["host"].fmt("comma")])
    return table(["perspective", "PSNR dB", "shading dB", "host insn/px"], rows, ["---", "---:", "---:", "---:"])


def apron_off_perspectives(m):
    return [m.sweep_point("pond", "--apron off --perspective %s" % p)["psnr"] for p in PERSPECTIVES]


KEYS["sweep.pond.apron-off.perspective_least"] = lambda m: min(apron_off_perspectives(m), key=lambda f: f.num)
KEYS["sweep.pond.apron-off.perspective_most"] = lambda m: max(apron_off_perspectives(m), key=lambda f: f.num)
KEYS["sweep.pond.apron-off.perspective_spread"] = lambda m: diff(KEYS["sweep.pond.apron-off.perspective_most"](m),
                                                                 KEYS["sweep.pond.apron-off.perspective_least"](m), 2)

M0_PERSPECTIVE = "--quality fast --water-block 1 --depth-interpolation exact --tile 42 --perspective "
for _p in ("affine", "span:16", "pixel"):
    FW_VARIANTS["m0-fast-nb-" + _p.replace(":", "")] = ("qemu-m0", "pond", M0_PERSPECTIVE + _p)
FW_VARIANTS["m0-fast-recip-2"] = ("qemu-m0", "pond", "--quality fast --recip-steps 2 --fog-bits 16")
add_fw_keys()


@block
def m0_perspective(m):
    """The M0's cost of each perspective at the fast preset's other knobs, each in an image of its own."""
    rows = [["`%s`" % p, fw("m0-fast-nb-" + p.replace(":", ""))(m)["insn_per_pixel"].fmt("comma")]
            for p in ("affine", "span:16", "pixel")]
    return table(["perspective", "M0 insn/px"], rows, ["---", "---:"])


KEYS["fw.m0-affine.saving"] = lambda m: pct_less(fw("m0-fast-nb-affine")(m)["insn_per_pixel"],
                                                 fw("m0-fast-nb-span16")(m)["insn_per_pixel"])
KEYS["fw.m0-recip-2.more"] = lambda m: pct_more(fw("m0-fast-recip-2")(m)["insn_per_pixel"],
                                                fw("m0-fast")(m)["insn_per_pixel"])
KEYS["fw.m0-blocks.saving"] = lambda m: pct_less(fw("m0-fast")(m)["insn_per_pixel"],
                                                 fw("m0-fast-wb1")(m)["insn_per_pixel"])
KEYS["memory.pond.fast.block_bytes"] = lambda m: diff(m.memory("pond", "--quality fast")["baked_bytes"],
                                                      m.memory("pond", "--quality fast --water-block 1")[
                                                          "baked_bytes"]).fmt("comma")


def sweep_budget(board, what):
    def fn(m):
        line = m.code("host/sweep/sweep_target.c", r'^\s*\{"%s", (16384u - \d+u - \d+u)\}' % board)
        if isinstance(line, Placeholder):
            return Fig("1", 1.0)
        ram, stack, other = (int(x) for x in re.findall(r"\d+", line.text))
        return exact(ram - stack - other if what == "budget" else stack).fmt("comma")
    return fn


for _b in ("qemu-m0", "qemu-rv32"):
    KEYS["sweep.budget.%s" % _b] = sweep_budget(_b, "budget")
    KEYS["sweep.stack.%s" % _b] = sweep_budget(_b, "stack")


def wall_sweep_minutes(m):
    path = os.path.join(ROOT, "build/figures/sweep-docs.seconds")
    if not os.path.exists(path):
        return wall(None)
    with open(path) as f:
        return wall("%d" % round(int(f.read()) / 60.0))


KEYS["wall.sweep-docs.minutes"] = wall_sweep_minutes


def conversion(column_dither):
    def fn(m):
        header, _, rows = front_table(m, "pond", "preset | dither")
        for row in rows:
            if row[0] == "`fast`" and row[1] == ("ordered 4x4" if column_dither else "none"):
                return exact(row[header.index("qemu-m0 conversion insn/px")])
        return Fig("1", 1.0)
    return fn


KEYS["sweep.m0.convert"] = conversion(False)
KEYS["sweep.m0.convert_dither"] = conversion(True)


@tool
def profile_still(m):
    """make profile-target BOARD=qemu-m0-still FW_TIMES=1000: every instruction of its run, by
    function (in a directory of its own: the times are not the board's own build's)."""
    return run(["make", "--no-print-directory", "-s", "profile-target", "BOARD=qemu-m0-still", "TOP=1000",
                "FW_TIMES=" + PROFILE_TIMES, "FW_BUILD_DIR=" + os.path.join(OUT, "profile", "qemu-m0-still")])


def profile_functions(m):
    text = m.output("profile_still")
    out = {}
    if not isinstance(text, str):
        return out
    part = text.split("functions:")[1].split("files:")[0] if "functions:" in text else ""
    for line in part.splitlines():
        w = line.split()
        if len(w) >= 3:
            out[w[2]] = int(w[0])
    return out


# a profiled run: its streamed frames (PROFILE_TIMES) and nothing else
PROFILED_FRAMES = len(PROFILE_TIMES.split(","))


def profile_per_pixel(functions):
    """Instructions a pixel of the pond's frame (240x240) in the named functions."""
    def fn(m):
        f = profile_functions(m)
        if not f:
            return Fig("1", 1.0)
        return insn(sum(f.get(name, 0) for name in functions) / (PROFILED_FRAMES * 57600.0))
    return fn


KEYS["profile.still.convert_rows"] = profile_per_pixel(["convert_rows"])

# ---- the extreme scenes: the worst case of a knob over scenes/extremes (docs/sweep/stability.md)

EXTREMES = ["dense", "far", "grazing", "huge", "steep", "tiny"]
STABILITY_KNOBS = {"balanced": "", "fog-bits-4": "--fog-bits 4", "fog-bits-6": "--fog-bits 6",
                   "perspective-affine": "--perspective affine", "perspective-span64": "--perspective span:64",
                   "recip-steps-0": "--recip-steps 0", "apron-off": "--apron off", "apron-4": "--apron 4",
                   "exp2-8nearest": "--exp2 8:nearest", "subpixel-1": "--subpixel 1", "subpixel-2": "--subpixel 2"}


def worst(knob, field, scene_name=False):
    def fn(m):
        got = [(m.compare("extremes/" + s, STABILITY_KNOBS[knob], 1000)[field], s) for s in EXTREMES]
        pick = (min if field == "psnr" else max)(got, key=lambda g: g[0].num)
        if scene_name:
            return exact(pick[1])
        return pick[0] if field == "psnr" else exact("%d%%" % round(pick[0].num))
    return fn


for _k in STABILITY_KNOBS:
    KEYS["stability.%s.psnr" % _k] = worst(_k, "psnr")
    KEYS["stability.%s.psnr_scene" % _k] = worst(_k, "psnr", True)
    KEYS["stability.%s.over8" % _k] = worst(_k, "over8")
    KEYS["stability.%s.over8_scene" % _k] = worst(_k, "over8", True)
KEYS["stability.huge.over8"] = lambda m: exact("%d%%" % round(m.compare("extremes/huge", "", 1000)["over8"].num))


# ---- docs/firmware.md ------------------------------------------------------------------------

def comma(fig):
    return fig.fmt("comma")


@block
def fw_report_example(m):
    """build/firmware/qemu-m0/report.txt, the M0's report line (make firmware-run)."""
    r = m.bench("qemu-m0")
    frames = r["frame_insn"] if isinstance(r["frame_insn"], list) else [r["frame_insn"]] * 4
    listed = [frames[0]]
    for f in frames[1:]:
        listed += [",", f]
    return code_block(["target board=qemu-m0 scene=pond size=240x240 insn_per_pixel=", r["insn_per_pixel"],
                       " render_insn_per_pixel=", r["render_insn_per_pixel"], "\n       stack_peak_bytes=",
                       r["stack_peak_bytes"], " frame_insn="] + listed +
                      [" counter_check=", r["counter_check"], "/", r["counter_check_loop"], "\n"])


def board_bake_flags(board, scene=None):
    """The flags a board bakes a scene with, read from its board.mk: the scene's own
    (BOARD_BAKE_FLAGS.NAME) where it gives them."""
    own = board_mk_value(board, "BOARD_BAKE_FLAGS.%s" % scene) if scene else None
    return own or board_mk_value(board, "BOARD_BAKE_FLAGS") or "the default: balanced"


def quoted_flags(flags):
    return "`%s`" % flags if flags[0] == "-" else flags


BOARD_ROWS = [(b, s, "%s 240x240, %s" % (s, quoted_flags(board_bake_flags(b, s))))
              for b in BOARDS for s in board_scenes(b)]


@block
def fw_boards(m):
    """make bench-target: every emulated board's line, one a scene."""
    rows = []
    for board, scene, what in BOARD_ROWS:
        b = board_bench(m, board, scene)
        on_cores = ["", b["parts_insn_per_pixel"], " (", b["parts"], ")"] if "parts" in b else ""
        rows.append(["`%s`" % board, what, b["insn_per_pixel"], b["render_insn_per_pixel"], on_cores,
                     comma(b["ram_bytes"]),
                     [comma(b["flash_bytes"]), " (", comma(b["scene_bytes"]), " + ", comma(b["code_bytes"]), ")"],
                     [b["stack_bytes"], " / ", b["stack_peak_bytes"], " / ", b["stack_reserved_bytes"]],
                     b["panel_psnr"]])
    return table(["board", "scene, quality", "insn/pixel", "core alone", "core on its cores", "RAM",
                  "flash (scene + code)", "stack bound / peak / reserved", "panel PSNR dB"], rows,
                 ["---", "---", "---:", "---:", "---:", "---:", "---:", "---", "---:"])


# the RAM boards' scenes as they were baked before strips and the vertex pass (at
# the boards' quality), the moving pond in 16-row strips with the whole apron and
# no vertex pass (as they baked it before), at the exact preset the boards baked
# before that, and at a leaner quality than the boards'
RAM_BOARD_QUALITY = "--quality balanced --depth-interpolation plane"
FW_VARIANTS.update({
    "m0-264k-orbit-tiles": ("qemu-m0-264k", "pond-orbit", RAM_BOARD_QUALITY + " --tile 64"),
    "m0-264k-orbit-strips16": ("qemu-m0-264k", "pond-orbit", RAM_BOARD_QUALITY + " --frame strips --tile 16"),
    "m0-264k-orbit-exact": ("qemu-m0-264k", "pond-orbit", "--quality exact --frame strips --tile 16"),
    "m0-264k-orbit-lean": ("qemu-m0-264k", "pond-orbit", RAM_BOARD_QUALITY + " --frame strips --tile 16 "
                           "--refraction-normal shared"),
    "m0-264k-opaque-tiles": ("qemu-m0-264k", "pond-opaque", RAM_BOARD_QUALITY + " --tile 64"),
    "m0-264k-opaque-strips": ("qemu-m0-264k", "pond-opaque", RAM_BOARD_QUALITY + " --frame strips --tile 64"),
    "m0-264k-opaque-pass16": ("qemu-m0-264k", "pond-opaque", RAM_BOARD_QUALITY + " --frame strips --tile 64 "
                              "--vertices frame"),
    "m0-264k-opaque-exact": ("qemu-m0-264k", "pond-opaque", "--quality exact --frame strips --tile 64 --vertices frame"),
    "rv32-400k-orbit-tiles": ("qemu-rv32-400k", "pond-orbit", RAM_BOARD_QUALITY + " --tile 64"),
    # the boards' own flags with a plane for each channel of the lit colour
    "m0-264k-orbit-lit-planes": ("qemu-m0-264k", "pond-orbit",
                                 board_mk_value("qemu-m0-264k", "BOARD_BAKE_FLAGS") + " --lit planes"),
    "m0-264k-opaque-lit-planes": ("qemu-m0-264k", "pond-opaque",
                                  board_mk_value("qemu-m0-264k", "BOARD_BAKE_FLAGS.pond-opaque") + " --lit planes"),
    "rv32-400k-opaque-tiles": ("qemu-rv32-400k", "pond-opaque", RAM_BOARD_QUALITY + " --tile 64"),
})


# Each real board's own build (its scene, bake flags, cores and code in RAM) counted
# on the emulated board that stands for its chip: the RP2040's memory and Cortex-M0
# code on qemu-m0-264k, the STM32F411's on the Cortex-M3 of qemu-m3 (the M4 runs the
# M3's instructions; its own build may pick a few of its own). The frame's time is the
# core's on its cores, its slower part's where it has two; a frame rate from it at the
# board's clock, one instruction a cycle, is a bound no frame reaches: loads, stores
# and taken branches take two cycles on both, and flash waits where a cache misses.
REAL_COUNTED_ON = {"rp2040-st7789": "qemu-m0-264k", "stm32f411-st7789": "qemu-m3"}
for _b, _on in REAL_COUNTED_ON.items():
    FW_VARIANTS["real-" + _b] = (_on, board_scenes(_b)[0], board_mk_value(_b, "BOARD_BAKE_FLAGS") or "",
                                 tuple("%s=%s" % (v, board_mk_value(_b, v)) for v in ("BOARD_CORE_SPLIT", "BOARD_RAM_CODE")
                                       if board_mk_value(_b, v)))
# the RP2040's build before its cores shared one ring: the default quality in
# tiles, a part a core, each with memory of its own
FW_VARIANTS["rp2040-tile-parts"] = ("qemu-m0-264k", "pond-orbit", "", FW_VARIANTS["real-rp2040-st7789"][3][1:] +
                                    ("BOARD_CORE_SPLIT=parts",))
# the STM32F411's before: the default quality, 32-pixel tiles and the whole apron
FW_VARIANTS["stm32-default"] = ("qemu-m3", "pond-orbit", "")
# and the RP2040's before core 1's stack moved to SRAM4-5: the whole apron, each strip
# finding its vertices again
FW_VARIANTS["rp2040-whole-apron"] = ("qemu-m0-264k", "pond-orbit",
                                     "--quality balanced --depth-interpolation plane --frame strips --tile 8 "
                                     "--water-uv triangles", FW_VARIANTS["real-rp2040-st7789"][3])
add_fw_keys()


def real_frame_insn(board):
    """The core's instructions a pixel of a real board's frame on its cores."""
    def get(m):
        counted = fw("real-" + board)(m)
        return counted["parts_insn_per_pixel"] if "parts_insn_per_pixel" in counted else \
            counted["render_insn_per_pixel"]
    return get


def real_clock_hz(board):
    return lambda m: m.code("boards/%s/clock.h" % board, r"^#define CLOCK_PROCESSOR_HZ (\d+)u")


def real_clock_mhz(board):
    return lambda m: Fig("1", 1.0) if m.recording else exact(int(real_clock_hz(board)(m).num) // 1000000)


def real_fps_bound(board):
    def get(m):
        frame, clock, size = real_frame_insn(board)(m), real_clock_hz(board)(m), fw("real-" + board)(m)["size"]
        if m.recording:
            return Fig("1", 1.0)
        width, height = map(int, size.text.split("x"))
        fps = clock.num / (frame.num * width * height)
        return derived(fps, fps * frame.tol / frame.num, 2)
    return get


for _b in REAL_COUNTED_ON:
    KEYS["real.%s.frame_insn_per_pixel" % _b] = real_frame_insn(_b)
    KEYS["real.%s.clock_mhz" % _b] = real_clock_mhz(_b)
    KEYS["real.%s.fps_bound" % _b] = real_fps_bound(_b)


PROFILE_BOARDS = ("qemu-m0-264k", "qemu-rv32-400k")
PROFILE_STAGES = [("geometry: transform, clip, project, vertex cache", "vertices: transform, clip, project, light"),
                  ("cluster bins", "cluster bins"),
                  ("triangle setup: edges, planes, exact depth", "triangle setup"),
                  ("raster: coverage, depth, interpolation, texels", "opaque spans"),
                  ("water shading", "water"),
                  ("panel: RGB565 and the stream", "panel: RGB565 and the stream"),
                  ("frame: pose, tiles or strips, clears, copies", "frame: pose, strips, clears, copies"),
                  ("other", "other (start-up, the counter's check)")]


@block
def fw_profile(m):
    """make profile-target on the RAM boards: each stage's instructions a pixel."""
    rows = []
    for stage, label in PROFILE_STAGES:
        rows.append([label] + [m.profile(b).get(stage, insn(0)) for b in PROFILE_BOARDS])
    return table(["stage"] + ["`%s`" % b for b in PROFILE_BOARDS], rows, ["---", "---:", "---:"])


FW_VARIANTS.update({
    "m3-static-off": ("qemu-m3", "pond", "--static-view off"),
    "m0-static-off-36": ("qemu-m0", "pond", "--quality fast --static-view off --tile 36"),
    "rv32-static-off-36": ("qemu-rv32", "pond", "--quality fast --static-view off --tile 36"),
    "m3-fast": ("qemu-m3", "pond", "--quality fast"),
    "m3-fast-backdrop": ("qemu-m3", "pond", "--quality fast --backdrop on"),
    "m3-fast-still": ("qemu-m3", "pond", "--quality fast --backdrop still --water-block 4"),
    "rv32-fast-backdrop": ("qemu-rv32", "pond", "--quality fast --backdrop on"),
    # the fast preset over a backdrop, without the refraction qemu-m0-backdrop bakes
    "m0-fast-backdrop": ("qemu-m0", "pond", "--quality fast --backdrop on"),
    # qemu-m0-backdrop's flags with no apron: what its refraction adds
    "m0-backdrop-apron-off": ("qemu-m0", "pond", "--quality fast --backdrop on --apron off --water-block 1 --exp2 64 "
                              "--perspective pixel --depth 16"),
    "rv32-fast-still": ("qemu-rv32", "pond", "--quality fast --backdrop still --water-block 4"),
    "m0-refraction-apron4": ("qemu-m0", "effects/refraction", "--quality fast --apron 4 --tile 24"),
    "m0-none-apron4": ("qemu-m0", "effects/none", "--quality fast --apron 4 --tile 24"),
})
for _t in (16, 28, 32):
    FW_VARIANTS["m0-fast-tile%d" % _t] = ("qemu-m0", "pond", "--quality fast --tile %d" % _t)
    FW_VARIANTS["m0-backdrop-tile%d" % _t] = ("qemu-m0", "pond", "--quality fast --backdrop on --tile %d" % _t)
    FW_VARIANTS["m0-still-tile%d" % _t] = ("qemu-m0", "pond",
                                           "--quality fast --backdrop still --water-block 4 --tile %d" % _t)
for _s in ("beach", "murky", "lake"):
    FW_VARIANTS["m0-%s" % _s] = ("qemu-m0", _s, "--quality fast")
    FW_VARIANTS["m0-%s-backdrop" % _s] = ("qemu-m0", _s, "--quality fast --backdrop on")
    FW_VARIANTS["m0-%s-still" % _s] = ("qemu-m0", _s, "--quality fast --backdrop still --water-block 4")
add_fw_keys()
# qemu-m0-backdrop's flags with 2x2 water blocks: what sharing effects saves once the water refracts
FW_VARIANTS["m0-backdrop-wb2"] = ("qemu-m0", "pond", "--quality fast --backdrop on --apron 18 --exp2 64 "
                                  "--perspective pixel --depth 16")
add_fw_keys()
# qemu-m0-264k's flags with the plane's texture coordinates (the balanced preset's)
FW_VARIANTS["m0-264k-uv-plane"] = ("qemu-m0-264k", "pond-orbit", "--quality balanced --depth-interpolation plane "
                                   "--frame strips --tile 12 --apron 24 --vertices frame --water-uv plane")
add_fw_keys()
# what two of its flags bring: its frame's panel_psnr less that without each (tarn compare at its time)
BACKDROP_BOARD_TIME = 1000
for _name, _drop in (("perspective_db", "--perspective pixel"), ("exp2_db", "--exp2 64")):
    KEYS["board.qemu-m0-backdrop.%s" % _name] = (lambda drop: lambda m: diff(
        m.compare("pond", board_bake_flags("qemu-m0-backdrop"), BACKDROP_BOARD_TIME)["panel_psnr"],
        m.compare("pond", board_bake_flags("qemu-m0-backdrop").replace(" " + drop, ""),
                  BACKDROP_BOARD_TIME)["panel_psnr"], 2))(_drop)
# what refraction adds on qemu-m0-backdrop: its frame less the same bake without an apron
KEYS["board.qemu-m0-backdrop.refraction_insn"] = lambda m: diff(
    m.bench("qemu-m0-backdrop")["insn_per_pixel"], fw("m0-backdrop-apron-off")(m)["insn_per_pixel"])
# qemu-m0-still without refraction (the fast preset's apron off, so no landing depth)
FW_VARIANTS["m0-still-apron-off"] = ("qemu-m0", "pond", "--quality fast --backdrop still --water-block 4 "
                                     "--perspective pixel --depth 32")
add_fw_keys()
KEYS["board.qemu-m0-still.refraction_insn"] = lambda m: diff(
    m.bench("qemu-m0-still")["insn_per_pixel"], fw("m0-still-apron-off")(m)["insn_per_pixel"])
# its landing depth (--landing-depth): the board's, and 1 and 4 world units, at the
# still figures' time
STILL_BOARD_TIME = 1750
for _depth in ("1", "4"):
    KEYS["still.landing-%s.panel_psnr" % _depth] = (lambda depth: lambda m: m.compare(
        "pond", re.sub(r"--landing-depth [\d.]+", "--landing-depth " + depth, board_bake_flags("qemu-m0-still")),
        STILL_BOARD_TIME)["panel_psnr"])(_depth)
    KEYS["bake.still-landing-%s.depth_values" % _depth] = (lambda depth: lambda m: comma(m.bake(
        "pond", re.sub(r"--landing-depth [\d.]+", "--landing-depth " + depth,
                       board_bake_flags("qemu-m0-still")))["count.backdrop_depth"]))(_depth)
KEYS["still.landing-board.panel_psnr"] = lambda m: m.compare("pond", board_bake_flags("qemu-m0-still"),
                                                             STILL_BOARD_TIME)["panel_psnr"]
KEYS["still.landing.board_depth"] = lambda m: m.code("boards/qemu-m0-still/board.mk",
                                                     r"--landing-depth ([\d.]+)")

KEYS["memory.pond.fast.bins_bytes"] = lambda m: diff(m.memory("pond", "--quality fast")["bytes"],
                                                     m.memory("pond", "--quality fast")["baked_bytes"]).fmt("comma")
KEYS["limit.qemu-m0.code_bytes"] = lambda m: m.code("boards/qemu-m0/board.mk",
                                                    r"^BOARD_CODE_BYTES_MAX := (\d+)").fmt("comma")
for _b in ("qemu-m0", "qemu-rv32", "qemu-m3"):
    KEYS["limit.%s.stack_bytes" % _b] = (lambda b: lambda m: m.code(
        "boards/%s/board.mk" % b, r"^BOARD_STACK_BYTES := (\d+)").fmt("comma"))(_b)
for _b in ("qemu-m0", "qemu-m0-still"):
    KEYS["board.%s.panel_insn" % _b] = (lambda b: lambda m: diff(
        m.bench(b)["insn_per_pixel"], m.bench(b)["render_insn_per_pixel"]))(_b)


def host_frames(args):
    """The host's instructions a pixel for one frame of tarn render ARGS when the
    first frame also makes the backdrop: (3 frames - 1 frame) / 2."""
    def fn(m):
        one = m.host("pond", args)["total"]
        three = m.host("pond", args + " --frames 3")["total"]
        v = (three.num - one.num) / 2.0 / 57600.0
        return insn(v)
    return fn


HOST_STILL = "--quality fast --backdrop still --water-block 4"
KEYS["host.pond.fast.total"] = lambda m: m.host("pond", "--quality fast")["total"].fmt("comma")
KEYS["host.pond.backdrop"] = host_frames("--quality fast --backdrop on")
KEYS["host.pond.still"] = host_frames(HOST_STILL)
KEYS["fw.m0-over-m3"] = lambda m: ratio(m.bench("qemu-m0")["insn_per_pixel"], fw("m3-fast")(m)["insn_per_pixel"])


@block
def fw_cpus(m):
    """The pond at the fast preset on each CPU: the boards, builds of other flags, callgrind."""
    ins = lambda d: d["insn_per_pixel"]  # noqa: E731
    rows = [["meshes, static view", ins(m.bench("qemu-m0")), ins(fw("m3-fast")(m)), ins(m.bench("qemu-rv32")),
             host_of("--quality fast")(m)],
            ["backdrop", ins(fw("m0-fast-backdrop")(m)), ins(fw("m3-fast-backdrop")(m)),
             ins(fw("rv32-fast-backdrop")(m)), KEYS["host.pond.backdrop"](m)],
            ["still water", ins(m.bench("qemu-m0-still")), ins(fw("m3-fast-still")(m)),
             ins(fw("rv32-fast-still")(m)), KEYS["host.pond.still"](m)]]
    return table(["bake", "Cortex-M0", "Cortex-M3", "rv32imac", "x86-64 host (callgrind, `tarn_render_frame`)"],
                 rows, ["---", "---:", "---:", "---:", "---:"])


FITS_ROWS = [  # label, quality flags, board that uses it, note
    ("fast (apron off, depth 16, bins, water blocks), tile 16", "--quality fast --tile 16", None, ""),
    ("fast, tile 28", "--quality fast --tile 28", None, ""),
    ("fast, tile 32", "--quality fast --tile 32", None, ""),
    ("fast, tile 40", "--quality fast", "qemu-m0", ": the preset and the boards' choice"),
    ("fast, tile 40, `--backdrop on`", "--quality fast --backdrop on", None, ": the backdrop takes flash, not RAM"),
    ("fast, tile 40, `--backdrop on --apron 18 --water-block 1`", board_bake_flags("qemu-m0-backdrop"),
     "qemu-m0-backdrop", ": `qemu-m0-backdrop`; its refracted samples read the picture in flash"),
    ("fast, tile 40, `--backdrop still --water-block 4`", "--quality fast --backdrop still --water-block 4",
     "qemu-m0-still", ": `qemu-m0-still`; no depth buffer, no water pass buffers"),
    ("fast, tile 40, no bins", "--quality fast --bins off", None, "bins"),
    ("fast, tile 40, `--static-view off` (bins in RAM)", "--quality fast --static-view off", None, ""),
    ("fast, tile 42", "--quality fast --tile 42", None, ""),
    ("fast, tile 44", "--quality fast --tile 44", None, ""),
    ("fast without water blocks, tile 43 (an odd tile takes no blocks)", "--quality fast --water-block 1 --tile 43",
     None, ""),
    ("fast with 32-bit depth, tile 32", "--quality fast --depth 32 --tile 32", None, ""),
    ("fast with 32-bit depth, tile 40", "--quality fast --depth 32", None, ""),
    ("fast with a 4-pixel apron, tile 24", "--quality fast --apron 4 --tile 24", None, ""),
    ("fast with the apron on, tile 8", "--quality fast --apron on --tile 8", None, ""),
    ("default: balanced (apron on, tile 32, depth 32, bins)", "", None, "; it runs on `qemu-m3`"),
]


def renderer_bytes(m, flags):
    """What a frame of the pond at these bake flags needs: tarn bake's memory_bytes."""
    return comma(m.bake("pond", flags)["memory_bytes"])


def m0_other_bytes(m):
    """qemu-m0's RAM besides the renderer's memory and the stack: .data and the rest of .bss."""
    b = m.bench("qemu-m0")
    return b["ram_bytes"].num - b["stack_reserved_bytes"].num - m.bake("pond", "--quality fast")["memory_bytes"].num


@block
def fw_fits(m):
    """Which qualities of the pond fit qemu-m0's RAM: tarn bake's memory_bytes, the board's stack and data."""
    ram = 16384
    stack = m.bench("qemu-m0")["stack_reserved_bytes"].num
    other = m0_other_bytes(m)
    rows = []
    for label, flags, board, note in FITS_ROWS:
        need = renderer_bytes(m, flags)
        total = need.num + stack + other
        if board:
            fits = ["yes (", comma(m.bench(board)["ram_bytes"]), " used)", note]
        elif note == "bins":
            fits = ["yes, but ", fw("m0-fast-bins-off")(m)["insn_per_pixel"], " insn/pixel instead of ",
                    m.bench("qemu-m0")["insn_per_pixel"]]
        elif total <= ram:
            fits = ["yes" + note]
        else:
            fits = ["no (", exact("{:,}".format(int(total))), " needed" + note + ")"]
        rows.append([label, need, fits])
    return table(["pond, quality", "renderer bytes", "fits `qemu-m0`'s 16 KB of RAM with its stack?"], rows,
                 ["---", "---:", "---"])


KEYS["board.qemu-m0.other_bytes"] = lambda m: exact(int(m0_other_bytes(m))) if not m.recording else Fig("1", 1.0)


@block
def fw_tiles(m):
    """The M0's cost by tile size: builds of the pond at each tile."""
    rows = []
    for label, name, at_40 in (("insn/pixel", "m0-fast-tile%d", m.bench("qemu-m0")),
                               ("insn/pixel, `--backdrop on`", "m0-backdrop-tile%d", fw("m0-fast-backdrop")(m)),
                               ("insn/pixel, `--backdrop still --water-block 4`", "m0-still-tile%d",
                                m.bench("qemu-m0-still"))):
        rows.append([label] + [fw(name % t)(m)["insn_per_pixel"] for t in (16, 28, 32)] + [at_40["insn_per_pixel"]])
    return table(["tile", "16", "28", "32", "40"], rows, ["---", "---:", "---:", "---:", "---:"])


for _n, _a in (("off", "--apron off"), ("4", "--apron 4"), ("on", "--apron on")):
    KEYS["pond.m0-quality.apron-%s.psnr" % _n] = (lambda a: lambda m: m.compare(
        "pond", a + " --tile 28 --depth 16")["psnr"])(_a)

EFFECTS_M0 = [("none", "none (opaque only)"), ("ramp", "ramp"), ("depth_colour", "depth_colour"),
              ("fresnel", "fresnel"), ("fog", "fog"), ("foam", "foam"), ("absorption", "absorption"),
              ("refraction", "refraction (no apron at this quality: the normal maps alone)"),
              ("normals", "normals (with their specular)"), ("sparkles", "sparkles"),
              ("underwater", "underwater (tile 16: the view's second buffer; water blocks do not apply)")]
EFFECT_FLAGS = ["--quality fast", "--quality fast --backdrop on", "--quality fast --backdrop still --water-block 4"]


def effect_cost(m, scene, flags):
    extra = " --tile 16" if scene == "underwater" else ""
    d = m.bench("qemu-m0", "effects/" + scene, flags + extra, may_fail=True)
    if "failed" in d:
        if "--backdrop still" not in d["failed"]:
            raise MeasureError(d["failed"])
        return None
    return d["insn_per_pixel"]


@block
def fw_effects(m):
    """What each water effect costs the M0: scenes/effects/ built with the board's quality (and over a
    backdrop, and still water), as scripts/bench-effects-target.sh does."""
    base = [effect_cost(m, "none", f) for f in EFFECT_FLAGS]
    rows = []
    for scene, label in EFFECTS_M0:
        row = [label]
        for k, f in enumerate(EFFECT_FLAGS):
            c = effect_cost(m, scene, f)
            if c is None:
                row += ["refused", ""]
            elif scene == "none":
                row += [c, ""]
            else:
                row += [c, diff(c, base[k], sign=True)]
        rows.append(row)
    return table(["effect", "insn/pixel", "over `none`", "backdrop", "over `none`", "still water", "over `none`"],
                 rows, ["---"] + ["---:"] * 6)


KEYS["fw.m0-refraction-apron4.over_none"] = lambda m: diff(fw("m0-refraction-apron4")(m)["insn_per_pixel"],
                                                           fw("m0-none-apron4")(m)["insn_per_pixel"], sign=True)


def backdrop_bake(m):
    return m.bake("pond", "--quality fast --backdrop on")


# Refraction over an opaque backdrop, read from the picture in flash (docs/bake.md).
BACKDROP_REFRACTION_FAST = "--quality fast --backdrop on --apron on --water-block 1 --perspective pixel"
KEYS["bake.backdrop.balanced.memory_bytes"] = lambda m: comma(m.bake("pond", "--backdrop on")["memory_bytes"])
KEYS["bake.balanced.memory_bytes"] = lambda m: comma(m.bake("pond")["memory_bytes"])
KEYS["bake.backdrop-refraction.depths"] = lambda m: comma(m.bake("pond", BACKDROP_REFRACTION_FAST)["count.backdrop_depth"])
KEYS["bake.backdrop-refraction.const_bytes"] = lambda m: comma(m.bake("pond", BACKDROP_REFRACTION_FAST)["const_bytes"])
KEYS["bake.backdrop-refraction.panel_psnr"] = lambda m: m.compare("pond", BACKDROP_REFRACTION_FAST)["panel_psnr"]


KEYS["bake.backdrop.indices_bytes"] = lambda m: comma(backdrop_bake(m)["bytes.backdrop_colour"])
KEYS["bake.backdrop.colours"] = lambda m: comma(backdrop_bake(m)["backdrop.colours"])
KEYS["bake.backdrop.index_bits"] = lambda m: backdrop_bake(m)["backdrop.bits"]
KEYS["bake.backdrop.palette_bytes"] = lambda m: comma(backdrop_bake(m)["bytes.backdrop_palette"])
KEYS["bake.backdrop.depth_bytes"] = lambda m: comma(backdrop_bake(m)["bytes.backdrop_depth"])
KEYS["bake.backdrop.depths"] = lambda m: comma(backdrop_bake(m)["count.backdrop_depth"])
KEYS["bake.backdrop.bytes"] = lambda m: comma(backdrop_bake(m)["bytes.backdrop"])
KEYS["bake.backdrop.water_triangles"] = lambda m: exact(sum(
    int(v.text) for k, v in backdrop_bake(m).items() if re.match(r"count\.mesh_\d+_indices$", k)) // 3) \
    if not m.recording else Fig("1", 1.0)


@block
def fw_backdrop(m):
    """The pond's M0 boards with and without the backdrop: make bench-target."""
    rows = []
    for label, b in (("`qemu-m0` (meshes, static view), `--quality fast`", m.bench("qemu-m0")),
                     ("`--quality fast --backdrop on`", fw("m0-fast-backdrop")(m)),
                     ("`qemu-m0-backdrop`: `%s`" % board_bake_flags("qemu-m0-backdrop"), m.bench("qemu-m0-backdrop"))):
        rows.append([label, comma(b["scene_bytes"]), comma(b["flash_bytes"]), b["insn_per_pixel"],
                     b["render_insn_per_pixel"], b["panel_psnr"]])
    return table(["pond", "scene data", "flash", "insn/pixel", "core alone", "panel_psnr"], rows,
                 ["---", "---:", "---:", "---:", "---:", "---:"])


@block
def fw_scenes(m):
    """Other scenes on the M0, from the meshes, over a backdrop and over still water."""
    rows = []
    for scene, size in (("pond", "240x240"), ("beach", "240x240"), ("murky", "240x240"), ("lake", "240x160")):
        if scene == "pond":
            bs = [m.bench("qemu-m0"), fw("m0-fast-backdrop")(m), m.bench("qemu-m0-still")]
        else:
            bs = [fw("m0-%s" % scene)(m), fw("m0-%s-backdrop" % scene)(m), fw("m0-%s-still" % scene)(m)]
        row = ["%s %s" % (scene, size)]
        for b in bs:
            row += [b["insn_per_pixel"], comma(b["flash_bytes"])]
        rows.append(row)
    return table(["scene", "insn/pixel", "flash", "`--backdrop on`", "flash", "`--backdrop still --water-block 4`",
                  "flash"], rows, ["---"] + ["---:"] * 6)


# where the still board's instructions go: make profile-target's functions, by the work they do
PROFILE_WORK = [  # the work, its functions, what it is
    ("the walk", ["tarn__water_still_tile", "over_still", "tarn__water_finish", "sharp_at", "tarn__water_sharp_at"],
     "the scan of every tile pixel for each water object's marks, then each water pixel: its block, whether "
     "a sharp feature can show, its colour"),
    ("the panel", ["convert_rows", "stream_data", "stream_command", "board_write", "semihosting_write",
                   "tarn_panel_send_tile", "panel_sink_send_tile", "set_window", "set_address_range"],
     "RGB565 with the ordered dither (`convert_rows`), the ST7789 stream"),
    ("reading the picture", ["tarn__backdrop_fill"], "a palette index a pixel, read a word at a time"),
    ("the highlight", ["tarn__water_surface_normal", "map_texels", "tarn__water_specular", "tarn__water_texel_at",
                       "tarn_rsqrt_q16", "tarn__water_normalise"],
     "once a block: both normal maps' texels, the normal's direction, the specular's test"),
    ("foam", ["tarn__water_foam", "tarn__water_foam_over", "tarn__backdrop_foam_band", "tarn_sin_q15"],
     "the band's pixels at every frame: the line's phase, the foam texel, the blend"),
    ("texture coordinates", ["texture_coordinate", "recip_normalised_q30", "tarn_recip_q30"],
     "a reciprocal of near/d and two products a block's top-left pixel and a foam pixel"),
    ("the scene check", ["tarn__backdrop_valid", "tarn__scene_check"], "the backdrop's palette and spans, every frame"),
]


@block
def fw_profile_still(m):
    """make profile-target BOARD=qemu-m0-still, its functions grouped by the work they do."""
    f = profile_functions(m)
    rows = [[work, profile_per_pixel(names)(m), what] for work, names, what in PROFILE_WORK]
    named = {n for _, names, _ in PROFILE_WORK for n in names} | {"spin"}
    rest = sum(v for k, v in f.items() if k not in named)
    rows.append(["the rest", insn(rest / (PROFILED_FRAMES * 57600.0)) if f else Fig("1", 1.0),
                 "every other function (the counter check's loop, `spin`, left out)"])
    return table(["work", "insn/pixel", "what it is"], rows, ["---", "---:", "---"])


def profile_total(m):
    text = m.output("profile_still")
    mt = re.search(r"instructions=(\d+)", text) if isinstance(text, str) else None
    return comma(insn(int(mt.group(1)))) if mt else Fig("1", 1.0)


KEYS["profile.still.total"] = profile_total


def fw_sweep_run(board, points=None):
    def fn(m):
        pts = points or "firmware/points/pond.txt"
        return run(["make", "--no-print-directory", "-s", "firmware-sweep", "BOARD=" + board,
                    "SCENE=scenes/pond.json", "BAKE_FLAGS=--apron off --tile 28 --depth 16", "POINTS=" + pts,
                    "FW_BUILD_DIR=build/figures/fws-%s%s" % (board, "-one" if points else "")])
    return fn


@tool
def fw_sweep_m0(m):
    return fw_sweep_run("qemu-m0")(m)


@tool
def fw_sweep_rv32(m):
    return fw_sweep_run("qemu-rv32")(m)


@tool
def fw_sweep_m0_one(m):
    """The sweep's first point alone (its own points file)."""
    path = os.path.join(ROOT, "build/figures/points-one.txt")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("--depth 16\n")
    return fw_sweep_run("qemu-m0", "build/figures/points-one.txt")(m)


def sweep_lines(text):
    out = []
    for line in (text if isinstance(text, str) else "").splitlines():
        if not line.startswith(("point ", "sweep ")):
            continue
        parts = []
        for i, word in enumerate(line.split()):
            parts.append(" " if i else "")
            k, _, v = word.partition("=")
            if not v or k in ("board", "scene", "size", "status"):
                parts.append(word)
            elif k in ("insn_per_pixel", "frame_insn", "convert_insn_per_pixel", "dither_insn_per_pixel"):
                parts += [k + "=", insn(int(v))]
            elif k == "counter_check":
                got, want = v.split("/")
                parts += [k + "=", Fig(got, float(got), 0.0001 * float(want)), "/" + want]
            else:
                parts += [k + "=", exact(v)]
        out.append(parts + ["\n"])
    return out


@block
def fw_sweep_example(m):
    """make firmware-sweep of firmware/points/pond.txt on qemu-m0 and qemu-rv32."""
    parts = ["qemu-m0:\n"]
    for line in sweep_lines(m.output("fw_sweep_m0")):
        parts += line
    parts.append("qemu-rv32:\n")
    for line in sweep_lines(m.output("fw_sweep_rv32")):
        parts += line
    return code_block(parts)


def sweep_field(tool_name, index, field):
    def fn(m):
        text = m.output(tool_name)
        for line in (text if isinstance(text, str) else "").splitlines():
            if line.startswith("point index=%d " % index):
                return insn(int(dict(w.split("=", 1) for w in line.split()[1:])[field]))
        return Fig("1", 1.0)
    return fn


KEYS["fwsweep.m0.0.insn_per_pixel"] = sweep_field("fw_sweep_m0", 0, "insn_per_pixel")
KEYS["fwsweep.m0-one.0.insn_per_pixel"] = sweep_field("fw_sweep_m0_one", 0, "insn_per_pixel")
KEYS["fwsweep.m0-one.0.frame_insn"] = lambda m: comma(sweep_field("fw_sweep_m0_one", 0, "frame_insn")(m))
FW_VARIANTS["m0-points-bake"] = ("qemu-m0", "pond", "--apron off --tile 28 --depth 16")
add_fw_keys()


def points_bake_frame(m):
    frames = fw("m0-points-bake")(m)["frame_insn"]
    return frames[-1] if isinstance(frames, list) else frames


KEYS["fw.m0-points-bake.render_frame_insn"] = lambda m: comma(points_bake_frame(m))
KEYS["fwsweep.m0.sink_per_tile"] = lambda m: derived(
    (sweep_field("fw_sweep_m0_one", 0, "frame_insn")(m).num - points_bake_frame(m).num) / 81.0, 5.0)
KEYS["sweep.pond.m0_points"] = lambda m: exact(re.search(r"### pond on qemu-m0: (\d+) of", front_section(
    m, "pond")).group(1)) if front_section(m, "pond") else Fig("1", 1.0)


@tool
def stack_chain_m0(m):
    m.bench("qemu-m0")
    conf = open(os.path.join(ROOT, "build/firmware/qemu-m0/firmware.conf")).read()
    entry = re.search(r"^stack_entry=(.*)$", conf, re.M).group(1).split()
    return run(["firmware/stack_bound.sh", "arm-none-eabi-", "build/firmware/qemu-m0/obj"] + entry)


@block
def fw_stack_chain(m):
    """firmware/stack_bound.sh on qemu-m0's build: its deepest chain, each function's frame."""
    text = m.output("stack_chain_m0")
    chain = []
    for line in (text if isinstance(text, str) else "").splitlines()[1:]:
        mt = re.match(r"\s*(\d+) (\w+)$", line)
        if mt:
            chain.append((mt.group(2), mt.group(1)))
    parts, width = [], 0
    for i, (name, frame) in enumerate(chain):
        piece = "%s (%s)" % (name, frame)
        if i:
            if width + len(piece) + 3 > 88:
                parts.append(" →\n")
                width = 0
            else:
                parts.append(" → ")
                width += 3
        parts += [name + " (", exact(frame), ")"]
        width += len(piece)
    return code_block(parts + ["\n"])


# ---- the firmware's error messages, from builds that fail as the docs say ------------------

def run_failing(argv):
    """The output of a command that must fail (a build too large for a board)."""
    p = subprocess.run(argv, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode == 0:
        raise MeasureError("%s succeeded, but the docs show how it fails" % " ".join(argv))
    return p.stdout


def bad_build(*args):
    return run_failing(["make", "--no-print-directory", "firmware"] + list(args))


SPHERE = """{
  "frame": {"width": 240, "height": 240},
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 60, "near": 0.1, "far": 100},
  "materials": {"red": {"colour": "#d0452f"}},
  "objects": [{"type": "sphere", "material": "red", "radius": 1, "segments": 128, "rings": 64}]
}
"""


@tool
def error_board(m):
    return run_failing(["make", "--no-print-directory", "firmware", "BOARD=nope"])


@tool
def error_ram(m):
    return bad_build("BOARD=qemu-m0", "SCENE=scenes/pond.json", "BAKE_FLAGS=--quality fast --depth 32",
                     "FW_BUILD_DIR=build/figures/bad-ram")


@tool
def error_flash(m):
    path = os.path.join(ROOT, "build/figures/big-sphere.json")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(SPHERE)
    return bad_build("BOARD=qemu-m0", "SCENE=build/figures/big-sphere.json", "BAKE_FLAGS=--quality fast",
                     "FW_BUILD_DIR=build/figures/bad-flash")


@tool
def error_stack(m):
    return bad_build("BOARD=qemu-m0", "BOARD_STACK_BYTES=3000", "FW_BUILD_DIR=build/figures/bad-stack")


@tool
def error_stm32_ram(m):
    return bad_build("BOARD=stm32f411-st7789", "BAKE_FLAGS=--tile 64", "FW_BUILD_DIR=build/figures/bad-stm32")


def numbered(line):
    """A message line with each number in it a figure (exact)."""
    parts = []
    for i, piece in enumerate(re.split(r"(\d+)", line)):
        if piece:
            parts.append(exact(piece) if i % 2 else piece)
    return parts


def message_lines(text, patterns):
    out = []
    for pattern in patterns:
        for line in (text if isinstance(text, str) else "").splitlines():
            mt = re.search(pattern, line)
            if mt:
                out.append(mt.group(0))
                break
        else:
            if isinstance(text, str) and text:
                raise MeasureError("no line matching %s in:\n%s" % (pattern, text[-1500:]))
    return out


def error_block(tool_name, patterns, doc):
    def fn(m):
        lines = message_lines(m.output(tool_name), patterns)
        parts = []
        for line in lines:
            parts += numbered(line) + ["\n"]
        return code_block(parts) if lines else [Fig("1", 1.0)]
    fn.__doc__ = doc
    return fn


BLOCKS["fw-error-board"] = error_block("error_board", [r"^tarn: no board .*"], "make firmware BOARD=nope")
BLOCKS["fw-error-ram"] = error_block("error_ram", [r"region .RAM. overflowed by \d+ bytes", r"^tarn: .*"],
                                     "a build too large for qemu-m0's RAM")
BLOCKS["fw-error-flash"] = error_block("error_flash", [r"region .FLASH. overflowed by \d+ bytes", r"^tarn: .*"],
                                       "a sphere too large for qemu-m0's flash")
BLOCKS["fw-error-stack"] = error_block("error_stack", [r"^tarn: .*deepest call chain.*"],
                                       "qemu-m0 with too small a stack reserved")
KEYS["bad.stm32-tile64.ram_overflow"] = lambda m: exact(re.search(
    r"region .RAM. overflowed by (\d+) bytes", m.output("error_stm32_ram")).group(1)) \
    if isinstance(m.output("error_stm32_ram"), str) else Fig("1", 1.0)


# ---- docs/bake.md ------------------------------------------------------------------------------

@tool
def bake_pond_example(m):
    """tarn bake scenes/pond.json -o build/pond.c: its line, and the files it writes."""
    line = run([TARN, "bake", "scenes/pond.json", "-o", "build/pond.c"]).strip().splitlines()[-1]
    files = {}
    for name in ("pond.c", "pond.h", "pond_link.h"):
        with open(os.path.join(ROOT, "build", name)) as f:
            files[name] = f.read()
    return {"line": line, "files": files}


def bake_example(m):
    return m.output("bake_pond_example") if not m.recording else None


@block
def bake_example_line(m):
    """What tarn bake scenes/pond.json -o build/pond.c prints."""
    ex = bake_example(m)
    if ex is None:
        return [Fig("1", 1.0)]
    return code_block(["$ tarn bake scenes/pond.json -o build/pond.c\n"] + numbered(ex["line"]) + ["\n"])


@block
def bake_header(m):
    """The first comment of build/pond.c (tarn bake scenes/pond.json -o build/pond.c) and its include."""
    ex = bake_example(m)
    if ex is None:
        return [Fig("1", 1.0)]
    text = ex["files"]["pond.c"]
    head = text[:text.index("*/") + 2] + "\n" + re.search(r"^#include .*$", text, re.M).group(0) + "\n"
    parts = []
    for line in head.splitlines(True):
        parts += numbered(line) if re.search(r"\d", line) and not line.startswith(("/* pond.c", " *   tarn bake")) \
            else [line]
    return ["```c\n"] + parts + ["```\n"]


@block
def bake_memory_define(m):
    """build/pond.h's memory macro and declarations."""
    ex = bake_example(m)
    if ex is None:
        return [Fig("1", 1.0)]
    h = ex["files"]["pond.h"]
    lines = [ln for ln in h.splitlines() if ln.startswith(("#define POND_MEMORY_BYTES", "extern "))]
    parts = []
    for i, ln in enumerate(lines):
        parts += numbered(ln) + ["\n"]
        if i == 0:
            parts.append("\n")
    return ["```c\n"] + parts + ["```\n"]


@block
def bake_link(m):
    """build/pond_link.h's switches (tarn bake scenes/pond.json)."""
    ex = bake_example(m)
    if ex is None:
        return [Fig("1", 1.0)]
    lines = [ln + "\n" for ln in ex["files"]["pond_link.h"].splitlines() if ln.startswith("#define TARN_LINK_")]
    return ["```c\n"] + lines + ["```\n"]


KEYS["bake.pond.static.mesh_bytes"] = lambda m: comma(m.bake("pond", "")["bytes.mesh"])
KEYS["bake.pond.static.static_bytes"] = lambda m: comma(m.bake("pond", "")["bytes.static_vertices"])
KEYS["bake.pond.static.const_bytes"] = lambda m: comma(m.bake("pond", "")["const_bytes"])
KEYS["bake.pond.dynamic.mesh_bytes"] = lambda m: comma(m.bake("pond", "--static-view off")["bytes.mesh"])
KEYS["bake.pond.dynamic.const_bytes"] = lambda m: comma(m.bake("pond", "--static-view off")["const_bytes"])
KEYS["bake.backdrop.const_bytes"] = lambda m: comma(backdrop_bake(m)["const_bytes"])
KEYS["bake.backdrop.texture_bytes"] = lambda m: comma(backdrop_bake(m)["bytes.texture"])
KEYS["bake.backdrop.rest_bytes"] = lambda m: comma(exact(
    backdrop_bake(m)["bytes.backdrop"].num - backdrop_bake(m)["bytes.backdrop_colour"].num -
    backdrop_bake(m)["bytes.backdrop_palette"].num - backdrop_bake(m)["bytes.backdrop_depth"].num).fmt("int")) \
    if not m.recording else Fig("1", 1.0)

STILL_FLAGS = "--quality fast --backdrop still --water-block 4"


def still_bake(m):
    return m.bake("pond", STILL_FLAGS)


KEYS["bake.still-refracting.depth_values"] = lambda m: comma(
    m.bake("pond", board_bake_flags("qemu-m0-still"))["count.backdrop_depth"])
KEYS["bake.still.colours"] = lambda m: comma(still_bake(m)["backdrop.colours"])
KEYS["bake.still.index_bits"] = lambda m: still_bake(m)["backdrop.bits"]
KEYS["bake.still.foam_places"] = lambda m: comma(still_bake(m)["count.backdrop_depth"])
KEYS["bake.still.bytes"] = lambda m: comma(still_bake(m)["bytes.backdrop"])
KEYS["bake.still.const_bytes"] = lambda m: comma(still_bake(m)["const_bytes"])
KEYS["bake.still.indices_bytes"] = lambda m: comma(still_bake(m)["bytes.backdrop_colour"])
KEYS["bake.still.palette_bytes"] = lambda m: comma(still_bake(m)["bytes.backdrop_palette"])
KEYS["bake.still.foam_bytes"] = lambda m: comma(still_bake(m)["bytes.backdrop_depth"])
KEYS["bake.still.rest_bytes"] = lambda m: comma(exact(
    still_bake(m)["bytes.backdrop"].num - still_bake(m)["bytes.backdrop_colour"].num -
    still_bake(m)["bytes.backdrop_palette"].num - still_bake(m)["bytes.backdrop_depth"].num).fmt("int")) \
    if not m.recording else Fig("1", 1.0)
KEYS["bake.still.texture_bytes"] = lambda m: comma(still_bake(m)["bytes.texture"])
KEYS["bake.still.mesh_static_bytes"] = lambda m: comma(exact(
    still_bake(m)["bytes.mesh"].num + still_bake(m)["bytes.static_vertices"].num).fmt("int")) \
    if not m.recording else Fig("1", 1.0)
KEYS["compare.pond.fast.1750.psnr"] = lambda m: m.compare("pond", "--quality fast", 1750)["psnr"]
KEYS["compare.pond.fast-wb4.1750.psnr"] = lambda m: m.compare("pond", "--quality fast --water-block 4", 1750)["psnr"]
FW_VARIANTS["m0-static-off-40"] = ("qemu-m0", "pond", "--quality fast --static-view off")


@block
def bake_boards(m):
    """The pond's three M0 boards: make bench-target."""
    rows = []
    for label, b in (("meshes, static view (`qemu-m0`: `--quality fast`)", m.bench("qemu-m0")),
                     ("backdrop (`--quality fast --backdrop on`)", fw("m0-fast-backdrop")(m)),
                     ("backdrop, refracting (`qemu-m0-backdrop`)", m.bench("qemu-m0-backdrop")),
                     ("still water (`qemu-m0-still`)", m.bench("qemu-m0-still"))):
        rows.append([label, comma(b["scene_bytes"]), comma(b["flash_bytes"]), b["insn_per_pixel"]])
    return table(["", "scene data", "M0 flash", "M0 insn/pixel"], rows, ["---", "---:", "---:", "---:"])


@block
def bake_backdrop_boards(m):
    """The pond's M0 boards with and without the backdrop: make bench-target."""
    rows = []
    for label, b in (("meshes, static view (`--quality fast`)", m.bench("qemu-m0")),
                     ("backdrop (`--quality fast --backdrop on`)", fw("m0-fast-backdrop")(m))):
        rows.append([label, comma(b["scene_bytes"]), comma(b["flash_bytes"]), b["insn_per_pixel"]])
    return table(["", "scene data", "M0 flash", "M0 insn/pixel"], rows, ["---", "---:", "---:", "---:"])


# ---- docs/panels.md --------------------------------------------------------------------------

@tool
def test_panel(m):
    """build/release/tests/test_panel's messages (make check builds it)."""
    run(["make", "--no-print-directory", "-s", "build/release/tests/test_panel"])
    return run(["build/release/tests/test_panel"])


def panel_frames(m):
    text = m.output("test_panel")
    out = {}
    for mt in re.finditer(r"240x240 frame, tile (\d+): (\d+) bytes on the wire \((\d+) pixel bytes \+ (\d+) for "
                          r"windows\), (\d+) bytes of stream", text if isinstance(text, str) else ""):
        out[int(mt.group(1))] = [int(x) for x in mt.groups()[1:]]
    return out


@block
def panel_tile_bytes(m):
    """A 240x240 frame sent a tile at a time: tests/test_panel.c's test_stream_round_trips_a_frame."""
    frames = panel_frames(m)
    rows = []
    for tile in sorted(frames):
        wire, pixels, windows, stream = frames[tile]
        tiles = ((240 + tile - 1) // tile) ** 2
        rows.append([exact(tile), exact(tiles), exact(spaced(wire)),
                     [exact(spaced(windows)), " (", exact("%.1f" % (100.0 * windows / wire)), " %)"],
                     exact(spaced(stream))])
    if not rows:
        return [Fig("1", 1.0)]
    return table(["tile", "tiles", "bytes on the SPI wire", "of which windows", "bytes in the stream format"], rows)


def panel_frame_key(tile, what):
    def fn(m):
        frames = panel_frames(m)
        if tile not in frames:
            return Fig("1", 1.0)
        wire = frames[tile][0]
        if what == "wire":
            return exact(spaced(wire))
        if what == "ms40":
            return exact("%.1f" % (wire * 8 / 40e6 * 1000))
        if what == "rows":
            return exact(spaced(((240 + tile - 1) // tile) ** 2 * tile))
    return fn


KEYS["panel.tile16.wire"] = panel_frame_key(16, "wire")
KEYS["panel.tile16.ms40"] = panel_frame_key(16, "ms40")
KEYS["panel.tile16.rows"] = panel_frame_key(16, "rows")


def bench_panel_row(link, send, tile):
    def fn(m):
        text = m.output("bench_panels")
        for line in (text if isinstance(text, str) else "").splitlines():
            w = line.split()
            if w[:3] == [link, send, str(tile)]:
                return w
        return None
    return fn


def fps_loss(m):
    bands, tiles = bench_panel_row("spidev", "bands", 32)(m), bench_panel_row("spidev", "tiles", 16)(m)
    if not bands or not tiles:
        return Fig("1", 1.0)
    return exact("%d" % round(100.0 * (1 - float(tiles[6]) / float(bands[6]))))


def command_clock_cost(m):
    panel, spidev = bench_panel_row("panel", "bands", 32)(m), bench_panel_row("spidev", "bands", 32)(m)
    if not panel or not spidev:
        return Fig("1", 1.0)
    return exact("%.2f" % (100.0 * (1 - float(spidev[5]) / float(panel[5]))))


KEYS["panel.spidev.tiles_fps_loss"] = fps_loss
KEYS["panel.spidev.command_clock_cost"] = command_clock_cost
KEYS["panel.band.frame_bytes"] = lambda m: exact(spaced(int(bench_panel_row("spidev", "bands", 32)(m)[3]))) \
    if bench_panel_row("spidev", "bands", 32)(m) else Fig("1", 1.0)


@tool
def test_display_links(m):
    """build/release/tests/test_display_links's messages (make check builds it)."""
    run(["make", "--no-print-directory", "-s", "build/release/tests/test_display_links"])
    return run(["build/release/tests/test_display_links"])


def mcp2210_changed(m):
    text = m.output("test_display_links")
    mt = re.search(r"second frame through the MCP2210: (\d+) of 225 tiles changed", text or "")
    if isinstance(text, str) and not mt:
        raise MeasureError("build/release/tests/test_display_links printed no MCP2210 line")
    return exact(mt.group(1)) if mt else Fig("1", 1.0)


KEYS["panel.mcp2210.tiles_changed"] = mcp2210_changed
KEYS["panel.spidev.ceiling_fps"] = lambda m: exact("%.1f" % float(bench_panel_row("spidev", "bands", 32)(m)[7])) \
    if bench_panel_row("spidev", "bands", 32)(m) else Fig("1", 1.0)
for _b in ("qemu-m3", "qemu-rv32", "qemu-m0-264k", "qemu-rv32-400k"):
    KEYS["board.%s.counter_check" % _b] = (lambda b: lambda m: m.bench(b)["counter_check"].fmt("comma"))(_b)
