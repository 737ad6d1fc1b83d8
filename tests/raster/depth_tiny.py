#!/usr/bin/env python3
"""depth_tiny.py OUT: a list of small depth-tested triangles piled on a few strips' boundaries
(suite raster-strips). Each is a few pixels wide, so one triangle's span is often the next one's
two clocks later: the case where the depth buffer's write of a span cleared by epoch (strip
builds) must be seen by the read of the next triangle (gpu_span_walker's forwarding). Fixed seed:
the same list every run."""
import random
import sys

rng = random.Random(26)
with open(sys.argv[1], "w") as out:
    out.write("clear 3\n")
    for _ in range(750):
        # a 64 x 48 pixel area across the boundaries of rows 16 and 32 (and 48 = 16 x 3), in Q12.4;
        # four triangles in a row at each place, so that they meet in the same spans back to back
        x, y = rng.randint(288 * 16, 352 * 16), rng.randint(8 * 16, 56 * 16)
        for _ in range(4):
            pts = [(x + rng.randint(-96, 96), y + rng.randint(-96, 96)) for _ in range(3)]
            z = [rng.randint(0, 65535) for _ in range(3)]
            out.write("ztri %d %d %d %d %d %d %d %d %d %d\n"
                      % (pts[0][0], pts[0][1], z[0], pts[1][0], pts[1][1], z[1], pts[2][0], pts[2][1], z[2],
                         rng.randint(1, 255)))
