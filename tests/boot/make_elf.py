#!/usr/bin/env python3
"""make_elf.py — a minimal 32-bit little-endian RISC-V ELF for the boot image's tests (tests/boot):
two PT_LOAD segments, a gap between them, and a .bss beyond the second's file contents.

    make_elf.py OUT.elf BASE ENTRY_OFFSET TEXT_BYTES GAP DATA_BYTES BSS_BYTES

The text is bytes i*7 mod 251, the data i*13 mod 241 (any known, non-repeating contents do).
"""
import struct
import sys


def main():
    out, base, entry_off, text_n, gap, data_n, bss_n = sys.argv[1], *(int(v, 0) for v in sys.argv[2:8])
    text = bytes(i * 7 % 251 for i in range(text_n))
    data = bytes(i * 13 % 241 for i in range(data_n))
    ehsize, phentsize = 52, 32
    text_off = ehsize + 2 * phentsize
    data_off = text_off + len(text)
    data_addr = base + text_n + gap
    ident = b"\x7fELF" + bytes([1, 1, 1]) + bytes(9)
    header = ident + struct.pack("<HHIIIIIHHHHHH", 2, 243, 1, base + entry_off, ehsize, 0, 0, ehsize, phentsize, 2, 40, 0, 0)
    ph_text = struct.pack("<IIIIIIII", 1, text_off, base, base, text_n, text_n, 5, 4)
    ph_data = struct.pack("<IIIIIIII", 1, data_off, data_addr, data_addr, data_n, data_n + bss_n, 6, 4)
    with open(out, "wb") as f:
        f.write(header + ph_text + ph_data + text + data)


if __name__ == "__main__":
    main()
