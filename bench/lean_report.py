#!/usr/bin/env python3
"""lean_report.py — `make lean-report`: per scene, the full build against the scene's manifest
build (firmware/scenes/<scene>.manifest.toml, mk/manifest.mk), as one Markdown table.

usage: lean_report.py --build BUILD [--make make] [--jobs N] [--frames N] [--no-synth] SCENE...

Per scene and build (full: `FULL=1`; lean: the manifest's):
  RAM, LUT4 FF EBR MULT18   the ULX3S build's ECP5 synthesis (`make synth-board BOARD=ulx3s`,
                            synth/ecp5_bitstream.py's resources.json), JOBS at a time (default 2)
  text data bss             riscv64-unknown-elf-size of that build's firmware (FRAMES 0, the board's)
  instr, CPU cyc, GPU cyc   per frame on socsim, the whole SoC (`make soc-fw` of FRAMES frames,
                            default 4), averaged over the frames after the first as bench-soc does
                            (bench/bench_soc.py): the firmware's "fw instr", "cpu cycles", "gpu cycles"
  frames identical          the lean build's socsim frames against the full build's, byte for byte
                            (each run is also checked against the golden model, which socsim
                            builds with its GPU's own parameters, capacities included)
A lean build's RAM is the one its manifest build derives from the linked image (the board
firmware's <elf>.ramkib, bsp/soc/postlink.py); the full build's is the contract's default.
Caching: a synthesis whose resources.json is newer than its firmware image and every RTL file is
not run again. The full builds of all scenes have one RTL configuration (the contract's GPU,
192 KiB): only the RAM's contents differ, so the first scene's full synthesis stands for all of
them (--full-synth-each synthesizes each). Logs and frames: BUILD/lean-report/.
"""
import argparse
import glob
import hashlib
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_soc import FW_LINE  # noqa: E402  (the firmware's frame line, parsed as bench-soc does)

RTL_GLOBS = ["gpu_rtl/*.v", "gpu_rtl/*.sv", "soc_rtl/*.v", "soc_rtl/*.sv", "boards/ulx3s/*.v", "boards/common/*.v"]


def make(args, targets, variables, log, quiet=False):
    cmd = [args.make, "--no-print-directory"] + (["-s"] if quiet else []) + targets + \
          [f"{k}={v}" for k, v in variables.items()]
    if quiet:
        return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    with open(log, "w") as out:
        if subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT) != 0:
            sys.exit(f"lean_report: {' '.join(cmd)} failed (see {log})")
    return ""


def show(args, variables):
    out = make(args, ["manifest-show"], variables, None, quiet=True)
    return dict(line.split("=", 1) for line in out.splitlines() if "=" in line and not line.startswith("scene="))


def run_socsim(socsim, elf, out_dir):
    """{frame: [instr, gpu cycles, cpu cycles]} of the firmware's frame lines; frames in out_dir/frames."""
    os.makedirs(os.path.join(out_dir, "frames"), exist_ok=True)
    p = subprocess.run([socsim, "--fw", elf, "--frames", os.path.join(out_dir, "frames"),
                        "--uart-log", os.path.join(out_dir, "uart.log")],
                       capture_output=True, text=True)
    with open(os.path.join(out_dir, "socsim.out"), "w") as f:
        f.write(p.stdout + p.stderr)
    if p.returncode != 0:
        sys.exit(f"lean_report: {elf}: socsim exited with {p.returncode} (see {out_dir}/socsim.out)")
    fw = {}
    for line in p.stdout.splitlines():
        m = FW_LINE.match(line)
        if m:
            fw[int(m[1])] = [int(v) for v in m.groups()[1:]]
    return fw


def fw_size(elf):
    out = subprocess.run(["riscv64-unknown-elf-size", elf], check=True, capture_output=True, text=True).stdout
    text, data, bss = out.splitlines()[1].split()[:3]
    return int(text), int(data), int(bss)


