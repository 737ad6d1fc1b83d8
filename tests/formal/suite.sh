#!/usr/bin/env bash
# make test's formal suite: every task of make formal (tests/formal/*.sby), and the first broken
# copy of each check (make formal-broken's short form), which must fail — so a proof that stopped
# checking anything (a property compiled out, a solver that no longer runs) fails the suite too.
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir formal)
export VENV_BIN="$PWD/.venv/bin" BUILD="$work"
run_to "$work/prove.log" 900 bash tests/formal/run.sh prove
cat "$work/prove.log"
expect_status 0 "make formal's proofs (log: $work/prove.log)"
proved=$(count '\| PASS \|' "$work/prove.log")
BROKEN_LIMIT=1 run_to "$work/broken.log" 900 bash tests/formal/run.sh broken
cat "$work/broken.log"
expect_status 0 "a broken copy the proofs did not catch (log: $work/broken.log)"
caught=$(count 'FAIL, as it must' "$work/broken.log")
checks=$(ls tests/formal/*.broken | wc -l)
expect_eq "$caught" "$checks" "broken copies caught, one per check"
pass "formal: $proved proofs and covers passed; the first broken copy of each of $checks checks failed, as it must"
