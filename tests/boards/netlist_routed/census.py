#!/usr/bin/env python3
"""What the placed-and-routed netlist of tests/boards/netlist_routed/tiny.v holds, against what the
test means it to exercise: every cell type, mode and parameter value of cosim/netlist/ecp5_routed
that the board's own routed netlist uses. A new yosys or nextpnr that stopped producing one of them
would make the RTL comparison prove less: then this fails, naming what is missing.

    census.py TINY_ROUTED.json      (nextpnr's --write, before routed_json.py)

Prints one line of counts; exits 1 naming the missing features.
"""
import json
import sys


def s(v):
    return v[:-1] if isinstance(v, str) and v.endswith(" ") else v


def unpermuted(init):
    """A DPRAM LUT's INITVAL read in address order (nextpnr's dram_to_comb permutation undone)."""
    out = 0
    for i in range(16):
        if (init >> i) & 1:
            out |= 1 << (((i & 1) << 3) | (i & 2) | (i & 4) | ((i >> 3) & 1))
    return out


def main():
    cells = json.load(open(sys.argv[1]))["modules"]["top"]["cells"].values()
    have = {}

    def mark(feature):
        have[feature] = have.get(feature, 0) + 1

    for c in cells:
        t, p, conn = c["type"], c["parameters"], c["connections"]
        mark(t)
        if t == "TRELLIS_COMB":
            mode = s(p.get("MODE", "LOGIC"))
            mark(f"COMB {mode}")
            k = c["attributes"].get("NEXTPNR_BEL", "")[-2:]
            if conn.get("OFX"):
                mark(f"COMB OFX on {k}")
            if mode == "CCU2" and not conn.get("FCI"):
                mark("COMB CCU2 with FCI unconnected")
            if mode == "CCU2" and conn.get("FCI") and conn.get("F"):
                mark("COMB CCU2 sum from carry")
            if mode == "DPRAM":
                init = int(p["INITVAL"], 2)
                if unpermuted(init) != init:
                    mark("COMB DPRAM INITVAL whose LUT order matters")
        elif t == "TRELLIS_FF":
            mark(f"FF SD {s(p['SD'])}")
            mark(f"FF CEMUX {s(p.get('CEMUX', '1'))}")
            mark(f"FF REGSET {s(p.get('REGSET', 'RESET'))}")
            mark("FF LSR " + ("connected" if conn.get("LSR") else "unconnected"))
        elif t == "TRELLIS_IO":
            mark(f"IO {s(p.get('DIR'))} {s(p.get('DATAMUX_ODDR', 'PADDO'))}")
        elif t == "SIOLOGIC":
            mark(f"SIOLOGIC {s(p.get('MODE'))}")
    want = ["TRELLIS_RAMW", "DCCA", "COMB LOGIC", "COMB CCU2", "COMB DPRAM", "COMB RAMW_BLOCK",
            "COMB OFX on K0", "COMB OFX on K1", "COMB CCU2 with FCI unconnected", "COMB CCU2 sum from carry",
            "COMB DPRAM INITVAL whose LUT order matters", "FF SD 0", "FF SD 1", "FF CEMUX CE",
            "FF CEMUX INV", "FF CEMUX 1", "FF REGSET SET", "FF REGSET RESET", "FF LSR connected",
            "FF LSR unconnected", "IO INPUT PADDO", "IO OUTPUT PADDO", "IO OUTPUT IOLDO",
            "SIOLOGIC IDDRX1_ODDRX1"]
    missing = [w for w in want if w not in have]
    print("census: " + ", ".join(f"{w} {have.get(w, 0)}" for w in want))
    if missing:
        print("census: the tiny design no longer exercises: " + ", ".join(missing), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
