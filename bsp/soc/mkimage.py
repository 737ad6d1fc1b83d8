#!/usr/bin/env python3
"""mkimage.py — the boot image of an SDRAM build's firmware (docs/boot.md): ELF -> IMAGE.

    mkimage.py PROGRAM.elf IMAGE [--mem-base ADDR --mem-bytes N]

The image is what the boot program (bsp/soc/boot/boot.c) reads from the flash: a header of eight
little-endian words — magic, header bytes, load address, payload bytes, entry, the payload's CRC-32,
0, the CRC-32 of the seven words before it — and the payload, the program's loadable segments from
the lowest address to the end of the last one's file contents (the gaps 0, padded to a word; .bss is
not in it). The constants come from contract/soc_map.h. An image whose memory (its .bss included)
does not lie within [mem-base, mem-base + mem-bytes) is refused with the numbers, as is an entry
outside the payload. Writes IMAGE and prints its size and CRC.
"""
import argparse
import pathlib
import struct
import sys
import zlib

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from elf_to_hex import flat_image, load_segments, soc_map_value  # noqa: E402  (the one ELF reader of bsp/soc)


def entry_of(path):
    return struct.unpack_from("<I", pathlib.Path(path).read_bytes(), 24)[0]


def build_image(segs, entry):
    """(header + payload bytes, load address, payload bytes) of the loadable segments segs."""
    load = min(addr for addr, _, _ in segs)
    payload = flat_image(segs, load)
    if not load <= entry < load + len(payload) or entry % 4:
        sys.exit(f"mkimage: the entry 0x{entry:08X} is not a word of the payload 0x{load:08X}..0x{load + len(payload):08X}")
    words = [soc_map_value("SOC_BOOT_IMAGE_MAGIC"), soc_map_value("SOC_BOOT_IMAGE_HEADER_BYTES"), load,
             len(payload), entry, zlib.crc32(payload), 0]
    head = struct.pack("<7I", *words)
    head += struct.pack("<I", zlib.crc32(head))
    assert len(head) == soc_map_value("SOC_BOOT_IMAGE_HEADER_BYTES")
    return head + bytes(payload), load, len(payload)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf")
    ap.add_argument("image")
    ap.add_argument("--mem-base", type=lambda s: int(s, 0), default=None)
    ap.add_argument("--mem-bytes", type=lambda s: int(s, 0), default=None)
    a = ap.parse_args()
    base = soc_map_value("SOC_SDRAM_BASE") if a.mem_base is None else a.mem_base
    size = soc_map_value("SOC_SDRAM_DEFAULT_BYTES") if a.mem_bytes is None else a.mem_bytes

    # Segments without file bytes (linker/soc.ld's .fast: the stack and scratch in the on-chip RAM,
    # which postlink checks) have nothing to copy.
    segs = [seg for seg in load_segments(a.elf) if len(seg[1]) > 0]
    lo = min(addr for addr, _, _ in segs)
    mem_end = max(addr + memsz for addr, _, memsz in segs)
    if lo < base or mem_end > base + size:
        sys.exit(f"mkimage: {a.elf} needs 0x{lo:08X}..0x{mem_end:08X} ({mem_end - lo} bytes), outside the memory "
                 f"0x{base:08X}..0x{base + size:08X} ({size} bytes) it is loaded into")
    image, load, nbytes = build_image(segs, entry_of(a.elf))
    flash_room = soc_map_value("SOC_FLASH_WINDOW_BYTES") - soc_map_value("SOC_BOOT_FLASH_IMAGE_OFFSET")
    if len(image) > flash_room:
        sys.exit(f"mkimage: the image ({len(image)} bytes) is larger than the flash holds above its offset "
                 f"({flash_room} bytes)")
    pathlib.Path(a.image).write_bytes(image)
    print(f"mkimage: {a.image}: {nbytes} bytes to 0x{load:08X}, entry 0x{entry_of(a.elf):08X}, "
          f"CRC 0x{zlib.crc32(image[32:]):08X}")


if __name__ == "__main__":
    main()
