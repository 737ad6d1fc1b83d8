#!/usr/bin/env bash
# Exact-once coverage through the RTL: meshes of edge-sharing triangles drawn over colour 0 must
# write every covered pixel exactly once (PERF_PIXELS equals the number of non-zero pixels), a mesh
# over the whole guard band must cover every pixel of the frame, and RTL and model must agree.
# The rasterizer is the subject, not the scan-out: the fast display path reads the frame from the
# RTL's front bank in 1/40 of the time a VGA capture takes.
source "$(dirname "$0")/../lib.sh"
need GPUSIM_FAST BUILD PYTHON
work=$(fresh_dir raster-mesh)
checked=0
for kind in grid fan; do
    for seed in 1 2 3 4 5 6; do
        "$PYTHON" tests/raster/gen_mesh.py "$kind" "$seed" >"$work/$kind$seed.txt"
        "$GPUSIM_FAST" raster --in "$work/$kind$seed.txt" --out "$work/$kind$seed" >/dev/null
        "$PYTHON" - "$work/$kind$seed" "$kind" <<'PY'
import json, sys, tomllib
out, kind = sys.argv[1], sys.argv[2]
limits = tomllib.load(open("contract/gpu_contract.toml", "rb"))["limits"]
pixels = limits["fb_width"] * limits["fb_height"]
stats = json.load(open(out + "/stats.json"))
raw = open(out + "/rtl.raw", "rb").read()
covered = sum(1 for b in raw if b)
if stats["pixels"] != covered:
    sys.exit(f"{out}: {stats['pixels']} pixel writes for {covered} covered pixels: a pixel was written twice")
if kind == "grid" and covered != pixels:
    sys.exit(f"{out}: {pixels - covered} pixels left uncovered by a mesh over the whole screen: a crack")
PY
        checked=$((checked + 1))
    done
done
pass "mesh: $checked meshes, every covered pixel written exactly once, no cracks"
