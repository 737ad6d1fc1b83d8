#!/usr/bin/env python3
"""xwd_to_png: an X window dump (`xwd -id WINDOW -silent`) as a PNG file, RGB888.

    xwd_to_png.py IN.xwd OUT.png

Reads the XWD header (big-endian 32-bit fields, X11 XWDFileHeader), takes ZPixmap images of 24 or 32
bits a pixel in the byte order the header states, and extracts each channel with the header's masks
(a TrueColor or DirectColor visual with 8 bits a channel, as Xvfb's depth-24 screen has; DirectColor's
colormap is taken as the identity, which is what X servers install for it). Anything else is refused
with a message. Written for the window test (tests/window/window.sh) and the README's screenshot:
netpbm's xwdtopnm reads Xvfb's little-endian dumps with the wrong byte order."""
import struct
import sys
import zlib

ZPIXMAP = 2
LSB_FIRST = 0


def fail(msg):
    sys.exit(f"xwd_to_png: {msg}")


def shift_of(mask):
    """The shift that brings an 8-bit channel mask down to 0xFF."""
    shift = (mask & -mask).bit_length() - 1  # the lowest set bit
    if mask == 0 or mask >> shift != 0xFF:
        fail(f"channel mask {mask:#x} is not 8 contiguous bits")
    return shift


def read_xwd(data):
    if len(data) < 100:
        fail("file shorter than an XWD header")
    (header_size, version, pixmap_format, _depth, width, height, _xoff, byte_order, _unit, _bit_order, _pad,
     bits_per_pixel, bytes_per_line, _visual, red_mask, green_mask, blue_mask, _bits_rgb, _cmap_entries,
     ncolors) = struct.unpack(">20I", data[:80])
    if version != 7 or pixmap_format != ZPIXMAP or bits_per_pixel not in (24, 32):
        fail(f"unsupported dump: version {version}, format {pixmap_format}, {bits_per_pixel} bits a pixel")
    start = header_size + 12 * ncolors  # XWDColor entries follow the header and the window name
    if len(data) < start + bytes_per_line * height:
        fail("pixel data cut short")
    shifts = [shift_of(m) for m in (red_mask, green_mask, blue_mask)]
    step = bits_per_pixel // 8
    order = "little" if byte_order == LSB_FIRST else "big"
    rows = []
    for y in range(height):
        line = data[start + y * bytes_per_line:start + y * bytes_per_line + width * step]
        row = bytearray(3 * width)
        for x in range(width):
            p = int.from_bytes(line[x * step:(x + 1) * step], order)
            row[3 * x:3 * x + 3] = bytes((p >> s) & 0xFF for s in shifts)
        rows.append(bytes(row))
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\0" + r for r in rows)  # filter type 0 on every row
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(png)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: xwd_to_png.py IN.xwd OUT.png")
    with open(sys.argv[1], "rb") as f:
        width, height, rows = read_xwd(f.read())
    write_png(sys.argv[2], width, height, rows)


if __name__ == "__main__":
    main()
