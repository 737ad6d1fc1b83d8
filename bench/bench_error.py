#!/usr/bin/env python3
"""`make bench-error`: pixel error against counted cost, for every knob that trades accuracy for
speed, on every scene's default view. A Markdown table on stdout, a plot in
BUILD/bench-error/error-vs-cost.png, one progress line per co-simulated configuration on stderr.

Reference R: the most accurate configuration the project builds - the float arithmetic backend,
the GPU's depth buffer (RTL built with ENABLE_ZBUF; firmware built with FW_DEPTH_TEST=1), the
contract's 4 sub-pixel bits (Q12.4), SPAN_W = 8. Every other configuration changes exactly one knob
of R, so its error is that knob's own; the row "default build" changes all of them at once to what
`make run` builds (fixed point, painter's sort, 4 bits, SPAN_W = 8, no depth buffer):

  arithmetic      fixed point (q16_16 / q2_30) instead of float (firmware/math/real.h)
  depth order     the painter's sort alone (GPU without depth buffer) instead of the depth test
  sub-pixel bits  2 and 0 fraction bits kept in projected vertices (FW_SUBPIXEL_BITS, proj.h;
                  the switch also takes 3 and 1, left out here to keep the run short)
  span width      GPUs built with SPAN_W = 1, 4, 16 (the rasterizer is exact: error must be 0)
  sine table      64 and 1024 entries per turn instead of 256 (FW_SIN_TABLE_BITS, math/fixed.h;
                  every rotation and the scenes' generated shapes use it; the camera path does not)
  depth bits      GPUs whose depth buffer keeps 12 and 8 of the 16 bits (ZBUF_BITS, contract
                  "Depth"), the memory it saves in docs/accuracy-vs-cost.md

Each configuration is co-simulated (QEMU -icount + the Verilator GPU, like `make bench-fw`) for
FRAMES frames from boot, no keys; every number below is a mean over those frames.

Metrics, per scene and configuration (frames compared as captured from the VGA pins; each
framebuffer pixel is a 2 x 2 block there, tools/png_diff.c compares one pixel per block):
  pixels differing  framebuffer pixels (of 320 x 240 = 76,800) whose RGB differs from R's frame
  mean |dRGB|       sum over all framebuffer pixels and the three channels of |RGB - RGB_R|
                    (8-bit values) divided by 76,800 x 3: 0 for identical frames, 255 at most
Costs, counted (never timed):
  fw instr/frame    the firmware's per-frame `fw instr` (minstret delta under QEMU -icount shift=0)
  GPU cycles/frame  the firmware's per-frame `gpu cycles` (PERF_BUSY_CYCLES of the RTL, summed
                    over the frame's batches)
  SoC CPU cycles    with --socsim: the firmware's per-frame `cpu cycles` (mcycle, DONE_SEQ polls
                    excluded) of the same configuration built for the SoC (bsp/soc: one scene, no
                    line emulation) on socsim, the whole SoC Verilated (VexRiscv_FullCfu, its caches,
                    bus, RAM, GPU) - see "CPU cycles on the SoC" below

With --path VIEWS (`make bench-error-path`, and the second half of `make bench-error`): the same
configurations plus the reciprocal's Newton steps (0 and 2 instead of fixed point's 1), on a seeded
camera path of VIEWS views per scene, against the exact reference E (bench/exact_ref) instead of
R: per configuration the mean, 95th percentile and worst view of the pixels differing from E, the
Pareto front of error against cost and whether the default build lies on it, the plot in
BUILD/bench-error/path/error-vs-cost.png and each configuration's worst view beside E's in
BUILD/bench-error/path/worst/<scene>-<configuration>.png (see "camera paths" below).

    bench_error.py --build BUILD --frames N [--jobs J] [--no-run] [SOC] SCENE...
    bench_error.py --build BUILD --path VIEWS [--cost-views K] [--jobs J] [--no-run | --keep] [SOC] SCENE...
      SOC: --socsim SIM=SOCSIM... [--soc-views N] [--soc-span-scenes "S..."]
    bench_error.py --check-metric PNG_DIFF WORKDIR     (the test: the metric on known images)
"""
import argparse
import concurrent.futures
import os
import re
import shutil
import struct
import subprocess
import sys
import tomllib
import zlib

with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contract", "gpu_contract.toml"), "rb") as _f:
    _LIMITS = tomllib.load(_f)["limits"]
FB_PIXELS = _LIMITS["fb_width"] * _LIMITS["fb_height"]  # the contract's frame

# Configurations: key -> (firmware, BUILD/fw-error/<scene>-<firmware>.elf; simulator, BUILD/<sim>/gpusim;
# plot label). "-z" firmware starts with the depth test on and runs on a GPU that has the buffer.
CONFIGS = {
    "ref":     ("float-z",     "sim-z-w8",  "reference R"),
    "fixed":   ("fixed-z",     "sim-z-w8",  "fixed point"),
    "painter": ("float",       "sim-w8",    "painter's sort"),
    "sp2":     ("float-sp2-z", "sim-z-w8",  "2 sub-pixel bits"),
    "sp0":     ("float-sp0-z", "sim-z-w8",  "0 sub-pixel bits"),
    "w1":      ("float-z",     "sim-z-w1",  "SPAN_W 1"),
    "w4":      ("float-z",     "sim-z-w4",  "SPAN_W 4"),
    "w16":     ("float-z",     "sim-z-w16", "SPAN_W 16"),
    "sin6":    ("float-sin6-z", "sim-z-w8", "64 sine entries"),
    "sin10":   ("float-sin10-z", "sim-z-w8", "1024 sine entries"),
    "zb12":    ("float-z",     "sim-zb12-w8", "12 depth bits"),
    "zb8":     ("float-z",     "sim-zb8-w8", "8 depth bits"),
    "default": ("fixed",       "sim-w8",    "default build"),
}

# Table rows: (knob, setting, configuration key), grouped by knob; R appears in every group.
KNOBS = [
    ("arithmetic", [("float (R)", "ref"), ("fixed point", "fixed")]),
    ("depth order", [("depth buffer (R)", "ref"), ("painter's sort", "painter")]),
    ("sub-pixel bits", [("4 (R)", "ref"), ("2", "sp2"), ("0", "sp0")]),
    ("span width", [("8 (R)", "ref"), ("1", "w1"), ("4", "w4"), ("16", "w16")]),
    ("sine table entries", [("256 (R)", "ref"), ("64", "sin6"), ("1024", "sin10")]),
    ("depth-buffer bits", [("16 (R)", "ref"), ("12", "zb12"), ("8", "zb8")]),
    ("default build", [("fixed, painter, 4 bits, SPAN_W 8", "default")]),
]

