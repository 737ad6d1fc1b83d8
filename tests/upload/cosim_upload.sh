#!/usr/bin/env bash
# A model uploaded over the UART into a running co-simulation (QEMU + the Verilated GPU, frames
# from the VGA pins and checked against the golden model), through the harness's pseudo-terminal
# (gpusim cosim --uart-pty) with tools/mesh_upload.py, as a user would to a board's serial port:
#   1. a file the firmware's validator refuses (a face index out of range, the CRC intact): the
#      upload is rejected with the validator's reason, and the tetrahedron stays on screen;
#   2. a good file sent through a faulty line — bits flipped, frames duplicated and reordered,
#      garbage between frames, a frame cut in half, an oversized header, and the keys "qwq" typed
#      during the transfer (a quit, if the receiver let it through): it commits.
# The frames before the swap must be byte-identical to the host build's tetrahedron without any
# upload, and the frames from the swap on to the host build's model scene drawing the same file
# (fw-host --model): the uploaded bytes, not merely some model, are what is drawn.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD PYTHON
dir="$BUILD/fw-test"
elf="$dir/upload-tetra.elf"
need_file "$elf" "$dir/host-upload-tetra" "$dir/host-upload-model"
work=$(fresh_dir upload-cosim)
frames=$(sed -n 's/^FW_UPLOAD_TEST_FRAMES := //p' firmware/firmware.mk)
[ -n "$frames" ] || fail "no FW_UPLOAD_TEST_FRAMES in firmware/firmware.mk"

# The pyserial tool runs on the system's Python (Debian's python3-serial), not the project's venv.
TOOL_PY=${TOOL_PY:-/usr/bin/python3}
"$PYTHON" tests/upload/gmsh.py sphere "$work/ball.gmsh" --rings 6 --segments 8 --material 7 >/dev/null
"$PYTHON" tests/upload/gmsh.py sphere "$work/bad.gmsh" --rings 6 --segments 8 --break index >/dev/null

"$GPUSIM" cosim --fw "$elf" --frames "$work/cosim" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$work/uart.pty" >"$work/cosim.out" 2>&1 &
cosim=$!
trap 'kill $cosim 2>/dev/null' EXIT
wait_for_pty "$work/uart.pty" "the co-simulation" "$work/cosim.out" '^scene tetra'

run_to "$work/bad.out" 120 "$TOOL_PY" tools/mesh_upload.py "$work/uart.pty" "$work/bad.gmsh" --session 11 \
    --chunk 256 --window 8 --timeout 30 --quiet
expect_status 1 "the upload of a file with an index out of range"
expect_line 'reject.*mesh: face [0-9]+: index [0-9]+ out of range' "$work/bad.out"

run_to "$work/good.out" 180 "$TOOL_PY" tools/mesh_upload.py "$work/uart.pty" "$work/ball.gmsh" --session 12 \
    --chunk 256 --window 8 --timeout 30 --inject-seed 5 --corrupt 0.25 --duplicate 0.25 --reorder 0.25 \
    --garbage 0.3 --keys qwq --oversize --truncate-frame 2
cat "$work/good.out"
expect_status 0 "the upload through the faulty line"

wait $cosim
status=$?
trap - EXIT
expect_status 0 "gpusim cosim ($(tail -n 2 "$work/cosim.out"))"
expect_eq "$(summary frames "$work/summary")" "$frames" "frames rendered (a leaked 'q' would end the run early)"
expect_eq "$(summary frames_model_checked "$work/summary")" "$frames" "frames equal to the golden model"
expect_line '^model: 80 faces, 42 vertices, uploaded$' "$work/uart.log"
expect_line '^@up ok 12 faces 80 verts 42$' "$work/uart.log"

# The swap's frame: the first frame line after the model scene's line.
swap=$(awk '/^model: 80 faces/ {seen = 1} seen && /^frame [0-9]+:/ {sub(":", "", $2); print $2; exit}' \
       "$work/uart.log")
[ -n "$swap" ] || fail "no frame after the swap"
[ "$swap" -ge 2 ] && [ "$swap" -le $((frames - 2)) ] || fail "swap at frame $swap of $frames: no room for both checks"

"$dir/host-upload-tetra" --frames "$work/ref-tetra" >"$work/ref-tetra.out" 2>&1 || fail "host tetra failed"
"$dir/host-upload-model" --model "$work/ball.gmsh" --frames "$work/ref-model" >"$work/ref-model.out" 2>&1 ||
    fail "host model failed"
for ((i = 0; i < frames; i++)); do
    got=$(printf '%s/cosim/%04d.png' "$work" "$i")
    if [ "$i" -lt "$swap" ]; then
        want=$(printf '%s/ref-tetra/%04d.png' "$work" "$i")
        cmp -s "$got" "$want" || fail "frame $i (before the swap) is not the tetrahedron's"
    else
        want=$(printf '%s/ref-model/%04d.png' "$work" $((i - swap)))
        cmp -s "$got" "$want" || fail "frame $i (model frame $((i - swap))) is not the uploaded model's"
    fi
done
pass "upload into co-simulation: bad file rejected, good file through the faulty line committed at" \
     "frame $swap of $frames; frames 0-$((swap - 1)) the tetrahedron's, $swap-$((frames - 1)) the model's;" \
     "$(grep -m1 -E 'bytes on the wire|wire' "$work/good.out" | head -c 200)"
