#!/usr/bin/env python3
"""The clock-domain crossings of a synthesized ECP5 netlist, each checked against a file of declared
crossings: a table of them, status 1 for an undeclared one.

    crossings.py NETLIST.json --declared CROSSINGS.toml [--top T] [--report OUT.md]

NETLIST.json is yosys' `synth_ecp5 -json` output (cells LUT4, TRELLIS_FF, CCU2C, PFUMX, L6MUX21,
DP16KD, TRELLIS_DPR16X4, MULT18X18D, ODDRX1F, EHXPLLL). Every clocked element gets the domain of its
clock, traced back through buffers and inverters to a source named in the file's [clocks] table (a
PLL output, or a top-level input); top-level inputs and the PLL's LOCK are the domain `async`. Then
the combinational fan-in of every clocked input (a flop's DI, CE and LSR; a block RAM port's address,
data, enables and reset; a LUT RAM's write side; a DDR output's data) is traced back through LUT4,
CCU2C, PFUMX, L6MUX21, MULT18X18D and a LUT RAM's asynchronous read, to the elements that launch it.
A path whose source domain is not its destination's is a crossing. A memory is one in its own right
where a port of one domain reads what a port of another wrote (block RAM); a LUT RAM's contents are a
source of its write clock's domain, so reading them on another clock is a crossing at the flop that
captures the read.

Crossings are grouped by (source domain, destination domain, destination) — the destination named by
the netlist's hierarchical net names (a flop by its output net, a memory by its cell name less the
indices yosys adds) — and each group must match an entry of the file (see boards/ulx3s/crossings.toml
for its format): the table says which kind of crossing it is and how many paths it has. It is
printed with the errors; --report writes it with each entry's reason as Markdown. Status 1
names every undeclared group, every entry that matched nothing (so the file cannot rot), and every
synchroniser entry whose structure is wrong (logic on its first flop's output, more sources than it
allows, a source it does not name). Status 2: the netlist or the file cannot be read.
"""
import argparse
import collections
import json
import re
import sys
import tomllib

# What an entry's kind may be, and what each means (the report's legend).
KINDS = {
    "sync2": "the first flop of a two-flop synchroniser (gpu_cdc_sync or the same structure)",
    "pulse": "a pulse synchroniser (gpu_cdc_pulse: a toggle through a two-flop synchroniser)",
    "reset": "a reset synchroniser (a reset level through two flops, released synchronously)",
    "dual-clock-ram": "a memory written on one clock, read on another: a protocol keeps them apart",
    "related-clock": "clocks of one PLL in a fixed ratio and phase: sampled when the data is stable",
    "accepted": "no synchroniser: the worst case is stated and accepted",
}
# Kinds whose destination is the first flop of a synchroniser: checked for structure.
SYNC_KINDS = ("sync2", "pulse", "reset")

# Combinational cells: for each output, the inputs it depends on (None: every input).
COMB_OUT_DEPS = {
    "PFUMX": {"Z": ("ALUT", "BLUT", "C0")},
    "L6MUX21": {"Z": ("D0", "D1", "SD")},
    "CCU2C": {"S0": ("A0", "B0", "C0", "D0", "CIN"),
              "S1": ("A0", "B0", "C0", "D0", "A1", "B1", "C1", "D1", "CIN"),
              "COUT": ("A0", "B0", "C0", "D0", "A1", "B1", "C1", "D1", "CIN")},
    "MULT18X18D": None,
}
IGNORED = ("$scopeinfo",)
CONSTANT_BITS = ("0", "1", "x", "z")


class NetlistError(Exception):
    pass


def param_int(value):
    """A yosys JSON parameter as an integer (a binary string, or an int)."""
    if isinstance(value, int):
        return value
    return int(value.strip(), 2)


def param_str(value):
    # yosys marks a string parameter that looks like bits with a trailing space ("1 ").
    return value.strip() if isinstance(value, str) else str(value)


