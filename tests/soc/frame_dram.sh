#!/usr/bin/env bash
# The whole SoC with everything in the SDRAM (suite soc-sdram-dram): the firmware (booted from the
# flash into the SDRAM) and the GPU's two 640x480 frames (FRAME_DRAM, strips of 16 rows, contract
# "Frames in external memory") on LiteDRAM's two user ports, the chip model on the pins serving the
# CPU's cache lines, the strips' flushes and the scan-out's rows. landscape, two frames: painter's
# order, then depth-tested (Z at doorbell 1, read at frame 1); each frame from the VGA pins equal to
# the model and byte-identical to the host build's at 640x480, no SDRAM violation, no scan-out
# underflow, the slowest row fetch within its display line (socsim_frame_tap), the traffic reported.
source "$(dirname "$0")/../lib.sh"
need BUILD
socsim=${1:?usage: frame_dram.sh SOCSIM_SDRAM_DRAM}
scene=landscape
elf="$BUILD/fw-test-soc-sdram/$scene-2f.elf"
boot="$BUILD/soc/boot-fast.elf.hex"
host="$BUILD/fw-test/host-$scene"
need_file "$socsim" "$elf.img" "$boot" "$host"
work=$(fresh_dir soc-sdram-dram)
run_to "$work/host.uart" 300 "$host" --frame 640x480 --zbuf --gouraud --keys-at 1:z --frames "$work/host"
expect_status 0 "host build of $scene"
run_to "$work/soc.out" 600 "$socsim" --boot "$boot" --stop-frames 2 --fw "$elf" --frames "$work/soc" \
    --uart-log "$work/soc.uart" --keys-at 1:z --summary "$work/soc.summary"
expect_status 0 "socsim of $scene (log: $work/soc.out)"
s="$work/soc.summary"
expect_eq "$(summary frames "$s")" 2 "$scene: frames on socsim"
expect_eq "$(summary frames_model_checked "$s")" 2 "$scene: socsim frames equal to the model"
expect_eq "$(summary sdram_violations "$s")" 0 "$scene: SDRAM chip model violations"
expect_eq "$(summary scanout_underflows "$s")" 0 "$scene: SCANOUT_UNDERFLOWS"
worst=$(summary scanout_worst_row_clocks "$s")
# A row's deadline is one display line: 800 pixels of 2 system clocks (socsim's 50 MHz, the 25 MHz rate).
[ "${worst:-0}" -gt 0 ] && [ "$worst" -lt 1600 ] || fail "$scene: the slowest row fetch took ${worst:-?} clocks (deadline 1,600)"
expect_line '^strips: the GPU draws 16 rows at a time on chip' "$work/soc.uart"
expect_line '^depth buffer on' "$work/soc.uart"
for f in "$work/soc"/*.png; do   # the host build runs more frames: the first two are compared
    cmp -s "$f" "$work/host/$(basename "$f")" || fail "$scene: $(basename "$f") differs from the host build's"
done
pass "soc-sdram-dram: $scene at 640x480 with the firmware and the frames in the SDRAM, 2 frames = model = host; SDRAM words read $(summary sdram_words_read "$s"), written $(summary sdram_words_written "$s"), 0 violations, 0 underflows, the slowest row in $worst of its 1,600 clocks"
