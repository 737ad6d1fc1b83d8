#!/usr/bin/env bash
# The SoC against co-simulation: every scene's FW_TEST_FRAMES build runs on socsim (the whole SoC:
# VexRiscv, caches, Wishbone bus, RAM, UART, the GPU and its VGA pins) and on `gpusim cosim` (QEMU
# and the Verilated GPU), with the same scripted keys at the same doorbell. Both must end with
# status 0, check every frame against the golden model, and write byte-identical PNG files; the
# keys must have arrived whole before the firmware read them (keys_late 0), as in co-simulation.
# SOC_SCENES='tetra cubes' limits the scenes.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need GPUSIM BUILD
need_file "$socsim"
# J J J W at doorbell 1 (frame 0's first batch): look or swing left three times and move forward or
# zoom in, in every camera mode; the firmware reads them at frame 1 in both worlds. No scene key.
keys='1:jjjw'
work=$(fresh_dir soc-vs-cosim)
scenes=${SOC_SCENES:-$(soc_scenes)}
total=0
for s in $scenes; do
    qemu_elf="$BUILD/fw-test/$s.elf"
    soc_elf="$soc_test_dir/$s.elf"
    need_file "$qemu_elf" "$soc_elf.hex"
    run_to "$work/$s.cosim.out" 300 "$GPUSIM" cosim --fw "$qemu_elf" --frames "$work/$s-cosim" \
        --uart-log "$work/$s.cosim.uart" --keys-at "$keys" --summary "$work/$s.cosim.summary"
    expect_status 0 "co-simulation of $s"
    run_to "$work/$s.soc.out" 300 "$socsim" --fw "$soc_elf" --frames "$work/$s-soc" \
        --uart-log "$work/$s.soc.uart" --keys-at "$keys" --summary "$work/$s.soc.summary"
    expect_status 0 "socsim of $s"
    frames=$(summary frames "$work/$s.soc.summary")
    [ "$frames" -ge 2 ] || fail "$s: only $frames frames on socsim"
    expect_eq "$(summary frames_model_checked "$work/$s.soc.summary")" "$frames" "$s: socsim frames equal to the model"
    expect_eq "$(summary frames_model_checked "$work/$s.cosim.summary")" \
        "$(summary frames "$work/$s.cosim.summary")" "$s: co-simulated frames equal to the model"
    expect_eq "$(summary keys_late "$work/$s.soc.summary")" 0 "$s: keys still on the line when read"
    same_pngs "$work/$s-soc" "$work/$s-cosim" "$s: socsim against co-simulation"
    # The keys moved the camera: frame 1 differs from what it would be without them is not checked
    # here (the host tests do), but both worlds must have read them: same frame lines' triangles.
    diff <(grep '^frame ' "$work/$s.soc.uart" | sed 's/ | fw instr.*//') \
         <(grep '^frame ' "$work/$s.cosim.uart" | sed 's/ | fw instr.*//') >/dev/null ||
        fail "$s: the firmware's triangle counts differ between socsim and co-simulation"
    total=$((total + frames))
    echo "$s: $frames frames identical, $(sed -n 's/^cycles=//p' "$work/$s.soc.summary") SoC cycles"
done
pass "soc-vs-cosim: $(echo $scenes | wc -w) scenes, $total frames byte-identical to co-simulation, all equal to the model"