FRAME_RE = re.compile(r"^frame (\d+): .*\| fw instr (\d+) \| gpu cycles (\d+) \|")
SOC_FW_LINE = re.compile(r"^frame (\d+): .*\| fw instr (\d+) \|.*\| cpu cycles (\d+)")


def run_config(build, frames, scene, key, rerun=True):
    """Co-simulate one configuration (or, rerun False, read the last run's results); returns
    {frame: (fw instr, gpu cycles)} and the frame directory."""
    variant, sim, _ = CONFIGS[key]
    work = os.path.join(build, "bench-error", scene, key)
    if rerun:
        cosim(build, work, scene, variant, sim)
    return parse_log(work, frames, scene, key, variant, sim), os.path.join(work, "frames")


def cosim(build, work, scene, variant, sim):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    cmd = [os.path.join(build, sim, "gpusim"), "cosim",
           "--fw", os.path.join(build, "fw-error", "%s-%s.elf" % (scene, variant)),
           "--frames", os.path.join(work, "frames"), "--uart-log", os.path.join(work, "uart.log"),
           "--no-model-check"]
    with open(os.path.join(work, "cosim.out"), "w") as out:
        if subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode != 0:
            raise RuntimeError("%s-%s on %s: co-simulation failed, see %s/cosim.out" % (scene, variant, sim, work))


def parse_log(work, frames, scene, key, variant, sim):
    counts = {}
    with open(os.path.join(work, "uart.log")) as log:
        for line in log:
            m = FRAME_RE.match(line)
            if m:
                counts[int(m.group(1))] = (int(m.group(2)), int(m.group(3)))
    if sorted(counts) != list(range(frames)):
        raise RuntimeError("%s %s: expected frames 0..%d in %s/uart.log" % (scene, key, frames - 1, work))
    log = open(os.path.join(work, "uart.log")).read()
    if variant.endswith("-z") != ("depth buffer on" in log):
        raise RuntimeError("%s %s: depth test on/off not as configured" % (scene, key))
    bits = sim[len("sim-zb"):].split("-")[0] if sim.startswith("sim-zb") else "16"
    if variant.endswith("-z") and "depth buffer on (FW_DEPTH_TEST, %s-bit depths)" % bits not in log:
        raise RuntimeError("%s %s: the GPU does not report %s depth bits (CAPS_ZBUF_BITS)" % (scene, key, bits))
    return counts


def png_diff_fields(tool, ref, img, *options):
    """png_diff's fields (pixels, differing, abs_sum, max_abs; box_abs_sum with --box) of img
    against ref, compared in framebuffer pixels."""
    out = subprocess.run([tool, "--block", "2", *options, ref, img], check=True, capture_output=True,
                         text=True).stdout.split()
    fields = dict(zip(out[0::2], (int(v) for v in out[1::2])))
    if fields["pixels"] != FB_PIXELS:
        raise RuntimeError("%s: %d framebuffer pixels, expected %d" % (img, fields["pixels"], FB_PIXELS))
    return fields


def png_diff(tool, ref, img):
    """(framebuffer pixels differing, sum of |dRGB|) of img against ref."""
    fields = png_diff_fields(tool, ref, img)
    return fields["differing"], fields["abs_sum"]


def parallel(items, work, jobs, report):
    """{item: work(*item)} for every item, jobs at a time, stopping at the first failure;
    report(done, total, item, result) after each, for the progress lines."""
    out = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(work, *item): item for item in items}
        for done, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            item = futures[fut]
            try:
                out[item] = fut.result()
            except Exception:
                pool.shutdown(wait=True, cancel_futures=True)
                raise
            report(done, len(items), item, out[item])
    return out


def measure(build, frames, scenes, jobs, rerun):
    tool = os.path.join(build, "tools", "png_diff")
    todo = [(scene, key) for scene in scenes for key in CONFIGS]

    def report(done, total, item, _):
        scene, key = item
        variant, sim, _ = CONFIGS[key]
        print("bench-error: [%2d/%d] %-9s %-8s %s-%s.elf on %s" % (done, total, scene, key, scene, variant, sim),
              file=sys.stderr, flush=True)
    runs = parallel(todo, lambda scene, key: run_config(build, frames, scene, key, rerun), jobs, report)
    results = {}
    compared = range(frames)
    for scene, key in todo:
        counts, fdir = runs[(scene, key)]
        ref_dir = runs[(scene, "ref")][1]
        diff = [png_diff(tool, os.path.join(ref_dir, "%04d.png" % f), os.path.join(fdir, "%04d.png" % f))
                for f in compared]
        n = len(diff)
        results[(scene, key)] = {
            "differing": sum(d for d, _ in diff) / n,
            "mae": sum(s for _, s in diff) / (n * FB_PIXELS * 3),
            "instr": sum(counts[f][0] for f in compared) / n,
            "cycles": sum(counts[f][1] for f in compared) / n,
        }
    return results


def knob_rows(knobs, scenes, results, cells):
    """Markdown rows, one per knob setting and scene (knob by knob, scene by scene): knob, setting,
    scene, then cells(scene, r) for that configuration's results r."""
    return ["| %s |" % " | ".join([knob, setting, scene] + cells(scene, results[(scene, key)]))
            for knob, settings in knobs for scene in scenes for setting, key in settings]


def differing_cell(r):
    return "%.1f (%.2f%%)" % (r["differing"], 100.0 * r["differing"] / FB_PIXELS)


def progress(fmt):
    """A report for parallel(): fmt % (done, total, *item) on stderr."""
    return lambda done, total, item, _: print(fmt % (done, total, *item), file=sys.stderr, flush=True)