def lut_inputs(cell):
    """The LUT4 inputs its INIT depends on (an x in INIT: all of them)."""
    init = param_str(cell["parameters"].get("INIT", "x"))
    try:
        val = param_int(init) if not init.lower().startswith("0x") else int(init, 16)
    except ValueError:
        return ("A", "B", "C", "D")
    live = []
    for k, pin in enumerate("ABCD"):
        if any(((val >> i) & 1) != ((val >> (i ^ (1 << k))) & 1) for i in range(16)):
            live.append(pin)
    return tuple(live)


def glob_re(pattern):
    """A destination pattern: `re:REGEX` (searched), or a glob whose only wildcards are * and ?
    (brackets are literal: net names have them), matched against the whole name."""
    if pattern.startswith("re:"):
        return re.compile(pattern[3:])
    out = "".join(".*" if c == "*" else "." if c == "?" else re.escape(c) for c in pattern)
    return re.compile(out + r"\Z")


def pattern_matches(rx, pattern, names):
    if pattern.startswith("re:"):
        return any(rx.search(n) for n in names)
    return any(rx.match(n) for n in names)


class Netlist:
    """The top module of a yosys JSON netlist: drivers, loads and names of its bits."""

    def __init__(self, path, top=None):
        try:
            with open(path) as f:
                data = json.load(f)
        except (OSError, ValueError) as e:
            raise NetlistError(f"{path}: {e}")
        mods = data.get("modules", {})
        if top is None:
            tops = [n for n, m in mods.items() if param_int(m.get("attributes", {}).get("top", "0")) == 1]
            if len(tops) != 1:
                raise NetlistError(f"{path}: no single top module ({', '.join(tops) or 'none'}): give --top")
            top = tops[0]
        if top not in mods:
            raise NetlistError(f"{path}: no module {top}")
        self.path = path
        self.top = top
        mod = mods[top]
        self.cells = {n: c for n, c in mod["cells"].items() if c["type"] not in IGNORED}
        self.ports = mod.get("ports", {})
        self.driver = {}   # bit -> (cell name or None for a top port, pin or port name)
        self.loads = collections.defaultdict(list)  # bit -> [(cell name or None, pin)]
        for name, p in self.ports.items():
            for b in p["bits"]:
                if b in CONSTANT_BITS:
                    continue
                if p["direction"] != "output":
                    self.driver[b] = (None, name)  # an input (or inout): the async domain
                if p["direction"] != "input":
                    self.loads[b].append((None, name))
        for name, c in self.cells.items():
            dirs = c.get("port_directions", {})
            for pin, bits in c["connections"].items():
                for b in bits:
                    if b in CONSTANT_BITS:
                        continue
                    if dirs.get(pin) == "output":
                        self.driver[b] = (name, pin)
                    else:
                        self.loads[b].append((name, pin))
        # Names: every netname of a bit, as NAME[i] for a vector, NAME for a single bit.
        self.names = collections.defaultdict(list)  # bit -> [(label, base, netname attrs)]
        for nname, n in mod.get("netnames", {}).items():
            if n.get("hide_name", 0):
                continue
            bits = n["bits"]
            offset = n.get("offset", 0)
            upto = n.get("upto", 0)
            for i, b in enumerate(bits):
                if b in CONSTANT_BITS:
                    continue
                if len(bits) == 1:
                    label = nname
                else:
                    idx = offset + (len(bits) - 1 - i if upto else i)
                    label = f"{nname}[{idx}]"
                self.names[b].append((label, nname, n.get("attributes", {})))

    @staticmethod
    def src_of(attrs):
        """(file, line) of a src attribute's first location."""
        src = attrs.get("src", "")
        m = re.match(r"([^:|]+):(\d+)", src)
        return (m.group(1), int(m.group(2))) if m else (None, 0)

    def bit_name(self, b, cell=None):
        """(label, base) naming bit b: a name the source code declares (hdlname), preferably in the
        file of the cell that drives it, the nearest declaration above that cell's code."""
        cands = self.names.get(b)
        if not cands:
            return (f"${b}", f"${b}")
        cfile, cline = self.src_of(self.cells[cell].get("attributes", {})) if cell else (None, 0)

        def rank(c):
            label, base, attrs = c
            nfile, nline = self.src_of(attrs)
            same = cfile is not None and nfile == cfile
            above = same and nline <= cline
            return ("hdlname" not in attrs, not same, not above, -nline if above else 0,
                    base.count("."), len(label), label)
        label, base, _ = min(cands, key=rank)
        return (label, base)

    def aliases(self, b):
        """Every name of bit b: NAME[i] and NAME of each net it is in."""
        return sorted({x for label, base, _ in self.names.get(b, []) for x in (label, base)})


