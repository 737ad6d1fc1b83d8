#!/usr/bin/env python3
"""postlink.py — FW_POSTLINK of the soc platform (bsp/soc/bsp.mk): ELF -> ELF.hex for the RTL's
RAM_INIT ($readmemh: one 32-bit little-endian word per line, from address 0; written by
tools/elf_to_hex.py), after checking that the program, its bss and its stack fit the on-chip RAM.

The linker script (linker/soc.ld) links into the whole address range on purpose; this is where an
image too large is refused, with the numbers: text (code and read-only data), data, bss, the stack
and the RAM. On refusal the ELF is deleted, so that make does not take it as built, and the status
is 1.

usage: postlink.py --ram-bytes N [--size S] [--nm N] FILE.elf
"""
import argparse
import os
import subprocess
import sys


def symbols(nm, elf):
    out = subprocess.run([nm, elf], check=True, capture_output=True, text=True).stdout
    table = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3:
            table[parts[2]] = int(parts[0], 16)
    return table


def berkeley_sizes(size, elf):
    out = subprocess.run([size, elf], check=True, capture_output=True, text=True).stdout
    text, data, bss = (int(v) for v in out.splitlines()[1].split()[:3])
    return text, data, bss


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--ram-bytes", type=int, required=True)
    p.add_argument("--size", default="riscv64-unknown-elf-size")
    p.add_argument("--nm", default="riscv64-unknown-elf-nm")
    p.add_argument("elf")
    a = p.parse_args()

    sym = symbols(a.nm, a.elf)
    text, data, bss = berkeley_sizes(a.size, a.elf)
    ram_base = sym.get("__ram", 0)
    stack = sym["__stack_size"]
    bss_end = sym["__bss_end"] - ram_base
    needed = bss_end + stack
    if sym.get("__ram_size") != a.ram_bytes:
        sys.exit(f"postlink: {a.elf} was linked for {sym.get('__ram_size')} bytes of RAM, not {a.ram_bytes}")
    if needed > a.ram_bytes:
        os.remove(a.elf)
        sys.stderr.write(
            f"error: {os.path.basename(a.elf)} does not fit the SoC's RAM: text {text} + data {data} + bss {bss} "
            f"+ stack {stack} = {needed} bytes (with alignment), RAM {a.ram_bytes} bytes "
            f"({a.ram_bytes // 1024} KiB): {needed - a.ram_bytes} bytes over. Build with a larger "
            f"SOC_RAM_KIB or smaller capacities/scenes.\n")
        return 1

    # The image itself: tools/elf_to_hex.py, the SoC's one ELF -> RAM_INIT converter.
    tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "elf_to_hex.py")
    subprocess.run([sys.executable, tool, a.elf, a.elf + ".hex", "--ram-bytes", str(a.ram_bytes),
                    "--base", str(ram_base)], check=True, stdout=subprocess.DEVNULL)
    print(f"postlink: {a.elf}.hex: RAM use {needed} of {a.ram_bytes} bytes "
          f"(text {text}, data {data}, bss {bss}, stack {stack})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
