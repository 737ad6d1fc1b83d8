#!/usr/bin/env python3
"""The cells of a netlist (yosys' or nextpnr's JSON) against the simulation models make netlist-sim
compiles: every cell type of the top module must be a module of one of the model files, or the
simulation would hold a black box (or Verilator would stop on an unknown module with less to say).

    netlist_cells.py NETLIST.json TOP MODEL.v...

Prints one line: the cell types and their counts; exits 1 naming each cell type without a model.
`include "x.vh" lines in a model file are followed (yosys' cells_sim.v includes its .vh files); a
module marked (* blackbox *) is no model (yosys' DP16KD is one); a cell type with two models is an
error too, since which one the simulator takes would be a guess.
"""
import json
import os
import re
import sys


def modules_of(path, seen, where):
    """The modules path defines (and the files it includes), each into where[name] (the files);
    a (* blackbox *) module is a declaration only, no model: left out."""
    if path in seen or not os.path.exists(path):
        return
    seen.add(path)
    with open(path) as f:
        text = f.read()
    for m in re.finditer(r"^(\(\*[^*]*\*\)\s*)*\s*module\s+\\?([A-Za-z_$][\w$]*)", text, re.M):
        if "blackbox" not in (m.group(0).split("module")[0]):
            where.setdefault(m.group(2), []).append(path)
    for inc in re.findall(r'^\s*`include\s+"([^"]+)"', text, re.M):
        modules_of(os.path.join(os.path.dirname(path), inc), seen, where)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    netlist, top, models = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(netlist) as f:
        design = json.load(f)
    if top not in design["modules"]:
        sys.exit(f"netlist_cells: {netlist} has no module {top}")
    counts = {}
    for cell in design["modules"][top]["cells"].values():
        if cell["type"] != "$scopeinfo":  # yosys' record of the flattened hierarchy: no logic
            counts[cell["type"]] = counts.get(cell["type"], 0) + 1
    where = {}
    seen = set()
    for m in models:
        modules_of(m, seen, where)
    missing = sorted(t for t in counts if t not in where)
    twice = sorted(t for t in counts if len(where.get(t, [])) > 1)
    print("cells: " + ", ".join(f"{n} {t}" for t, n in sorted(counts.items(), key=lambda kv: -kv[1])), flush=True)
    for t in missing:
        print(f"netlist-sim: no simulation model for cell {t} ({counts[t]} in {netlist}): "
              f"write one in cosim/netlist/ecp5/{t}.v from Lattice's documentation", file=sys.stderr)
    for t in twice:
        print(f"netlist-sim: cell {t} has two models: {', '.join(where[t])}", file=sys.stderr)
    return 1 if missing or twice else 0


if __name__ == "__main__":
    sys.exit(main())
