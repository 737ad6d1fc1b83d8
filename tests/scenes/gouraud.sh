#!/usr/bin/env bash
# Gouraud shading end to end (ENABLE_GOURAUD, CAPS_GOURAUD; firmware FW_WITH_GOURAUD):
#  1. The landscape (its objects carry vertex normals) co-simulated on a GPU built with Gouraud
#     triangles ($BUILD/sim-fast-g-w8, the fast display path, CTRL_DITHER on): every frame equals
#     the golden model's (the harness checks it) and the host build's on the model with --gouraud.
#  2. The same firmware on a GPU without them draws the landscape flat: its frames differ from the
#     Gouraud ones (the shading is really there), and a Gouraud frame has more distinct colours.
#  3. Scenes without vertex normals are unchanged by a GPU with Gouraud (tetra, knot: identical
#     frames with and without --gouraud), and the float backend shades the landscape too.
#  4. Against the unquantised frames U (fw-host --unquantised-frames: bench-error's undithered
#     reference), frame by frame: Gouraud undithered is nearer than flat, and the dither brings the
#     4 x 4 box means nearer than without it (png_diff --box 4); the frames drawn beside U are
#     those drawn without it.
source "$(dirname "$0")/../lib.sh"
need BUILD
dir="$BUILD/fw-test"
gsim="$BUILD/sim-fast-g-w8/gpusim"
need_file "$dir/landscape.elf" "$dir/host-landscape" "$dir/host-landscape-float" "$dir/host-tetra" \
    "$dir/host-knot" "$dir/host-landscape-nodither" "$BUILD/tools/png_diff" "$gsim"
work=$(fresh_dir scene-gouraud)

# 1. co-simulated against the host build
run_to "$work/cosim.out" 300 "$gsim" cosim --fw "$dir/landscape.elf" --frames "$work/cosim" \
    --uart-log "$work/cosim.log" --summary "$work/summary.txt"
[ "$status" -eq 0 ] || { tail -n 5 "$work/cosim.out"; fail "Gouraud co-simulation failed (status $status)"; }
"$dir/host-landscape" --gouraud --frames "$work/host" >"$work/host.log"
same_pngs "$work/cosim" "$work/host" "Gouraud landscape"
expect_no_line "errors 0x[1-9a-f]" "$work/cosim.log"
echo "cosim: $(png_count "$work/cosim") Gouraud landscape frames, RTL = model = host build"

# 2. flat on a GPU without Gouraud, and the difference is real
"$dir/host-landscape" --frames "$work/flat" >"$work/flat.log"
for f in "$work"/flat/*.png; do
    cmp -s "$f" "$work/host/$(basename "$f")" && fail "flat frame $(basename "$f") equals the Gouraud one"
done
colours() { "$PYTHON" - "$1" <<'EOF'
import sys, zlib, struct
data = open(sys.argv[1], "rb").read()
# Decode the PNG's IDAT (8-bit RGB, filter bytes per row) just enough to count distinct pixels.
pos, idat, w, h = 8, b"", 0, 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        w, h = struct.unpack(">II", body[:8])
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
stride = 3 * w + 1
prev = bytearray(3 * w)
seen = set()
for y in range(h):
    ft, row = raw[y * stride], bytearray(raw[y * stride + 1:(y + 1) * stride])
    for i in range(len(row)):
        a = row[i - 3] if i >= 3 else 0
        b = prev[i]
        c = prev[i - 3] if i >= 3 else 0
        if ft == 1: row[i] = (row[i] + a) & 255
        elif ft == 2: row[i] = (row[i] + b) & 255
        elif ft == 3: row[i] = (row[i] + (a + b) // 2) & 255
        elif ft == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            row[i] = (row[i] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
    seen.update(bytes(row[i:i + 3]) for i in range(0, len(row), 3))
    prev = row
print(len(seen))
EOF
}
cg=$(colours "$work/host/0001.png")
cf=$(colours "$work/flat/0001.png")
[ "$cg" -gt "$cf" ] || fail "Gouraud frame has $cg colours, not more than the flat one's $cf"
echo "flat: frames differ from Gouraud; frame 1 shows $cf colours flat, $cg Gouraud"

# 3. scenes without vertex normals: unchanged by the GPU's Gouraud; the float backend shades
for scene in tetra knot; do
    "$dir/host-$scene" --frames "$work/$scene-plain" >/dev/null
    "$dir/host-$scene" --gouraud --frames "$work/$scene-g" >/dev/null
    same_pngs "$work/$scene-plain" "$work/$scene-g" "$scene with and without CAPS_GOURAUD"
done
"$dir/host-landscape-float" --gouraud --frames "$work/float-g" >/dev/null
"$dir/host-landscape-float" --frames "$work/float-flat" >/dev/null
cmp -s "$work/float-g/0001.png" "$work/float-flat/0001.png" && fail "float backend: Gouraud frame equals the flat one"

# 4. the error against the unquantised frames
"$dir/host-landscape" --gouraud --frames "$work/dithered" --unquantised-frames "$work/unquantised" >/dev/null
"$dir/host-landscape-nodither" --gouraud --frames "$work/undithered" >/dev/null
same_pngs "$work/dithered" "$work/host" "the landscape with and without --unquantised-frames"
field() { "$BUILD/tools/png_diff" --block 2 --box 4 "$work/unquantised/$2" "$work/$3/$2" | awk -v k="$1" '{for (i = 1; i < NF; i++) if ($i == k) print $(i + 1)}'; }
for f in "$work"/unquantised/*.png; do
    n=$(basename "$f")
    flat=$(field abs_sum "$n" flat)
    und=$(field abs_sum "$n" undithered)
    und_box=$(field box_abs_sum "$n" undithered)
    dith_box=$(field box_abs_sum "$n" dithered)
    [ -n "$flat" ] && [ -n "$und" ] && [ -n "$und_box" ] && [ -n "$dith_box" ] || fail "png_diff on $n"
    [ "$und" -gt 0 ] || fail "$n: the unquantised frame equals the undithered one (no Gouraud pixel?)"
    [ "$und" -lt "$flat" ] || fail "$n: undithered Gouraud ($und) not nearer U than flat ($flat)"
    [ "$dith_box" -lt "$und_box" ] || fail "$n: 4x4 box error dithered $dith_box not below undithered $und_box"
done
echo "unquantised: last frame's |dRGB| sums against U: flat $flat, Gouraud $und; 4x4 box sums: undithered $und_box, dithered $dith_box"
pass "gouraud: landscape co-simulated on the Gouraud GPU = host build; flat elsewhere; other scenes unchanged; nearer U: Gouraud than flat, dithered boxes than undithered"
