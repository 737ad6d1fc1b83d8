#!/usr/bin/env python3
"""depth_tiny.py OUT: a list of small depth-tested triangles piled on a few strips' boundaries
(suite raster-strips). Each covers a few pixels of a span, so a span cleared by epoch (strip
builds, gpu_raster) is first written by a triangle that wins only some of its lanes, and the
triangles after it, four at each place, test against what that write left in the others: seen to
fail with the stale span's write covering only its winning lanes, and with a cleared span compared
against the RAM's old depths. Fixed seed: the same list every run."""
import random
import sys

rng = random.Random(26)
with open(sys.argv[1], "w") as out:
    out.write("clear 3\n")
    for _ in range(750):
        # a 64 x 48 pixel area across the boundaries of rows 16 and 32 (and 48 = 16 x 3), in Q12.4;
        # four triangles in a row at each place, so that they meet in the same spans
        x, y = rng.randint(288 * 16, 352 * 16), rng.randint(8 * 16, 56 * 16)
        for _ in range(4):
            pts = [(x + rng.randint(-96, 96), y + rng.randint(-96, 96)) for _ in range(3)]
            z = [rng.randint(0, 65535) for _ in range(3)]
            out.write("ztri %d %d %d %d %d %d %d %d %d %d\n"
                      % (pts[0][0], pts[0][1], z[0], pts[1][0], pts[1][1], z[1], pts[2][0], pts[2][1], z[2],
                         rng.randint(1, 255)))
