#!/usr/bin/env python3
"""make profile-fw — where a scene's firmware instructions go, function by function.

Runs one firmware ELF in co-simulation with QEMU executing one instruction per translation block
and logging every block it executes (-singlestep -d exec,nochain), so the log has one line per
retired instruction. The log streams through a FIFO (it would be hundreds of MB as a file: the
boot-time clearing of .bss alone is millions of instructions) and each program counter is
attributed to the function containing it (nm of the ELF). A frame runs from one entry into
scene_update to the next; the first frame and everything before it are skipped (warm-up:
scene building, first-use caches), and the table gives the mean over the remaining frames.

The counts are exact and deterministic (QEMU -icount); they include the DONE_SEQ polling in
gpu_wait and the frame report's printing, which the firmware's own "fw instr" figure excludes,
so both are listed separately below the table.

With --startup the table is the start-up's instead: everything before the first frame (the C
runtime's start, the scene's building, the messages), counted once.

With --lines N a second table follows: the N source lines whose instructions ran most (addr2line of
each program counter; a line inlined into several functions sums all its copies), to find the hot
statements inside a hot function.

With --hazards a third table follows: the pipeline hazards of VexRiscv_FullCfu the frames' instruction
sequence meets (a load's or a multiply's result used one or two instructions later, branches
against the core's static prediction, jumps, back-to-back stores), each counted from the trace and
weighted with the extra cycles `make bench-cpu` measures for it on the SoC (PIPELINE_CHARGES): an
estimate of the cycles the pipeline waits, beside the caches' refills, which bench-soc counts.

Usage: profile_fw.py GPUSIM ELF [--top N] [--startup] [--lines N] [--hazards] [--uart-log FILE]
"""
import argparse
import bisect
import collections
import os
import re
import subprocess
import sys
import tempfile
import threading

FRAME_MARK = "scene_update"
# Waiting for the GPU, not work (the firmware's "fw instr" leaves the same span out): the polling
# of DONE_SEQ (gpu_wait, inlined into gpu_wait_idle) and the UART draining done between polls.
NOT_PIPELINE = {"gpu_wait", "gpu_wait_idle", "app_drain_uart"}

# VexRiscv_FullCfu's extra cycles for each hazard, as `make bench-cpu` measures them on socsim
# (tests/soc/pipeline_cycles.c; suite soc-pipeline-cycles fails when they differ from this table).
PIPELINE_CHARGES = {
    "load_use_next": 2,             # a load's result read by the next instruction
    "load_use_after_one": 1,        # ... by the one after
    "mul_use_next": 2,              # a multiply's (mul, mulh, mulhu, mulhsu)
    "mul_use_after_one": 1,
    "branch_forward_taken": 2,      # static prediction: forward not taken, backward taken
    "branch_backward_not_taken": 2,
    "branch_backward_taken": 1,
    "jump": 1,                      # jal (j, call)
    "return": 2,                    # jalr (ret, an indirect call): call_return minus a jump
    "stores": 2,                    # a store right after a store (write-through bus cycles)
}
LOADS = {"lw", "lh", "lhu", "lb", "lbu"}
MULS = {"mul", "mulh", "mulhu", "mulhsu"}
STORES = {"sw", "sh", "sb"}
BRANCHES = {"beq", "bne", "blt", "bge", "bltu", "bgeu"}
REGISTER = re.compile(r"\b(zero|ra|sp|gp|tp|t[0-6]|s1[01]|s[0-9]|a[0-7])\b")


def decode(elf):
    """pc -> (mnemonic, destination register or None, source registers, branch target or None)."""
    objdump = os.environ.get("RV_OBJDUMP", "riscv64-unknown-elf-objdump")
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", "-M", "no-aliases", elf],
                         capture_output=True, text=True, check=True).stdout
    table = {}
    for line in out.splitlines():
        m = re.match(r"\s*([0-9a-f]+):\s+(\S+)\s*(.*)", line)
        if not m:
            continue
        mnemonic, operands = m.group(2), m.group(3)
        target = re.search(r"\b([0-9a-f]+) <", operands)
        regs = REGISTER.findall(operands.split("#")[0])
        if mnemonic in STORES or mnemonic in BRANCHES:
            dest, sources = None, regs
        else:
            dest, sources = (regs[0], regs[1:]) if regs else (None, [])
        table[int(m.group(1), 16)] = (mnemonic, None if dest == "zero" else dest, sources,
                                      int(target.group(1), 16) if target else None)
    return table


