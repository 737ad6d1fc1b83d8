#!/usr/bin/env python3
"""stack_depth.py — the deepest stack a RISC-V firmware ELF can use, from its disassembly.

    stack_depth.py [--objdump OBJDUMP] [--verbose] ELF

Prints "<bytes> <deepest chain>" where bytes is the sum of the stack frames along the deepest call
chain from the entry (_start), plus the trap handler's chain on top of it (a fatal trap may come
at the deepest point and runs on the same stack).

How: every function's frame is its prologue's `addi sp,sp,-N` (or `li t0,N; sub sp,sp,t0`), plus
the frame of a `__riscv_save_K` it calls with `jal t0` (-msave-restore: that routine lowers sp for
the caller's whole body). Calls are `jal`/`call` (ra) and tail calls `j` to another function's
start. An indirect call (`jalr` through a register) may reach any function whose address is
taken: one that appears as a word in a data section, or is named in a non-call instruction's
operand comment (`addi a0,a0,... # 8000... <fn>`). Recursion is reported (exit 2) and the cycle
cut, so the figure is then a lower bound.

This is a static bound of the code as linked, not a measurement: interrupts are not enabled by
the firmware, alloca and variable-length arrays are not used (a `sub sp,sp,<reg>` that is not the
prologue form is reported).
"""
import argparse
import re
import subprocess
import sys

FUNC_RE = re.compile(r'^([0-9a-f]+) <([^>]+)>:$')
INSN_RE = re.compile(r'^\s*([0-9a-f]+):\s+([0-9a-f]+)\s+(\S+)\s*(.*)$')
TARGET_RE = re.compile(r'([0-9a-f]+) <([^>+]+)>')
REF_RE = re.compile(r'<([^>+]+)>')


def disassemble(objdump, elf):
    out = subprocess.run([objdump, '-d', '--no-show-raw-insn', elf], check=True,
                         capture_output=True, text=True).stdout
    funcs = {}  # name -> list of (mnemonic, operands)
    addr_of = {}
    cur = None
    for line in out.splitlines():
        m = FUNC_RE.match(line)
        if m:
            cur = m.group(2)
            funcs[cur] = []
            addr_of[int(m.group(1), 16)] = cur
            continue
        if cur is None:
            continue
        m = re.match(r'^\s*([0-9a-f]+):\s+(\S+)\s*(.*)$', line)
        if m:
            funcs[cur].append((m.group(2), m.group(3)))
    return funcs, addr_of


def data_words(objdump, elf):
    out = subprocess.run([objdump, '-s', '-j', '.rodata', '-j', '.data', '-j', '.sdata',
                          '-j', '.srodata', elf], capture_output=True, text=True).stdout
    words = set()
    for line in out.splitlines():
        m = re.match(r'^\s*[0-9a-f]+ ((?:[0-9a-f]{8} ?){1,4})', line)
        if not m:
            continue
        for w in m.group(1).split():
            b = bytes.fromhex(w)
            words.add(int.from_bytes(b, 'little'))
    return words


def frame_of(insns):
    """The function's own frame: its first sp decrement."""
    li = {}
    for mn, ops in insns[:40]:
        if mn in ('addi', 'add') and re.match(r'^sp,sp,-\d+', ops):
            return int(ops.split(',')[2].split()[0].lstrip('-'))
        if mn == 'li':
            r, v = ops.split(',')[:2]
            try:
                li[r] = int(v.split()[0], 0)
            except ValueError:
                pass
        if mn == 'sub' and ops.startswith('sp,sp,'):
            r = ops.split(',')[2].split()[0]
            if r in li:
                return li[r]
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--objdump', default='riscv64-unknown-elf-objdump')
    ap.add_argument('--verbose', action='store_true')
    ap.add_argument('elf')
    a = ap.parse_args()

    funcs, addr_of = disassemble(a.objdump, a.elf)
    names = set(funcs)
    words = data_words(a.objdump, a.elf)
    taken = {addr_of[w] for w in words if w in addr_of}
    frame = {}
    calls = {}
    indirect = set()
    for f, insns in funcs.items():
        fr = frame_of(insns)
        cs = set()
        for mn, ops in insns:
            if mn in ('jal', 'call', 'tail', 'j'):
                m = TARGET_RE.search(ops)
                if not m:
                    continue
                tgt = m.group(2)
                if tgt not in names or (mn == 'j' and tgt == f):
                    continue
                if mn == 'jal' and ops.startswith('t0,') and tgt.startswith('__riscv_save'):
                    fr += frame_of(funcs[tgt])
                    continue
                if tgt.startswith('__riscv_restore'):
                    continue
                if mn == 'j' and '+' in ops.split('<', 1)[-1]:
                    continue  # a jump inside a function
                cs.add(tgt)
            elif mn == 'jalr':
                if not re.search(r'<', ops):
                    indirect.add(f)
            else:
                for ref in REF_RE.findall(ops):
                    if ref in names and ref != f:
                        taken.add(ref)
        frame[f] = fr
        calls[f] = cs
    # The entry's address is a word of the start-up data, not a function pointer anyone calls.
    taken -= {'_start', '_cstart', 'main'}
    for f in indirect:
        calls[f] |= {t for t in taken if t != f}

    memo = {}
    recursion = []
    sys.setrecursionlimit(10000)

    def depth(f, stack):
        if f in memo:
            return memo[f]
        if f in stack:
            recursion.append(' -> '.join(stack[stack.index(f):] + [f]))
            return (0, [])
        stack.append(f)
        best = (0, [])
        for c in calls.get(f, ()):
            d = depth(c, stack)
            if d[0] > best[0]:
                best = d
        stack.pop()
        memo[f] = (frame[f] + best[0], [f] + best[1])
        return memo[f]

    entry = '_start' if '_start' in funcs else next(iter(funcs))
    main_d, main_chain = depth(entry, [])
    trap = next((t for t in ('trap_entry', 'bsp_trap_entry') if t in funcs), None)
    trap_d, trap_chain = depth(trap, []) if trap else (0, [])
    total = main_d + trap_d
    chain = ' > '.join(main_chain) + ((' + trap: ' + ' > '.join(trap_chain)) if trap else '')
    print(f'{total} {chain}')
    if a.verbose:
        for f in main_chain + trap_chain:
            print(f'  {frame[f]:6d} {f}', file=sys.stderr)
    if recursion:
        print('recursion (cut, so the figure is a lower bound): ' + '; '.join(sorted(set(recursion))),
              file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