def table(results, scenes, frames, soc_lines=()):
    lines = ["| knob | setting | scene | pixels differing | mean abs dRGB | fw instructions/frame | GPU cycles/frame | SoC CPU cycles/frame |",
             "|---|---|---|---:|---:|---:|---:|---:|"]
    lines += knob_rows(KNOBS, scenes, results, lambda scene, r: [
        differing_cell(r), "%.4f" % r["mae"], "%d" % round(r["instr"]), "%d" % round(r["cycles"]), soc_cell(r)])
    lines.append("")
    lines.append("R = float, depth buffer (16 bits), 4 sub-pixel bits, SPAN_W 8, 256 sine entries. Error against R's frame; means "
                 "over the first %d frames of each scene's default view; counts from co-simulation "
                 "(QEMU -icount, Verilator cycles)." % frames)
    lines.extend(notes(results, scenes))
    lines.extend(soc_lines)
    return "\n".join(lines)


def span(values, fmt):
    """A range over the scenes as text: one value when both ends print alike, else "lo .. hi"."""
    lo, hi = min(values), max(values)
    return fmt % lo if fmt % lo == fmt % hi else (fmt + " .. " + fmt) % (lo, hi)


def knob_ranges(results, scenes, knobs, error_columns):
    """Markdown rows, one per knob setting: each error column's range over the scenes, then the
    firmware's instructions and the GPU's cycles relative to R's. error_columns: (header, result
    key, format)."""
    costs = ["instr", "cycles"] + (["soc"] if "soc" in results[(scenes[0], "ref")] else [])
    names = {"instr": "fw instructions / R's", "cycles": "GPU cycles / R's", "soc": "SoC CPU cycles / R's"}
    lines = ["| knob | setting | %s | %s |" % (" | ".join(h for h, _, _ in error_columns), " | ".join(names[c] for c in costs)),
             "|---|---|%s%s" % ("---:|" * len(error_columns), "---:|" * len(costs))]
    for knob, settings in knobs:
        for setting, key in settings:
            if key == "ref" and knob != "arithmetic":
                continue
            rs = [results[(sc, key)] for sc in scenes]
            refs = [results[(sc, "ref")] for sc in scenes]
            cells = [knob if key != "ref" else "reference R",
                     setting if key != "ref" else "float, depth buffer (16 bits), 4 bits, SPAN_W 8, 256 sine entries"]
            cells += [span([r[field] for r in rs], fmt) for _, field, fmt in error_columns]
            cells += [span([r[cost] / q[cost] for r, q in zip(rs, refs)], "%.2f") for cost in costs]
            lines.append("| %s |" % " | ".join(cells))
    return lines


def summary(results, scenes):
    """The short version: per setting, the range over the scenes."""
    lines = knob_ranges(results, scenes, KNOBS, [("pixels differing from R", "differing", "%.1f")])
    lines.append("")
    lines.append("Ranges over the scenes (%s); pixels differing: framebuffer pixels of 76,800 per frame, "
                 "mean of the frames." % ", ".join(scenes))
    return "\n".join(lines)


def notes(results, scenes):
    """Notes computed from the numbers, so that they cannot go stale."""
    out = []
    if not all(k in CONFIGS for k in ("w1", "w4", "w16", "sp2", "sp0")):
        return out  # --only: a partial run
    span_err = max(results[(s, k)]["differing"] for s in scenes for k in ("w1", "w4", "w16"))
    out.append("- span width: %s" % ("every frame identical to R's: the rasterizer is exact at every width"
                                      if span_err == 0 else "FRAMES DIFFER FROM R (a rasterizer bug)"))
    def change(cost):
        c = [100.0 * (results[(s, k)][cost] / results[(s, "ref")][cost] - 1.0)
             for k in ("sp2", "sp0") for s in scenes]
        return "%+.1f%% .. %+.1f%%" % (min(c), max(c))
    out.append("- sub-pixel bits: against R, firmware instructions change by %s and GPU cycles by %s "
               "(the rounding itself is a shift per coordinate; with fewer bits some thin triangles "
               "become empty); "
               "an accuracy knob, not a speed one" % (change("instr"), change("cycles")))
    return out


# Both plots' marker per configuration (the path's configurations are a superset of the default view's).
MARKERS = {"ref": "*", "fixed": "s", "painter": "D", "sp2": "v", "sp0": "^",
           "w1": "1", "w4": "2", "w16": "3", "default": "o", "nr0": "<", "nr2": ">",
           "sin6": "P", "sin10": "X", "zb12": "p", "zb8": "h"}


def cost_panels(results, scenes, relative):
    """The plots' x axes: instructions, GPU cycles and, where measured, the SoC's CPU cycles."""
    rel = ", relative to R" if relative else ""
    panels = [("instr", "firmware instructions / frame%s (QEMU -icount)" % rel),
              ("cycles", "GPU cycles / frame%s (Verilator%s)" % (rel, "" if relative else ", PERF_BUSY_CYCLES"))]
    if "soc" in results[(scenes[0], "ref")]:
        panels.append(("soc", "CPU cycles / frame on the SoC%s (socsim%s)" % (rel, "" if relative else ", path view 0")))
    return panels


