#!/usr/bin/env python3
"""nextpnr-ecp5's placed-and-routed JSON (its --write) made simulable: the input pins that nextpnr left
unconnected get the constant that the fabric gives them, and each TRELLIS_COMB learns which LUT of its
slice it is. In Verilog an unconnected input reads z (0 in Verilator); in the ECP5 it reads what
nextpnr configured, and nextpnr's packer disconnects constant inputs relying on that.

    routed_json.py IN.json OUT.json

Writes OUT.json (IN rewritten; a connection bit may be the string "0" or "1", as yosys' JSON allows),
prints what it tied, and exits 1 (writing nothing) on a cell that the simulation models
(cosim/netlist/ecp5_routed) could not simulate faithfully. The rules, each from nextpnr-ecp5's source
(ecp5/pack.cc, ecp5/bitstream.cc, ecp5/globals.cc; nextpnr 0.11):

  TRELLIS_COMB  A, B, C, D -> 1. bitstream.cc write_comb sets the mux of every LUT input with no
                routed net to "1"; pack.cc set_net_constant disconnects CCU2 inputs tied high
                (is_ccu2c_port_high: "disconnected port is high"), and the carry feed-in it makes
                (make_carry_feed_in, LUT4 = 0 from INIT 0x000A) needs B, C, D at 1. A LOGIC LUT's
                INIT no longer depends on an input its packer disconnected (set_lut_input_constant).
                Also writes IS_Z1 (0 or 1) from the placement, NEXTPNR_BEL ending ".K0" or ".K1": the
                slice's K0 LUT has the PFUMX (OFX = M ? F1 : F), its K1 LUT the L6MUX21
                (OFX = M ? FXB : FXA); TRELLIS_COMB.v refuses a cell without it.
  TRELLIS_FF    LSR -> its inactive level: 0 with LSRMUX "LSR", 1 with "INV". pack.cc
                set_net_constant disconnects an LSR tied to that level (an LSR tied active would stay
                connected), so an unconnected LSR means no reset.
  TRELLIS_IO    T -> 0 on an OUTPUT or BIDIR pad: bitstream.cc write_io ties an unconnected T (with
                no IOLTO) low, the output enabled.
  DCCA          CE -> 1: bitstream.cc write_dcc configures gating only when CE has a net (and
                globals.cc inserts its DCCAs without one): the clock passes.
  DP16KD        the CIB clock/LSR/CE pins CLKA/B, WEA/B, RSTA/B, CEA/B, OCEA/B, CSA0-2, CSB0-2
                -> 1: bitstream.cc write_bram ties them high (tie_cib_signal(..., true)); their
                *MUX parameter then passes (the port's name) or inverts ("INV") that 1. When the
                parameter is absent it adds it as write_bram does: "INV" for CLK, WE, RST and CS
                (emulating 0), the port's name for CE and OCE (1). (pack.cc set_net_constant turns a
                constant on these pins into the port's name for 1, "INV" for 0, and disconnects it.)
                The CIB A-D pins (DIA*, DIB*, ADA*, ADB*) -> their *MUX parameter: "1" gives 1, "0"
                or none gives 0 (write_bram: "Tie signals low unless explicit MUX param specified";
                set_net_constant writes "1"/"0" for a constant). In pseudo-dual-port mode
                (DATA_WIDTH_A 36) nextpnr ties neither WEA, WEB nor ADA4 (the PDPW16KD has no use for
                them): tied here by the same rules all the same, and a *MUX is not added for WEA/WEB.
  MULT18X18D    every input but CLK*, CE*, RST*, SRO*, SRI*, RO*, MA*, MB*, CFB*, CIN*, SOURCE*,
                SIGNED*, OP* -> its *MUX parameter, "1" 1 else 0 (bitstream.cc tieoff_dsp_ports, as
                for DP16KD's A-D pins). The pins it skips are left alone (unused by the
                unregistered multiplier that cosim/netlist/ecp5/MULT18X18D.v models).

Refused (exit 1), as the models would be wrong there: a CCU2 TRELLIS_COMB with an unconnected FCI
that its used outputs depend on; an OFX with no M, or on a LUT that is not LOGIC; a DPRAM LUT with
an unconnected write pin; a RAMW_BLOCK with a net; a TRELLIS_FF with CEMUX "CE"/"INV" but no CE, or
with no net on the data input that SD selects; a TRELLIS_RAMW with an unconnected input; a SIOLOGIC
with a net on anything but CLK, LSR, TXDATA0, TXDATA1, IOLDO (the ODDRX1F that SIOLOGIC.v models);
a *MUX that names no constant where a constant is needed.
"""
import json
import re
import sys
from collections import Counter

