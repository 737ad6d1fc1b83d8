#!/usr/bin/env python3
"""bench_soc.py — `make bench-soc`: benchmark builds (firmware.mk's FW_BENCH_FRAMES frames,
FW_PLATFORM=soc) on socsim, the whole SoC at 50 MHz, as one Markdown table.

usage: bench_soc.py --socsim SOCSIM [--boot BOOT.hex] --out DIR SCENE=ELF...

With --boot (SOC_MEM=sdram, docs/boot.md) socsim is the system with SDRAM: the boot program copies
each ELF's image from the flash into the SDRAM first; its cycles come before frame 0 and are no
frame's.

Per scene, averaged over the frames after the first (frame 0 carries the boot: banner, scene set-up):
  instr/frame     the firmware's "fw instr" (minstret over the frame's work, DONE_SEQ polls excluded)
  CPU cycles      the firmware's "cpu cycles" (mcycle over the same span)
  CPI             CPU cycles / instructions
  I$ / D$ refills cache-line refills per frame, counted by socsim on the core's Wishbone buses
                  (VexRiscv_FullCfu has no miss counters of its own)
  GPU busy        the GPU's PERF_BUSY_CYCLES summed over the frame's batches
  ready           cycles from the previous swap to the doorbell of the frame's last batch (the
                  firmware computes a frame while the GPU still draws the last one, app.c, so
                  what follows that swap: the frame's buffers filled, its doorbells, its strips)
  frame cycles    cycles from swap to swap (the GPU swaps at vertical blank: a multiple of the
                  VGA frame, 840,000 clocks at 50 MHz, is the floor)
  fps 50 MHz      50e6 / frame cycles, measured
  SDRAM busy      (--boot) the share of those cycles with a request on the SDRAM's port

and where the CPU's cycles go, per scene, from socsim's count of the clocks each of the core's
buses spends in a cycle between swaps (the core waits through them):
  I$ / D$ refill clocks   clocks of the instruction bus's cycles / of the data bus's line refills,
                  and per refill
  stores, store clocks    the stores (the data cache writes through: each is a bus cycle) and the
                  clocks of their cycles, and per store
  uncached load clocks    the clocks of loads outside the caches: the GPU's and the peripherals'
                  registers, so also the polling of DONE_SEQ between batches
  CPI without refills     (CPU cycles - both refills' clocks) / instructions: what the core's
                  pipeline (load-use, branches, multiplies and divides, stores) costs by itself; an
                  estimate, since a few refills fall outside the firmware's counted span
(No column estimates another clock: a rate is measured at the clock simulated, the board's.)
"""
import argparse
import os
import re
import subprocess
import sys
import time

FW_LINE = re.compile(r"^frame (\d+): .*\| fw instr (\d+) \| gpu cycles (\d+) .*\| cpu cycles (\d+)")
SIM_LINE = re.compile(r"^socsim: frame (\d+) -> .* \| swap at cycle (\d+), \+(\d+) \| ready \+(\d+) \| "
                      r"instructions (\d+) \| refills I\$ (\d+) D\$ (\d+) \| "
                      r"bus clocks I\$ (\d+) D\$ (\d+) stores (\d+) \((\d+)\) loads (\d+)"
                      r"(?: \| SDRAM busy (\d+))?")
SPEED_LINE = re.compile(r"^socsim: (\d+) cycles .* in ([\d.]+) s: ([\d.]+) M cycles/s")
CLK = 50e6


def mean(xs):
    return sum(xs) / len(xs) if xs else float("nan")


