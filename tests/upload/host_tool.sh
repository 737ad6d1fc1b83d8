#!/usr/bin/env bash
# tools/mesh_upload.py end to end against the firmware's own receiver (firmware/model/upload.c in
# upload_peer, on a pseudo-terminal at host speed, a "frame" every 16 ms as at 60 frames/s):
#   - a clean transfer: committed, the file written by the peer identical to the one sent;
#   - four seeds of every fault at once (bits flipped, frames dropped, duplicated, reordered,
#     garbage between frames, keys typed, a frame cut in half, an oversized header): each commits
#     the identical file, every fault was injected, and no typed key reached the key decoder;
#   - a file the validator refuses: exit 1 with the validator's reason;
#   - --abandon-after: exit 3, and the peer commits nothing;
#   - a file that is not a mesh file: exit 2 before the port is touched.
source "$(dirname "$0")/../lib.sh"
need BUILD PYTHON
peer="$BUILD/tests/upload_peer"
need_file "$peer"
work=$(fresh_dir upload-host-tool)
TOOL_PY=${TOOL_PY:-/usr/bin/python3}  # pyserial is Debian's python3-serial, not in the venv
"$PYTHON" tests/upload/gmsh.py sphere "$work/ball.gmsh" --rings 12 --segments 24 --material 5 >/dev/null
"$PYTHON" tests/upload/gmsh.py sphere "$work/bad.gmsh" --rings 12 --segments 24 --break index >/dev/null

# upload NAME PEER_FRAMES TOOL_ARGS...: the peer on $work/NAME.pty, then the tool; sets $tool
# (the tool's status) and $peer_status.
upload() {
    local name=$1 frames=$2
    shift 2
    "$peer" --pty "$work/$name.pty" --out "$work/$name.got" --frame-ms 16 --frames "$frames" \
        2>"$work/$name.peer" &
    local pid=$!
    for _ in $(seq 100); do
        [ -e "$work/$name.pty" ] && break
        sleep 0.05
    done
    run_to "$work/$name.out" 120 "$TOOL_PY" tools/mesh_upload.py "$work/$name.pty" "$@"
    tool=$status
    peer_status=0
    wait "$pid" || peer_status=$?
}

upload clean 2000 "$work/ball.gmsh" --session 3 --quiet
expect_eq "$tool" 0 "the clean upload's status"
expect_eq "$peer_status" 0 "the peer's status after the clean upload"
cmp -s "$work/clean.got" "$work/ball.gmsh" || fail "the peer committed other bytes than were sent"
expect_line ', 0 retransmissions, 0 naks,' "$work/clean.out"

for seed in 1 2 3 4; do
    upload "faults$seed" 3000 "$work/ball.gmsh" --session $((10 + seed)) --quiet --chunk 128 --window 6 \
        --timeout 1 --inject-seed "$seed" --corrupt 0.2 --drop 0.1 --duplicate 0.2 --reorder 0.2 \
        --garbage 0.3 --keys qwq --truncate-frame 5 --oversize
    expect_eq "$tool" 0 "seed $seed: the upload's status ($(tail -n 2 "$work/faults$seed.out"))"
    expect_eq "$peer_status" 0 "seed $seed: the peer's status"
    cmp -s "$work/faults$seed.got" "$work/ball.gmsh" || fail "seed $seed: the committed file differs"
    for kind in corrupt drop duplicate reorder garbage keys truncate oversize; do
        expect_line "injected: .*\\b$kind [1-9]" "$work/faults$seed.out"
    done
    expect_line ' 0 keys,' "$work/faults$seed.peer"  # none of the typed keys got through
done

upload reject 150 "$work/bad.gmsh" --session 20 --quiet
expect_eq "$tool" 1 "the refused upload's status"
expect_line 'rejected: mesh: face [0-9]+: index [0-9]+ out of range' "$work/reject.out"
expect_eq "$peer_status" 1 "the peer's status (nothing committed)"

upload abandon 250 "$work/ball.gmsh" --session 21 --abandon-after 3
expect_eq "$tool" 3 "--abandon-after's status"
expect_line 'abandoned after 3 DATA frames' "$work/abandon.out"
expect_eq "$peer_status" 1 "the peer's status after an abandoned transfer"

run_to "$work/usage.out" 10 "$TOOL_PY" tools/mesh_upload.py "$work/none.pty" tests/upload/gmsh.py
expect_status 2 "a file that is not a mesh file"
pass "upload-host-tool: clean, 4 seeds of every fault, reject, abandon and usage against the firmware's receiver"