DP16KD_CIB_CTRL = re.compile(r"^(CLK[AB]|WE[AB]|RST[AB]|CE[AB]|OCE[AB]|CS[AB][0-2])$")
DSP_SKIPPED = ("CLK", "CE", "RST", "SRO", "SRI", "RO", "MA", "MB", "CFB", "CIN", "SOURCE", "SIGNED", "OP")


def sval(v):
    """A string parameter as nextpnr wrote it: yosys' JSON marks a string that looks like bits with a
    trailing space ("0 ")."""
    return v[:-1] if isinstance(v, str) and v.endswith(" ") else v


def bit_const(value, what):
    """A *MUX constant for an A-D pin: "1" gives 1, "0" or none 0 (nextpnr's bool_or_default)."""
    if value is None:
        return "0"
    v = sval(value)
    if isinstance(v, str) and re.fullmatch(r"0*[01]", v):   # "0"/"1", or a bit vector written as bits
        return v[-1]
    raise ValueError(f"{what} is {value!r}: no constant for its unconnected pin")


def lut_depends_on_fci(init, conn):
    """A CCU2 half's outputs as functions of FCI (the LUT inputs with no net read 1): (F depends,
    FCO depends). F = L4 ^ FCI unless injected; FCO = ~L4 & g | L4 & FCI depends iff L4 can be 1."""
    free = [i for i, p in enumerate("ABCD") if conn.get(p)]
    l4_can_be_1 = False
    for k in range(1 << len(free)):
        idx = 0
        for i in range(4):
            bit = ((k >> free.index(i)) & 1) if i in free else 1
            idx |= bit << i
        l4_can_be_1 |= bool((init >> idx) & 1)
    return l4_can_be_1


def param_int(v):
    if isinstance(v, int):
        return v
    return int(sval(v), 2)


