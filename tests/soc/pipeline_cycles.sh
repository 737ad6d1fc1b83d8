#!/usr/bin/env bash
# The pipeline's charges on the SoC: tests/soc/pipeline_cycles.c times each hazard the firmware's
# hot loops meet with mcycle on socsim (`make bench-cpu` prints them as a table). The method holds
# when plain adds cost one cycle each (groups of 1..4 adds: 64 cycles more a group size); the
# charges must be the ones `make profile-fw PROFILE_HAZARDS=1` weights the trace's hazards with
# (firmware/tools/profile_fw.py, PIPELINE_CHARGES); bench/bench_cpu.py (`make bench-cpu`) makes
# its table from the same program.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test pipeline_cycles soc-pipeline-cycles

run_socsim 120 --max-cycles 1e7
expect_status 0 "socsim"
grep -q '^pipeline: done$' "$work/uart.log" || fail "no 'pipeline: done' line: $(tail -3 "$work/uart.log")"
read -r a1 a2 a3 a4 < <(sed -n 's/^pipeline: adds \([0-9]*\) \([0-9]*\) \([0-9]*\) \([0-9]*\) cycles.*/\1 \2 \3 \4/p' "$work/uart.log")
[ -n "${a4:-}" ] || fail "no adds line"
[ $((a2 - a1)) -eq 64 ] && [ $((a3 - a2)) -eq 64 ] && [ $((a4 - a3)) -eq 64 ] ||
    fail "plain adds do not take one cycle each: $a1 $a2 $a3 $a4 for groups of 1..4 (64 of each)"
python3 - "$work/uart.log" <<'PY' || fail "the measured charges differ from PIPELINE_CHARGES"
import sys
sys.path.insert(0, "firmware/tools")
from profile_fw import PIPELINE_CHARGES
measured = {}
for line in open(sys.argv[1]):
    parts = line.split()
    if len(parts) == 3 and parts[0] == "pipeline:":
        measured[parts[1]] = float(parts[2])
# the table's names for what the program times under other names
as_measured = {"stores": measured.get("stores"), "jump": measured.get("jump"),
               "return": measured["call_return"] - measured["jump"]}
bad = []
for name, charge in PIPELINE_CHARGES.items():
    got = as_measured.get(name, measured.get(name))
    if got is None or abs(got - charge) > 0.1:
        bad.append(f"{name}: measured {got}, table {charge}")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
# make bench-cpu's table from the same program: a row a case
rows=$(python3 bench/bench_cpu.py "$socsim" "$elf" | grep -c '^| [a-z_]* | .* | -\?[0-9.]* |$') || fail "bench_cpu.py failed"
[ "$rows" -eq "$(grep -c '^pipeline: [a-z_]* -\?[0-9.]*$' "$work/uart.log")" ] || fail "bench_cpu.py printed $rows rows"
pass "soc-pipeline-cycles: $(grep -c '^pipeline: [a-z_]* -\?[0-9.]*$' "$work/uart.log") cases, one cycle an add, the charges those of profile-fw's hazard table"
