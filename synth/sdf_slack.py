#!/usr/bin/env python3
"""Every endpoint's setup slack on one clock of a placed and routed ECP5 design, grouped by module:
what stands between a build and a faster clock (issue #27), where nextpnr names one path a clock.

    sdf_slack.py DESIGN.sdf [--period NS] [--clock REGEX] [--top N] [--depth D]

DESIGN.sdf is nextpnr-ecp5's delay file of the routed design (`make timing-groups` writes it from
the build's routed netlist without placing or routing again). The analysis is nextpnr's own kind:
every flop, block RAM and DSP output clocked by the chosen clock starts a path at its clock-to-out
delay; each cell arc (IOPATH) and each routed connection (INTERCONNECT) adds its delay, the slow
corner's (the SDF's max: nextpnr times setup with it); each clocked input with a setup check on the
same clock ends one, against the period, its clock's arrival and its setup time. Paths from or to
other clocks are left out, as nextpnr leaves them (unconstrained). A combinational loop's arcs are
left out and counted.

--clock picks the clock by its driver's name (a regular expression; default: the clock with the
most endpoints); --period is the target (default 13.333 ns, 75 MHz). The table lists each module
(the endpoint's hierarchical name up to --depth levels) with endpoints failing the target: how many,
the worst slack, its path's start and end, its cells, and how much of its delay is routing. The
first line gives the worst path's delay, nextpnr's critical path for the same clock: equal to the
picosecond on the ULX3S's USB build (17.23 ns), within 0.5 % on tests/boards/sdf_slack.sh's small
design (one carry cell's FCI -> F arc, which nextpnr takes 40 ps shorter than its SDF says).
"""
import argparse
import collections
import re
import sys

TRIPLE = r"\((-?[\d.]*):(-?[\d.]*):(-?[\d.]*)\)"
IOPATH_RE = re.compile(r"\(IOPATH\s+(\S+)\s+(\S+)\s+" + TRIPLE + r"\s*" + TRIPLE)
INTERCONNECT_RE = re.compile(r"\(INTERCONNECT\s+(\S+)\s+(\S+)\s+" + TRIPLE + r"\s*" + TRIPLE)
SETUP_RE = re.compile(r"\((?:SETUPHOLD|SETUP)\s+\((?:posedge|negedge)\s+(\S+)\)\s+\((?:posedge|negedge)\s+(\S+)\)\s+"
                      + TRIPLE)
INSTANCE_RE = re.compile(r"\(INSTANCE\s*(\S*)\)")


def unescape(name):
    return re.sub(r"\\(.)", r"\1", name)


def split_pin(ref):
    """'inst/pin' (SDF, escaped) -> (inst, pin): the last unescaped '/' divides them."""
    m = re.match(r"^(.*?)(?<!\\)/([^/]*)$", ref)
    if not m:
        sys.exit(f"sdf_slack: cannot split {ref!r} into instance and pin")
    return unescape(m.group(1)), unescape(m.group(2))


def worst(triple):
    """The slow corner of (min:typ:max) in ps; an empty field counts 0."""
    return max(float(v) if v else 0.0 for v in triple)


