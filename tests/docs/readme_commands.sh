#!/usr/bin/env bash
# Every make command README.md shows is run by a test (tests/docs/readme_commands.py lists them and
# each one's way). Two suites, side by side: `readme_commands.sh run` runs the README's `make run`
# commands on QEMU and the GPU, `readme_commands.sh other` the rest (the SoC's run among them, with
# the lean-report that shares its socsim, so that no simulator is built twice at once).
# Each "run" command runs short (two frames, no ECP5 synthesis, the bitstream's flow up to its
# checked inputs) on make test's simulators, with its firmware, frames and manifest builds in the
# suite's own folder. Each must end well, print no command line (quiet builds: V=1 shows them) and
# make what it should: two frames, the lean-report's table, the bitstream's checked inputs. A
# "suite" command must name a suite that exists; the "none" ones are listed with their reasons.
source "$(dirname "$0")/../lib.sh"
need BUILD PYTHON
part=${1:?usage: readme_commands.sh run|other}
[[ "$part" == run || "$part" == other ]] || fail "part '$part': run or other"
work=$(fresh_dir "docs-readme-$part")
# mine ARGS: this part's command? `make run` on QEMU for the part "run", the rest for "other".
mine() {
    local is_run=other
    [[ " $1 " == *" run "* && " $1 " != *" PLATFORM=soc "* ]] && is_run=run
    [ "$is_run" = "$part" ]
}

run_to "$work/plan.tsv" 20 "$PYTHON" tests/docs/readme_commands.py --plan
expect_status 0 "readme_commands.py --plan: $(cat "$work/plan.tsv")"
SUITE='*' bash tests/run_all.sh --list >"$work/suites.txt"

n=0 ran=0 elsewhere=0 skipped=()
while IFS=$'\t' read -r way first second; do
    n=$((n + 1))
    case "$way" in
    run)
        mine "$first" || continue
        eval "args=($first)"
        out="$work/$n"
        mkdir -p "$out"
        start=$SECONDS
        build="$BUILD"
        # make clean removes BUILD and OUT: here, a BUILD and an OUT of its own.
        [[ " $first " != *" clean "* ]] || { build="$out/build"; mkdir -p "$build" "$out/out"; }
        # One firmware folder for all the commands: those with the same flags share their objects.
        run_to "$out/make.log" 1200 make --no-print-directory "${args[@]}" BUILD="$build" OUT="$out/out" \
            FW_DIR="$work/fw" SOC_FW_DIR="$work/fw-soc" LEAN_ROOT="$work/lean" </dev/null
        echo "== make $first ($((SECONDS - start)) s)" >>"$work/commands.log"
        cat "$out/make.log" >>"$work/commands.log"
        [ "$status" -eq 0 ] || fail "README's 'make $first' failed (status $status): $(tail -n 15 "$out/make.log")"
        # Quiet by default: one short line a step, never a compiler's or Verilator's command line.
        expect_no_line '^(gcc|g\+\+|clang|clang\+\+-14|riscv64-unknown-elf-[a-z]+|verilator|ar) ' "$out/make.log"
        case " $first " in
        *" run "*)
            expect_eq "$(png_count "$out/out/frames")" 2 "'make $first': frames in $out/out/frames" ;;
        *" test-list "*)
            [ -s "$out/make.log" ] || fail "'make $first' selects no suite" ;;
        *" lean-report "*)
            expect_line '^\| [a-z]+ \| lean \| [0-9]+ \|.*\| yes \|$' "$out/make.log" ;;
        *" bitstream "*)
            expect_line '^inputs: ulx3s_(sdram_)?top from [0-9]+ sources, .*RAM image [0-9]+ words' "$out/make.log" ;;
        *" clean "*)
            [ ! -e "$out/build" ] && [ ! -e "$out/out" ] || fail "'make $first' left BUILD or OUT behind" ;;
        esac
        ran=$((ran + 1))
        ;;
    same)
        mine "$first" || continue
        elsewhere=$((elsewhere + 1))
        ;;
    suite)
        [ "$part" = other ] || continue
        grep -qx "$first" "$work/suites.txt" || fail "README's '$second': suite $first is not among make test's suites"
        elsewhere=$((elsewhere + 1))
        ;;
    none)
        [ "$part" = other ] || continue
        skipped+=("$first")
        ;;
    *)
        fail "readme_commands.py --plan: unknown way '$way'"
        ;;
    esac
done <"$work/plan.tsv"
[ "$ran" -gt 0 ] || fail "README.md shows no make command of part $part"
not_here=$(IFS=';'; echo "${skipped[*]}")
pass "README ($part): $n make commands: $ran run here, $elsewhere by their suites or as another run, ${#skipped[@]} not runnable here${not_here:+ (${not_here//;/; })}"