def plot(results, scenes, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.patches
    import matplotlib.pyplot as plt

    colours = dict(zip(scenes, ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]))
    panels = cost_panels(results, scenes, relative=False)
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.6), sharey=True)
    for ax, (cost, label) in zip(axes, panels):
        for scene in scenes:
            for key in CONFIGS:
                r = results[(scene, key)]
                ax.scatter(r[cost], r["differing"], marker=MARKERS[key], color=colours[scene], s=36)
        ax.set_xscale("log")
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_ylim(bottom=-0.2)
        ax.set_xlabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("framebuffer pixels differing from R / frame")
    handles = [plt.Line2D([], [], color="grey", marker=MARKERS[k], linestyle="", label=CONFIGS[k][2])
               for k in CONFIGS]
    handles += [matplotlib.patches.Patch(color=colours[s], label=s) for s in scenes]
    fig.legend(handles=handles, loc="center right", fontsize=8, frameon=False)
    fig.suptitle("Pixel error against counted cost, one marker per configuration and scene "
                 "(R = float, 16-bit depth buffer, 4 sub-pixel bits, SPAN_W 8, 256 sine entries)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 0.86, 0.95))
    fig.savefig(path, dpi=90)


# ---- camera paths against the exact reference (--path) -------------------------------------------
#
# Every configuration above, on FW_PATH_VIEWS seeded views per scene (firmware/app/cam_path.h:
# orbit, fly-through, close-ups at the near plane, grazing angles), against the exact reference E
# (bench/exact_ref: double precision, exact coverage at pixel centres, per-pixel depth). Where the
# numbers come from, the cheapest honest split:
#   frames  the host build through the golden model (bsp/host; bit-exact with the RTL by test, and
#           here checked again on the co-simulated views), every view of the path;
#   scene   the float-z host build's --dump-scene of every view (world-space triangles, camera,
#           light, palette: scene data only), rendered by exact_ref;
#   costs   co-simulation of the same path firmware (QEMU -icount + the Verilator GPU on the pins)
#           for the first COST_VIEWS views (all four kinds of view when a multiple of 4): fw
#           instructions and GPU cycles per frame, as in the table above.

PATH_DIR = "path"
# The camera paths measure one knob more: the Newton steps of the fixed backend's reciprocal
# (FW_RECIP_NEWTON_STEPS, math/fixed.h), whose rows change that knob of "fixed point" (fixed-z).
PATH_CONFIGS = dict(CONFIGS)
PATH_CONFIGS["nr0"] = ("fixed-nr0-z", "sim-z-w8", "0 Newton steps")
PATH_CONFIGS["nr2"] = ("fixed-nr2-z", "sim-z-w8", "2 Newton steps")
PATH_KNOBS = KNOBS[:-1] + [
    ("reciprocal Newton steps", [("1 (fixed point)", "fixed"), ("0", "nr0"), ("2", "nr2")]),
    KNOBS[-1]]


def path_host_cmd(build, scene, key, frames_dir, dump_dir=None):
    variant, sim, _ = PATH_CONFIGS[key]
    cmd = [os.path.join(build, "fw-path", "host-%s-%s" % (scene, variant)), "--frames", frames_dir,
           "--span-w", sim.rsplit("-w", 1)[1]]
    if sim.startswith("sim-z"):
        cmd.append("--zbuf")
    if sim.startswith("sim-zb"):  # sim-zb<bits>-w8: the depth buffer keeping <bits> bits
        cmd += ["--zbuf-bits", sim[len("sim-zb"):].split("-")[0]]
    if dump_dir:
        cmd += ["--dump-scene", dump_dir]
    return cmd


def path_run(build, scene, key, views, cost_views, rerun):
    """Frames of every view (host build), the exact reference's (key "ref" only) and the costs of
    the first cost_views views (co-simulation). Returns (frame dir, {view: (instr, cycles)})."""
    variant, sim, _ = PATH_CONFIGS[key]
    work = os.path.join(build, "bench-error", PATH_DIR, scene, key)
    if rerun == "keep" and os.path.exists(os.path.join(work, "done")):
        rerun = False
    if rerun:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        # Every configuration dumps its scenes, for the cameras (cameras.txt: every configuration
        # must see the same views, app/cam_path.h); only R's dump is kept, for the exact reference.
        dump = os.path.join(work, "scene" if key == "ref" else "scene-tmp")
        with open(os.path.join(work, "host.out"), "w") as out:
            if subprocess.run(path_host_cmd(build, scene, key, os.path.join(work, "frames"), dump),
                              stdout=out, stderr=subprocess.STDOUT).returncode != 0:
                raise RuntimeError("%s %s: host run failed, see %s/host.out" % (scene, key, work))
        with open(os.path.join(work, "cameras.txt"), "w") as cams:
            for name in sorted(os.listdir(dump)):
                with open(os.path.join(dump, name)) as f:
                    cams.write(name + " " + next((l for l in f if l.startswith("camera ")), "none\n"))
        if key != "ref":
            shutil.rmtree(dump)
            dump = None
        if dump:
            os.makedirs(os.path.join(work, "exact"))
            subprocess.run([os.path.join(build, "tools", "exact_ref"), "--dir", dump,
                            os.path.join(work, "exact")], check=True, stdout=subprocess.DEVNULL)
        if cost_views > 0:
            path_cosim(build, sim, os.path.join(build, "fw-path", "%s-%s.elf" % (scene, variant)), work,
                       cost_views)
        open(os.path.join(work, "done"), "w").close()
    return work, path_costs(work, cost_views) if cost_views > 0 else {}


def path_cosim(build, sim, elf, work, views):
    """Co-simulate the first views of a path ELF on BUILD/<sim>/gpusim: work/cosim-frames, work/uart.log."""
    cmd = [os.path.join(build, sim, "gpusim"), "cosim", "--fw", elf,
           "--frames", os.path.join(work, "cosim-frames"),
           "--uart-log", os.path.join(work, "uart.log"), "--no-model-check",
           "--stop-after-frames", str(views)]
    with open(os.path.join(work, "cosim.out"), "w") as out:
        if subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode != 0:
            raise RuntimeError("%s on %s: co-simulation failed, see %s/cosim.out" % (elf, sim, work))


def path_costs(work, views):
    """{view: (fw instr, gpu cycles)} of path_cosim's first views. The run may log a frame past the
    last one captured (the firmware runs ahead of the overlapped scan-out): those are left out."""
    counts = {}
    with open(os.path.join(work, "uart.log")) as log:
        for line in log:
            m = FRAME_RE.match(line)
            if m and int(m.group(1)) < views:
                counts[int(m.group(1))] = (int(m.group(2)), int(m.group(3)))
    if sorted(counts) != list(range(views)):
        raise RuntimeError("expected frames 0..%d in %s/uart.log" % (views - 1, work))
    return counts


# ---- CPU cycles on the SoC (--socsim) -------------------------------------------------------------
#
# socsim simulates about 0.6 M cycles a second of CPU, every frame is at least one VGA frame
# (840,000 cycles) and the boot ~2.4 M (its banner through the 115200-baud UART), while a float
# frame of the knot is 17.6 M: so each configuration is measured once, on the first SOC_VIEWS
# views of its camera path (firmware.mk FW_PATH_SOC_VIEWS: the path ELF with that many frames,
# $(BUILD)/fw-path-soc/<scene>-<variant>-<N>v.elf), and that one number is the SoC column of both
# tables. Its picture is checked: the socsim frames of those views must equal the host build's
# (the golden model's) byte for byte, else the run fails. The span widths change only the GPU,
# and "cpu cycles" leaves the DONE_SEQ polls out, so their rows take R's number ("R's firmware");
# that this holds is measured: R's firmware on a SPAN_W 1 GPU (--socsim sim-z-w1=...) for the
# scenes of --soc-span-scenes, against R's, in a note under each table.

SOC_DIR = "soc"
SOC_GPUS = ("sim-w8", "sim-z-w8")  # the GPUs measured on the SoC: the depth buffer or not, SPAN_W 8
# Configurations not run on the SoC, shown with R's number ("as R"): the span widths and depth bits
# (GPU knobs: R's firmware), and the sine tables, whose only change is the table's size and index
# shift (the same instructions a sine; QEMU counts 1.00 of R's on every scene).
SOC_AS_R_KEYS = ("sin6", "sin10")


def soc_elf(build, scene, variant, views):
    return os.path.join(build, "fw-path-soc", "%s-%s-%dv.elf" % (scene, variant, views))


def soc_run(build, socsims, scene, key, views, sim=None):
    """One configuration on socsim, cached while the program image and the simulator are the same:
    {"cpu": mean cpu cycles over the views, "views": [...], "mismatch": text or None}."""
    import hashlib
    import json
    variant, cfg_sim, _ = PATH_CONFIGS[key]
    sim = sim or cfg_sim
    elf = soc_elf(build, scene, variant, views)
    work = os.path.join(build, "bench-error", SOC_DIR, scene, key + ("" if sim == cfg_sim else "-" + sim))
    with open(elf + ".hex", "rb") as f:
        cache_key = {"hex": hashlib.sha256(f.read()).hexdigest(), "socsim": os.path.getmtime(socsims[sim]),
                     "views": views}
    cache = os.path.join(work, "result.json")
    if os.path.exists(cache):
        with open(cache) as f:
            c = json.load(f)
        if c["key"] == cache_key:
            if "instr" not in c["result"]:  # a cache written before the instructions were kept
                with open(os.path.join(work, "uart.log")) as log:
                    n = [int(m.group(2)) for m in map(SOC_FW_LINE.match, log) if m and int(m.group(1)) < views]
                c["result"]["instr"] = sum(n) / views
            return c["result"], True
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    # The host build's frames of the same configuration and path (every view; milliseconds each).
    with open(os.path.join(work, "host.out"), "w") as out:
        if subprocess.run(path_host_cmd(build, scene, key, os.path.join(work, "host-frames")),
                          stdout=out, stderr=subprocess.STDOUT).returncode != 0:
            raise RuntimeError("%s %s: host run failed, see %s/host.out" % (scene, key, work))
    cmd = [socsims[sim], "--fw", elf, "--frames", os.path.join(work, "frames"),
           "--uart-log", os.path.join(work, "uart.log"), "--summary", os.path.join(work, "summary"),
           "--no-model-check"]
    with open(os.path.join(work, "socsim.out"), "w") as out:
        if subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode != 0:
            raise RuntimeError("%s %s: socsim failed, see %s/socsim.out" % (scene, key, work))
    cpu, instr = {}, {}
    with open(os.path.join(work, "uart.log")) as log:
        for line in log:
            m = SOC_FW_LINE.match(line)
            if m:
                instr[int(m.group(1))] = int(m.group(2))
                cpu[int(m.group(1))] = int(m.group(3))
    if sorted(cpu) != list(range(views)):
        raise RuntimeError("%s %s: expected frames 0..%d in %s/uart.log" % (scene, key, views - 1, work))
    tool = os.path.join(build, "tools", "png_diff")
    bad = []
    for f in range(views):
        d, _ = png_diff(tool, os.path.join(work, "host-frames", "%04d.png" % f),
                        os.path.join(work, "frames", "%04d.png" % f))
        if d:
            bad.append("view %d: %d pixels" % (f, d))
    result = {"cpu": sum(cpu.values()) / views, "views": [cpu[f] for f in range(views)],
              "instr": sum(instr.values()) / views,
              "mismatch": "; ".join(bad) or None}
    with open(cache, "w") as f:
        json.dump({"key": cache_key, "result": result}, f)
    return result, False


def soc_measure(build, socsims, scenes, keys, views, span_scenes, jobs):
    """{(scene, key): soc result} for every key whose GPU socsims has; the span widths' keys get R's
    result marked "as_r"; ("span-check", scene): R's firmware on the SPAN_W 1 GPU where given."""
    todo = [(sc, k, None) for sc in scenes for k in keys
            if PATH_CONFIGS[k][1] in SOC_GPUS and PATH_CONFIGS[k][1] in socsims and k not in SOC_AS_R_KEYS]
    if "sim-z-w1" in socsims:
        todo += [(sc, "ref", "sim-z-w1") for sc in span_scenes if sc in scenes]
    t0 = os.times()

    def report(done, total, item, result):
        sc, k, sim = item
        r, cached = result
        print("bench-error SoC: [%2d/%d] %-9s %-8s%s cpu cycles/frame %d%s" % (
            done, total, sc, k, "" if sim is None else " on " + sim, r["cpu"],
            " (cached)" if cached else ""), file=sys.stderr, flush=True)
    runs = parallel(todo, lambda sc, k, sim: soc_run(build, socsims, sc, k, views, sim), jobs, report)
    out = {(sc, k) if sim is None else ("span-check", sc): r for (sc, k, sim), (r, _) in runs.items()}
    t1 = os.times()
    print("bench-error SoC: %d socsim runs, %.0f s of CPU" % (len(todo), (t1.children_user + t1.children_system)
                                                              - (t0.children_user + t0.children_system)),
          file=sys.stderr, flush=True)
    mismatches = ["%s %s %s" % (sc, k, r["mismatch"]) for (sc, k), r in out.items() if r["mismatch"]]
    if mismatches:
        raise RuntimeError("SoC frames differ from the host build's: " + "; ".join(mismatches))
    for sc in scenes:
        for k in keys:
            if (sc, k) not in out:
                out[(sc, k)] = dict(out[(sc, "ref")], as_r=True)
    return out


def soc_notes(soc, scenes, views):
    """The table's SoC lines: what was measured, and the span-width check."""
    lines = ["- SoC CPU cycles: the same configuration built for the SoC on socsim (VexRiscv_FullCfu, 50 MHz "
             "model), mcycle per frame without the DONE_SEQ polls, on %s of the scene's camera path "
             "(frame 0: cold caches), measured once and shown in both tables; its frames equal the host "
             "build's on those views; span widths, depth bits and sine tables: R's number (\"as R\", see SOC_AS_R_KEYS)" % (
                 "the first view" if views == 1 else "the first %d views (mean)" % views)]
    checks = [(sc, soc[("span-check", sc)]["cpu"], soc[(sc, "ref")]["cpu"]) for sc in scenes if ("span-check", sc) in soc]
    if checks:
        lines.append("- SoC CPU cycles against SPAN_W: R's firmware on a SPAN_W 1 GPU against SPAN_W 8: %s (%s)" % (
            ", ".join("%s %d / %d" % c for c in checks),
            "equal" if all(a == b for _, a, b in checks) else "NOT EQUAL: the span width changes the CPU's cycles"))
    return lines


def soc_table(soc, scenes, views):
    """--soc-only: the SoC column alone, every configuration of the camera paths."""
    lines = ["| knob | setting | scene | SoC CPU cycles/frame | / R's | SoC instructions/frame | CPI |",
             "|---|---|---|---:|---:|---:|---:|"]
    lines += knob_rows(PATH_KNOBS, scenes, soc, lambda scene, r: [
        soc_cell({"soc": r["cpu"], "soc_as_r": r.get("as_r", False)}), "%.2f" % (r["cpu"] / soc[(scene, "ref")]["cpu"]),
        "%d" % r["instr"] if "instr" in r else "—", "%.2f" % (r["cpu"] / r["instr"]) if "instr" in r else "—"])
    lines.append("")
    lines.extend(soc_notes(soc, scenes, views))
    return "\n".join(lines)


def soc_merge(results, soc, scenes, keys):
    if soc:
        for sc in scenes:
            for k in keys:
                results[(sc, k)]["soc"] = soc[(sc, k)]["cpu"]
                results[(sc, k)]["soc_as_r"] = soc[(sc, k)].get("as_r", False)


def soc_cell(r):
    if "soc" not in r:
        return "—"
    return "%d%s" % (round(r["soc"]), " (as R)" if r["soc_as_r"] else "")


def percentile(values, q):
    """The q-th percentile (0..100), linear between the closest ranks."""
    v = sorted(values)
    pos = (len(v) - 1) * q / 100.0
    lo = int(pos)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (pos - lo)


def path_measure(build, scenes, views, cost_views, jobs, rerun):
    tool = os.path.join(build, "tools", "png_diff")
    todo = [(scene, key) for scene in scenes for key in PATH_CONFIGS]
    runs = parallel(todo, lambda scene, key: path_run(build, scene, key, views, cost_views, rerun), jobs,
                    progress("bench-error --path: [%2d/%d] %-9s %-8s"))
    results = {}
    mismatches = []
    for scene, key in todo:
        work, counts = runs[(scene, key)]
        exact = os.path.join(runs[(scene, "ref")][0], "exact")
        with open(os.path.join(work, "cameras.txt")) as a, \
                open(os.path.join(runs[(scene, "ref")][0], "cameras.txt")) as b:
            cams, ref_cams = a.read(), b.read()
        if cams != ref_cams or len(cams.splitlines()) != views:
            mismatches.append("%s %s: cameras differ from R's (%s/cameras.txt)" % (scene, key, work))
        diff = [png_diff(tool, os.path.join(exact, "%04d.png" % f),
                         os.path.join(work, "frames", "%04d.png" % f)) for f in range(views)]
        for f in range(cost_views):  # the host frames are the co-simulated ones
            d, _ = png_diff(tool, os.path.join(work, "cosim-frames", "%04d.png" % f),
                            os.path.join(work, "frames", "%04d.png" % f))
            if d:
                mismatches.append("%s %s view %d: %d pixels" % (scene, key, f, d))
        px = [d for d, _ in diff]
        worst = max(range(views), key=lambda f: (px[f], f))
        results[(scene, key)] = {
            "differing": sum(px) / views,
            "p95": percentile(px, 95),
            "worst": px[worst],
            "worst_view": worst,
            "mae": sum(s for _, s in diff) / (views * FB_PIXELS * 3),
            "instr": sum(c[0] for c in counts.values()) / max(1, len(counts)),
            "cycles": sum(c[1] for c in counts.values()) / max(1, len(counts)),
            "work": work,
            "exact": exact,
        }
    return results, mismatches


def path_worst_images(build, results, scenes):
    """build/bench-error/path/worst/<scene>-<key>.png: exact reference | configuration, the
    configuration's worst view, side by side (a 16-pixel grey gap)."""
    import matplotlib.image
    import numpy
    out_dir = os.path.join(build, "bench-error", PATH_DIR, "worst")
    os.makedirs(out_dir, exist_ok=True)
    for scene in scenes:
        for key in PATH_CONFIGS:
            r = results[(scene, key)]
            name = "%04d.png" % r["worst_view"]
            a = matplotlib.image.imread(os.path.join(r["exact"], name))[:, :, :3]
            b = matplotlib.image.imread(os.path.join(r["work"], "frames", name))[:, :, :3]
            gap = numpy.full((a.shape[0], 16, 3), 0.5, dtype=a.dtype)
            matplotlib.image.imsave(os.path.join(out_dir, "%s-%s.png" % (scene, key)),
                                    numpy.concatenate([a, gap, b], axis=1))
    return out_dir


def pareto(points):
    """Keys of the (cost, error) points no other point dominates (<= in both, < in one)."""
    front = []
    for k, (c, e) in points.items():
        if not any((c2 <= c and e2 <= e) and (c2 < c or e2 < e) for k2, (c2, e2) in points.items() if k2 != k):
            front.append(k)
    return front


def path_aggregate(results, scenes, cost):
    """Per configuration: (cost relative to R's, geometric mean over the scenes; error, mean over
    the scenes of the mean pixels differing from E)."""
    agg = {}
    for key in PATH_CONFIGS:
        ratio = 1.0
        for s in scenes:
            ratio *= results[(s, key)][cost] / results[(s, "ref")][cost]
        agg[key] = (ratio ** (1.0 / len(scenes)), sum(results[(s, key)]["differing"] for s in scenes) / len(scenes))
    return agg


def path_table(results, scenes, views, cost_views, mismatches, soc_lines=()):
    lines = ["| knob | setting | scene | pixels differing from E: mean | p95 | worst (view) | mean abs dRGB | fw instructions/frame | GPU cycles/frame | SoC CPU cycles/frame |",
             "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    lines += knob_rows(PATH_KNOBS, scenes, results, lambda scene, r: [
        differing_cell(r), "%.0f" % r["p95"], "%d (%d)" % (r["worst"], r["worst_view"]), "%.4f" % r["mae"],
        "%d" % round(r["instr"]), "%d" % round(r["cycles"]), soc_cell(r)])
    lines.append("")
    lines.append("E = the exact reference (bench/exact_ref). Errors over the %d views of each scene's "
                 "camera path (firmware/app/cam_path.h, seed FW_PATH_SEED), frames from the host build "
                 "through the golden model; costs means over the first %d views, co-simulated (QEMU "
                 "-icount, Verilator cycles)." % (views, cost_views))
    lines.append("- host frames against the co-simulated ones on those views, and every "
                 "configuration's cameras (eye, yaw, pitch of all %d views) against R's: %s" % (
                     views, "identical" if not mismatches else "DIFFER: " + "; ".join(mismatches[:5])))
    lines.extend(soc_lines)
    costs = [("instr", "fw instructions"), ("cycles", "GPU cycles")]
    if "soc" in results[(scenes[0], "ref")]:
        costs.append(("soc", "SoC CPU cycles"))
    for cost, name in costs:
        agg = path_aggregate(results, scenes, cost)
        front = pareto(agg)
        lines.append("- Pareto front (%s relative to R's, geometric mean over the scenes; mean pixels "
                     "differing from E): %s; the default build %s" % (
                         name, ", ".join("%s (%.2f, %.1f)" % (PATH_CONFIGS[k][2], agg[k][0], agg[k][1])
                                         for k in sorted(front, key=lambda k: agg[k][0])),
                         "lies on it" if "default" in front else
                         "does NOT lie on it" if "default" in PATH_CONFIGS else "is not in this run"))
    return "\n".join(lines)