def read_sdf(path):
    """The arcs: cell arcs (inst, from, to, ps), routed connections ((inst, pin), (inst, pin), ps)
    and setup checks (inst, data pin, clock pin, ps)."""
    cell_arcs, wires, checks = [], [], []
    inst = None
    timescale = 1.0
    with open(path) as f:
        for line in f:
            if "(TIMESCALE" in line:
                m = re.search(r"TIMESCALE\s+(\d+)\s*(ps|ns)", line)
                if m:
                    timescale = float(m.group(1)) * (1000.0 if m.group(2) == "ns" else 1.0)
                continue
            m = INSTANCE_RE.search(line)
            if m:
                inst = unescape(m.group(1))
                continue
            m = INTERCONNECT_RE.search(line)
            if m:
                wires.append((split_pin(m.group(1)), split_pin(m.group(2)),
                              timescale * max(worst(m.groups()[2:5]), worst(m.groups()[5:8]))))
                continue
            m = IOPATH_RE.search(line)
            if m:
                a, b = unescape(m.group(1)), unescape(m.group(2))
                ps = timescale * max(worst(m.groups()[2:5]), worst(m.groups()[5:8]))
                # A carry cell's two halves carry its FCI -> FCO delay once: nextpnr's own timing
                # gives the second half's 0, its SDF writes the first's for both.
                if a == "FCI" and b == "FCO" and inst.endswith("$CCU2_COMB1"):
                    ps = 0.0
                cell_arcs.append((inst, a, b, ps))
                continue
            m = SETUP_RE.search(line)
            if m:
                checks.append((inst, unescape(m.group(1)), unescape(m.group(2)),
                               timescale * worst(m.groups()[2:5])))
    return cell_arcs, wires, checks


def analyse(cell_arcs, wires, checks, clock_re, period_ps):
    driver = {}                                   # (inst, pin) -> ((inst, pin), ps): its wire
    fanout = collections.defaultdict(list)        # node -> [(node, ps, is_wire)]
    for src, dst, ps in wires:
        driver[dst] = (src, ps)
    clock_pins = {(inst, clk) for inst, _, clk, _ in checks}

    def clock_source(node):
        """The clock pin's source: follow wires and single-input cell arcs back to a driver that
        is not a clock buffer's output chain (nextpnr's global buffers, DCCA, and the PLL)."""
        seen = 0
        ps = 0.0
        while node in driver and seen < 8:
            node, d = driver[node]
            ps += d
            seen += 1
            back = [a for a in arcs_into.get(node, [])]
            if len(back) == 1:
                node, d = back[0]
                ps += d
        return node, ps

    arcs_into = collections.defaultdict(list)
    for inst, a, b, ps in cell_arcs:
        arcs_into[(inst, b)].append(((inst, a), ps))

    domain = {}                                   # clock pin -> (source, its arrival)
    for node in clock_pins:
        domain[node] = clock_source(node)
    counts = collections.Counter(src for src, _ in domain.values())
    if not counts:
        sys.exit("sdf_slack: the SDF has no setup checks")
    if clock_re:
        chosen = [c for c in counts if re.search(clock_re, "/".join(c))]
        if not chosen:
            sys.exit(f"sdf_slack: no clock matches {clock_re!r}; clocks: "
                     + ", ".join(sorted("/".join(c) for c in counts)))
        clock = max(chosen, key=lambda c: counts[c])
    else:
        clock = counts.most_common(1)[0][0]

    # Start points: arcs out of a clock pin of the chosen clock (clock to out).
    start = {}
    for inst, a, b, ps in cell_arcs:
        node = (inst, a)
        if node in clock_pins or a.startswith("CLK") or a in ("WCK",):
            src = domain.get(node) or clock_source(node)
            if src[0] == clock:
                out = (inst, b)
                t = src[1] + ps
                if t > start.get(out, (-1.0,))[0]:
                    start[out] = (t, node)
    # Combinational arcs: cell arcs not from a clock pin, and wires (not into clock pins).
    for inst, a, b, ps in cell_arcs:
        if (inst, a) in clock_pins or a.startswith("CLK") or a == "WCK":
            continue
        fanout[(inst, a)].append(((inst, b), ps))
    for src, dst, ps in wires:
        if dst in clock_pins:
            continue
        fanout[src].append((dst, ps))

    # Longest arrival by Kahn's order over what the start points reach.
    reach = set(start)
    stack = list(start)
    while stack:
        n = stack.pop()
        for m, _ in fanout.get(n, ()):
            if m not in reach:
                reach.add(m)
                stack.append(m)
    indeg = collections.Counter()
    for n in reach:
        for m, _ in fanout.get(n, ()):
            indeg[m] += 1
    arrival = {n: (t, None) for n, (t, _) in start.items()}
    ready = [n for n in reach if indeg[n] == 0]
    done = 0
    while ready:
        n = ready.pop()
        done += 1
        t = arrival.get(n, (float("-inf"), None))[0]
        for m, ps in fanout.get(n, ()):
            if t + ps > arrival.get(m, (float("-inf"), None))[0]:
                arrival[m] = (t + ps, n)
            indeg[m] -= 1
            if indeg[m] == 0:
                ready.append(m)
    looped = len(reach) - done

    ends = []
    for inst, pin, clk, setup in checks:
        node = (inst, pin)
        cnode = (inst, clk)
        if domain.get(cnode, (None,))[0] != clock or node not in arrival:
            continue
        t = arrival[node][0]
        if t == float("-inf"):
            continue
        slack = period_ps + domain[cnode][1] - setup - t
        ends.append((slack, node, t + setup - domain[cnode][1]))
    return clock, counts[clock], ends, arrival, start, looped


