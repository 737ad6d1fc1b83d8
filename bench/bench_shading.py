#!/usr/bin/env python3
"""`make bench-error-shading` (the third part of `make bench-error`): the shading knobs' error
against their counted cost, on the scenes whose meshes carry vertex normals (FW_SHADING_SCENES).

Reference U, undithered: the Gouraud build's own frames with every Gouraud pixel in its unquantised
colour (fw-host --unquantised-frames, the golden model's shade probe): the intensity i(p) the GPU
interpolates (Q4.12), before its level is rounded down or dithered, mixed linearly between the two
entries of the material's ramp around it. Every configuration below draws the same geometry with the
same depth test, so its error against U is its shading's alone:

  flat                 the face's level on every pixel (FW_GOURAUD=0: the flat rule)
  Gouraud              the interpolated level, rounded down (FW_DITHER=0)
  Gouraud, dithered    ... and raised by the 4 x 4 ordered dither (CTRL_DITHER: the default)

all on a Gouraud GPU with the depth buffer (sim-g-w8), the fixed backend, on the seeded camera path
of `make bench-error-path` (FW_PATH_VIEWS views, frames from the host build through the golden model).
Metrics per view against U (tools/png_diff, framebuffer pixels):
  pixels differing   framebuffer pixels whose RGB differs from U's
  mean abs dRGB      mean over pixels and channels of |RGB - RGB_U| (0..255)
  4x4 mean abs dRGB  the same after averaging each aligned 4 x 4 box of both frames (png_diff --box
                     4): the error seen from afar, over the dither's period, where the dithered
                     levels average to the intensity they stand for
Costs, counted: fw instructions and GPU cycles per frame, co-simulated (QEMU -icount, Verilator) on
the first COST_VIEWS views; the co-simulated frames must equal the host build's.

    bench_shading.py --build BUILD --views N [--cost-views K] [--jobs J] [--no-run] SCENE...
"""
import argparse
import os
import shutil
import subprocess
import sys

from bench_error import FB_PIXELS, parallel, pareto, path_cosim, path_costs, percentile, png_diff_fields, progress

SIM = "sim-g-w8"  # ENABLE_GOURAUD with the depth buffer, SPAN_W 8
# key -> (firmware variant, $(FW_PATH_DIR)/host-<scene>-<variant> and <scene>-<variant>.elf; label)
CONFIGS = {
    "flat":     ("fixed-flat-z",     "flat"),
    "gouraud":  ("fixed-nodither-z", "Gouraud"),
    "dithered": ("fixed-z",          "Gouraud, dithered"),
}
REF_KEY = "dithered"  # its run writes U (any Gouraud run's probe holds the same i(p))
BOX = 4               # the Bayer matrix's period
MARKERS = {"flat": "s", "gouraud": "^", "dithered": "o"}


def run(build, scene, key, views, cost_views, rerun):
    """Host frames of every view (and U, for REF_KEY), costs of the first cost_views co-simulated.
    Returns (work dir, {view: (instr, cycles)})."""
    variant, _ = CONFIGS[key]
    work = os.path.join(build, "bench-error", "shading", scene, key)
    if rerun:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        cmd = [os.path.join(build, "fw-path", "host-%s-%s" % (scene, variant)), "--frames",
               os.path.join(work, "frames"), "--span-w", "8", "--zbuf", "--gouraud"]
        if key == REF_KEY:
            cmd += ["--unquantised-frames", os.path.join(work, "unquantised")]
        with open(os.path.join(work, "host.out"), "w") as out:
            if subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT).returncode != 0:
                raise RuntimeError("%s %s: host run failed, see %s/host.out" % (scene, key, work))
        path_cosim(build, SIM, os.path.join(build, "fw-path", "%s-%s.elf" % (scene, variant)), work, cost_views)
    return work, path_costs(work, cost_views)


def measure(build, scenes, views, cost_views, jobs, rerun):
    tool = os.path.join(build, "tools", "png_diff")
    todo = [(scene, key) for scene in scenes for key in CONFIGS]
    runs = parallel(todo, lambda scene, key: run(build, scene, key, views, cost_views, rerun), jobs,
                    progress("bench-error shading: [%d/%d] %-9s %s"))
    results, mismatches = {}, []
    for scene, key in todo:
        work, counts = runs[(scene, key)]
        ref = os.path.join(runs[(scene, REF_KEY)][0], "unquantised")
        diff = [png_diff_fields(tool, os.path.join(ref, "%04d.png" % f), os.path.join(work, "frames", "%04d.png" % f),
                                "--box", str(BOX)) for f in range(views)]
        for f in range(cost_views):  # the host frames are the co-simulated ones
            d = png_diff_fields(tool, os.path.join(work, "cosim-frames", "%04d.png" % f),
                                os.path.join(work, "frames", "%04d.png" % f))["differing"]
            if d:
                mismatches.append("%s %s view %d: %d pixels" % (scene, key, f, d))
        mae = [d["abs_sum"] / (FB_PIXELS * 3) for d in diff]
        box = [d["box_abs_sum"] / (FB_PIXELS * 3) for d in diff]
        results[(scene, key)] = {
            "differing": sum(d["differing"] for d in diff) / views,
            "mae": sum(mae) / views,
            "mae_p95": percentile(mae, 95),
            "box": sum(box) / views,
            "box_p95": percentile(box, 95),
            "max_abs": max(d["max_abs"] for d in diff),
            "instr": sum(c[0] for c in counts.values()) / cost_views,
            "cycles": sum(c[1] for c in counts.values()) / cost_views,
        }
    return results, mismatches