def memory_base(cell_name):
    """A block or LUT RAM's name without the .i.j indices yosys gives the pieces of one memory."""
    return re.sub(r"(\.\d+)+$", "", cell_name)


class Analysis:
    def __init__(self, nl, clocks):
        self.nl = nl
        self.clocks = clocks      # {"CELL_TYPE_OR_NAME:PIN" or "port:NAME": domain}
        self.clock_domain_memo = {}
        self.dest = []            # (cell, pin, bit, domain)
        self.source_dom = {}      # (cell, pin) of a clocked output -> domain
        self.mem_writes = collections.defaultdict(set)  # block RAM cell -> write domains
        self.mem_reads = collections.defaultdict(set)   # block RAM cell -> read domains
        self.dpr_dom = {}         # LUT RAM cell -> its write clock's domain
        self._classify()

    # ---- clocks ----
    def clock_domain(self, b, seen=()):
        if b in CONSTANT_BITS:
            return None
        if b in self.clock_domain_memo:
            return self.clock_domain_memo[b]
        drv = self.nl.driver.get(b)
        dom = None
        if drv is None:
            dom = None
        elif drv[0] is None:
            dom = self.clocks.get(f"port:{drv[1]}")
            if dom is None:
                raise NetlistError(f"a clock comes from the top-level input {drv[1]}, which [clocks] does not name")
        else:
            cell = self.nl.cells[drv[0]]
            for key in (f"{drv[0]}:{drv[1]}", f"{cell['type']}:{drv[1]}"):
                if key in self.clocks:
                    dom = self.clocks[key]
                    break
            else:
                if cell["type"] == "LUT4" and len(lut_inputs(cell)) == 1 and b not in seen:
                    inp = cell["connections"][lut_inputs(cell)[0]][0]
                    dom = self.clock_domain(inp, seen + (b,))
                else:
                    raise NetlistError(f"a clock comes from {cell['type']} {drv[0]} pin {drv[1]}, which is neither "
                                       f"a buffer nor named in [clocks] (net {self.nl.bit_name(b)[0]})")
        self.clock_domain_memo[b] = dom
        return dom

    def clk(self, cell, pin):
        bits = cell["connections"].get(pin, ["0"])
        return self.clock_domain(bits[0])

    # ---- clocked elements: their inputs (destinations) and outputs (sources) ----
    def _classify(self):
        nl = self.nl
        for name, c in nl.cells.items():
            t = c["type"]
            conn = c["connections"]
            if t == "TRELLIS_FF":
                d = self.clk(c, "CLK")
                if d is None:
                    continue  # constant clock: never clocked
                for pin in ("DI", "CE", "LSR"):
                    for b in conn.get(pin, []):
                        self.dest.append((name, pin, b, d))
                self.source_dom[(name, "Q")] = d
            elif t == "ODDRX1F":
                d = self.clk(c, "SCLK")
                for pin in ("D0", "D1", "RST"):
                    for b in conn.get(pin, []):
                        self.dest.append((name, pin, b, d))
                self.source_dom[(name, "Q")] = d
            elif t == "TRELLIS_DPR16X4":
                d = self.clk(c, "WCK")
                for pin in ("DI", "WAD", "WRE"):
                    for b in conn.get(pin, []):
                        self.dest.append((name, pin, b, d))
                self.dpr_dom[name] = d
            elif t == "DP16KD":
                self._classify_dp16kd(name, c)
            elif t == "EHXPLLL":
                for pin, dirn in c["port_directions"].items():
                    if dirn == "output":
                        self.source_dom[(name, pin)] = "async"
            elif t == "MULT18X18D":
                regs = [k for k, v in c["parameters"].items() if k.startswith("REG_") and param_str(v) != "NONE"]
                if regs:
                    raise NetlistError(f"MULT18X18D {name}: registered ({', '.join(regs)}): not modelled here")
            elif t not in ("LUT4",) and t not in COMB_OUT_DEPS:
                raise NetlistError(f"cell {name}: type {t} is not known to this checker")

    def _classify_dp16kd(self, name, c):
        p = c["parameters"]
        conn = c["connections"]
        pdp = param_int(p.get("DATA_WIDTH_A", 18)) == 36  # pseudo dual port: A writes 36 bits, B reads
        side = {}
        for pin in conn:
            m = re.match(r"(CLK|CE|OCE|RST|WE|CS|AD|DI|DO)([AB])(\d*)$", pin)
            if not m:
                continue
            what, port = m.group(1), m.group(2)
            if pdp and what == "DI":
                port = "A"
            if pdp and what == "DO":
                port = "B"
            side[pin] = (what, port)
        for port in "AB":
            d = self.clk(c, "CLK" + port)
            we = conn.get("WE" + port, ["0"])[0]
            writes = (pdp and port == "A") or (not pdp and we != "0")
            dos = [(pin, b) for pin, (what, q) in side.items() if what == "DO" and q == port for b in conn[pin]]
            reads = any(self.nl.loads.get(b) for _, b in dos if b not in CONSTANT_BITS)
            if d is None:
                if reads or writes:
                    raise NetlistError(f"DP16KD {name}: port {port} is used but its clock is constant")
                continue
            if writes:
                self.mem_writes[name].add(d)
            if reads:
                self.mem_reads[name].add(d)
            for pin, (what, q) in side.items():
                if q != port:
                    continue
                if what == "DO":
                    self.source_dom[(name, pin)] = d
                elif what != "CLK":
                    for b in conn[pin]:
                        self.dest.append((name, pin, b, d))

    # ---- combinational fan-in ----
    def fanin(self, b):
        """(inputs, own): the bits a combinational driver of b reads, and the source b is when it is
        launched by a clocked element ((domain, source label) or None)."""
        drv = self.nl.driver.get(b)
        if drv is None:
            return [], None
        cname, pin = drv
        if cname is None:
            if f"port:{pin}" in self.clocks:
                return [], (self.clocks[f"port:{pin}"], f"port {pin} (a clock)")
            return [], ("async", f"port {pin}")
        c = self.nl.cells[cname]
        t = c["type"]
        if (cname, pin) in self.source_dom:
            dom = self.source_dom[(cname, pin)]
            if t == "TRELLIS_FF" or t == "ODDRX1F":
                label = self.nl.bit_name(b, cname)[0]
            elif t == "DP16KD":
                label = f"{memory_base(cname)} (block RAM read)"
            else:
                label = f"{cname}.{pin}"
            return [], (dom, label)
        conn = c["connections"]
        if t == "LUT4":
            pins = lut_inputs(c)
        elif t == "TRELLIS_DPR16X4":
            # The asynchronous read: the address, and the contents (the write clock's domain).
            return ([x for x in conn["RAD"]],
                    (self.dpr_dom[cname], f"{memory_base(cname)} (LUT RAM contents)"))
        elif t in COMB_OUT_DEPS:
            deps = COMB_OUT_DEPS[t]
            if deps is None:
                pins = [q for q, dirn in c["port_directions"].items() if dirn == "input"]
            else:
                pins = deps.get(pin)
                if pins is None:
                    raise NetlistError(f"{t} {cname}: output {pin} not modelled")
        else:
            raise NetlistError(f"{t} {cname} pin {pin}: not a combinational output this checker knows")
        return [x for q in pins for x in conn.get(q, [])], None

    def domains(self, root):
        """The source domains of bit root (memoised, iterative: carry chains are deep)."""
        memo = self._dom_memo
        if root in memo:
            return memo[root]
        stack = [(root, False)]
        onstack = set()
        while stack:
            b, done = stack.pop()
            if b in CONSTANT_BITS or b in memo and not done:
                continue
            if b not in self._fanin_memo:
                self._fanin_memo[b] = self.fanin(b)
            ins, own = self._fanin_memo[b]
            if not done:
                if b in onstack:
                    continue  # a combinational loop: its bits count once
                onstack.add(b)
                stack.append((b, True))
                for x in ins:
                    if x not in CONSTANT_BITS and x not in memo and x not in onstack:
                        stack.append((x, False))
            else:
                s = set()
                if own:
                    s.add(own[0])
                for x in ins:
                    if x not in CONSTANT_BITS:
                        s |= memo.get(x, frozenset())
                memo[b] = frozenset(s)
                onstack.discard(b)
        return memo.get(root, frozenset())

    def sources_in(self, root, dom):
        """The launching elements of bit root in domain dom, as {label: source bit}."""
        out = {}
        seen = set()
        stack = [root]
        while stack:
            b = stack.pop()
            if b in seen or b in CONSTANT_BITS or dom not in self.domains(b):
                continue
            seen.add(b)
            ins, own = self._fanin_memo[b]
            if own and own[0] == dom:
                out.setdefault(own[1], b)
            stack.extend(ins)
        return out

    def run(self):
        self._dom_memo = {}
        self._fanin_memo = {}
        found = []   # dicts: from, to, cell, pin, bit, sources {label: bit}
        for cell, pin, b, d in self.dest:
            if b in CONSTANT_BITS:
                continue
            for s in sorted(self.domains(b) - {d}):
                found.append({"from": s, "to": d, "cell": cell, "pin": pin, "bit": b,
                              "sources": self.sources_in(b, s)})
        for cell in sorted(self.mem_writes):
            for w in sorted(self.mem_writes[cell]):
                for r in sorted(self.mem_reads[cell] - {w}):
                    found.append({"from": w, "to": r, "cell": cell, "pin": "memory", "bit": None,
                                  "sources": {f"{memory_base(cell)} (written on {w})": None}})
        return found


