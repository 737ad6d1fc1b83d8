#!/usr/bin/env python3
"""Classify the pixels of an anaglyph frame (PNG, 8-bit RGB as cosim/png_write.c writes it) by eye.

The write mask's anaglyph (firmware/render/palette.h, palette_build_anaglyph) shows palette index
(l << 4) | r as RGB (l, r, r): red is the left eye, green = blue the right eye. A pixel is
  both    red and cyan non-zero: the two eyes overlap there and each kept its own plane
  left    red only
  right   cyan only
  other   neither palette form (green != blue): not an anaglyph pixel at all
Black (the background of both eyes) is not counted.

    anaglyph_pixels.py FRAME.png --expect-both     fail unless many pixels carry both eyes, both
                                                   eyes also show alone, and none is `other`
    anaglyph_pixels.py FRAME.png --expect-none     fail if any pixel carries both eyes (a GPU
                                                   without the mask: the right eye overwrites)
    anaglyph_pixels.py FRAME.png --crop X Y W H OUT.png   also write that region, scaled 2x

Prints one line of counts. Exit 1 on a failed expectation, 2 on a bad file.
"""
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype != 2 or interlace != 0:
                print(f"{path}: only 8-bit RGB non-interlaced PNGs are read", file=sys.stderr)
                sys.exit(2)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = width * 3
    rows, prev = [], bytearray(stride)
    for y in range(height):
        ftype = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, rows


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\x00" + r for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[1] not in ("--expect-both", "--expect-none"):
        print(__doc__, file=sys.stderr)
        return 2
    width, height, rows = read_png(args[0])
    counts = {"both": 0, "left": 0, "right": 0, "other": 0}
    for row in rows:
        for x in range(width):
            r, g, b = row[3 * x], row[3 * x + 1], row[3 * x + 2]
            if g != b:
                counts["other"] += 1
            elif r and g:
                counts["both"] += 1
            elif r:
                counts["left"] += 1
            elif g:
                counts["right"] += 1
    print(f"{args[0]}: both eyes {counts['both']}, left only {counts['left']}, right only "
          f"{counts['right']}, not anaglyph {counts['other']} (screen pixels)")
    if len(args) >= 8 and args[2] == "--crop":
        x0, y0, w, h = (int(v) for v in args[3:7])
        out = []
        for y in range(y0, y0 + h):
            line = b"".join(rows[y][3 * x:3 * x + 3] * 2 for x in range(x0, x0 + w))
            out += [line, line]
        write_png(args[7], 2 * w, 2 * h, out)
    if args[1] == "--expect-both":
        # Where the eyes overlap most of an object is seen by both: far more pixels carry both
        # planes than either eye's fringe, and each fringe exists (the eyes are apart).
        ok = counts["other"] == 0 and counts["both"] > 2000 and counts["left"] > 0 and \
            counts["right"] > 0 and counts["both"] > counts["left"] and counts["both"] > counts["right"]
    else:
        ok = counts["both"] == 0 and counts["left"] > 0 and counts["right"] > 0
    if not ok:
        print(f"{args[0]}: expectation {args[1]} not met", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
