#!/usr/bin/env python3
"""board_fit.py — `make board-fit`: the ULX3S build's resources (and, with --pnr, fmax per clock)
for the board's default build (the firmware and the frames in the SDRAM), the on-chip builds
(SOC_MEM=ram: with and without the depth buffer, every scene's lean build), as one Markdown table with the fit on each of the ULX3S's
parts (LFE5U-12F, -25F, -45F, -85F).

usage: board_fit.py --build BUILD [--pnr] [--jobs N] [--scenes S ...] [--make make]

Builds, each through `make synth-board BOARD=ulx3s` (or `make bitstream`, with --pnr):
  on-chip      SOC_MEM=ram: SCENE tetra, the contract's 192 KiB RAM, SPAN_W 8, lines, no depth
               buffer, the frames on chip (320x240)
  on-chip-zbuf the same with ENABLE_ZBUF (the 16-bit depth buffer: 75 EBR more) and without the
               framebuffer write mask (4 EBR less: board.mk's WMASK default beside the depth buffer)
  <scene>-lean (on chip) the scene's one-scene firmware and a RAM just large enough for it: the linked
               image's need (bsp/soc/postlink.py's <elf>.ramkib: image, bss and stack, rounded up
               to the RAM's granule), as the scene's manifest build sizes it
  zbuf-<scene>-lean  the depth-buffer build with the smallest lean RAM (a depth buffer fits only so)
  default      the board's default build (boards/ulx3s/defaults.mk): the firmware in the SDRAM
               (SOC_MEM=sdram, a 16 KiB boot RAM) and the GPU's frames there too (FRAME_DRAM=1,
               FB=640x480: strips of 16 rows on chip), with the depth buffer (a strip's)
The firmware of every build is made first, one after another (they share object files); then the
builds run JOBS at a time (default 2: yosys and nextpnr use one core each). Each build's numbers come from synth/ecp5_bitstream.py's resources.json and fmax.json in its
directory; a build that does not fit the 85F is reported as such (no place and route).
"""
import argparse
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bsp", "soc"))
from elf_to_hex import soc_map_value  # noqa: E402  (contract/soc_map.h's values, read once here)

SCENES = ["tetra", "cubes", "landscape", "voxel", "knot"]


def make(args, targets, variables, log):
    # FULL=1: these builds are board_fit's own (a scene's manifest build would be another).
    cmd = [args.make, "--no-print-directory", "FULL=1"] + targets + [f"{k}={v}" for k, v in variables.items()]
    with open(log, "w") as out:
        status = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT)
    with open(log) as f:
        return status, f.read()


def default_kib():
    """The contract's default RAM (contract/soc_map.h SOC_RAM_DEFAULT_BYTES), in KiB."""
    return soc_map_value("SOC_RAM_DEFAULT_BYTES") // 1024


