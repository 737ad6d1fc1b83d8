#!/usr/bin/env python3
"""The strip renderer's binning workload, counted from the scenes' own batches (issue #26's
"binning" choice): for each scene and strip height, how many strips each primitive reaches and
what that costs each way of getting primitives to their strips.

    strip_bins.py SCALE HEIGHT... -- SCENE=LISTDIR...

LISTDIR holds one scene's batches as `gpusim cosim --dump-lists` writes them (batchNNNN.txt, the
`make raster` list format; a batch that clears starts a frame). SCALE multiplies the lists' frame
(the contract's 320x240) to the strip renderer's (2 for 640x480: every coordinate doubled, which
is what the firmware's projection does at twice the size); HEIGHT is a strip height in lines of
the scaled frame.

A primitive reaches the strips that hold a row of its box of pixel centres (a line: the rows
between its end points); one that covers no pixel centre reaches none. Columns (per frame, the
mean over the frames of the lists):
  prims      primitives submitted
  strips     strips of the frame
  reached    primitive-strip pairs: what a binned primitive is drawn as
  per prim   reached / prims
  G fetch    the GPU walking each batch once per strip: primitives fetched, batches x strips x
             the batch's primitives (the set-up takes one every 3 clocks: three vertex reads)
  G clocks   3 x G fetch: the set-up's clocks before any pixel, against 3 x prims today
  F resent   the firmware binning after projection: the primitives sent beyond the first time
             (reached less the primitives that reach a strip at all), each with its vertices
             again (batch.c) and one more bin entry
"""
import math
import os
import re
import sys

SUB = 16  # Q12.4


def rows_of(op, vals, scale, height):
    """First and last pixel row a primitive covers in the scaled frame, or None."""
    if op in ("tri", "ztri", "gtri"):
        step = 3 if op != "tri" else 2
        ys = [vals[1 + i * step] * scale for i in range(3)]
        lo = math.ceil((min(ys) - SUB // 2) / SUB)   # rows whose centre y*16+8 is inside the box
        hi = math.floor((max(ys) - SUB // 2) / SUB)
    elif op == "line":
        ys = [vals[1] * scale, vals[3] * scale]
        lo, hi = min(ys) // SUB, max(ys) // SUB
    else:
        return None
    lo, hi = max(lo, 0), min(hi, height - 1)
    return (lo, hi) if lo <= hi else None


def load_frames(listdir, scale, frame_h):
    """Frames of batches, each batch a list of (first row, last row) or None per primitive."""
    frames, current = [], None
    for name in sorted(os.listdir(listdir)):
        if not re.match(r"batch\d+\.txt$", name):
            continue
        batch = []
        with open(os.path.join(listdir, name)) as f:
            for line in f:
                words = line.split("#")[0].split()
                if not words:
                    continue
                if words[0] == "clear":
                    if current is None or batch or any(current):
                        current = []
                        frames.append(current)
                    continue
                batch.append(rows_of(words[0], [int(w) for w in words[1:]], scale, frame_h))
        if current is None:
            current = []
            frames.append(current)
        current.append(batch)
    return [fr for fr in frames if any(fr)]


def main():
    if "--" not in sys.argv or len(sys.argv) < 5:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    cut = sys.argv.index("--")
    scale = int(sys.argv[1])
    heights = [int(h) for h in sys.argv[2:cut]]
    frame_h = 240 * scale
    print(f"| scene | strip height | strips | prims | reached | per prim | G fetch | G clocks | F resent |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for arg in sys.argv[cut + 1:]:
        scene, listdir = arg.split("=", 1)
        frames = load_frames(listdir, scale, frame_h)
        if not frames:
            print(f"strip_bins: {listdir}: no batches", file=sys.stderr)
            return 1
        for h in heights:
            strips = -(-frame_h // h)
            tot = {"prims": 0, "drawn": 0, "reached": 0, "gfetch": 0}
            for fr in frames:
                for batch in fr:
                    tot["prims"] += len(batch)
                    tot["gfetch"] += strips * len(batch)
                    for r in batch:
                        if r is not None:
                            tot["drawn"] += 1
                            tot["reached"] += r[1] // h - r[0] // h + 1
            n = len(frames)
            prims, drawn, reached, gfetch = (tot[k] / n for k in ("prims", "drawn", "reached", "gfetch"))
            print(f"| {scene} | {h} | {strips} | {prims:,.0f} | {reached:,.0f} | "
                  f"{reached / max(prims, 1):.2f} | {gfetch:,.0f} | {3 * gfetch:,.0f} | {reached - drawn:,.0f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
