#!/usr/bin/env python3
"""`make bench-gpu`: covered pixels per clock and clocks per primitive of the RTL, counted by the
Verilator simulation (PERF_BUSY_CYCLES: doorbell to last pixel written, clear included when the list
clears), for each span width, on three workloads:
  large  - 24 large random triangles over the screen (no clear)
  scene  - the default scene's buffers, every frame, as the firmware submitted them (with clears)
  tiny   - 10,000 random triangles of at most 2 px across (no clear)
and, on the depth-buffer build (sim-z-w8, SPAN_W = 8 only), the large and tiny triangles again as
depth-tested `ztri` with random vertex depths (the first batch clears the depth buffer; its
320 * 240 / SPAN_W clocks are left out of these rows' cycles, and their pixels are those written, i.e.
that passed the depth test):
  zlarge - the large triangles, depth-tested
  ztiny  - the tiny triangles, depth-tested (those that cover a pixel centre each need the depth-plane
           division)
and on the Gouraud build (sim-g-w8, ENABLE_GOURAUD with the depth buffer, SPAN_W = 8), the same
triangles as Gouraud `gtri` with random vertex intensities, dithered (no depth test):
  glarge - the large triangles, Gouraud shaded
  gtiny  - the tiny triangles, Gouraud shaded (each drawn one needs the intensity-plane division)
  large, tiny on that build again as flat `tri`: what building the interpolator in costs flat ones

A second table: the large triangles at the contract's largest frame (640x480: every coordinate
doubled, four times the pixels), flat and depth-tested (zlarge), SPAN_W 8, on three GPUs with the
depth buffer:
  whole frame  sim-f640-w8: both frames and the depth buffer on chip, the batch drawn once
  strips       sim-s16-f640-w8: strips of 16 rows on chip (colour and depth), flushed to frames on
               chip that take a span a clock; `gpusim raster` rings the batch once per strip (30),
               each strip's first batch clearing it (its 1,280 spans: a clear the whole frame does
               not need here, counted apart)
  SDRAM        sim-dram-s16-f640-w8: the same strips flushed through the model of LiteDRAM's 32-bit
               native port (cosim/native_port_model.h, not throttled; the width from the run's
               stats.json): 2 words a span, so a frame's flush takes at least 76,800 clocks,
               whatever is drawn
The busy cycles are PERF_BUSY_CYCLES summed over the batches (the last strip's flush runs on after
the last, before the swap, and is not in them).

    bench_gpu.py BUILD SCENE_LISTS_DIR
"""
import json
import os
import random
import subprocess
import sys
import tomllib

WIDTHS = [1, 4, 8, 16]


# The frame, from the contract (contract/gpu_contract.toml).
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contract", "gpu_contract.toml"), "rb") as _f:
    _LIMITS = tomllib.load(_f)["limits"]
FB_W, FB_H = _LIMITS["fb_width"], _LIMITS["fb_height"]


def write_large(path, rng):
    with open(path, "w") as f:
        for _ in range(24):
            pts = [(rng.randint(-40, FB_W + 40) * 16, rng.randint(-40, FB_H + 40) * 16) for _ in range(3)]
            f.write("tri %d %d %d %d %d %d %d\n" % (*pts[0], *pts[1], *pts[2], rng.randint(1, 255)))


def write_tiny(path, rng):
    with open(path, "w") as f:
        for _ in range(10000):
            x, y = rng.randint(0, (FB_W - 1) * 16), rng.randint(0, (FB_H - 1) * 16)
            pts = [(x + rng.randint(0, 32), y + rng.randint(0, 32)) for _ in range(3)]
            f.write("tri %d %d %d %d %d %d %d\n" % (*pts[0], *pts[1], *pts[2], rng.randint(1, 255)))


def write_per_vertex(path, src, rng, kind, colour):
    """The triangles of src again, as `kind` lines with a random 16-bit value after each vertex and
    colour(the colour field) as their colour."""
    with open(src) as f, open(path, "w") as out:
        for line in f:
            v = line.split()
            w = [rng.randint(0, 65535) for _ in range(3)]
            out.write("%s %s %s %d %s %s %d %s %s %d %s\n" % (kind, v[1], v[2], w[0], v[3], v[4], w[1], v[5], v[6],
                                                               w[2], colour(v[7])))


def write_depth(path, src, rng):
    """The triangles of src again, as ztri with random vertex depths."""
    write_per_vertex(path, src, rng, "ztri", lambda c: c)


def write_gouraud(path, src, rng):
    """The triangles of src again, as gtri with random vertex intensities (VTX_I, Q4.12)."""
    write_per_vertex(path, src, rng, "gtri", lambda c: "%d" % (int(c) & 0xF0))


def write_scene(path, lists_dir):
    with open(path, "w") as f:
        for name in sorted(os.listdir(lists_dir)):
            with open(os.path.join(lists_dir, name)) as batch:
                f.write(batch.read())


def write_doubled(path, src):
    """The list src with every coordinate doubled (depths and colours kept): the same triangles on
    a frame of twice the width and height."""
    with open(src) as f, open(path, "w") as out:
        for line in f:
            v = line.split()
            if v[0] == "tri":
                xy, rest = v[1:7], v[7:]
            else:  # ztri X0 Y0 Z0 X1 Y1 Z1 X2 Y2 Z2 C
                xy, rest = [v[1], v[2], v[4], v[5], v[7], v[8]], [v[3], v[6], v[9], v[10]]
            d = [str(2 * int(c)) for c in xy]
            if v[0] == "tri":
                out.write(" ".join(["tri"] + d + rest) + "\n")
            else:
                out.write(" ".join(["ztri", d[0], d[1], rest[0], d[2], d[3], rest[1], d[4], d[5], rest[2], rest[3]]) + "\n")


