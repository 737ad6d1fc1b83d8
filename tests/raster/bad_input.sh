#!/usr/bin/env bash
# `gpusim raster` on malformed lists: a clear message naming the line, exit status 2, no crash.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
work=$(fresh_dir raster-bad-input)
check() {  # check NAME CONTENT EXPECTED-MESSAGE
    printf '%b' "$2" >"$work/$1.txt"
    run_to "$work/$1.out" 30 "$GPUSIM" raster --in "$work/$1.txt" --out "$work/$1"
    if [ "$status" -ne 2 ] || ! grep -q -- "$3" "$work/$1.out"; then
        cat "$work/$1.out"; fail "$1: expected status 2 and '$3', got status $status"
    fi
}
check unknown   "clear 0\ncircle 1 2 3 4\n"          "2: unknown primitive 'circle'"
check short     "tri 0 0 16 16 0\n"                   "1: tri takes 7 integers, got 5"
check text      "line 0 0 x 16 3\n"                   "1: 'x' is not an integer"
check range     "tri 0 0 40000 0 0 16 1\n"            "outside Q12.4"
check colour    "line 0 0 16 16 256\n"                "not a palette index"
check negative  "clear -1\n"                          "not a palette index"
check overflow  "tri 0 0 0 99999999999999999999 0 0 1\n" "not an integer"
# A NUL byte inside a number used to end it there, so this read as colour 5 (found by
# tests/fuzz/fuzz_prim_list); the message shows the byte escaped.
check nul       "clear 0\ntri 0 0 16 0 0 16 5\0x\n"    "2: '5.x00x' is not an integer"
run_to "$work/missing.out" 30 "$GPUSIM" raster --in "$work/does-not-exist.txt" --out "$work/x"
expect_status 2 "a missing list"
expect_line "cannot read" "$work/missing.out"
pass "raster bad input: 9 malformed inputs rejected with a message naming the problem"
