#!/usr/bin/env bash
# tests/meshconv/run.sh — the model converter (tools/meshconv) on real models and on bad ones.
#
#   - real models convert and pass --check (the firmware's validator): spider.obj, the binary and
#     ASCII spider STL (identical files), cube.ply and cube_binary.ply (identical), a glTF 2 box,
#     a glTF with a node transform and a base colour (tests/fuzz/meshconv_seeds.py's), Wuson.ply;
#   - every file of assimp's invalid/ set: a non-zero status with one "meshconv: error:" line and
#     no output, or a valid file;
#   - generated bad input: empty, random bytes, NaN and infinite coordinates, indices out of range,
#     a PLY whose header claims more than it holds, points only, lines only: refused, no output;
#   - scale: a cube at 1e30 and at 1e-30 gives the unit cube's bytes;
#   - capacity: over it without --max-faces, status 3 with the numbers; with --max-faces 500 at
#     most 500 faces and a valid file; a 100k-face sphere with --max-faces 4096 (its time printed);
#   - a corrupted file fails --check; usage errors give status 2.
source "$(dirname "$0")/../lib.sh"
need BUILD
: "${MESHCONV:=$BUILD/tools/meshconv}" "${PYTHON:=python3}"
MODELS=${MESHCONV_MODELS:-/usr/share/assimp/models}
need_file "$MESHCONV" "$MODELS/OBJ/spider.obj"
work=$(fresh_dir meshconv)
# The converter's default capacity: the firmware's (meshfile.h).
cap_faces=$(sed -n 's/^#define MESHFILE_DEFAULT_MAX_FACES \([0-9]*\)u.*/\1/p' firmware/model/meshfile.h)
cap_verts=$(sed -n 's/^#define MESHFILE_DEFAULT_MAX_VERTS \([0-9]*\)u.*/\1/p' firmware/model/meshfile.h)
[ -n "$cap_faces" ] && [ -n "$cap_verts" ] || fail "no MESHFILE_DEFAULT_MAX_* in firmware/model/meshfile.h"
[ "$cap_faces" -lt 3732 ] || fail "Wuson.ply (3732 faces) is within the default $cap_faces faces"
checks=0

# convert NAME IN [OPTIONS]: IN -> $work/NAME.gmsh, status 0 and a valid file required.
convert() {
    local name="$1" in="$2"
    shift 2
    run_to "$work/$name.log" 60 "$MESHCONV" "$in" "$work/$name.gmsh" "$@"
    [ "$status" -eq 0 ] || fail "$name: status $status: $(tail -n 3 "$work/$name.log")"
    valid "$name" "$@"
}

# valid NAME [--max-faces N] [--max-verts N]: $work/NAME.gmsh passes --check with these limits.
valid() {
    local name="$1" limits=()
    shift
    while [ $# -gt 0 ]; do
        case "$1" in
            --max-faces|--max-verts) limits+=("$1" "$2"); shift 2 ;;
            *) shift ;;
        esac
    done
    run_to "$work/$name.check" 10 "$MESHCONV" --check "$work/$name.gmsh" "${limits[@]}"
    [ "$status" -eq 0 ] || fail "$name: --check refuses it: $(cat "$work/$name.check")"
    checks=$((checks + 1))
}

