#!/usr/bin/env bash
# socsim is deterministic: two runs of one scene (tetra's 3-frame test build, with keys) give
# byte-identical PNG files, UART logs and summaries (every count the harness keeps: cycles, retired
# instructions, cache refills). The two runs go at the same time, on two cores: a run must depend on
# nothing but its inputs.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
soc_test tetra-3f soc-determinism

one_run() {
    run_to "$work/$1.out" 120 "$socsim" --fw "$elf" --frames "$work/$1" --uart-log "$work/$1.uart" \
        --keys-at 1:jw --summary "$work/$1.summary"
    expect_status 0 "socsim run $1"
}
one_run a &
pid_a=$!
one_run b || fail "run b"
wait "$pid_a" || fail "run a"
same_pngs "$work/a" "$work/b" "two socsim runs"
cmp -s "$work/a.uart" "$work/b.uart" || fail "the UART logs differ: $(diff "$work/a.uart" "$work/b.uart" | head -3)"
cmp -s "$work/a.summary" "$work/b.summary" ||
    fail "the summaries differ: $(diff "$work/a.summary" "$work/b.summary" | head -3)"
pass "soc-determinism: $(summary frames "$work/a.summary") frames, UART log and $(summary cycles "$work/a.summary") cycles identical across two runs"
