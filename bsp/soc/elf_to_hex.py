#!/usr/bin/env python3
"""Turn a 32-bit little-endian RISC-V ELF into the SoC RAM's $readmemh image (soc_rtl/soc_ram.v).

    elf_to_hex.py PROGRAM.elf OUT.hex [--ram-bytes N] [--base ADDR]

The image: one 32-bit hex word per line, line n = the word at byte address base + 4n, from the
program's loadable segments (PT_LOAD, by physical address; the bytes between and after them up to
the last one are 0). It refuses, with the sizes, a program whose memory (file contents and .bss,
i.e. every PT_LOAD's memory size) does not lie within [base, base + ram_bytes), so an image that
does not fit the RAM is an error here rather than a silent wrap in the simulator or on the board.
Defaults: --base SOC_RAM_BASE and --ram-bytes SOC_RAM_DEFAULT_BYTES, read from contract/soc_map.h.
"""
import argparse
import pathlib
import re
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def soc_map_value(name):
    text = (ROOT / "contract" / "soc_map.h").read_text()
    m = re.search(rf"#define {name}\s+(0x[0-9A-Fa-f]+|[0-9]+)u", text)
    if not m:
        sys.exit(f"elf_to_hex: {name} not in contract/soc_map.h")
    return int(m.group(1), 0)


def load_segments(path):
    data = pathlib.Path(path).read_bytes()
    if data[:4] != b"\x7fELF" or data[4] != 1 or data[5] != 1:
        sys.exit(f"elf_to_hex: {path} is not a 32-bit little-endian ELF")
    (e_type, e_machine, _, _, e_phoff, _, _, _, e_phentsize, e_phnum) = struct.unpack_from("<HHIIIIIHHH", data, 16)
    if e_machine != 243:
        sys.exit(f"elf_to_hex: {path} is not a RISC-V ELF (e_machine {e_machine})")
    segs = []
    for i in range(e_phnum):
        p_type, p_offset, _, p_paddr, p_filesz, p_memsz, _, _ = struct.unpack_from("<IIIIIIII", data, e_phoff + i * e_phentsize)
        if p_type == 1 and p_memsz > 0:   # PT_LOAD
            segs.append((p_paddr, data[p_offset:p_offset + p_filesz], p_memsz))
    if not segs:
        sys.exit(f"elf_to_hex: {path} has no loadable segment")
    return segs


def flat_image(segs, base):
    """The loadable segments' file contents as one byte image from base to the end of the last one's
    contents, the gaps 0, padded to a whole word."""
    file_end = max(addr + len(body) for addr, body, _ in segs)
    image = bytearray((file_end - base + 3) // 4 * 4)
    for addr, body, _ in segs:
        image[addr - base:addr - base + len(body)] = body
    return image


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf")
    ap.add_argument("hex")
    ap.add_argument("--ram-bytes", type=lambda s: int(s, 0), default=None)
    ap.add_argument("--base", type=lambda s: int(s, 0), default=None)
    a = ap.parse_args()
    base = soc_map_value("SOC_RAM_BASE") if a.base is None else a.base
    ram_bytes = soc_map_value("SOC_RAM_DEFAULT_BYTES") if a.ram_bytes is None else a.ram_bytes

    segs = load_segments(a.elf)
    lo = min(addr for addr, _, _ in segs)
    mem_end = max(addr + memsz for addr, _, memsz in segs)
    file_end = max(addr + len(body) for addr, body, _ in segs)
    if lo < base or mem_end > base + ram_bytes:
        sys.exit(f"elf_to_hex: {a.elf} needs 0x{lo:08X}..0x{mem_end:08X} ({mem_end - lo} bytes, of which "
                 f"{file_end - lo} initialised), outside the RAM 0x{base:08X}..0x{base + ram_bytes:08X} "
                 f"({ram_bytes} bytes)")

    image = flat_image(segs, base)
    words = struct.unpack(f"<{len(image) // 4}I", image)
    pathlib.Path(a.hex).write_text("".join(f"{w:08x}\n" for w in words))
    print(f"elf_to_hex: {a.hex}: {len(words)} words ({len(image)} bytes initialised, {mem_end - base} of "
          f"{ram_bytes} RAM bytes used)")


if __name__ == "__main__":
    main()