# refused NAME IN [WANT_STATUS [PATTERN [OPTIONS...]]]: a non-zero status (WANT_STATUS when not
# empty), exactly one "meshconv: error:" line on stderr (matching PATTERN when not empty), and no
# output file.
refused() {
    local name="$1" in="$2" want="${3:-}" pattern="${4:-}"
    shift $(($# < 4 ? $# : 4))
    rm -f "$work/$name.gmsh"
    status=0
    timeout 60 "$MESHCONV" "$in" "$work/$name.gmsh" "$@" >"$work/$name.out" 2>"$work/$name.err" || status=$?
    [ "$status" -ne 0 ] || fail "$name: accepted"
    [ "$status" -lt 124 ] || fail "$name: status $status (a crash or a timeout)"
    [ -z "$want" ] || expect_status "$want" "$name"
    [ "$(count '^meshconv: error: ' "$work/$name.err")" -eq 1 ] ||
        fail "$name: expected one 'meshconv: error:' line, got: $(cat "$work/$name.err")"
    [ -z "$pattern" ] || expect_line "^meshconv: error: .*$pattern" "$work/$name.err"
    [ ! -e "$work/$name.gmsh" ] || fail "$name: an output file was left behind"
    [ -z "$(find "$work" -name "$name.gmsh.tmp*")" ] || fail "$name: a temporary file was left behind"
    checks=$((checks + 1))
}

# The number after "valid: ... N faces" of a --check log.
faces_of() { sed -n 's/.*valid: [0-9]* vertices, \([0-9]*\) faces.*/\1/p' "$work/$1.check"; }
ms_of() { sed -n 's/.*, in \([0-9]*\) ms$/\1/p' "$work/$1.log"; }

# ---- real models ----
# At a capacity they all fit (the default is the SoC's, smaller than the spider): conversion, not
# simplification, is what this part checks.
roomy=(--max-faces 4096 --max-verts 4096)
convert spider "$MODELS/OBJ/spider.obj" "${roomy[@]}"
expect_line '^meshconv: wrote .*spider.gmsh' "$work/spider.log"
convert stl_bin "$MODELS/STL/Spider_binary.stl" "${roomy[@]}"
convert stl_ascii "$MODELS/STL/Spider_ascii.stl" "${roomy[@]}"
cmp -s "$work/stl_bin.gmsh" "$work/stl_ascii.gmsh" || fail "Spider_binary.stl and Spider_ascii.stl differ"
convert ply "$MODELS/PLY/cube.ply" "${roomy[@]}"
convert ply_bin "$MODELS/PLY/cube_binary.ply" "${roomy[@]}"
cmp -s "$work/ply.gmsh" "$work/ply_bin.gmsh" || fail "cube.ply and cube_binary.ply differ"
expect_eq "$(faces_of ply)" 12 "cube.ply's faces (6 quads)"
convert gltf2 "$MODELS/glTF2/BoxTextured-glTF/BoxTextured.gltf" "${roomy[@]}"
expect_eq "$(faces_of gltf2)" 12 "the glTF 2 box's faces"
# A node's transform (scale 2 in x) is applied, and a glTF base colour picks its material.
"$PYTHON" -c 'import sys; sys.path.insert(0, "tests/fuzz"); import meshconv_seeds as s; sys.stdout.buffer.write(s.gltf())' \
    >"$work/scaled.gltf"
convert scaled "$work/scaled.gltf" "${roomy[@]}"
expect_line 'box \(-16384 -8192 -8192\) \.\. \(16384 8192 8192\)' "$work/scaled.check"
expect_line '^meshconv: materials: 12 faces coloured.*: green 12$' "$work/scaled.log"
# Wuson (3732 faces) is over the default capacity: simplified to it.
convert wuson "$MODELS/PLY/Wuson.ply" --max-faces "$cap_faces"

# ---- assimp's invalid models: refused cleanly, or converted to a valid file ----
invalid=0
for f in "$MODELS"/invalid/*; do
    name="invalid_$(basename "$f" | tr -c 'A-Za-z0-9_\n' _)"
    status=0
    timeout 60 "$MESHCONV" "$f" "$work/$name.gmsh" >"$work/$name.out" 2>"$work/$name.err" || status=$?
    if [ "$status" -eq 0 ]; then
        valid "$name"
    else
        refused "$name" "$f"
    fi
    invalid=$((invalid + 1))
done
[ "$invalid" -gt 0 ] || fail "no files in $MODELS/invalid"

# ---- generated bad input ----
gen="$work/gen"
mkdir -p "$gen"
: >"$gen/empty.obj"
head -c 4096 /dev/urandom >"$gen/random.bin"
cp "$gen/random.bin" "$gen/random.stl"
cp "$gen/random.bin" "$gen/random.ply"
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$gen/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n' >"$gen/inf.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$gen/index.obj"
printf 'ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$gen/short.ply"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\np 2\np 3\n' >"$gen/points.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n' >"$gen/lines.obj"
refused empty "$gen/empty.obj" 1
refused random "$gen/random.bin" 1
# Random bytes named as a format: assimp's reader of that format gets them.
for f in random.stl random.ply; do
    status=0
    timeout 60 "$MESHCONV" "$gen/$f" "$work/$f.gmsh" >"$work/$f.out" 2>&1 || status=$?
    if [ "$status" -eq 0 ]; then valid "$f"; else refused "$f" "$gen/$f" 1; fi
done
refused nan "$gen/nan.obj" 1 'non-finite'
refused inf "$gen/inf.obj" 1 'non-finite'
refused index "$gen/index.obj" 1 'index'
# The header claims 8 vertices and 12 faces, the body holds 3 and 1: refused, or converted from
# what is there (a valid file).
status=0
timeout 60 "$MESHCONV" "$gen/short.ply" "$work/short.gmsh" >"$work/short.log" 2>&1 || status=$?
if [ "$status" -eq 0 ]; then valid short; else refused short "$gen/short.ply" 1; fi
refused points "$gen/points.obj" 1 'no triangles'
# A binary PLY cut short (fuzz_meshconv's find from our own seed): assimp 5.2.5 crashes on it
# (SIGSEGV inside libassimp); the converter's child process takes the crash, the CLI reports it.
base64 -d >"$gen/crash.ply" <<'EOF'
cGx5CmZvcm1hdCBiaW5hcnlfbGl0dGxlX2VuZGlhbiAxLjAKZWxlbWVudCB2ZXJ0ZXggOApwcm9wZXJ0eSBmbG9hdCB4CnBy
b3BlcnR5IGZsb2F0IHkKcHJvcGVydHkgZmxvYXQgegpwcm9wZXJ0eSB1Y2hhciByZWQKcHJvcGVydHkgdWNoYXIgZ3JlAAAA
AwQAAAAFAAAABwAAAAMEAAAABwAAAAYAAAADAAAAAAEAAAAFAAAAAwAAAAAFAAAABAAAAAMCAAAABgAAAAcAAAADAgAAAAcA
AAADAAAAAwAAAAAEAAAABgAAAAMAAAAABgAAAAIAAAADAQAAAAMAAAAHAAAAAwEAAAAHAAAABQAAAA==
EOF
status=0
timeout 60 "$MESHCONV" "$gen/crash.ply" "$work/crash.gmsh" >"$work/crash.log" 2>&1 || status=$?
if [ "$status" -eq 0 ]; then valid crash; else refused crash "$gen/crash.ply" 1; fi
refused lines "$gen/lines.obj" 1 'no triangles'

# ---- scale: 1e30 and 1e-30 copies of the unit cube give its bytes ----
cube() {  # cube SCALE: a unit cube's OBJ (corners 0 and SCALE), 12 counter-clockwise triangles
    awk -v s="$1" 'BEGIN {
        for (i = 0; i < 8; i++) printf "v %s %s %s\n", (i % 2) ? s : 0, (int(i / 2) % 2) ? s : 0, (int(i / 4)) ? s : 0
        print "f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6"
    }'
}
cube 1 >"$gen/cube1.obj"
cube 1e30 >"$gen/cube1e30.obj"
cube 1e-30 >"$gen/cube1e-30.obj"
convert cube1 "$gen/cube1.obj"
convert cube1e30 "$gen/cube1e30.obj"
convert cube1e-30 "$gen/cube1e-30.obj"
cmp -s "$work/cube1.gmsh" "$work/cube1e30.gmsh" || fail "the 1e30 cube differs from the unit cube"
cmp -s "$work/cube1.gmsh" "$work/cube1e-30.gmsh" || fail "the 1e-30 cube differs from the unit cube"
expect_eq "$(faces_of cube1)" 12 "the cube's faces"
# Centred, and the largest half-extent 4.0 units (16384 in Q3.12): the cube's box, exactly.
expect_line 'box \(-16384 -16384 -16384\) \.\. \(16384 16384 16384\)' "$work/cube1.check"
convert cube_small "$gen/cube1.obj" --extent 1
expect_line 'box \(-4096 -4096 -4096\) \.\. \(4096 4096 4096\)' "$work/cube_small.check"

# ---- capacity ----
# sphere STACKS SLICES: a UV sphere, 2 * SLICES * (STACKS - 1) triangles.
sphere() {
    awk -v st="$1" -v sl="$2" 'BEGIN {
        pi = 3.14159265358979
        print "v 0 0 1"
        for (i = 1; i < st; i++) for (j = 0; j < sl; j++)
            printf "v %.9f %.9f %.9f\n", sin(pi*i/st)*cos(2*pi*j/sl), sin(pi*i/st)*sin(2*pi*j/sl), cos(pi*i/st)
        print "v 0 0 -1"
        last = 2 + (st - 1) * sl
        for (j = 0; j < sl; j++) printf "f 1 %d %d\n", 2 + j, 2 + (j + 1) % sl
        for (i = 1; i < st - 1; i++) for (j = 0; j < sl; j++) {
            a = 2 + (i - 1) * sl + j; b = 2 + (i - 1) * sl + (j + 1) % sl
            c = a + sl; d = b + sl
            printf "f %d %d %d\nf %d %d %d\n", a, c, d, a, d, b
        }
        for (j = 0; j < sl; j++) printf "f %d %d %d\n", last, 2 + (st - 2) * sl + (j + 1) % sl, 2 + (st - 2) * sl + j
    }'
}
sphere 40 64 >"$gen/sphere5k.obj"   # 4992 faces, 2498 vertices
refused over "$gen/sphere5k.obj" 3 "4992 faces and 2498 vertices after merging; the firmware holds $cap_faces and $cap_verts: pass --max-faces N"
convert simplified "$gen/sphere5k.obj" --max-faces 500
[ "$(faces_of simplified)" -le 500 ] || fail "--max-faces 500 gave $(faces_of simplified) faces"
[ "$(faces_of simplified)" -ge 250 ] || fail "--max-faces 500 gave only $(faces_of simplified) faces"
# --max-verts alone is a capacity, not a licence to simplify.
refused over_verts "$gen/sphere5k.obj" 3 'pass --max-faces N' --max-verts 100
sphere 251 200 >"$gen/sphere100k.obj"  # 100000 faces
convert big "$gen/sphere100k.obj" --max-faces 4096 --max-verts 4096
[ "$(faces_of big)" -le 4096 ] || fail "the 100k sphere gave $(faces_of big) faces"
big_line=$(grep '^meshconv: simplification' "$work/big.log")
echo "100k-face sphere: $big_line; $(ms_of big) ms"

# ---- --check refuses a damaged file; usage errors ----
cp "$work/cube1.gmsh" "$work/damaged.gmsh"
printf '\x7f' | dd of="$work/damaged.gmsh" bs=1 seek=40 conv=notrunc 2>/dev/null
run_to "$work/damaged.check" 10 "$MESHCONV" --check "$work/damaged.gmsh"
expect_status 1 "--check of a damaged file"
expect_line '^meshconv: error: ' "$work/damaged.check"
for args in "" "--max-faces" "--max-faces 0 a b" "--extent 9 a b" "--material purple a b" "--bogus a b" "a b c"; do
    # shellcheck disable=SC2086 # the words are the arguments
    run_to "$work/usage.log" 10 "$MESHCONV" $args
    expect_status 2 "meshconv $args"
done

pass "meshconv: $checks checks (spider $(faces_of spider) faces in $(ms_of spider) ms, 100k sphere -> $(faces_of big) faces in $(ms_of big) ms)"
