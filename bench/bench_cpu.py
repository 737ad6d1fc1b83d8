#!/usr/bin/env python3
"""make bench-cpu — what VexRiscv_FullCfu's pipeline charges for each hazard, measured on socsim.

Runs tests/soc/pipeline_cycles.c's program (each case a group of instructions repeated, timed with
mcycle against as many plain adds) and prints its extra cycles a group as a Markdown table: the
charges `make profile-fw PROFILE_HAZARDS=1` weights a scene's instruction trace with
(firmware/tools/profile_fw.py, PIPELINE_CHARGES; suite soc-pipeline-cycles checks they agree).

Usage: bench_cpu.py SOCSIM ELF
"""
import os
import subprocess
import sys
import tempfile

WHAT = {
    "chain": "an add reading the add before it (the bypass)",
    "load_use_next": "a load, its result read by the next instruction",
    "load_use_after_one": "... by the one after",
    "load_use_after_two": "... two after",
    "load_address": "a load's result, one instruction later, as the next load's address",
    "loads": "two independent loads",
    "mul_use_next": "a multiply, its result read by the next instruction",
    "mul_use_after_one": "... by the one after",
    "mul_use_after_two": "... two after",
    "mulh_use_next": "a high multiply (mulh), its result read next",
    "muls": "two independent multiplies",
    "store": "a store and an add",
    "stores": "two stores back to back (the data cache writes through)",
    "store_load": "a store, then a load of another word",
    "branch_forward_taken": "a forward branch taken (static prediction: not taken)",
    "branch_forward_not_taken": "a forward branch not taken",
    "branch_backward_not_taken": "a backward branch not taken (predicted taken)",
    "branch_backward_taken": "a backward branch taken (a loop)",
    "jump": "a jump (jal)",
    "call_return": "a call (jal) and its return (jalr)",
}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.splitlines()[-1])
    socsim, elf = sys.argv[1:]
    with tempfile.TemporaryDirectory(prefix="bench-cpu-") as tmp:
        log = os.path.join(tmp, "uart.log")
        run = subprocess.run([socsim, "--fw", elf, "--frames", os.path.join(tmp, "frames"),
                              "--uart-log", log, "--max-cycles", "1e7"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"bench-cpu: socsim failed ({run.returncode}): {run.stderr[-400:]}")
        lines = open(log).read().splitlines()
    if "pipeline: done" not in lines:
        sys.exit("bench-cpu: the program did not finish: " + " / ".join(lines[-3:]))
    print("| case | what | extra cycles |")
    print("|---|---|---:|")
    for line in lines:
        parts = line.split()
        if len(parts) == 3 and parts[0] == "pipeline:":
            print(f"| {parts[1]} | {WHAT.get(parts[1], '')} | {parts[2]} |")
        elif line.startswith("pipeline: adds"):
            reference = line[len("pipeline: "):]
    print()
    print(f"Extra cycles a group of the case against as many plain adds ({reference}: one cycle "
          "an add); the group repeated 64 times in a row, its second run timed with mcycle on "
          "socsim (VexRiscv_FullCfu, the data in the data cache).")


if __name__ == "__main__":
    main()
