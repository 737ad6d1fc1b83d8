#!/usr/bin/env bash
# make profile-soc's counts (socsim --profile, cosim/soc/cpu_profile.h; firmware/tools/profile_soc.py)
# on tetra's test build: every retired instruction is charged the clocks since the one before, so
# over the kept frames the charges sum to the span's clocks, and the retirements to the core's own
# minstret count over the same span (read from the CSR, not from the retire signal the tap counts);
# tetra makes 60 frames a second, so a frame (scene_update to scene_update) is about one VGA frame
# of clocks (within a quarter: two frames after the first are not yet locked to the swaps, 790,000
# clocks a frame today); the refills charged are the cache refills socsim counts, within the run's total; and the
# table names the frame's functions and the polling apart.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test tetra soc-profile

# (30 lines: the printing's bsp and libc lines can fill the first few)
run_to "$work/out" 120 python3 firmware/tools/profile_soc.py "$socsim" "$elf" --lines 30 --raw "$work/profile.txt"
expect_status 0 "profile_soc.py"
raw="$work/profile.txt"
frames=$(awk '$1 == "frames" { print $2 }' "$raw")
span_cycles=$(awk '$1 == "span_cycles" { print $2 }' "$raw")
span_instret=$(awk '$1 == "span_instret" { print $2 }' "$raw")
read -r cycles instructions drefills irefills < <(awk 'NF == 5 && $1 ~ /^[0-9a-f]+$/ {
    c += $2; i += $3; d += $4; r += $5 } END { printf "%d %d %d %d\n", c, i, d, r }' "$raw")
[ "${frames:-0}" -ge 2 ] || fail "profile: $frames frames kept (FW_TEST_FRAMES 4: frames 1 and 2 expected)"
expect_eq "$cycles" "$span_cycles" "clocks charged against the kept frames' span"
expect_eq "$instructions" "$span_instret" "retirements charged against minstret over the span"
frame_clocks=$(awk -v c="$cycles" -v n="$frames" 'BEGIN { printf "%d", c / n }')
vga=$((800 * 525 * 2))  # one 640x480 VGA frame at the 25 MHz pixel clock, in 50 MHz clocks
[ "$frame_clocks" -ge $((vga - vga / 4)) ] && [ "$frame_clocks" -le $((vga + vga / 4)) ] ||
    fail "profile: $frame_clocks clocks a frame, not about one VGA frame ($vga): tetra makes 60 frames a second"
[ "$drefills" -gt 0 ] && [ "$irefills" -gt 0 ] || fail "profile: no refill charged ($drefills data, $irefills instruction)"
grep -q '^| render_object |' "$work/out" || fail "profile: no render_object row"
grep -q '^| \*\*total, polling excluded\*\* |' "$work/out" || fail "profile: no total row"
grep -q '^gpu_wait.* cycles/frame, not counted above' "$work/out" || fail "profile: the polling not apart"
grep -q '^| firmware/.*:[0-9]* |' "$work/out" || fail "profile: no source line rows (--lines)"
pass "soc-profile: $frames frames of $frame_clocks clocks; $cycles clocks and $instructions instructions charged, as the span and minstret; $drefills data and $irefills instruction refills"