def lean_kib(args, scene, logdir):
    """The scene's RAM need: its board firmware's <elf>.ramkib (bsp/soc/postlink.py: the linked
    image's stack top, rounded up to the RAM's granule)."""
    log = os.path.join(logdir, f"fw-{scene}.log")
    status, _ = make(args, ["board-fw"], {"BOARD": "ulx3s", "SCENE": scene, "SOC_MEM": "ram", "BUILD": args.build}, log)
    elf = os.path.join(args.build, "board-fw", f"{scene}-{default_kib()}k.elf")
    if status != 0 or not os.path.exists(elf):
        sys.exit(f"board_fit: could not build {scene}'s firmware (see {log})")
    with open(elf + ".ramkib") as f:
        return int(f.read())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--pnr", action="store_true", help="place and route each build that fits: fmax per clock")
    ap.add_argument("--scenes", nargs="*", default=SCENES)
    ap.add_argument("--make", default="make")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    logdir = os.path.join(args.build, "board-fit")
    os.makedirs(logdir, exist_ok=True)

    kib = {s: lean_kib(args, s, logdir) for s in args.scenes}
    smallest = min(args.scenes, key=lambda s: kib[s])
    # (name, scene, RAM in KiB, depth buffer, board.mk's variables beyond those)
    on_chip = {"SOC_MEM": "ram"}
    builds = [("default", "tetra", soc_map_value("SOC_RAM_BOOT_BYTES") // 1024, 1,
               {"SOC_MEM": "sdram", "FRAME_DRAM": 1, "FB": "640x480"})]
    builds += [("on-chip", "tetra", default_kib(), 0, on_chip), ("on-chip-zbuf", "tetra", default_kib(), 1, on_chip)]
    builds += [(f"{s}-lean", s, kib[s], 0, on_chip) for s in args.scenes]
    builds += [(f"zbuf-{smallest}-lean", smallest, kib[smallest], 1, on_chip)]

    for name, scene, ram, zbuf, more in builds:
        status, _ = make(args, ["board-fw"], {"BOARD": "ulx3s", "SCENE": scene, "SOC_RAM_KIB": ram, "BUILD": args.build, **more},
                         os.path.join(logdir, f"fw-{name}.log"))
        if status != 0:
            sys.exit(f"board_fit: {name}: the firmware does not build (see {logdir}/fw-{name}.log)")

    def one(build):
        name, scene, ram, zbuf, more = build
        target = "bitstream" if args.pnr else "synth-board"
        variables = {"BOARD": "ulx3s", "SCENE": scene, "SOC_RAM_KIB": ram, "ZBUF": zbuf, "BUILD": args.build, **more}
        print(f"board_fit: {name}: {target} " + " ".join(f"{k}={v}" for k, v in variables.items() if k != "BUILD") + " ...",
              flush=True)
        start = time.monotonic()
        status, _ = make(args, [target], variables, os.path.join(logdir, f"{name}.log"))
        out = subprocess.run([args.make, "-s", "--no-print-directory", "FULL=1", "ulx3s-dir"] + [f"{k}={v}" for k, v in variables.items()],
                             check=True, capture_output=True, text=True).stdout.strip()
        res_path = os.path.join(out, "resources.json")
        if not os.path.exists(res_path):
            sys.exit(f"board_fit: {name}: no {res_path} (see {logdir}/{name}.log)")
        with open(res_path) as f:
            res = json.load(f)
        fmax = {}
        if args.pnr and os.path.exists(os.path.join(out, "fmax.json")):
            with open(os.path.join(out, "fmax.json")) as f:
                fmax = json.load(f)
        print(f"board_fit: {name}: status {status} in {time.monotonic() - start:.0f} s", flush=True)
        return (name, scene, ram, zbuf, more, res, fmax, status)

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        rows = list(pool.map(one, builds))

    print()
    parts = ("12k", "25k", "45k", "85k")
    print("| build | RAM | LUT4 | FF | EBR | MULT18 | " + " | ".join(f"fits {p[:-1]}F" for p in parts)
          + " | fmax sys / pix / tmds (/ SDRAM PHY 2x) (MHz) |")
    print("|---|---:|---:|---:|---:|---:|" + "---|" * len(parts) + "---|")
    for name, scene, ram, zbuf, more, res, fmax, status in rows:
        c = res["cells"]
        clocks = " / ".join(f"{fmax[k]['fmax_mhz']:.1f}" for k in sorted(fmax, key=clock_order)) if fmax else "—"
        where = ", firmware and 640x480 frames in the SDRAM" if more.get("FRAME_DRAM") else ""
        print(f"| {name} ({scene}{', depth buffer' if zbuf else ''}{where}) | {ram} KiB | {c['LUT4']} | {c['TRELLIS_FF']} "
              f"| {c['DP16KD']} | {c['MULT18X18D']} | " + " | ".join('yes' if res['fits'][p] else 'no' for p in parts)
              + f" | {clocks} |")
    return 0


def clock_order(name):
    for i, key in enumerate(("sys", "pix", "tmds", "clk2x")):
        if key in name:
            return i
    return 9


if __name__ == "__main__":
    sys.exit(main())
