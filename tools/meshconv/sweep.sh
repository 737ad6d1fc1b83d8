#!/usr/bin/env bash
# tools/meshconv/sweep.sh DIR... — `make meshconv-sweep`: converts every file under DIR (models,
# textures, readmes alike: whatever assimp is handed, it must refuse cleanly or convert), each
# under `timeout $MESHCONV_TIMEOUT` with the options $MESHCONV_ARGS, and prints a Markdown table and the totals. A crash (a signal,
# or a failure without the one "meshconv: error:" line) or a timeout fails the sweep.
set -uo pipefail
: "${MESHCONV:?}" "${BUILD:=build}" "${MESHCONV_TIMEOUT:=30}" "${MESHCONV_ARGS:=}"
[ $# -gt 0 ] || { echo "usage: sweep.sh DIR..."; exit 2; }
work="$BUILD/meshconv-sweep"
rm -rf "$work" && mkdir -p "$work"
ok=0 refused=0 crashed=0 timedout=0

echo "| file | faces in | faces out | vertices out | status | ms |"
echo "|---|---:|---:|---:|---|---:|"
while IFS= read -r -d '' f; do
    log="$work/log"
    t0=$(date +%s%N)
    # shellcheck disable=SC2086 # the options are words
    timeout -k 5 "$MESHCONV_TIMEOUT" "$MESHCONV" "$f" "$work/out.gmsh" $MESHCONV_ARGS >"$log" 2>&1
    rc=$?
    ms=$(( ($(date +%s%N) - t0) / 1000000 ))
    faces_in=$(sed -n 's/^meshconv: read .*: \([0-9]*\) faces in .*/\1/p' "$log" | tail -n 1)
    wrote=$(sed -n 's/^meshconv: wrote .*: [0-9]* bytes, \([0-9]*\) faces, \([0-9]*\) vertices, .*/\1 \2/p' "$log")
    errors=$(grep -c '^meshconv: error: ' "$log")
    case $rc in
        0)
            status=ok
            # shellcheck disable=SC2086
            if ! "$MESHCONV" --check "$work/out.gmsh" $MESHCONV_ARGS >"$work/check" 2>&1; then
                status="crashed: written file invalid: $(head -c 200 "$work/check")"
                crashed=$((crashed + 1))
            else
                ok=$((ok + 1))
            fi
            ;;
        124|137) status="timed out (${MESHCONV_TIMEOUT} s)"; timedout=$((timedout + 1)) ;;
        1|2|3)
            if [ "$errors" -eq 1 ] && [ ! -e "$work/out.gmsh" ]; then
                status="refused: $(grep '^meshconv: error: ' "$log" | sed "s|^meshconv: error: ||; s|$f: ||" | head -c 120)"
                refused=$((refused + 1))
            else
                status="crashed: status $rc with $errors error lines"
                crashed=$((crashed + 1))
            fi
            ;;
        *) status="crashed: status $rc"; crashed=$((crashed + 1)) ;;
    esac
    rm -f "$work/out.gmsh"
    # Pipes would split the table's cells.
    status=${status//|/\/}
    echo "| ${f#"$1"/} | ${faces_in:--} | ${wrote% *} | ${wrote#* } | $status | $ms |" | sed 's/|  |/| - |/g'
done < <(find "$@" -type f -print0 | sort -z)
echo
echo "totals: $ok ok, $refused refused, $crashed crashed, $timedout timed out"
[ "$crashed" -eq 0 ] && [ "$timedout" -eq 0 ]
