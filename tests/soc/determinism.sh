#!/usr/bin/env bash
# socsim is deterministic: two runs of one scene's test build give byte-identical PNG files, UART
# logs and summaries (every count the harness keeps, cycles and cache refills included).
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
elf="$soc_test_dir/tetra.elf"
need_file "$socsim" "$elf.hex"
work=$(fresh_dir soc-determinism)

for run in a b; do
    run_to "$work/$run.out" 120 "$socsim" --fw "$elf" --frames "$work/$run" --uart-log "$work/$run.uart" \
        --keys-at 2:jw --summary "$work/$run.summary"
    expect_status 0 "socsim run $run"
done
same_pngs "$work/a" "$work/b" "two socsim runs"
cmp -s "$work/a.uart" "$work/b.uart" || fail "the UART logs differ: $(diff "$work/a.uart" "$work/b.uart" | head -3)"
cmp -s "$work/a.summary" "$work/b.summary" || fail "the summaries differ: $(diff "$work/a.summary" "$work/b.summary" | head -3)"
pass "soc-determinism: $(summary frames "$work/a.summary") frames, UART log and $(summary cycles "$work/a.summary") cycles identical across two runs"
