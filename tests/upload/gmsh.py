#!/usr/bin/env python3
"""Mesh files (docs/mesh-format.md) for the tests, written independently of tools/meshconv: a
cube or a UV sphere, valid, or broken in one named way (each rule of the format), so that the
firmware's validator and the upload's rejections can be checked rule by rule.

    gmsh.py cube OUT.gmsh [--break RULE] [--material M]
    gmsh.py sphere OUT.gmsh --rings R --segments S [--break RULE]
    gmsh.py --rules          the RULE names
"""
import argparse
import math
import struct
import sys
import zlib

FRAC = 12
ONE = 16384


def cube():
    v = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    faces = []
    for a, b, c, d in quads:
        faces += [(a, b, c), (a, c, d)]
    return [tuple(4.0 * c for c in p) for p in v], faces


def sphere(rings, segments):
    v = [(0.0, 4.0, 0.0)]
    for i in range(1, rings):
        t = math.pi * i / rings
        for j in range(segments):
            p = 2 * math.pi * j / segments
            v.append((4.0 * math.sin(t) * math.cos(p), 4.0 * math.cos(t), 4.0 * math.sin(t) * math.sin(p)))
    v.append((0.0, -4.0, 0.0))
    faces = []
    ring = lambda i, j: 1 + (i - 1) * segments + (j % segments)
    for j in range(segments):
        faces.append((0, ring(1, j + 1), ring(1, j)))
        faces.append((len(v) - 1, ring(rings - 1, j), ring(rings - 1, j + 1)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)
            faces += [(a, b, c), (a, c, d)]
    return v, faces


def normal(v, f):
    a, b, c = (v[i] for i in f)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    length = math.sqrt(sum(x * x for x in n))
    return tuple(int(round(x / length * ONE)) for x in n)


RULES = ["magic", "version", "frac_bits", "flags", "vert_count", "face_count", "size", "crc",
         "box", "vertex_outside", "index", "repeated_index", "normal", "material", "face_flags"]


def encode(verts, faces, material=8, broken=None):
    q = [tuple(int(round(c * (1 << FRAC))) for c in p) for p in verts]
    lo = [min(p[k] for p in q) for k in range(3)]
    hi = [max(p[k] for p in q) for k in range(3)]
    records = []
    for i, f in enumerate(faces):
        n = normal([tuple(c / (1 << FRAC) for c in p) for p in q], f)
        idx, mat, flags = list(f), material, 0
        if i == len(faces) // 2:
            if broken == "index":
                idx[1] = len(q) + 5
            elif broken == "repeated_index":
                idx[2] = idx[0]
            elif broken == "normal":
                n = (n[0] // 2, n[1] // 2, n[2] // 2)
            elif broken == "material":
                mat = 14
            elif broken == "face_flags":
                flags = 0x80
        records.append(struct.pack("<3H3hBB", *idx, *n, mat, flags))
    if broken == "box":
        lo[0], hi[0] = hi[0], lo[0]
    if broken == "vertex_outside":
        hi[1] -= 1
    nv = len(q) if broken != "vert_count" else 70000
    nf = len(faces) if broken != "face_count" else 0
    head = struct.pack("<4sHHII3h3hI", b"GMSX" if broken == "magic" else b"GMSH",
                       2 if broken == "version" else 1, 8 if broken == "frac_bits" else FRAC,
                       nv, nf, *lo, *hi, 1 if broken == "flags" else 0)
    body = head + b"".join(struct.pack("<3h", *p) for p in q) + b"".join(records)
    if broken == "size":
        body += b"\0\0"
    crc = zlib.crc32(body)
    if broken == "crc":
        crc ^= 1
    return body + struct.pack("<I", crc)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("shape", nargs="?", choices=["cube", "sphere"])
    ap.add_argument("out", nargs="?")
    ap.add_argument("--break", dest="broken", choices=RULES)
    ap.add_argument("--material", type=int, default=8)
    ap.add_argument("--rings", type=int, default=12)
    ap.add_argument("--segments", type=int, default=16)
    ap.add_argument("--rules", action="store_true")
    a = ap.parse_args()
    if a.rules:
        print(" ".join(RULES))
        return 0
    if not a.shape or not a.out:
        ap.error("a shape and an output file")
    v, f = cube() if a.shape == "cube" else sphere(a.rings, a.segments)
    data = encode(v, f, a.material, a.broken)
    with open(a.out, "wb") as fh:
        fh.write(data)
    print(f"gmsh.py: {a.shape}: {len(v)} vertices, {len(f)} faces, {len(data)} bytes"
          + (f", broken: {a.broken}" if a.broken else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
