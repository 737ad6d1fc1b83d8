#!/usr/bin/env bash
# A model uploaded into the whole SoC (socsim: VexRiscv, bus, RAM, the RTL UART at 115200 baud in
# simulated time, the GPU) while it renders the built-in model: the bytes go through soc_uart's
# receiver and its 2,048-byte FIFO, the firmware's receiver commits them, and the model scene
# swaps to the new mesh at a frame boundary. The frames before the swap must equal the host
# build's built-in model and those after it the host build drawing the uploaded file (fw-host
# --model), every one also equal to the golden model.
source "$(dirname "$0")/../lib.sh"
need BUILD PYTHON
source "$(dirname "$0")/soc_lib.sh"
soc_test model-upload soc-upload
host="$BUILD/fw-test/host-upload-model"
need_file "$host"
frames=$(sed -n 's/^SOC_UPLOAD_FRAMES := //p' firmware/firmware.mk)
[ -n "$frames" ] || fail "no SOC_UPLOAD_FRAMES in firmware/firmware.mk"
TOOL_PY=${TOOL_PY:-/usr/bin/python3}
"$PYTHON" tests/upload/gmsh.py cube "$work/cube.gmsh" --material 1 >/dev/null

timeout 300 "$socsim" --fw "$elf" --frames "$work/soc" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$work/tty" >"$work/out" 2>&1 &
sim=$!
trap 'kill $sim 2>/dev/null' EXIT
wait_for_pty "$work/tty" socsim "$work/out" '^scene '
run_to "$work/tool.out" 240 "$TOOL_PY" tools/mesh_upload.py "$work/tty" "$work/cube.gmsh" --session 21 \
    --chunk 64 --window 4 --timeout 60 --quiet
cat "$work/tool.out"
expect_status 0 "the upload into socsim"
wait $sim
status=$?
trap - EXIT
expect_status 0 "socsim ($(tail -n 2 "$work/out"))"
expect_eq "$(summary frames "$work/summary")" "$frames" "frames"
expect_eq "$(summary uart_framing_errors "$work/summary")" 0 "UART framing errors"
expect_eq "$(count 'equals golden model' "$work/out")" "$frames" "frames equal to the golden model"
expect_line '^model: 12 faces, 8 vertices, uploaded$' "$work/uart.log"
swap=$(awk '/^model: 12 faces/ {seen = 1} seen && /^frame [0-9]+:/ {sub(":", "", $2); print $2; exit}' \
       "$work/uart.log")
[ -n "$swap" ] && [ "$swap" -ge 1 ] && [ "$swap" -le $((frames - 1)) ] || fail "swap at frame '$swap' of $frames"

"$host" --frames "$work/ref-builtin" >"$work/ref-builtin.out" 2>&1 || fail "host build (built-in model) failed"
"$host" --model "$work/cube.gmsh" --frames "$work/ref-cube" >"$work/ref-cube.out" 2>&1 || fail "host build (cube) failed"
for ((i = 0; i < frames; i++)); do
    got=$(printf '%s/soc/%04d.png' "$work" "$i")
    if [ "$i" -lt "$swap" ]; then
        want=$(printf '%s/ref-builtin/%04d.png' "$work" "$i")
    else
        want=$(printf '%s/ref-cube/%04d.png' "$work" $((i - swap)))
    fi
    cmp -s "$got" "$want" || fail "frame $i (swap at $swap) differs from the host build's"
done
pass "soc-upload: a 252-byte model through soc_uart at 115200 baud, swapped in at frame $swap of $frames;" \
     "frames before it the built-in model's, after it the upload's; $(grep -o 'on the wire [0-9]* bytes' "$work/tool.out")"