def raster(sim, path, out):
    subprocess.run([sim, "raster", "--in", path, "--out", out], check=True, stdout=subprocess.DEVNULL)
    return json.load(open(os.path.join(out, "stats.json")))


def frame_640_table(build, work, workloads, zworkloads):
    big_w, big_h = 2 * FB_W, 2 * FB_H
    lists = {}
    for name, src in (("large", workloads["large"]), ("zlarge", zworkloads["zlarge"])):
        lists[name] = os.path.join(work, "%s-%d.txt" % (name, big_w))
        write_doubled(lists[name], src)
    span_w = 8
    gpus = [("whole frame", "sim-f%d-w%d" % (big_w, span_w)), ("strips of 16", "sim-s16-f%d-w%d" % (big_w, span_w)),
            ("strips of 16, frames in SDRAM", "sim-dram-s16-f%d-w%d" % (big_w, span_w))]
    rows = []
    for label, ident in gpus:
        busy = {}
        for name, path in lists.items():
            print("bench-gpu: %s at %dx%d, %s ..." % (name, big_w, big_h, label), file=sys.stderr, flush=True)
            s = raster(os.path.join(build, ident, "gpusim"), path, os.path.join(work, "%s-%d-%s" % (name, big_w, ident)))
            if not s["rtl_equals_model"]:
                sys.exit("bench-gpu: %s on %s: RTL and model differ" % (name, ident))
            # The clears on the raster's path: a whole frame's depths (zlarge; one span a clock). With
            # strips the flushes clear the banks and a depth clear is an epoch (docs/strips.md): left
            # are the first two strips' colour after reset (the banks then hold nothing known) and,
            # for zlarge, the depth tags' scrub after reset, a strip's spans each.
            strip_words = s["strip_rows"] * big_w // span_w
            if s["strip_rows"]:
                clears = (2 + (name == "zlarge")) * strip_words
            else:
                clears = big_w * big_h // span_w if name == "zlarge" else 0
            busy[name] = s["busy_cycles"] - clears
            rows.append((label, name, s["batches"], s["pixels"], s["busy_cycles"], clears,
                         s["frame_memory_word_bytes"] if "dram" in ident else 0))
        rows.append((label, "zlarge / large, without the clears", None, None, busy["zlarge"] / busy["large"], None, None))
    print()
    print("| %dx%d, SPAN_W %d | workload | batches | pixels written | busy cycles | of which clears | covered px/clk "
          "| without the clears |" % (big_w, big_h, span_w))
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    # Behind the port (word_bytes pixels a native word, one word a clock) each span is
    # SPAN_W / word_bytes words: a frame's flush is its pixels / word_bytes clocks, the strips'
    # clears and drawing hidden under it (so not taken off).
    for label, name, batches, pixels, cycles, clears, word_bytes in rows:
        if batches is None:
            print("| %s | %s | | | %.3f x | | | |" % (label, name, cycles))
            continue
        without = ("— (the flush: at least %d clocks)" % (big_w * big_h // word_bytes) if word_bytes
                   else "%.2f" % (pixels / (cycles - clears)))
        print("| %s | %s | %d | %d | %d | %d | %.2f | %s |" % (label, name, batches, pixels, cycles, clears,
                                                              pixels / cycles, without))


def main():
    build, lists_dir = sys.argv[1], sys.argv[2]
    work = os.path.join(build, "bench-gpu")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(2026)
    workloads = {"large": os.path.join(work, "large.txt"), "scene": os.path.join(work, "scene.txt"),
                 "tiny": os.path.join(work, "tiny.txt")}
    write_large(workloads["large"], rng)
    write_scene(workloads["scene"], lists_dir)
    write_tiny(workloads["tiny"], rng)
    zworkloads = {"zlarge": os.path.join(work, "zlarge.txt"), "ztiny": os.path.join(work, "ztiny.txt")}
    write_depth(zworkloads["zlarge"], workloads["large"], rng)
    write_depth(zworkloads["ztiny"], workloads["tiny"], rng)

    runs = [(os.path.join(build, "sim-w%d" % width, "gpusim"), width, workloads) for width in WIDTHS]
    runs.append((os.path.join(build, "sim-z-w8", "gpusim"), 8, zworkloads))
    gworkloads = {"glarge": os.path.join(work, "glarge.txt"), "gtiny": os.path.join(work, "gtiny.txt")}
    write_gouraud(gworkloads["glarge"], workloads["large"], rng)
    write_gouraud(gworkloads["gtiny"], workloads["tiny"], rng)
    gworkloads["large (g build)"] = workloads["large"]
    gworkloads["tiny (g build)"] = workloads["tiny"]
    runs.append((os.path.join(build, "sim-g-w8", "gpusim"), 8, gworkloads))
    rows = []
    for sim, width, loads in runs:
        for name, path in loads.items():
            out = os.path.join(work, "%s-w%d" % (name.split()[0] + ("-g" if "(g" in name else ""), width))
            print("bench-gpu: %s, SPAN_W=%d ..." % (name, width), file=sys.stderr, flush=True)
            s = raster(sim, path, out)
            cycles = s["busy_cycles"] - (FB_W * FB_H // width if name.startswith("z") else 0)
            rows.append((name, width, s["prims_in"], s["pixels"], cycles, s["spans_visited"]))

    print("| workload | SPAN_W | primitives | pixels written | busy cycles | covered px/clk | clk/primitive |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, width, prims, pixels, cycles, _ in rows:
        print("| %s | %d | %d | %d | %d | %.2f | %.2f |" % (name, width, prims, pixels, cycles,
                                                          pixels / cycles, cycles / max(prims, 1)))
    frame_640_table(build, work, workloads, zworkloads)


if __name__ == "__main__":
    main()