def load_declared(path):
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise NetlistError(f"{path}: {e}")
    clocks = data.get("clocks")
    if not isinstance(clocks, dict) or not clocks:
        raise NetlistError(f"{path}: no [clocks] table (domain = \"CELL_TYPE_OR_NAME:PIN\" or \"port:NAME\")")
    bypin = {}
    for dom, srcs in clocks.items():
        for s in ([srcs] if isinstance(srcs, str) else srcs):
            if ":" not in s:
                raise NetlistError(f"{path}: [clocks] {dom} = {s!r}: write CELL_TYPE_OR_NAME:PIN or port:NAME")
            bypin[s] = dom
    entries = []
    for i, e in enumerate(data.get("crossing", [])):
        where = f"{path}: crossing #{i + 1}"
        for k in ("endpoint", "from", "to", "kind", "why"):
            if k not in e:
                raise NetlistError(f"{where}: no {k}")
        unknown = set(e) - {"endpoint", "from", "to", "kind", "why", "sources", "max_fanin"}
        if unknown:
            raise NetlistError(f"{where}: unknown keys {', '.join(sorted(unknown))}")
        if e["kind"] not in KINDS:
            raise NetlistError(f"{where}: kind {e['kind']!r}: one of {', '.join(KINDS)}")
        pats = e["endpoint"] if isinstance(e["endpoint"], list) else [e["endpoint"]]
        srcs = e.get("sources")
        entries.append({
            "n": i + 1, "endpoint": pats, "rx": [glob_re(p) for p in pats], "from": e["from"], "to": e["to"],
            "kind": e["kind"], "why": " ".join(e["why"].split()),
            "sources": srcs, "src_rx": [glob_re(p) for p in srcs] if srcs else None,
            "max_fanin": e.get("max_fanin", 1 if e["kind"] in SYNC_KINDS else None),
        })
    return bypin, entries