def hazards_of(prev2, prev, pc, cur):
    """The hazards instruction cur (at pc) meets after prev and prev2 ((pc, decoded) or None)."""
    found = []
    if prev is not None:
        ppc, (pm, pdest, psrc, ptarget) = prev
        if pdest is not None and pdest in cur[2]:
            if pm in LOADS:
                found.append("load_use_next")
            elif pm in MULS:
                found.append("mul_use_next")
        if pm in BRANCHES and ptarget is not None:
            if pc != ppc + 4:
                found.append("branch_backward_taken" if ptarget < ppc else "branch_forward_taken")
            elif ptarget < ppc:
                found.append("branch_backward_not_taken")
        elif pm == "jal":
            found.append("jump")
        elif pm == "jalr":
            found.append("return")
        if pm in STORES and cur[0] in STORES:
            found.append("stores")
        if prev2 is not None:
            qm, qdest, _, _ = prev2[1]
            # the load two back, its result not waited for already by prev
            if (qdest is not None and qdest in cur[2] and qdest not in psrc and qdest != pdest):
                if qm in LOADS:
                    found.append("load_use_after_one")
                elif qm in MULS:
                    found.append("mul_use_after_one")
    return found


def symbols(elf):
    nm = os.environ.get("RV_NM", "riscv64-unknown-elf-nm")
    out = subprocess.run([nm, "-n", "--defined-only", elf], capture_output=True, text=True,
                         check=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[1] in "tTwW":
            syms.append((int(parts[0], 16), parts[2]))
    return syms


def function_finder(syms):
    """pc -> the name of the function that contains it (syms: symbols(), in address order)."""
    starts = [a for a, _ in syms]

    def function_of(pc):
        i = bisect.bisect_right(starts, pc) - 1
        return syms[i][1] if i >= 0 else "?"
    return function_of


def source_lines(elf, pcs):
    """Each of pcs' innermost source line ("file:line", relative to the working directory:
    addr2line), in the same order."""
    a2l = os.environ.get("RV_ADDR2LINE", "riscv64-unknown-elf-addr2line")
    out = subprocess.run([a2l, "-e", elf], input="".join(f"{pc:x}\n" for pc in pcs),
                         capture_output=True, text=True, check=True).stdout.splitlines()
    root = os.getcwd() + os.sep
    return [where.split(" (discriminator")[0].replace(root, "") for where in out]


def hot_lines(elf, measured, nf, work, n, waiting):
    """The n source lines with the most instructions per frame (addr2line, innermost line), the
    program counters for which waiting(pc) holds left out."""
    per_pc = collections.Counter()
    for frame in measured:
        per_pc.update(frame)
    per_pc = collections.Counter({pc: c for pc, c in per_pc.items() if not waiting(pc)})
    pcs = sorted(per_pc)
    by_line = collections.Counter()
    for pc, where in zip(pcs, source_lines(elf, pcs)):
        by_line[where] += per_pc[pc]
    print("| source line | instructions/frame | share |")
    print("|---|---:|---:|")
    for where, count in by_line.most_common(n):
        print(f"| {where} | {count / nf:.0f} | {100.0 * count / max(work, 1):.1f}% |")


def hazard_table(measured, nf, work, waiting, function_of, top=8):
    """The hazards a frame meets (their program counters for which waiting(pc) holds left out),
    each with its charge: the pipeline's estimated waits; then the functions that wait most."""
    count = collections.Counter()
    by_fn = collections.defaultdict(collections.Counter)
    for frame in measured:
        for (pc, h), n in frame.items():
            if not waiting(pc):
                count[h] += n
                by_fn[function_of(pc)][h] += n
    print("| hazard | per frame | extra cycles each | cycles/frame |")
    print("|---|---:|---:|---:|")
    total = 0
    for h, charge in PIPELINE_CHARGES.items():
        cycles = count[h] * charge
        total += cycles
        print(f"| {h} | {count[h] / nf:.0f} | {charge} | {cycles / nf:.0f} |")
    print(f"| **the pipeline's waits, estimated** | | | **{total / nf:.0f}** "
          f"({total / work:.2f} a polled-out instruction) |")
    print()
    short = {"load_use_next": "load", "load_use_after_one": "load", "mul_use_next": "mul",
             "mul_use_after_one": "mul", "stores": "stores"}
    groups = ["load", "mul", "branch", "jump", "stores"]
    print("| function | " + " | ".join(f"{g} waits" for g in groups) + " | cycles/frame |")
    print("|---|" + "---:|" * (len(groups) + 1))
    cost = {f: sum(n * PIPELINE_CHARGES[h] for h, n in c.items()) for f, c in by_fn.items()}
    for f in sorted(cost, key=cost.get, reverse=True)[:top]:
        g = collections.Counter()
        for h, n in by_fn[f].items():
            g[short.get(h, "branch" if h.startswith("branch") else "jump")] += n * PIPELINE_CHARGES[h]
        print(f"| {f} | " + " | ".join(f"{g[x] / nf:.0f}" for x in groups) + f" | {cost[f] / nf:.0f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("gpusim")
    ap.add_argument("elf")
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--startup", action="store_true",
                    help="profile the start-up (before the first frame) instead of the frames")
    ap.add_argument("--lines", type=int, default=0,
                    help="also list the N source lines that ran the most instructions")
    ap.add_argument("--hazards", action="store_true",
                    help="also estimate the pipeline's waits from the instruction sequence")
    ap.add_argument("--uart-log", help="keep the firmware's UART output (its frame lines) in this file")
    args = ap.parse_args()
    code = decode(args.elf) if args.hazards else {}

    syms = symbols(args.elf)
    function_of = function_finder(syms)
    mark = next((a for a, n in syms if n == FRAME_MARK), None)
    if mark is None:
        sys.exit(f"profile-fw: {args.elf} has no {FRAME_MARK} symbol")

    tmp = tempfile.mkdtemp(prefix="profile-fw-")
    fifo = os.path.join(tmp, "trace")
    wrapper = os.path.join(tmp, "qemu")
    os.mkfifo(fifo)
    with open(wrapper, "w") as f:
        f.write("#!/bin/sh\nexec qemu-system-riscv32 -singlestep -d exec,nochain "
                f"-D {fifo} \"$@\"\n")
    os.chmod(wrapper, 0o755)

    sim = subprocess.Popen([args.gpusim, "cosim", "--fw", args.elf, "--frames",
                            os.path.join(tmp, "frames"), "--no-model-check", "--qemu", wrapper,
                            "--uart-log", args.uart_log or os.path.join(tmp, "uart.log")],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    err = []
    threading.Thread(target=lambda: err.append(sim.stderr.read()), daemon=True).start()

    per_frame = []           # one Counter of pc -> count per frame
    pcs = collections.Counter()
    hazard_frames = []       # with --hazards: one Counter of (pc, hazard) -> count per frame
    hz = collections.Counter()
    prev = prev2 = None
    startup = collections.Counter()  # everything before the first frame
    frames_seen = -1         # entries into FRAME_MARK so far, minus one
    lines = 0
    with open(fifo) as trace:
        for line in trace:
            if not line.startswith("Trace"):
                continue
            pc = int(line.split("[", 1)[1].split("/", 2)[1], 16)
            lines += 1
            if pc == mark:
                if frames_seen >= 0:
                    per_frame.append(pcs)
                    hazard_frames.append(hz)
                else:
                    startup = pcs
                pcs = collections.Counter()
                hz = collections.Counter()
                frames_seen += 1
                print(f"profile-fw: frame {frames_seen} starts after {lines} instructions",
                      file=sys.stderr)
            pcs[pc] += 1
            if code:
                cur = code.get(pc)
                if cur is not None:
                    for h in hazards_of(prev2, prev, pc, cur):
                        hz[(pc, h)] += 1
                    prev2, prev = prev, (pc, cur)
    status = sim.wait()
    if status != 0:
        sys.exit(f"profile-fw: co-simulation failed ({status}): {''.join(err)[-400:]}")
    if pcs and frames_seen >= 0:
        per_frame.append(pcs)  # the last frame runs until the firmware exits
        hazard_frames.append(hz)
    if args.startup:
        if frames_seen < 0:
            sys.exit("profile-fw: the firmware never reached its first frame")
        measured = [startup]
    else:
        # per_frame[0] is frame 0 (warm-up): skip it; the last one also holds the exit path.
        measured = per_frame[1:-1] if len(per_frame) > 2 else per_frame[1:]
        hazard_measured = hazard_frames[1:-1] if len(per_frame) > 2 else hazard_frames[1:]
    if not measured:
        sys.exit("profile-fw: fewer than two frames in the run; build with FRAMES >= 3")

    by_fn = collections.Counter()
    for frame in measured:
        for pc, n in frame.items():
            by_fn[function_of(pc)] += n
    nf = len(measured)
    total = sum(by_fn.values())
    side = {k: by_fn.pop(k) for k in list(by_fn) if k in NOT_PIPELINE}
    work = total - sum(side.values())

    unit = "instructions" if args.startup else "instructions/frame"
    print(f"| function | {unit} | share |")
    print("|---|---:|---:|")
    shown = 0
    for name, n in by_fn.most_common(args.top):
        print(f"| {name} | {n / nf:.0f} | {100.0 * n / work:.1f}% |")
        shown += n
    rest = work - shown
    if rest > 0:
        print(f"| (other functions) | {rest / nf:.0f} | {100.0 * rest / work:.1f}% |")
    print(f"| **total, polling excluded** | **{work / nf:.0f}** | 100% |")
    print()
    for name, n in side.items():
        print(f"{name} (waiting for the GPU): {n / nf:.0f} instructions/frame, not counted above")
    if args.lines > 0:
        print()
        hot_lines(args.elf, measured, nf, work, args.lines, lambda pc: function_of(pc) in NOT_PIPELINE)
    if args.hazards and not args.startup:
        print()
        hazard_table(hazard_measured, nf, work, lambda pc: function_of(pc) in NOT_PIPELINE,
                     function_of)
    what = ("The start-up, before the first frame" if args.startup else
            f"Mean of {nf} frame(s) (frame 0 and the last skipped)")
    print(f"{what}; QEMU -icount, one line of the execution log per instruction.")


if __name__ == "__main__":
    main()