def trace(node, arrival, start):
    path = []
    while node is not None:
        path.append(node)
        prev = arrival.get(node, (0, None))[1]
        if prev is None and node in start:
            path.append(start[node][1])
        node = prev
    return list(reversed(path))


def module_of(inst, depth):
    parts = inst.split(".")
    return ".".join(parts[:-1][:depth]) or "(top)"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sdf")
    ap.add_argument("--period", type=float, default=1000.0 / 75.0, help="the target period, ns")
    ap.add_argument("--clock", help="regular expression on the clock's driver (default: the largest)")
    ap.add_argument("--top", type=int, default=25, help="modules listed")
    ap.add_argument("--depth", type=int, default=6, help="levels of the hierarchy a module keeps")
    a = ap.parse_args()
    cell_arcs, wires, checks = read_sdf(a.sdf)
    clock, n_ends, ends, arrival, start, looped = analyse(cell_arcs, wires, checks, a.clock, a.period * 1000.0)
    ends.sort(key=lambda e: e[0])
    if not ends:
        sys.exit("sdf_slack: no timed endpoint on that clock")
    worst_slack, worst_node, worst_need = ends[0]
    print(f"clock {'/'.join(clock)}: {n_ends} clocked inputs, {len(ends)} timed; worst path {worst_need / 1000:.2f} ns "
          f"({1e6 / worst_need:.2f} MHz); {sum(1 for e in ends if e[0] < 0)} endpoints fail "
          f"{a.period:.3f} ns" + (f"; {looped} nodes in combinational loops left out" if looped else ""))
    groups = collections.OrderedDict()
    for slack, node, need in ends:
        if slack >= 0:
            break
        g = groups.setdefault(module_of(node[0], a.depth), [0, slack, node, need])
        g[0] += 1
    print()
    print("| module (endpoint) | endpoints failing | worst path ns | slack ns | its start | its end | cells | routing |")
    print("|---|---:|---:|---:|---|---|---:|---:|")
    for name, (count, slack, node, need) in list(groups.items())[:a.top]:
        path = trace(node, arrival, start)
        cells = len({n[0] for n in path})
        # routing: the wires' share of the path's arrival
        wire_ps = 0.0
        for u, v in zip(path, path[1:]):
            if u[0] != v[0]:
                wire_ps += arrival[v][0] - arrival[u][0] if u in arrival and v in arrival else 0.0
        first = path[0][0] if path else "?"
        share = 100.0 * wire_ps / need if need > 0 else 0.0
        end = node[0][len(name) + 1:] if node[0].startswith(name + ".") else node[0]
        print(f"| `{name}` | {count} | {need / 1000:.2f} | {slack / 1000:+.2f} | `{first}` | `{end}.{node[1]}` "
              f"| {cells} | {share:.0f} % |")
    if len(groups) > a.top:
        print(f"| ({len(groups) - a.top} more modules) | {sum(g[0] for g in list(groups.values())[a.top:])} "
              "| | | | | | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
