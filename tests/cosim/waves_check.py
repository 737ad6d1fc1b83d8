#!/usr/bin/env python3
"""waves_check: does an FST trace of `make waves` hold what its GTKWave save files show, and exactly
one frame? Reads the trace through gtkwave's fst2vcd (tools/packages-waves.txt), streaming.

  waves_check.py FILE.fst --gtkw SAVE.gtkw... [--frame-count SIGNAL --frame N]

Checks, each failure one "waves_check: ..." line and exit status 1:
  - every signal a save file names (full hierarchical name, [msb:lsb] for a vector, as gtkwave
    writes and looks them up) is a variable of the trace;
  - with --frame-count: SIGNAL (a FRAME_COUNT) is N at the trace's first time and changes exactly
    once, to N + 1: the trace holds one frame's swap, neither more nor less.
Prints the trace's variables, time span and the counter's changes.
"""
import argparse
import re
import subprocess
import sys


def gtkw_signals(path):
    """The trace names a save file shows: its lines that are neither settings, flags nor comments."""
    names = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line and line[0] not in "[@*-":
                names.append(line)
    return names


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fst")
    ap.add_argument("--gtkw", action="append", default=[])
    ap.add_argument("--frame-count")
    ap.add_argument("--frame", type=int, default=0)
    a = ap.parse_args()

    vcd = subprocess.Popen(["fst2vcd", "-f", a.fst], stdout=subprocess.PIPE, text=True, bufsize=1 << 20)
    names = {}      # full name (with the range of a vector) -> identifier code
    scope = []
    for line in vcd.stdout:
        t = line.split()
        if not t:
            continue
        if t[0] == "$scope":
            scope.append(t[2])
        elif t[0] == "$upscope":
            scope.pop()
        elif t[0] == "$var":
            rng = t[5] if len(t) > 6 and t[5].startswith("[") else ""
            names[".".join(scope + [t[4]]) + rng] = t[3]
        elif t[0] == "$enddefinitions":
            break
    errors = []
    if not names:
        errors.append("%s: no variables (not an FST, or empty)" % a.fst)
    for g in a.gtkw:
        for n in gtkw_signals(g):
            if n not in names:
                errors.append("%s: %s is not in the trace" % (g, n))

    first = last = None
    changes = []    # (time, value) of the counter, its first value included
    if a.frame_count is not None:
        code = names.get(a.frame_count)
        if code is None:
            errors.append("--frame-count %s is not in the trace" % a.frame_count)
        # The value changes, in chunks of whole lines: a regex finds the counter's, the last "#time"
        # line before each is its time (a trace's VCD is hundreds of MB: no per-line Python loop).
        change = re.compile(r"^b([01xz]+) %s$" % re.escape(code or "\0"), re.M)
        rest = "\n"  # the body's first line is a time: every "#time" line follows a newline
        while True:
            block = vcd.stdout.read(1 << 24)
            data = rest + block
            cut = data.rfind("\n") + 1 if block else len(data)
            data, rest = data[:cut], data[cut:]
            if first is None:
                i = data.find("\n#")
                if i >= 0:
                    first = int(data[i + 2:data.index("\n", i + 1)])
            for m in change.finditer(data):
                t = data.rfind("\n#", 0, m.start())
                time = int(data[t + 2:data.index("\n", t + 1)]) if t >= 0 else last
                value = int(m.group(1).replace("x", "0").replace("z", "0"), 2)
                if not changes or changes[-1][1] != value:
                    changes.append((time, value))
            t = data.rfind("\n#")
            if t >= 0:
                last = int(data[t + 2:data.index("\n", t + 1)])
            if not block:
                break
    vcd.stdout.close()
    vcd.wait()

    print("waves_check: %s: %d variables; %d signals of %s found" %
          (a.fst, len(names), sum(len(gtkw_signals(g)) for g in a.gtkw), ", ".join(a.gtkw) or "no save file"))
    if a.frame_count is not None:
        print("waves_check: time %s .. %s; %s: %s" % (first, last, a.frame_count,
              ", ".join("%d at %d" % (v, t) for t, v in changes) or "never"))
        want = [a.frame, a.frame + 1]
        if [v for _, v in changes] != want:
            errors.append("%s went %s in the trace, expected %s (exactly one frame)" %
                          (a.frame_count, [v for _, v in changes], want))
        elif changes[0][0] != first:
            errors.append("%s has no value at the trace's first time %s" % (a.frame_count, first))
    for e in errors:
        print("waves_check: " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