def bits_label(labels, base):
    """NAME[7:0], NAME[3], NAME[0,2,5] or NAME for the bits of one destination."""
    idx = []
    for lab in labels:
        m = re.fullmatch(re.escape(base) + r"\[(\d+)\]", lab)
        if not m:
            return base if len(labels) > 1 else lab
        idx.append(int(m.group(1)))
    idx = sorted(set(idx))
    if len(idx) == 1:
        return f"{base}[{idx[0]}]"
    if idx == list(range(idx[0], idx[-1] + 1)):
        return f"{base}[{idx[-1]}:{idx[0]}]"
    return f"{base}[{','.join(map(str, idx))}]"


Result = collections.namedtuple("Result", "report table errors groups")


def check(netlist_path, declared_path, top=None):
    """A netlist against its declared crossings: Result(report: the whole Markdown, table: its first
    table, errors: [messages], groups: how many crossings)."""
    clocks, entries = load_declared(declared_path)
    nl = Netlist(netlist_path, top)
    an = Analysis(nl, clocks)
    found = an.run()
    errors = []

    # Each crossing path's destination: its names (for the patterns) and its group's.
    groups = collections.OrderedDict()
    matched = collections.Counter()
    for f in found:
        cell = nl.cells[f["cell"]]
        if cell["type"] == "TRELLIS_FF":
            q = cell["connections"]["Q"][0]
            label, base = nl.bit_name(q, f["cell"])
            names = nl.aliases(q) + [f["cell"]]
        else:
            label = base = memory_base(f["cell"])  # a memory's pieces (or a DDR output) as one
            names = [f["cell"], base]
        entry = next((e for e in entries if e["from"] == f["from"] and e["to"] == f["to"]
                      and any(pattern_matches(rx, p, names) for rx, p in zip(e["rx"], e["endpoint"]))), None)
        key = (f["from"], f["to"], base, entry["n"] if entry else 0)
        g = groups.setdefault(key, {"from": f["from"], "to": f["to"], "base": base, "entry": entry,
                                    "labels": set(), "pins": set(), "paths": 0, "sources": {},
                                    "cells": set(), "fanin": collections.Counter()})
        g["labels"].add(label)
        g["pins"].add(re.sub(r"\d+$", "", f["pin"]))
        g["paths"] += max(1, len(f["sources"]))
        g["sources"].update(f["sources"])  # label -> the bit it launches
        g["cells"].add(f["cell"])
        g["fanin"][label] += len(f["sources"])
        if entry:
            matched[entry["n"]] += 1

    rows = []
    for g in groups.values():
        e = g["entry"]
        endpoint = bits_label(sorted(g["labels"]), g["base"])
        if e is None:
            srcs = sorted(g["sources"])
            pins = ", ".join(sorted(g["pins"]))
            errors.append(f"undeclared crossing {g['from']} -> {g['to']} into {endpoint} ({pins}) "
                          f"from {', '.join(srcs[:4])}{' ...' if len(srcs) > 4 else ''}")
        else:
            errors += check_entry(nl, an, e, g, endpoint)
        rows.append((g["from"], g["to"], endpoint, e["kind"] if e else "UNDECLARED", g["paths"],
                     ", ".join(sorted(g["pins"])), f"#{e['n']}" if e else ""))
    for e in entries:
        if not matched[e["n"]]:
            errors.append(f"declared crossing #{e['n']} ({e['from']} -> {e['to']}, {' | '.join(e['endpoint'])}) "
                          f"matched nothing: remove it or correct its pattern")

    rows.sort(key=lambda r: (r[0], r[1], r[2]))
    table = ["| from | to | endpoint | kind | paths | pins | entry |", "|---|---|---|---|---:|---|---|"]
    table += [f"| {a} | {b} | {c} | {d} | {n} | {p} | {en} |" for a, b, c, d, n, p, en in rows]
    out = [f"# Clock-domain crossings of {nl.top}", "",
           f"From `{netlist_path}`, declared in `{declared_path}` (synth/crossings.py). "
           f"Domains: {', '.join(f'{d} ({s})' for s, d in sorted(clocks.items(), key=lambda x: x[1]))}; "
           "async: top-level inputs and the PLL's LOCK. Paths: pairs of a source bit and a destination "
           "bit (a memory: its block RAMs).", ""] + table
    out += ["", "| entry | kind | why it is safe |", "|---|---|---|"]
    out += [f"| #{e['n']} {', '.join(e['endpoint'])} | {e['kind']} | {e['why']} |" for e in entries]
    out += ["", "Kinds: " + "; ".join(f"{k}: {v}" for k, v in KINDS.items()) + "."]
    if errors:
        out += ["", "## Errors", ""] + [f"- {x}" for x in errors]
    return Result("\n".join(out) + "\n", "\n".join(table) + "\n", errors, len(rows))


