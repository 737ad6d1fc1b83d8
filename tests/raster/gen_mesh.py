#!/usr/bin/env python3
"""Primitive lists of triangle meshes whose triangles share edges and never overlap, for the
exact-once coverage test (tests/raster/mesh.sh): every pixel centre inside a mesh must be written by
exactly one triangle — no cracks, no double writes.

    gen_mesh.py grid SEED   jittered grid over the whole Q12.4 range (outer ring on the guard-band
                            corners, interior vertices jittered by up to +-1 px, some on pixel centres)
    gen_mesh.py fan SEED    a fan of triangles around a vertex exactly on a pixel centre
"""
import math
import random
import sys


def grid(rng):
    cols, rows = 13, 11
    xs = [-32768] + [round(i * 5120 / (cols - 2)) for i in range(cols - 1)] + [32767]
    ys = [-32768] + [round(j * 3840 / (rows - 2)) for j in range(rows - 1)] + [32767]
    pts = {}
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            inner = 0 < i < len(xs) - 1 and 0 < j < len(ys) - 1
            if inner:
                if rng.random() < 0.3:  # snap onto a pixel centre: edges through sample points
                    x, y = (x // 16) * 16 + 8, (y // 16) * 16 + 8
                else:
                    x, y = x + rng.randint(-16, 16), y + rng.randint(-16, 16)
            pts[i, j] = (x, y)
    out = ["clear 0"]
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            a, b, c, d = pts[i, j], pts[i + 1, j], pts[i, j + 1], pts[i + 1, j + 1]
            tris = [(a, b, d), (a, d, c)] if rng.random() < 0.5 else [(a, b, c), (b, d, c)]
            for t in tris:
                if rng.random() < 0.5:  # either winding
                    t = (t[0], t[2], t[1])
                out.append("tri %d %d %d %d %d %d %d" % (*t[0], *t[1], *t[2], rng.randint(1, 255)))
    return out


def fan(rng):
    cx, cy = 160 * 16 + 8, 120 * 16 + 8
    n = rng.randint(5, 24)
    # Every angular gap stays below pi, so neighbouring triangles never fold over each other.
    angles = [2 * math.pi * (k + rng.uniform(-0.4, 0.4)) / n for k in range(n)]
    radii = [rng.uniform(300, 1800) for _ in angles]
    ring = [(cx + round(r * math.cos(a)), cy + round(r * math.sin(a))) for r, a in zip(radii, angles)]
    out = ["clear 0"]
    for k in range(n):
        p, q = ring[k], ring[(k + 1) % n]
        out.append("tri %d %d %d %d %d %d %d" % (cx, cy, *p, *q, rng.randint(1, 255)))
    return out


if __name__ == "__main__":
    kind, seed = sys.argv[1], int(sys.argv[2])
    print("\n".join({"grid": grid, "fan": fan}[kind](random.Random(seed))))
