#!/usr/bin/env python3
"""readme_commands.py — every `make` command README.md shows, and how make test runs it.

usage: readme_commands.py [--readme README.md] --list     the commands, one per line
       readme_commands.py [--readme README.md] --plan     each command's way: "run<TAB>ARGS" (the
                                                          suite runs `make ARGS`), "suite<TAB>NAME<TAB>
                                                          COMMAND" (another suite runs it), "same<TAB>
                                                          ARGS<TAB>COMMAND" (an earlier run), or
                                                          "none<TAB>COMMAND<TAB>WHY"

A command is a line of a fenced code block that starts with `make` (its `#` comment cut off), or an
inline code span that starts with `make `. README shows literal commands, as typed: a placeholder
(`<name>`, `[...]`, `…`) is refused, since no test could run it.

The ways (tests/docs/readme_commands.sh runs the "run" ones):
  run    the command itself, with settings that keep it short and in the test's own folders:
         `make run …` with HEADLESS=1 FRAMES=2 (frames from the pins, two of them) and OUT in the
         test's folder; `make lean-report …` with LEAN_SYNTH=0 (the table without the ECP5
         synthesis); `make bitstream …` with BITSTREAM_STOP=inputs (the firmware, its RAM sized,
         and every input of the flow checked: everything before synthesis).
  same   once shortened, the same as an earlier "run" (named): run once.
  suite  another suite's command in tests/suites.toml is this command.
  none   commands no test can run here, each with its reason (make test itself; a board on USB;
         the chroot check, which runs both of the README's commands itself).
"""
import argparse
import os
import re
import shlex
import sys
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SUITES = os.path.join(ROOT, "tests", "suites.toml")

# Commands that no suite of make test can run, and why (matched on the target, the first word).
NOT_RUN = {
    "test": "make test itself: this run (a SUITE=… filter is checked with test-list instead)",
    "fresh-check": "runs the README's two commands in a fresh Debian chroot (root, ~30 min): by hand "
                   "before a set-up change is resolved",
    "flash": "needs a ULX3S on USB (boards-ulx3s-tools checks the refusal without a bitstream)",
    "load": "needs a ULX3S on USB (boards-ulx3s-tools checks the refusal without a bitstream)",
    "term": "needs a ULX3S on USB (boards-ulx3s-tools checks the refusal without a serial port)",
}
# Settings that keep a target short, appended to its command (the last setting of a variable wins).
SHORT = {
    "run": ["HEADLESS=1", "FRAMES=2"],
    "lean-report": ["LEAN_SYNTH=0", "LEAN_FRAMES=2"],
    "bitstream": ["BITSTREAM_STOP=inputs"],
}
PLACEHOLDER = re.compile(r"[<>\[\]…]|\.\.\.")


def commands(readme):
    """The README's make commands, in order, each once."""
    found = []
    fenced = False
    with open(readme) as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            if fenced:
                text = line.strip()
                if text.startswith("$ "):
                    text = text[2:]
                if text.startswith("make ") or text == "make":
                    found.append(text.split(" #", 1)[0].strip())
            else:
                found += [m.strip() for m in re.findall(r"`(make(?: [^`]*)?)`", line)]
    seen, out = set(), []
    for c in found:
        c = " ".join(c.split())
        if c not in seen:
            seen.add(c)
            out.append(c)
    return out


def suites_running(command):
    """Suites of tests/suites.toml whose command is `make [--no-print-directory] ARGS` of this
    command's arguments."""
    args = shlex.split(command)[1:]
    with open(SUITES, "rb") as f:
        table = tomllib.load(f)["suite"]
    names = []
    for name, spec in table.items():
        words = shlex.split(spec["run"])
        if words[:1] == ["make"] and [w for w in words[1:] if w != "--no-print-directory"] == args:
            names.append(name)
    return names


def plan(command):
    args = shlex.split(command)[1:]
    if PLACEHOLDER.search(command):
        raise ValueError(f"'{command}': a placeholder; README shows commands as typed")
    target = next((a for a in args if "=" not in a and not a.startswith("-")), "")
    if not target:
        target = "all"  # plain `make`
    if target == "test" and any(a.startswith("SUITE=") for a in args):
        return ("run", " ".join(["test-list"] + [shlex.quote(a) for a in args if a != "test"]))
    if target in NOT_RUN:
        return ("none", command, NOT_RUN[target])
    covering = suites_running(command)
    if covering:
        return ("suite", covering[0], command)
    return ("run", " ".join([shlex.quote(a) for a in args] + SHORT.get(target, [])))


def effect(run_args):
    """What a run does: its targets and its settings, the last of each variable winning as in make."""
    words = shlex.split(run_args)
    settings = dict(w.split("=", 1) for w in words if "=" in w)
    return (tuple(w for w in words if "=" not in w), tuple(sorted(settings.items())))


def plans(cmds):
    """Each command's plan; a run that does what an earlier one did, once shortened (`make run
    FRAMES=60` and `make run` both become two frames), is a "same" of that one instead."""
    out, first_of = [], {}
    for c in cmds:
        p = plan(c)
        if p[0] == "run":
            key = effect(p[1])
            if key in first_of:
                p = ("same", first_of[key], c)
            else:
                first_of[key] = p[1]
        out.append(p)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--readme", default=os.path.join(ROOT, "README.md"))
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--list", action="store_true")
    mode.add_argument("--plan", action="store_true")
    a = ap.parse_args()
    cmds = commands(a.readme)
    if not cmds:
        print(f"readme_commands: no make command in {a.readme}", file=sys.stderr)
        return 1
    if a.list:
        print("\n".join(cmds))
        return 0
    try:
        for p in plans(cmds):
            print("\t".join(p))
    except ValueError as e:
        print(f"readme_commands: {a.readme}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
