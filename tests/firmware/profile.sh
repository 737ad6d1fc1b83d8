#!/usr/bin/env bash
# `make profile-fw`'s script on make run's firmware (tetra): the table of functions, the waits for
# the GPU named and left out of it, and PROFILE_LINES' table of source lines. Its total must be the
# firmware's own count of a frame's work ("fw instr", which leaves the waits out too) plus what it
# prints: were a wait counted as work (tetra polls DONE_SEQ some 40,000 instructions a frame), the
# total would be many times the firmware's count.
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD PYTHON
work=$(fresh_dir fw-profile)
run_to "$work/out" 300 "$PYTHON" firmware/tools/profile_fw.py "$GPUSIM" "$FW_ELF" --lines 5 \
    --uart-log "$work/uart.log"
tail -n 16 "$work/out"
expect_status 0 "profile_fw.py"
expect_line '^\| function \| instructions/frame \| share \|$' "$work/out"
expect_line '^gpu_wait_idle \(waiting for the GPU\): [0-9]+ instructions/frame, not counted above$' "$work/out"
expect_no_line '^\| gpu_wait_idle \|' "$work/out"
expect_eq "$(count '^\| [^ ]+:[0-9]+ \| [0-9]+ \| [0-9.]+% \|$' "$work/out")" 5 "source lines listed"
total=$(sed -n 's/^| \*\*total, polling excluded\*\* | \*\*\([0-9]*\)\*\* |.*/\1/p' "$work/out")
[ -n "$total" ] || fail "no total in the profile"
# The firmware's own mean over the same frames (1 .. last - 1, as the profile skips frame 0 and the last).
fw=$(awk '/^frame [0-9]+:/ { n = $2; sub(":", "", n); for (i = 1; i <= NF; i++) if ($i == "instr") v[n] = $(i + 1); last = n }
          END { for (k = 1; k < last; k++) { s += v[k]; c++ } if (c) printf "%d", s / c }' "$work/uart.log")
[ -n "$fw" ] || fail "no frame lines in the firmware's UART log"
# At least the firmware's count, at most that plus a frame's printing (its statistics line, about
# 9,000 instructions of printf on tetra).
[ "$total" -ge "$fw" ] && [ "$total" -le $((fw + 15000)) ] ||
    fail "the profile's total $total is not the firmware's fw instr $fw plus its printing"
pass "profile-fw: tetra $total instructions a frame (the firmware counts $fw without its printing); the waits left out; 5 source lines"