def table(results, scenes, views, cost_views, mismatches):
    lines = ["| scene | shading | pixels differing from U | mean abs dRGB (p95) | 4x4 mean abs dRGB (p95) | "
             "largest channel error | fw instructions/frame | GPU cycles/frame |",
             "|---|---|---:|---:|---:|---:|---:|---:|"]
    for scene in scenes:
        for key, (_, label) in CONFIGS.items():
            r = results[(scene, key)]
            lines.append("| %s | %s | %.1f (%.2f%%) | %.3f (%.3f) | %.3f (%.3f) | %d | %d | %d |" % (
                scene, label, r["differing"], 100.0 * r["differing"] / FB_PIXELS, r["mae"], r["mae_p95"],
                r["box"], r["box_p95"], r["max_abs"], round(r["instr"]), round(r["cycles"])))
    lines.append("")
    lines.append("U = the Gouraud build's frames with unquantised intensities (the golden model's shade "
                 "probe). Errors: means over the %d views of each scene's camera path (p95: 95th percentile "
                 "of the views), 0..255 per channel; costs: means over the first %d views, co-simulated on "
                 "%s (QEMU -icount, Verilator cycles)." % (views, cost_views, SIM))
    lines.append("- host frames against the co-simulated ones on those views: %s" % (
        "identical" if not mismatches else "DIFFER: " + "; ".join(mismatches[:5])))
    for scene in scenes:
        r = {k: results[(scene, k)] for k in CONFIGS}
        lines.append("- %s: against flat, Gouraud costs %+.1f%% firmware instructions and %+.1f%% GPU cycles "
                     "and takes the mean error from %.3f to %.3f; the dither costs %+.2f%% and %+.2f%% and takes "
                     "it to %.3f per pixel (rounding down is biased, the dither is not) and, seen from afar, "
                     "from %.3f to %.3f" % (
                         scene, pct(r["gouraud"]["instr"], r["flat"]["instr"]),
                         pct(r["gouraud"]["cycles"], r["flat"]["cycles"]), r["flat"]["mae"], r["gouraud"]["mae"],
                         pct(r["dithered"]["instr"], r["gouraud"]["instr"]),
                         pct(r["dithered"]["cycles"], r["gouraud"]["cycles"]),
                         r["dithered"]["mae"], r["gouraud"]["box"], r["dithered"]["box"]))
        front = pareto({k: (r[k]["instr"], r[k]["box"]) for k in CONFIGS})
        lines.append("- %s: Pareto front of the 4x4 error against firmware instructions: %s" % (
            scene, ", ".join(CONFIGS[k][1] for k in CONFIGS if k in front)))
    return "\n".join(lines)


def pct(a, b):
    return 100.0 * (a / b - 1.0)


def plot(results, scenes, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [("instr", "firmware instructions / frame (QEMU -icount)"),
              ("cycles", "GPU cycles / frame (Verilator, PERF_BUSY_CYCLES)")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4), sharey=True)
    for ax, (cost, label) in zip(axes, panels):
        for scene in scenes:
            for key, (_, name) in CONFIGS.items():
                r = results[(scene, key)]
                ax.scatter(r[cost], r["mae"], marker=MARKERS[key], color="tab:blue", s=40)
                ax.scatter(r[cost], r["box"], marker=MARKERS[key], color="tab:red", s=40)
                ax.annotate(name, (r[cost], r["mae"]), fontsize=7, xytext=(4, 3), textcoords="offset points")
                ax.plot([r[cost], r[cost]], [r["box"], r["mae"]], color="grey", alpha=0.4, linewidth=1)
        ax.set_xlabel(label, fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("mean abs dRGB against U (0..255)")
    handles = [plt.Line2D([], [], color="tab:blue", marker="o", linestyle="", label="per pixel"),
               plt.Line2D([], [], color="tab:red", marker="o", linestyle="", label="4x4 box means (seen from afar)")]
    handles += [plt.Line2D([], [], color="grey", marker=MARKERS[k], linestyle="", label=CONFIGS[k][1]) for k in CONFIGS]
    axes[1].legend(handles=handles, fontsize=7, loc="upper right")
    fig.suptitle("Shading: error against the unquantised Gouraud frame U vs counted cost (%s, camera path)"
                 % ", ".join(scenes), fontsize=9)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", required=True)
    ap.add_argument("--views", type=int, required=True, help="the camera path's views (FW_PATH_VIEWS)")
    ap.add_argument("--cost-views", type=int, default=8, help="views co-simulated for the costs")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-run", action="store_true", help="tabulate and plot the last run again")
    ap.add_argument("scenes", nargs="+")
    a = ap.parse_args()
    if not 1 <= a.cost_views <= a.views:
        ap.error("1 <= --cost-views <= --views")
    results, mismatches = measure(a.build, a.scenes, a.views, a.cost_views, a.jobs, not a.no_run)
    print(table(results, a.scenes, a.views, a.cost_views, mismatches))
    path = os.path.join(a.build, "bench-error", "shading", "error-vs-cost.png")
    plot(results, a.scenes, path)
    print("\nPlot: %s" % path)
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