def synth_fresh(res_path, hex_path):
    if not os.path.exists(res_path):
        return False
    newest = max([os.path.getmtime(hex_path)] + [os.path.getmtime(f) for g in RTL_GLOBS for f in glob.glob(g)])
    return os.path.getmtime(res_path) > newest


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--build", default="build")
    ap.add_argument("--make", default="make")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--frames", type=int, default=4)
    ap.add_argument("--no-synth", action="store_true", help="leave the synthesis columns out")
    ap.add_argument("--full-synth-each", action="store_true", help="a full synthesis per scene")
    args = ap.parse_args()
    logdir = os.path.join(args.build, "lean-report")
    os.makedirs(logdir, exist_ok=True)

    builds = []  # (scene, kind, variables)
    # The on-chip build (SOC_MEM=ram, not the board's default, boards/ulx3s/defaults.mk): the firmware
    # in the RAM, which the lean build sizes to the scene.
    for s in args.scenes:
        builds.append((s, "full", {"SCENE": s, "FULL": 1, "SOC_MEM": "ram", "BUILD": args.build}))
        builds.append((s, "lean", {"SCENE": s, "SOC_MEM": "ram", "BUILD": args.build}))

    # Firmware and simulators first, one make at a time (the builds share objects).
    info = {}
    for s, kind, v in builds:
        name = f"{s}-{kind}"
        if kind == "lean":
            # The manifest build's RAM is what its board firmware needs (SOC_RAM_KIB=auto,
            # bsp/soc/soc_ram.mk): that firmware first, then every step with its size, the firmware
            # keeping the fit check it was linked with (so it is not linked again).
            auto = show(args, dict(v, BOARD="ulx3s"))
            make(args, ["board-fw"], dict(v, BOARD="ulx3s"), os.path.join(logdir, f"boardfw-{name}.log"))
            with open(auto["ULX3S_FW_ELF"] + ".ramkib") as f:
                v.update(SOC_RAM_KIB=int(f.read()), SOC_FW_RAM_BYTES=auto["SOC_FW_RAM_BYTES"])
        info[name] = show(args, dict(v, BOARD="ulx3s"))
        print(f"lean_report: {name}: firmware and socsim ...", flush=True)
        make(args, ["board-fw", "socsim"], dict(v, BOARD="ulx3s"), os.path.join(logdir, f"fw-{name}.log"))
        make(args, ["soc-fw"], dict(v, FRAMES=args.frames), os.path.join(logdir, f"socfw-{name}.log"))
        run_elf = show(args, dict(v, FRAMES=args.frames))["SOC_FW_ELF"]
        info[name]["RUN_ELF"] = os.path.join(logdir, f"{name}.elf")
        # soc-fw's path is per scene, not per FRAMES: a copy (socsim loads the ELF's .hex beside it).
        subprocess.run(["cp", run_elf, info[name]["RUN_ELF"]], check=True)
        subprocess.run(["cp", run_elf + ".hex", info[name]["RUN_ELF"] + ".hex"], check=True)

    def synth(build):
        s, kind, v = build
        name = f"{s}-{kind}"
        if kind == "full" and not args.full_synth_each and s != args.scenes[0]:
            return name, None  # the first scene's full synthesis stands for every full build
        d = info[name]
        res = os.path.join(d["ULX3S_DIR"], "resources.json")
        if synth_fresh(res, d["ULX3S_FW_ELF"] + ".hex"):
            print(f"lean_report: {name}: synthesis cached ({res})", flush=True)
        else:
            print(f"lean_report: {name}: synthesis ...", flush=True)
            make(args, ["synth-board"], dict(v, BOARD="ulx3s"), os.path.join(logdir, f"synth-{name}.log"))
        with open(res) as f:
            return name, json.load(f)

    synth_res = {}
    pool = ThreadPoolExecutor(max_workers=max(1, args.jobs))
    pending = [] if args.no_synth else [pool.submit(synth, b) for b in builds]

    # Meanwhile: each build on socsim.
    perf, frames = {}, {}
    for s, kind, v in builds:
        name = f"{s}-{kind}"
        out = os.path.join(logdir, name)
        # Cached while the program (its bytes) and the simulator are the same.
        key = {"elf": hashlib.sha256(open(info[name]["RUN_ELF"] + ".hex", "rb").read()).hexdigest(),
               "socsim": os.path.getmtime(info[name]["SOCSIM"])}
        cache = os.path.join(out, "perf.json")
        fw = None
        if os.path.exists(cache):
            with open(cache) as f:
                c = json.load(f)
            if c["key"] == key:
                fw = {int(k): v for k, v in c["fw"].items()}
                print(f"lean_report: {name}: socsim cached ({cache})", flush=True)
        if fw is None:
            subprocess.run(["rm", "-rf", out], check=True)
            print(f"lean_report: {name}: socsim, {args.frames} frames ...", flush=True)
            fw = run_socsim(info[name]["SOCSIM"], info[name]["RUN_ELF"], out)
            with open(cache, "w") as f:
                json.dump({"key": key, "fw": fw}, f)
        later = [fw[k] for k in sorted(fw) if k >= 1]
        perf[name] = [sum(x[i] for x in later) / len(later) for i in range(3)]  # instr, gpu cycles, cpu cycles
        frames[name] = sorted(glob.glob(os.path.join(out, "frames", "*.png")))
    for p in pending:
        name, res = p.result()
        synth_res[name] = res
    pool.shutdown()

    def identical(s):
        a, b = frames[f"{s}-full"], frames[f"{s}-lean"]
        if not a or len(a) != len(b):
            return "no"
        return "yes" if all(open(x, "rb").read() == open(y, "rb").read() for x, y in zip(a, b)) else "no"

    print()
    print("| scene | build | RAM KiB | LUT4 | FF | EBR | MULT18 | text | data | bss | instr/frame | CPU cycles/frame "
          "| GPU cycles/frame | frames identical |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    first_full = f"{args.scenes[0]}-full"
    for s, kind, v in builds:
        name = f"{s}-{kind}"
        res = synth_res.get(name) or (synth_res.get(first_full) if kind == "full" else None)
        cells = [res["cells"][k] for k in ("LUT4", "TRELLIS_FF", "DP16KD", "MULT18X18D")] if res else ["—"] * 4
        text, data, bss = fw_size(info[name]["ULX3S_FW_ELF"])
        instr, gpu, cpu = perf[name]
        same = identical(s) if kind == "lean" else "—"
        print(f"| {s} | {kind} | {info[name]['SOC_RAM_KIB']} | " + " | ".join(str(c) for c in cells) +
              f" | {text} | {data} | {bss} | {instr:,.0f} | {cpu:,.0f} | {gpu:,.0f} | {same} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
