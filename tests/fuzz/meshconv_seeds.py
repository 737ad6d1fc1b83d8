#!/usr/bin/env python3
"""Seeds of fuzz_meshconv (tests/fuzz/fuzz_meshconv.c), written into the build directory:
small models of our own in the formats the harness's first byte selects. Byte 0 of each seed:
the format hint (low 4 bits), leave to simplify (bit 4), the capacity (bits 5-7)."""
import base64
import json
import os
import struct
import sys

OBJ, STL, OFF, GLTF = 0, 1, 3, 4  # 2 was PLY: fuzz_meshconv.c leaves it out
SIMPLIFY = 0x10


def cap(i):
    return i << 5


CUBE_V = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_F = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
          (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]


def obj():
    lines = ["v %g %g %g" % v for v in CUBE_V]
    lines += ["f %d %d %d" % tuple(i + 1 for i in f) for f in CUBE_F]
    return ("\n".join(lines) + "\n").encode()


def stl_ascii():
    out = ["solid s"]
    for f in CUBE_F[:4]:
        out.append("facet normal 0 0 0\nouter loop")
        out += ["vertex %g %g %g" % CUBE_V[i] for i in f]
        out.append("endloop\nendfacet")
    out.append("endsolid s")
    return ("\n".join(out) + "\n").encode()


def stl_binary():
    b = b"seed".ljust(80, b" ") + struct.pack("<I", len(CUBE_F))
    for f in CUBE_F:
        b += struct.pack("<3f", 0, 0, 0)
        for i in f:
            b += struct.pack("<3f", *CUBE_V[i])
        b += b"\0\0"
    return b


def off():
    lines = ["OFF", "8 12 0"] + ["%g %g %g" % v for v in CUBE_V]
    lines += ["3 %d %d %d" % f for f in CUBE_F]
    return ("\n".join(lines) + "\n").encode()


def gltf():
    pos = b"".join(struct.pack("<3f", *v) for v in CUBE_V)
    idx = b"".join(struct.pack("<3H", *f) for f in CUBE_F)
    buf = pos + idx
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "scale": [2, 1, 1]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.8, 0.1, 1]}}],
        "buffers": [{"byteLength": len(buf),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}],
    }
    return json.dumps(doc).encode()


SEEDS = {
    "obj-cube": (OBJ | cap(6), obj()),
    "obj-cube-simplify": (OBJ | SIMPLIFY | cap(2), obj()),
    "obj-cube-over": (OBJ | cap(2), obj()),
    "stl-ascii": (STL | cap(6), stl_ascii()),
    "stl-binary": (STL | SIMPLIFY | cap(3), stl_binary()),
    "obj-cube-large-cap": (OBJ | cap(7), obj()),
    "off-cube": (OFF | cap(5), off()),
    "gltf-cube": (GLTF | cap(6), gltf()),
}

if __name__ == "__main__":
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, (first, body) in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(bytes([first]) + body)
