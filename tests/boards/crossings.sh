#!/usr/bin/env bash
# synth/crossings.py, the clock-domain crossing check of the board flow, on a design small enough to
# synthesise in seconds (tests/boards/crossings/xdemo.v: two clocks of one EHXPLLL, a two-flop
# synchroniser, a reset synchroniser, a block RAM and a LUT RAM across them, and one register
# sampled straight from the other domain). Through synth/ecp5_bitstream.py --synth-only --crossings
# (as make synth-board runs it): the flow stops, naming the undeclared crossing, with the declared
# ones in its table and crossings.md. Then crossings.py on that netlist: with the crossing declared
# it passes; a stale entry, a synchroniser whose first flop feeds logic, a source an entry does not
# name, and a file it cannot read each fail, saying so.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir boards-crossings)
py=${PYTHON:-python3}
fixture=tests/boards/crossings
# YoWASP's yosys sees the working directory (the repository) only: the build's path relative to it.
rel=$(realpath --relative-to=. "$work")
case "$rel" in ../*) fail "BUILD ($BUILD) is outside the repository: YoWASP's yosys cannot write there";; esac

run_to "$work/flow.out" 300 "$py" synth/ecp5_bitstream.py --top xdemo --files $fixture/files.f --lpf /dev/null \
    --out "$rel/x" --synth-only --crossings $fixture/declared.toml
cat "$work/flow.out"
expect_status 1 "the flow on xdemo with an undeclared crossing"
expect_line '^crossings: undeclared crossing a -> b into raw_b \(DI\) from cnt_a\[9\]$' "$work/flow.out"
expect_line 'ecp5_bitstream: 1 clock-domain crossing error' "$work/flow.out"
expect_eq "$(count '^crossings: ' "$work/flow.out")" 1 "error lines of the flow (only raw_b's)"
for row in '\| a \| b \| sync_b\[0\] \| sync2 \| 1 \| DI \|' '\| async \| b \| rst_sync_b\[0\] \| reset \| 1 \| DI \|' \
           '\| a \| b \| ram \| dual-clock-ram \| 1 \| memory \|' '\| a \| b \| lram_b\[3:0\] \| accepted \| 4 \| DI \|' \
           '\| a \| b \| raw_b \| UNDECLARED \| 1 \| DI \|'; do
    expect_line "$row" "$work/flow.out"
done
net="$work/x/xdemo.json"
need_file "$net" "$work/x/crossings.md"
expect_line '^\| #1 sync_b\[0\] \| sync2 \| a toggle' "$work/x/crossings.md"

# check TOML: crossings.py on the netlist against TOML; output in $work/check.out, status in $status
check() {
    run_to "$work/check.out" 60 "$py" synth/crossings.py "$net" --declared "$1" --report "$work/check.md"
}
entry() {  # entry ENDPOINT KIND [EXTRA]: a [[crossing]] from a to b
    printf '\n[[crossing]]\nendpoint = "%s"\nfrom = "a"\nto = "b"\nkind = "%s"\nwhy = "test"\n%s\n' "$1" "$2" "${3:-}"
}

{ cat $fixture/declared.toml; entry raw_b accepted; } >"$work/all.toml"
check "$work/all.toml"
expect_status 0 "every crossing declared"
expect_line '^crossings: 5 crossings, every one declared' "$work/check.out"
expect_line '^\| a \| b \| raw_b \| accepted \| 1 \| DI \| #5 \|$' "$work/check.out"

{ cat "$work/all.toml"; entry 'gone_b*' sync2; } >"$work/stale.toml"
check "$work/stale.toml"
expect_status 1 "a declared crossing that matches nothing"
expect_line '^crossings: declared crossing #6 \(a -> b, gone_b\*\) matched nothing' "$work/check.out"

{ cat $fixture/declared.toml; entry raw_b sync2; } >"$work/notsync.toml"
check "$work/notsync.toml"
expect_status 1 "a register that feeds logic declared as a synchroniser"
expect_line "crossing #5 \(sync2\) into raw_b: a synchroniser's first flop must feed the second flop's DI \(b\) and \
nothing else; 1 do not: raw_b feeds port led" "$work/check.out"

sed 's/^sources = \["toggle_a"\]/sources = ["cnt_a*"]/' "$work/all.toml" >"$work/sources.toml"
check "$work/sources.toml"
expect_status 1 "a source the entry does not name"
expect_line '^crossings: crossing #1 \(sync2\) into sync_b\[0\]: sources it does not declare: toggle_a$' "$work/check.out"

sed 's/^kind = "accepted"/kind = "fine"/' "$work/all.toml" >"$work/badkind.toml"
check "$work/badkind.toml"
expect_status 2 "an unknown kind"
expect_line "crossing #4: kind 'fine': one of sync2, pulse" "$work/check.out"

pass "boards-crossings: xdemo's 5 crossings found and typed; the flow stops on the undeclared one;" \
    "stale, unsynchronised, undeclared-source and malformed entries refused"
