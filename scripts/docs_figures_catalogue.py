"""What every figure of README.md and docs/ is, and the command that measures it
(scripts/docs_figures.py reads and writes them).

BLOCKS: a block's name -> a function of the measurer giving the block's text, its
    figures as Fig parts (their kinds say how each is checked).
KEYS: a key -> a function of the measurer giving one figure.
IMAGES: a PNG in docs/ -> the tarn command (without -o) that renders it.
TOOLS: a tool's name -> a function running it, whose output blocks and keys read.
"""

import os
import re
import subprocess

from docs_figures import (ROOT, TARN, Fig, MeasureError, Placeholder, derived, diff, exact, insn, pct_less,
                          pct_more, ratio, run, wall)

BLOCKS = {}
KEYS = {}
TOOLS = {}

IMAGES = {"docs/images/%s.png" % s: ["render", "scenes/%s.json" % s]
          for s in ("pond", "beach", "murky", "lake", "underwater")}


def block(fn):
    BLOCKS[fn.__name__.replace("_", "-")] = fn
    return fn


def tool(fn):
    TOOLS[fn.__name__] = fn
    return fn


def labelled(fig, label):
    f = Fig(fig.text, fig.num, fig.tol, label)
    return f


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
                parts.append(labelled(p, label) if isinstance(p, Fig) else p)
            parts.append(" |")
        parts.append("\n")
    return parts


def code_block(parts):
    return ["```\n"] + parts + ["```\n"]


# ---- the yardstick ---------------------------------------------------------------

def yard_whole(c):
    """PSNR / max error / >2 / >8 against the continuous reference."""
    return [c["psnr"], " dB / ", c["maxerr"], " / ", c["over2"], " / ", c["over8"]]


def yard_shading(c):
    return [c["shading_psnr"], " dB / ", c["shading_over2"]]


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


def board_key(board, field):
    def fn(m):
        v = m.bench(board)[field]
        return v
    return fn


BOARDS = ("qemu-m0", "qemu-m0-backdrop", "qemu-m0-still", "qemu-m3", "qemu-rv32")
BENCH_FIELDS = ("insn_per_pixel", "render_insn_per_pixel", "ram_bytes", "flash_bytes", "stack_bytes",
                "scene_bytes", "code_bytes", "stack_peak_bytes", "stack_reserved_bytes", "panel_psnr")
for _b in BOARDS:
    for _f in BENCH_FIELDS:
        KEYS["board.%s.%s" % (_b, _f)] = board_key(_b, _f)


def link_length(board, region):
    """A board's memory region in bytes, from its link.ld (LENGTH = 256K)."""
    def fn(m):
        v = m.code("boards/%s/link.ld" % board, r"^\s*%s\b.*LENGTH\s*=\s*(\d+K)" % region)
        if isinstance(v, Placeholder):
            return Fig("1", 1.0)
        return exact(int(v.text[:-1]) * 1024)
    return fn


KEYS["limit.qemu-m0.flash_bytes"] = link_length("qemu-m0", "FLASH")
KEYS["limit.qemu-m0.ram_bytes"] = link_length("qemu-m0", "RAM")
KEYS["limit.frame_size_max"] = lambda m: m.code("core/include/tarn/tarn_render.h",
                                                 r"#define TARN_FRAME_SIZE_MAX (\d+)u")


# ---- docs/figures.md -------------------------------------------------------------------

POND_KNOBS = ["", "--quality exact", "--quality fast", "--perspective span:4", "--perspective span:16",
              "--perspective affine", "--recip-steps 2", "--recip-steps 0", "--fog-bits 16", "--depth 16",
              "--subpixel 2", "--subpixel 5", "--subpixel 6", "--tile 16", "--tile 64", "--apron off",
              "--apron off --tile 16", "--bins off", "--water-block 2", "--quality fast --water-block 1",
              "--depth-interpolation plane", "--quality fast --depth-interpolation exact"]


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
    "m0-fast-bins-off": ("qemu-m0", "pond", "--quality fast --bins off"),
    "m0-fast-wb4": ("qemu-m0", "pond", "--quality fast --water-block 4"),
    "m0-fast-wb1": ("qemu-m0", "pond", "--quality fast --water-block 1"),
    "m0-fast-still-wb2": ("qemu-m0", "pond", "--quality fast --backdrop still"),
    "m0-fast-still-wb1": ("qemu-m0", "pond", "--quality fast --backdrop still --water-block 1"),
    "m0-fast-exact-depth": ("qemu-m0", "pond", "--quality fast --depth-interpolation exact"),
}


def fw(name):
    board, scene, flags = FW_VARIANTS[name]
    return lambda m: m.bench(board, scene, flags)


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
KEYS["fw.m0-bins.saving"] = lambda m: pct_less(m.bench("qemu-m0")["insn_per_pixel"],
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
KEYS["still.wb4.psnr_cost"] = lambda m: diff(KEYS["still.wb2.psnr"](m), KEYS["still.wb4.psnr"](m), 2)
KEYS["pond.plane.host_saving"] = lambda m: pct_less(host_of("--depth-interpolation plane")(m), host_of("")(m))
KEYS["pond.fast.plane_host_saving"] = lambda m: pct_less(
    host_of("--quality fast")(m), host_of("--quality fast --depth-interpolation exact")(m))
KEYS["fw.m0-plane.saving"] = lambda m: pct_less(m.bench("qemu-m0")["insn_per_pixel"],
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


def spf(scene, name, field):
    return m_get(lambda m: m.sweep_point(scene, SWEEP_POINTS[name])[field])


def m_get(fn):
    return fn


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
                                                m.bench("qemu-m0")["insn_per_pixel"])
KEYS["fw.m0-blocks.saving"] = lambda m: pct_less(m.bench("qemu-m0")["insn_per_pixel"],
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
    """make profile-target BOARD=qemu-m0-still: every instruction of its run, by function."""
    m.bench("qemu-m0-still")
    return run(["make", "--no-print-directory", "-s", "profile-target", "BOARD=qemu-m0-still", "TOP=1000"])


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


def profile_per_pixel(functions, frames=2):
    """Instructions a pixel of the pond's frame (240x240) in the named functions, over
    `frames` frames (the conversion runs in the two streamed frames)."""
    def fn(m):
        f = profile_functions(m)
        if not f:
            return Fig("1", 1.0)
        return insn(sum(f.get(name, 0) for name in functions) / (frames * 57600.0))
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