def check_entry(nl, an, e, g, endpoint):
    """A declared group's own rules: the sources it names; for a synchroniser, its fan-in and the
    first flop's output feeding nothing but the next flop."""
    errs = []
    where = f"crossing #{e['n']} ({e['kind']}) into {endpoint}"
    if e["src_rx"]:
        # A source matches by its label or by any name of the net it drives.
        bad = sorted(s for s, b in g["sources"].items()
                     if not any(pattern_matches(rx, p, [s] + (nl.aliases(b) if b is not None else []))
                                for rx, p in zip(e["src_rx"], e["sources"])))
        if bad:
            errs.append(f"{where}: sources it does not declare: {', '.join(bad[:6])}")
    if e["max_fanin"] is not None:
        over = {lab: n for lab, n in g["fanin"].items() if n > e["max_fanin"]}
        if over:
            lab, n = max(over.items(), key=lambda x: x[1])
            errs.append(f"{where}: {lab} has {n} source bits of another domain (at most {e['max_fanin']}: "
                        f"logic before a synchroniser can glitch)")
    if e["kind"] in SYNC_KINDS:
        bad = []
        for cname in sorted(g["cells"]):
            c = nl.cells[cname]
            if c["type"] != "TRELLIS_FF":
                bad.append(f"{cname} is a {c['type']}, not a flop")
                continue
            q = c["connections"]["Q"][0]
            loads = nl.loads.get(q, [])
            good = [ld for ld in loads if ld[0] is not None and nl.cells[ld[0]]["type"] == "TRELLIS_FF"
                    and ld[1] == "DI" and an.clk(nl.cells[ld[0]], "CLK") == g["to"]]
            if len(loads) != 1 or len(good) != 1:
                what = ", ".join(f"{nl.cells[c2]['type'] + ' ' + c2 if c2 else 'port'} {p}" for c2, p in loads[:3])
                bad.append(f"{nl.bit_name(q, cname)[0]} feeds {what or 'nothing'}")
        if bad:
            errs.append(f"{where}: a synchroniser's first flop must feed the second flop's DI ({g['to']}) and "
                        f"nothing else; {len(bad)} do not: {bad[0]}{' ...' if len(bad) > 1 else ''}")
    return errs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("netlist", help="yosys synth_ecp5 -json output")
    ap.add_argument("--declared", required=True, help="the declared crossings (TOML)")
    ap.add_argument("--top", help="the top module (default: the netlist's)")
    ap.add_argument("--report", help="also write the report (Markdown) here")
    a = ap.parse_args()
    try:
        res = check(a.netlist, a.declared, a.top)
    except NetlistError as e:
        print(f"crossings: {e}", file=sys.stderr)
        return 2
    sys.stdout.write(res.table)
    sys.stdout.write("".join(f"crossings: {e}\n" for e in res.errors))
    if a.report:
        with open(a.report, "w") as f:
            f.write(res.report)
    sys.stdout.flush()
    if res.errors:
        print(f"crossings: {len(res.errors)} error(s) against {a.declared}", file=sys.stderr)
        return 1
    print(f"crossings: {res.groups} crossings, every one declared in {a.declared}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