def path_summary(results, scenes):
    lines = knob_ranges(results, scenes, PATH_KNOBS, [("mean pixels differing from E", "differing", "%.1f"),
                                                      ("p95", "p95", "%.0f"), ("worst view", "worst", "%d")])
    lines.append("")
    lines.append("Ranges over the scenes (%s)." % ", ".join(scenes))
    return "\n".join(lines)


def path_plot(results, scenes, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = cost_panels(results, scenes, relative=True)
    fig, axes = plt.subplots(1, len(panels), figsize=(5.5 * len(panels), 4.6), sharey=True)
    for ax, (cost, label) in zip(axes, panels):
        agg = path_aggregate(results, scenes, cost)
        front = sorted(pareto(agg), key=lambda k: agg[k][0])
        ax.plot([agg[k][0] for k in front], [agg[k][1] for k in front], "-", color="tab:red",
                alpha=0.5, label="Pareto front")
        for key in PATH_CONFIGS:
            c, e = agg[key]
            ax.scatter(c, e, marker=MARKERS[key], s=60 if key == "default" else 40,
                       color="tab:red" if key in front else "tab:blue")
            ax.annotate(PATH_CONFIGS[key][2] + ("" if key != "default" else (" (on the front)" if key in front else " (off the front)")),
                        (c, e), fontsize=7, xytext=(4, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(label, fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("mean framebuffer pixels differing from E / view")
    fig.suptitle("Camera paths: error against the exact reference E vs counted cost, mean over %s "
                 "(red: Pareto front)" % ", ".join(scenes), fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(path, dpi=90)


# ---- the test: the metric on images with a known difference ------------------------------------

def write_png(path, width, height, rgb):
    """A minimal 8-bit RGB PNG (filter 0 on every row)."""
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    rows = b"".join(b"\0" + bytes(rgb[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def check_metric(tool, work):
    os.makedirs(work, exist_ok=True)
    w, h = 8, 6
    base = [(x * 31 + y * 7 + c * 50) % 256 for y in range(h) for x in range(w) for c in range(3)]
    changed = list(base)
    changed[(2 * w + 5) * 3 + 1] ^= 0x10   # one pixel, green channel, |d| = 16
    changed[(3 * w + 1) * 3 + 0] = 255 - changed[(3 * w + 1) * 3 + 0]
    expected_sum = 16 + abs(255 - 2 * base[(3 * w + 1) * 3])
    # Two changes of one 2 x 2 box that cancel in its mean: pixels (2, 4) and (3, 5), blue +-10.
    cancel = list(base)
    cancel[(4 * w + 2) * 3 + 2] = base[(4 * w + 2) * 3 + 2] + 10 if base[(4 * w + 2) * 3 + 2] < 200 else base[(4 * w + 2) * 3 + 2] - 10
    cancel[(5 * w + 3) * 3 + 2] = base[(5 * w + 3) * 3 + 2] - (cancel[(4 * w + 2) * 3 + 2] - base[(4 * w + 2) * 3 + 2])
    paths = {n: os.path.join(work, n + ".png") for n in ("a", "b", "c", "small", "cancel")}
    write_png(paths["a"], w, h, base)
    write_png(paths["b"], w, h, base)
    write_png(paths["c"], w, h, changed)
    write_png(paths["small"], w, h - 2, base[:w * (h - 2) * 3])
    write_png(paths["cancel"], w, h, cancel)

    def diff(*args):
        r = subprocess.run([tool, *args], capture_output=True, text=True)
        return r.returncode, r.stdout.split()
    failures = []
    rc, out = diff(paths["a"], paths["b"])
    if rc != 0 or out != ["pixels", "48", "differing", "0", "abs_sum", "0", "max_abs", "0"]:
        failures.append("identical images: %s (status %d)" % (" ".join(out), rc))
    rc, out = diff(paths["a"], paths["c"])
    want = ["pixels", "48", "differing", "2", "abs_sum", str(expected_sum), "max_abs",
            str(max(16, expected_sum - 16))]
    if rc != 0 or out != want:
        failures.append("two changed pixels: got %s, want %s" % (" ".join(out), " ".join(want)))
    rc, out = diff("--block", "2", paths["a"], paths["c"])  # (5, 2) and (1, 3) are not block corners
    if rc != 0 or out[:4] != ["pixels", "12", "differing", "0"]:
        failures.append("--block 2: %s" % " ".join(out))
    rc, _ = diff(paths["a"], paths["small"])
    if rc != 2:
        failures.append("different sizes: status %d, want 2" % rc)
    # --box: the changes of c lie in different 2 x 2 boxes (their sum stays), those of cancel in one.
    rc, out = diff("--box", "2", paths["a"], paths["c"])
    if rc != 0 or out[-2:] != ["box_abs_sum", str(expected_sum)]:
        failures.append("--box 2, changes in two boxes: %s (status %d)" % (" ".join(out), rc))
    rc, out = diff("--box", "2", paths["a"], paths["cancel"])
    if rc != 0 or out[4:6] != ["abs_sum", "20"] or out[-2:] != ["box_abs_sum", "0"]:
        failures.append("--box 2, changes cancelling in one box: %s (status %d)" % (" ".join(out), rc))
    rc, _ = diff("--box", "3", paths["a"], paths["c"])  # 8 x 6 is no whole number of 3 x 3 boxes
    if rc != 2:
        failures.append("--box 3 on 8 x 6: status %d, want 2" % rc)
    for f in failures:
        print("metric: " + f)
    return not failures


def select(keys, ap):
    """--only: keep R and the configurations named (CONFIGS, PATH_CONFIGS and the table rows)."""
    unknown = [k for k in keys if k not in PATH_CONFIGS]
    if unknown:
        ap.error("--only: no configuration %s (known: %s)" % (", ".join(unknown), ", ".join(PATH_CONFIGS)))
    keep = set(keys) | {"ref"}
    for table in (CONFIGS, PATH_CONFIGS):
        for k in [k for k in table if k not in keep]:
            del table[k]
    for knobs in (KNOBS, PATH_KNOBS):
        rows = [(knob, [(st, k) for st, k in settings if k in keep]) for knob, settings in knobs]
        knobs[:] = [(knob, settings) for knob, settings in rows if any(k != "ref" for _, k in settings)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build")
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-run", action="store_true", help="tabulate and plot the last run again")
    ap.add_argument("--check-metric", nargs=2, metavar=("PNG_DIFF", "WORKDIR"))
    ap.add_argument("--path", type=int, metavar="VIEWS",
                    help="camera paths of VIEWS views (the fw-path builds') against the exact reference")
    ap.add_argument("--cost-views", type=int, default=8, help="--path: views co-simulated for the costs")
    ap.add_argument("--keep", action="store_true", help="--path: reuse the finished runs of the last one")
    ap.add_argument("--socsim", action="append", default=[], metavar="SIM=SOCSIM",
                    help="the SoC's CPU cycles: socsim for the configurations run on gpusim SIM (sim-w8, "
                         "sim-z-w8; sim-z-w1: the span-width check)")
    ap.add_argument("--soc-only", action="store_true", help="--socsim: only the SoC's column, as its own table")
    ap.add_argument("--soc-views", type=int, default=1, help="--socsim: path views per configuration")
    ap.add_argument("--soc-span-scenes", default="tetra cubes",
                    help="--socsim sim-z-w1=...: the scenes of the span-width check")
    ap.add_argument("--only", metavar="KEY,...",
                    help="measure only these configurations (and R): a partial re-run, e.g. sin6,zb8")
    ap.add_argument("scenes", nargs="*")
    a = ap.parse_args()
    if a.only:
        select(a.only.split(","), ap)
    if a.check_metric:
        ok = check_metric(*a.check_metric)
        print("metric: 0 for identical images, the known sum for 2 changed pixels, box means, sizes checked"
              if ok else "metric: FAILED")
        return 0 if ok else 1
    socsims = {}
    for spec in a.socsim:
        sim, _, path = spec.partition("=")
        if not path or not os.path.exists(path):
            ap.error("--socsim %s: SIM=PATH of an existing socsim" % spec)
        socsims[sim] = path
    if socsims and "sim-z-w8" not in socsims:
        ap.error("--socsim: R's GPU, sim-z-w8=..., is needed")

    def soc_for(keys):
        if not socsims:
            return None, []
        soc = soc_measure(a.build, socsims, a.scenes, keys, a.soc_views, a.soc_span_scenes.split(), a.jobs)
        return soc, soc_notes(soc, a.scenes, a.soc_views)

    if a.soc_only:
        if not socsims or not a.build or not a.scenes:
            ap.error("--soc-only needs --build, --socsim and scenes")
        soc, _ = soc_for(list(PATH_CONFIGS))
        print(soc_table(soc, a.scenes, a.soc_views))
        return 0
    if a.path:
        if not a.build or not a.scenes or not 1 <= a.cost_views <= a.path:
            ap.error("--path needs --build, scenes and 1 <= --cost-views <= VIEWS")
        soc, soc_lines = soc_for(list(PATH_CONFIGS))
        results, mismatches = path_measure(a.build, a.scenes, a.path, a.cost_views, a.jobs,
                                           "keep" if a.keep else not a.no_run)
        soc_merge(results, soc, a.scenes, list(PATH_CONFIGS))
        print(path_table(results, a.scenes, a.path, a.cost_views, mismatches, soc_lines))
        print()
        print(path_summary(results, a.scenes))
        plot_path = os.path.join(a.build, "bench-error", PATH_DIR, "error-vs-cost.png")
        path_plot(results, a.scenes, plot_path)
        print("\nPlot: %s\nWorst views (exact | configuration): %s/<scene>-<configuration>.png"
              % (plot_path, path_worst_images(a.build, results, a.scenes)))
        return 1 if mismatches else 0
    if not a.build or not a.scenes or a.frames < 1:
        ap.error("--build, --frames and at least one scene are needed")
    soc, soc_lines = soc_for(list(CONFIGS))
    results = measure(a.build, a.frames, a.scenes, a.jobs, not a.no_run)
    soc_merge(results, soc, a.scenes, list(CONFIGS))
    print(table(results, a.scenes, a.frames, soc_lines))
    print()
    print(summary(results, a.scenes))
    path = os.path.join(a.build, "bench-error", "error-vs-cost.png")
    plot(results, a.scenes, path)
    print("\nPlot: %s" % path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
