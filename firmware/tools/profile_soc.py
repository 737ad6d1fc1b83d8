#!/usr/bin/env python3
"""make profile-soc — where a scene's CPU clocks go on the SoC, function by function.

Runs one firmware ELF on socsim with --profile (cosim/soc/cpu_profile.h): every retired
instruction is charged the clocks since the one before it retired, so the waits of the pipeline
and the caches land on the instructions that waited, and every cache-line refill on the
instruction that needed it. Frames as make profile-fw's (from one entry into scene_update to the
next; the first and the last left out), means per frame.

make profile-fw counts instructions in QEMU, which runs the firmware's C paths; this counts the
SoC's clocks, with its caches, its bus, its memory (SOC_MEM=sdram: the SDRAM) and its custom
instructions (the projection unit).

Usage: profile_soc.py SOCSIM ELF [--boot HEX] [--top N] [--lines N] [--raw FILE]
"""
import argparse
import collections
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from profile_fw import FRAME_MARK, NOT_PIPELINE, function_finder, source_lines, symbols  # noqa: E402


def run_profile(socsim, elf, boot, mark, raw):
    """socsim's per-address counts: (frames, {pc: (cycles, instructions, d_refills, i_refills)});
    raw: a path for a copy of socsim's file, or None."""
    with tempfile.TemporaryDirectory(prefix="profile-soc-") as tmp:
        out = os.path.join(tmp, "profile.txt")
        cmd = [socsim, "--fw", elf, "--frames", os.path.join(tmp, "frames"), "--no-model-check",
               "--uart-log", os.path.join(tmp, "uart.log"), "--profile", out,
               "--profile-mark", hex(mark)]
        if boot:
            cmd += ["--boot", boot]
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            sys.exit(f"profile-soc: socsim failed ({run.returncode}): {run.stdout[-600:]}")
        if raw:
            shutil.copyfile(out, raw)
        counts = {}
        frames = 0
        with open(out) as f:
            for line in f:
                parts = line.split()
                if parts[0] == "frames":
                    frames = int(parts[1])
                elif parts[0] not in ("mark", "span_cycles", "span_instret"):
                    counts[int(parts[0], 16)] = tuple(int(p) for p in parts[1:5])
    return frames, counts


def table(rows, nf, work_cycles, first_column, top):
    """rows: [(name, [cycles, instructions, d_refills, i_refills])], largest first."""
    print(f"| {first_column} | cycles/frame | share | instructions/frame | CPI | D$ refills/frame | "
          "I$ refills/frame |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for name, (cyc, ins, dref, iref) in rows[:top]:
        print(f"| {name} | {cyc / nf:,.0f} | {100.0 * cyc / max(work_cycles, 1):.1f}% | {ins / nf:,.0f} | "
              f"{cyc / max(ins, 1):.2f} | {dref / nf:,.0f} | {iref / nf:,.0f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("socsim")
    ap.add_argument("elf")
    ap.add_argument("--boot", help="the boot program (a firmware that runs from the SDRAM)")
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--lines", type=int, default=0,
                    help="also list the N source lines that took the most clocks")
    ap.add_argument("--raw", help="keep socsim's per-address counts (--profile's file) here")
    args = ap.parse_args()

    syms = symbols(args.elf)
    function_of = function_finder(syms)
    mark = next((a for a, n in syms if n == FRAME_MARK), None)
    if mark is None:
        sys.exit(f"profile-soc: {args.elf} has no {FRAME_MARK} symbol")

    nf, counts = run_profile(args.socsim, args.elf, args.boot, mark, args.raw)
    if nf == 0:
        sys.exit("profile-soc: no whole frame measured; build with FRAMES >= 3")
    by_fn = collections.defaultdict(lambda: [0, 0, 0, 0])
    for pc, c in counts.items():
        acc = by_fn[function_of(pc)]
        for k in range(4):
            acc[k] += c[k]
    side = {k: by_fn.pop(k) for k in list(by_fn) if k in NOT_PIPELINE}
    work = [sum(v[k] for v in by_fn.values()) for k in range(4)]
    rows = sorted(by_fn.items(), key=lambda kv: -kv[1][0])
    table(rows, nf, work[0], "function", args.top)
    rest = [work[k] - sum(v[k] for _, v in rows[:args.top]) for k in range(4)]
    if rest[0] > 0:
        print(f"| (other functions) | {rest[0] / nf:,.0f} | {100.0 * rest[0] / work[0]:.1f}% | "
              f"{rest[1] / nf:,.0f} | {rest[0] / max(rest[1], 1):.2f} | {rest[2] / nf:,.0f} | "
              f"{rest[3] / nf:,.0f} |")
    print(f"| **total, polling excluded** | **{work[0] / nf:,.0f}** | 100% | **{work[1] / nf:,.0f}** | "
          f"**{work[0] / max(work[1], 1):.2f}** | **{work[2] / nf:,.0f}** | **{work[3] / nf:,.0f}** |")
    print()
    for name, v in side.items():
        print(f"{name} (waiting for the GPU or the UART): {v[0] / nf:,.0f} cycles/frame, not counted above")

    if args.lines > 0:
        pcs = sorted(pc for pc in counts if function_of(pc) not in NOT_PIPELINE)
        by_line = collections.defaultdict(lambda: [0, 0, 0, 0])
        for pc, where in zip(pcs, source_lines(args.elf, pcs)):
            acc = by_line[where]
            for k in range(4):
                acc[k] += counts[pc][k]
        print()
        table(sorted(by_line.items(), key=lambda kv: -kv[1][0]), nf, work[0], "source line", args.lines)
    print()
    print(f"Mean of {nf} frame(s) (frame 0 and the last skipped); socsim's clocks, each retired "
          "instruction charged the clocks since the one before it.")


if __name__ == "__main__":
    main()