def process(design):
    ties = Counter()        # (cell type, pin, value) -> count
    added = Counter()       # (cell type, parameter, value) -> count
    errors = []

    def tie(cell, pin, value):
        cell["connections"][pin] = [value]
        ties[(cell["type"], pin, value)] += 1

    for mod in design["modules"].values():
        for name, cell in mod.get("cells", {}).items():
            t, conn, params = cell["type"], cell["connections"], cell["parameters"]
            dirs = cell.get("port_directions", {})

            def unconnected_inputs():
                return [p for p, d in dirs.items() if d == "input" and not conn.get(p)]

            def err(msg):
                errors.append(f"{t} {name}: {msg}")

            try:
                if t == "TRELLIS_COMB":
                    mode = sval(params.get("MODE", "LOGIC"))
                    bel = cell.get("attributes", {}).get("NEXTPNR_BEL", "")
                    m = re.search(r"\.K([01])$", bel)
                    if not m:
                        err(f"not placed on a LUT (NEXTPNR_BEL {bel!r})")
                        continue
                    z1 = int(m.group(1))
                    params["IS_Z1"] = format(z1, "032b")
                    if mode == "RAMW_BLOCK":
                        if any(conn.values()):
                            err("a RAMW_BLOCK placeholder with a net")
                        continue
                    if conn.get("OFX"):
                        if mode != "LOGIC":
                            err(f"OFX used in MODE {mode}")
                        if not conn.get("M"):
                            err("OFX used but M unconnected")
                    wrong = [p for p in (("F1",) if z1 else ("FXA", "FXB")) if conn.get(p)]
                    if wrong:
                        err(f"{', '.join(wrong)} used on a K{z1} LUT, which has no such mux input")
                    if mode == "CCU2" and not conn.get("FCI"):
                        init = param_int(params.get("INITVAL", "0"))
                        injected = sval(params.get("CCU2_INJECT1", "YES")) == "YES"
                        if (conn.get("F") and not injected) or \
                                (conn.get("FCO") and lut_depends_on_fci(init, conn)):
                            err("CCU2 with an unconnected FCI that a used output depends on")
                    if mode == "DPRAM":
                        missing = [p for p in ("WD", "WAD0", "WAD1", "WAD2", "WAD3", "WRE", "WCK")
                                   if not conn.get(p)]
                        if missing:
                            err(f"DPRAM with unconnected {', '.join(missing)}")
                    for p in "ABCD":
                        if not conn.get(p):
                            tie(cell, p, "1")

                elif t == "TRELLIS_FF":
                    sd = sval(params.get("SD", "0"))
                    data = "DI" if sd == "1" else "M"
                    if not conn.get(data):
                        err(f"SD {sd} but {data} unconnected")
                    if sval(params.get("CEMUX", "1")) in ("CE", "INV") and not conn.get("CE"):
                        err(f"CEMUX {sval(params.get('CEMUX'))} but CE unconnected")
                    if not conn.get("LSR"):
                        lsrmux = sval(params.get("LSRMUX", "LSR"))
                        if lsrmux not in ("LSR", "INV"):
                            raise ValueError(f"LSRMUX {lsrmux!r}")
                        tie(cell, "LSR", "0" if lsrmux == "LSR" else "1")

                elif t == "TRELLIS_IO":
                    if sval(params.get("DIR", "INPUT")) in ("OUTPUT", "BIDIR") and not conn.get("T") \
                            and not conn.get("IOLTO"):
                        tie(cell, "T", "0")

                elif t == "DCCA":
                    if not conn.get("CE"):
                        tie(cell, "CE", "1")

                elif t == "TRELLIS_RAMW":
                    if unconnected_inputs():
                        err(f"unconnected {', '.join(sorted(unconnected_inputs()))} (nextpnr ties none)")

                elif t == "SIOLOGIC":
                    extra = sorted(p for p, b in conn.items()
                                   if b and p not in ("CLK", "LSR", "TXDATA0", "TXDATA1", "IOLDO"))
                    if extra:
                        err(f"nets on {', '.join(extra)}: only the ODDRX1F (output) half is modelled")

                elif t == "DP16KD":
                    pdp = param_int(params.get("DATA_WIDTH_A", format(18, "032b"))) == 36
                    for p in sorted(unconnected_inputs()):
                        mux = p + "MUX"
                        if DP16KD_CIB_CTRL.match(p):
                            if mux not in params and not (pdp and p in ("WEA", "WEB")):
                                value = p if re.match(r"O?CE", p) else "INV"
                                params[mux] = value
                                added[(t, mux, value)] += 1
                            tie(cell, p, "1")
                        else:
                            tie(cell, p, bit_const(params.get(mux), f"{mux}"))

                elif t == "MULT18X18D":
                    for p in sorted(unconnected_inputs()):
                        if not p.startswith(DSP_SKIPPED):
                            tie(cell, p, bit_const(params.get(p + "MUX"), p + "MUX"))

            except ValueError as e:
                err(str(e))
    return ties, added, errors


def summary(ties, added):
    """One line per cell type: each pin group (digits folded: DIA0..17 -> DIA*) and value, counted."""
    lines = []
    for t in sorted({k[0] for k in ties} | {k[0] for k in added}):
        groups = Counter()
        for (tt, pin, value), n in ties.items():
            if tt == t:
                groups[(re.sub(r"\d+$", "*", pin), value)] += n
        parts = [f"{pin}={value} x{n}" for (pin, value), n in sorted(groups.items())]
        parts += [f"added {p}={v} x{n}" for (tt, p, v), n in sorted(added.items()) if tt == t]
        lines.append(f"routed_json: {t}: " + ", ".join(parts))
    return lines


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, dst = sys.argv[1], sys.argv[2]
    with open(src) as f:
        design = json.load(f)
    ties, added, errors = process(design)
    if errors:
        for e in errors[:20]:
            print(f"routed_json: {e}", file=sys.stderr)
        if len(errors) > 20:
            print(f"routed_json: ... {len(errors) - 20} more", file=sys.stderr)
        print(f"routed_json: {src}: {len(errors)} cells the routed models cannot simulate; nothing written",
              file=sys.stderr)
        return 1
    with open(dst, "w") as f:
        json.dump(design, f)
    for line in summary(ties, added):
        print(line)
    print(f"routed_json: {sum(ties.values())} unconnected inputs tied; written {dst}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
