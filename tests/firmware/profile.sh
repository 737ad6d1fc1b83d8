#!/usr/bin/env bash
# `make profile-fw`'s script on make run's firmware (tetra): the table of functions, the waits for
# the GPU named and left out of it, and PROFILE_LINES' table of source lines. Its total must be the
# firmware's own count of a frame's work ("fw instr", which leaves the waits out too) plus what it
# prints: were a wait counted as work (tetra polls DONE_SEQ some 40,000 instructions a frame), the
# total would be many times the firmware's count. With --hazards, the pipeline's table: its rows
# and total, and hazards_of's classification of known instruction sequences.
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD PYTHON
work=$(fresh_dir fw-profile)
run_to "$work/out" 300 "$PYTHON" firmware/tools/profile_fw.py "$GPUSIM" "$FW_ELF" --lines 5 \
    --hazards --uart-log "$work/uart.log"
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
# The hazard table: a row a charge, the total their sum.
rows=$(count '^\| [a-z_]+ \| [0-9]+ \| [0-9]+ \| [0-9]+ \|$' "$work/out")
expect_eq "$rows" "$("$PYTHON" -c 'import sys; sys.path.insert(0, "firmware/tools"); import profile_fw; print(len(profile_fw.PIPELINE_CHARGES))')" "hazard rows"
sum=$(awk -F'|' '/^\| [a-z_]+ \| [0-9]+ \| [0-9]+ \| [0-9]+ \|$/ { s += $5 } END { print s }' "$work/out")
est=$(sed -n 's/^| \*\*the pipeline.s waits, estimated\*\* | | | \*\*\([0-9]*\)\*\*.*/\1/p' "$work/out")
[ -n "$est" ] && [ $((sum - est)) -le 10 ] && [ $((est - sum)) -le 10 ] ||
    fail "the hazard table's total '$est' is not its rows' sum $sum"
"$PYTHON" - <<'PY' || fail "hazards_of misclassifies a known sequence"
import sys
sys.path.insert(0, "firmware/tools")
from profile_fw import hazards_of
lw = ("lw", "t0", ["a0"], None)
add_t0 = ("add", "t1", ["t0", "t0"], None)
add_other = ("add", "t2", ["t3", "t3"], None)
mul = ("mul", "t0", ["t1", "t2"], None)
back = ("bne", None, ["t0", "zero"], 0x100)   # at 0x200: a backward branch
fwd = ("beq", None, ["t0", "zero"], 0x300)    # at 0x200: a forward one
sw = ("sw", None, ["t1", "a0"], None)
cases = [
    ((None, (0x100, lw), 0x104, add_t0), ["load_use_next"]),
    (((0x100, lw), (0x104, add_other), 0x108, add_t0), ["load_use_after_one"]),
    (((0x100, lw), (0x104, add_t0), 0x108, add_t0), []),   # waited already
    ((None, (0x100, mul), 0x104, add_t0), ["mul_use_next"]),
    ((None, (0x200, back), 0x100, add_other), ["branch_backward_taken"]),
    ((None, (0x200, back), 0x204, add_other), ["branch_backward_not_taken"]),
    ((None, (0x200, fwd), 0x300, add_other), ["branch_forward_taken"]),
    ((None, (0x200, fwd), 0x204, add_other), []),
    ((None, (0x100, ("jal", None, ["zero"], 0x400)), 0x400, add_other), ["jump"]),
    ((None, (0x100, ("jalr", None, ["zero", "ra"], None)), 0x500, add_other), ["return"]),
    ((None, (0x100, sw), 0x104, sw), ["stores"]),
]
bad = [(args, want, hazards_of(*args)) for args, want in cases if hazards_of(*args) != want]
for b in bad:
    print("hazards_of%s: %s, want %s" % (b[0], b[2], b[1]))
sys.exit(1 if bad else 0)
PY
pass "profile-fw: tetra $total instructions a frame (the firmware counts $fw without its printing); the waits left out; 5 source lines; $rows hazards, $est cycles a frame"