def run_scene(socsim, boot, elf, out_dir):
    frames_dir = os.path.join(out_dir, "frames")
    os.makedirs(frames_dir, exist_ok=True)
    t0 = time.monotonic()
    p = subprocess.run([socsim, *(["--boot", boot] if boot else []), "--fw", elf, "--frames", frames_dir,
                        "--uart-log", os.path.join(out_dir, "uart.log"),
                        "--summary", os.path.join(out_dir, "summary")],
                       capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit(f"bench-soc: {elf}: socsim exited with {p.returncode}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    fw, sim, speed = {}, {}, None
    for line in p.stdout.splitlines():
        m = FW_LINE.match(line)
        if m:
            fw[int(m[1])] = [int(v) for v in m.groups()[1:]]
        m = SIM_LINE.match(line)
        if m:
            sim[int(m[1])] = [int(v) if v is not None else None for v in m.groups()[1:]]
        m = SPEED_LINE.match(line)
        if m:
            speed = (int(m[1]), float(m[2]), float(m[3]))
    return fw, sim, speed, wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--socsim", required=True)
    ap.add_argument("--boot", help="the boot program's RAM image: the ELFs run from the SDRAM")
    ap.add_argument("--out", required=True)
    ap.add_argument("runs", nargs="+", metavar="SCENE=ELF")
    a = ap.parse_args()

    rows, stalls, total_cycles, total_wall = [], [], 0, 0.0
    for run in a.runs:
        scene, elf = run.split("=", 1)
        fw, sim, speed, wall = run_scene(a.socsim, a.boot, elf, os.path.join(a.out, scene))
        # firmware frame numbers count the frames drawn; socsim's the frames captured: the same
        # sequence when no frame is lost (benchmark builds lose none).
        keys = sorted(k for k in fw if k >= 1 and k in sim)
        if not keys:
            sys.exit(f"bench-soc: {scene}: fewer than two frames")
        instr = mean([fw[k][0] for k in keys])
        gpu = mean([fw[k][1] for k in keys])
        cpu = mean([fw[k][2] for k in keys])
        frame = mean([sim[k][1] for k in keys])
        ready = mean([sim[k][2] for k in keys])
        irefill = mean([sim[k][4] for k in keys])
        drefill = mean([sim[k][5] for k in keys])
        # SDRAM builds: the share of the cycles between captured frames with a request on the SDRAM
        # port (waiting or answered), against the same span's cycles (swap to swap).
        busy = mean([sim[k][11] / sim[k][1] for k in keys]) if sim[keys[0]][11] is not None else None
        iclk = mean([sim[k][6] for k in keys])
        dclk = mean([sim[k][7] for k in keys])
        sclk = mean([sim[k][8] for k in keys])
        stores = mean([sim[k][9] for k in keys])
        lclk = mean([sim[k][10] for k in keys])
        rows.append((scene, len(keys), instr, cpu, cpu / instr, irefill, drefill, gpu, ready, frame,
                     CLK / frame, busy))
        stalls.append((scene, instr, cpu, iclk, iclk / max(irefill, 1), dclk, dclk / max(drefill, 1),
                       stores, sclk, sclk / max(stores, 1), lclk, cpu / instr,
                       (cpu - iclk - dclk) / instr))
        if speed:
            total_cycles += speed[0]
            total_wall += speed[1]

    sdram = a.boot is not None
    print("| scene | frames | instr/frame | CPU cycles/frame | CPI | I$ refills | D$ refills | GPU busy cycles "
          "| ready (cycles) | frame cycles (swap to swap) | fps 50 MHz |"
          + (" SDRAM busy |" if sdram else ""))
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" + ("---:|" if sdram else ""))
    for r in rows:
        print(f"| {r[0]} | {r[1]} | {r[2]:,.0f} | {r[3]:,.0f} | {r[4]:.2f} | {r[5]:,.0f} | {r[6]:,.0f} | "
              f"{r[7]:,.0f} | {r[8]:,.0f} | {r[9]:,.0f} | {r[10]:.1f} |"
              + (f" {100 * r[11]:.1f} % |" if sdram and r[11] is not None else ""))
    print("\nWhere the CPU's cycles go (bus clocks between swaps, socsim's taps on the core's buses):\n")
    print("| scene | instr/frame | CPU cycles/frame | I$ refill clocks | a refill | D$ refill clocks "
          "| a refill | stores | store clocks | a store | uncached load clocks | CPI | CPI without refills |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in stalls:
        print(f"| {r[0]} | {r[1]:,.0f} | {r[2]:,.0f} | {r[3]:,.0f} | {r[4]:.1f} | {r[5]:,.0f} | {r[6]:.1f} | "
              f"{r[7]:,.0f} | {r[8]:,.0f} | {r[9]:.1f} | {r[10]:,.0f} | {r[11]:.2f} | {r[12]:.2f} |")
    if total_wall > 0:
        print(f"\nsocsim: {total_cycles:,} cycles simulated in {total_wall:.1f} s: "
              f"{total_cycles / total_wall / 1e6:.2f} M cycles/s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
