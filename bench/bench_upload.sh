#!/usr/bin/env bash
# make bench-upload: the UART upload's cost per model, as a Markdown table — the file's bytes, the
# bytes on the wire (frames, offsets, CRCs, resends: none on a clean line), the protocol's overhead,
# the wire time at 115200 baud (what a board's upload takes: the window keeps the line full, see
# docs/upload-protocol.md), and the receiver's frames to commit at host speed (upload_peer: the
# firmware's receiver, 60 frames/s, FW_UART_BYTES_PER_FRAME bytes a frame).
#   bench_upload.sh BUILD PEER PEER_2048 MESHCONV
set -euo pipefail
# The host tool runs on the system Python (Debian's python3-serial), not the project's venv.
build=$1 peer=$2 peer2k=$3 meshconv=$4
work="$build/bench-upload"
rm -rf "$work" && mkdir -p "$work"
models=/usr/share/assimp/models

row() {  # name, peer, meshconv options, model file
    local name=$1 p=$2 opts=$3 src=$4 gmsh="$work/$1.gmsh" faces line
    # shellcheck disable=SC2086 # opts are words
    "$meshconv" "$src" "$gmsh" $opts --quiet >/dev/null
    faces=$("$meshconv" --check "$gmsh" $opts | sed -n 's/.* \([0-9]*\) faces.*/\1/p' | head -n 1)
    "$p" --pty "$work/$name.pty" --out "$work/$name.got" --frame-ms 16 >"$work/$name.peer" 2>&1 &
    local pid=$!
    for _ in $(seq 100); do [ -e "$work/$name.pty" ] && break; sleep 0.05; done
    line=$("${TOOL_PY:-/usr/bin/python3}" tools/mesh_upload.py "$work/$name.pty" "$gmsh" --quiet --timeout 5 | tail -n 1)
    wait "$pid"
    cmp -s "$gmsh" "$work/$name.got" || { echo "bench-upload: $name arrived different"; exit 1; }
    local bytes wire over secs frames
    bytes=$(stat -c %s "$gmsh")
    wire=$(echo "$line" | sed -n 's/.*on the wire \([0-9]*\) bytes.*/\1/p')
    over=$(awk -v w="$wire" -v b="$bytes" 'BEGIN { printf "%.1f", (w - b) * 100 / b }')
    secs=$(awk -v w="$wire" 'BEGIN { printf "%.2f", w * 10 / 115200 }')
    frames=$(sed -n 's/.*committed after \([0-9]*\) frames.*/\1/p' "$work/$name.peer")
    echo "| $name | $faces | $bytes | $wire | $over % | $secs s | $frames |"
}

echo "| model | faces | file bytes | on the wire | overhead | at 115200 baud | receiver frames to commit |"
echo "|---|---:|---:|---:|---:|---:|---:|"
row cube-12 "$peer" "" "$models/OBJ/box.obj"
row spider-1024 "$peer" "--max-faces 1024 --max-verts 1024" "$models/OBJ/spider.obj"
row wuson-1024 "$peer" "--max-faces 1024 --max-verts 1024" "$models/PLY/Wuson.ply"
row wuson-2048 "$peer2k" "--max-faces 2048 --max-verts 2048" "$models/PLY/Wuson.ply"
