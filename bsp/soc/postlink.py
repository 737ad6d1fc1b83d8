#!/usr/bin/env python3
"""postlink.py — FW_POSTLINK of the soc platform (bsp/soc/bsp.mk): ELF -> ELF.hex for the RTL's
RAM_INIT ($readmemh: one 32-bit little-endian word per line, from address 0; written by
bsp/soc/elf_to_hex.py), after checking that the program, its bss and its stack fit the on-chip RAM,
and ELF.ramkib: the RAM the program needs, in KiB, rounded up to the RAM's granule.

The RAM a program needs is read off its link: linker/soc.ld puts the stack right above .bss, so
the need is the stack's top (__stack). A build whose RAM is derived (a scene's manifest build,
mk/manifest.mk) gives --ram-bytes the RAM window's size, then builds its RAM from ELF.ramkib.

The linker script (linker/soc.ld) links into the whole address range on purpose; this is where an
image too large is refused, with the numbers: text (code and read-only data), data, bss, the stack
and the RAM. On refusal the ELF is deleted, so that make does not take it as built, and the status
is 1.

With --image (a build whose firmware runs from the SDRAM, bsp/soc/bsp.mk SOC_MEM=sdram) the program
is linked at the SDRAM's base, --ram-bytes is the SDRAM's size, and the output is ELF.img, the boot
image the boot program copies from the flash (bsp/soc/mkimage.py), instead of the RAM's hex. Such a
link gives __fast: its stack and its FW_FAST_DATA objects are in the on-chip RAM above the boot
program (linker/soc.ld's .fast), checked against that room instead of the SDRAM.

usage: postlink.py --ram-bytes N [--image] [--size S] [--nm N] FILE.elf
"""
import argparse
import os
import subprocess
import sys

# The RAM's size rounds up to whole groups of block RAM: soc_rtl/soc_ram.v's 32-bit words are four
# byte lanes, each an ECP5 EBR of 2 KiB (2048x9) on the board, so 8 KiB is the size that wastes none.
RAM_GRANULE_BYTES = 8 * 1024


def ram_kib_needed(needed_bytes):
    """The RAM, in KiB, for a program whose stack top is needed_bytes above the RAM's base."""
    granules = -(-needed_bytes // RAM_GRANULE_BYTES)
    return granules * RAM_GRANULE_BYTES // 1024


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
    p.add_argument("--image", action="store_true", help="write ELF.img, the SDRAM boot image")
    p.add_argument("elf")
    a = p.parse_args()

    sym = symbols(a.nm, a.elf)
    text, data, bss = berkeley_sizes(a.size, a.elf)
    ram_base = sym.get("__ram", 0)
    stack = sym["__stack_size"]
    needed = sym["__stack"] - ram_base  # the stack's top: image, bss, the stack's alignment, the stack
    if "__fast" in sym:
        # The stack and the FW_FAST_DATA objects are in the on-chip RAM above the boot program
        # (linker/soc.ld's .fast, __stack its top): the SDRAM holds the image and .bss only.
        needed = sym["__bss_end"] - ram_base
        fast_used = sym["__fast_end"] - sym["__fast"]
        fast_room = sym["__stack"] - sym["__fast"]
        if fast_used + stack > fast_room:
            os.remove(a.elf)
            sys.stderr.write(
                f"error: {os.path.basename(a.elf)}: its fast data ({fast_used} bytes, FW_FAST_DATA) and stack "
                f"({stack} bytes) do not fit the {fast_room} bytes of on-chip RAM above the boot program "
                f"(0x{sym['__fast']:08X}..0x{sym['__stack']:08X}): {fast_used + stack - fast_room} bytes over.\n")
            return 1
    if needed > a.ram_bytes:
        os.remove(a.elf)
        memory = "SDRAM" if a.image else "RAM"
        remedy = ("smaller capacities or models" if a.image else
                  f"a larger SOC_RAM_KIB (at least {ram_kib_needed(needed)}) or smaller capacities/scenes")
        sys.stderr.write(
            f"error: {os.path.basename(a.elf)} does not fit the SoC's {memory}: text {text} + data {data} + bss {bss} "
            f"+ stack {stack} = {needed} bytes (with alignment), {memory} {a.ram_bytes} bytes "
            f"({a.ram_bytes // 1024} KiB): {needed - a.ram_bytes} bytes over. Build with {remedy}.\n")
        return 1

    here = os.path.dirname(os.path.abspath(__file__))
    if a.image:
        subprocess.run([sys.executable, os.path.join(here, "mkimage.py"), a.elf, a.elf + ".img", "--mem-base",
                        str(ram_base), "--mem-bytes", str(a.ram_bytes)], check=True, stdout=subprocess.DEVNULL)
        where = (f"; on chip: fast data {sym['__fast_end'] - sym['__fast']} + stack {stack} of "
                 f"{sym['__stack'] - sym['__fast']} bytes" if "__fast" in sym else f", stack {stack}")
        print(f"postlink: {a.elf}.img: SDRAM use {needed} of {a.ram_bytes} bytes "
              f"(text {text}, data {data}, bss {bss}{where})")
        return 0
    # The image itself: bsp/soc/elf_to_hex.py, the SoC's one ELF -> RAM_INIT converter.
    tool = os.path.join(here, "elf_to_hex.py")
    subprocess.run([sys.executable, tool, a.elf, a.elf + ".hex", "--ram-bytes", str(a.ram_bytes),
                    "--base", str(ram_base)], check=True, stdout=subprocess.DEVNULL)
    with open(a.elf + ".ramkib", "w") as f:
        f.write(f"{ram_kib_needed(needed)}\n")
    print(f"postlink: {a.elf}.hex: RAM use {needed} of {a.ram_bytes} bytes "
          f"(text {text}, data {data}, bss {bss}, stack {stack}; needs {ram_kib_needed(needed)} KiB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
