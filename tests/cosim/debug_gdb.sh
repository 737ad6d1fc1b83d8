#!/usr/bin/env bash
# `make debug`'s path in batch mode: cosim/debug.sh starts `gpusim cosim --gdb PORT`, waits for
# QEMU's GDB stub and runs gdb-multiarch on the firmware with a command file. The commands stop at
# main, step into app_run, stop at gpu_submit_batch (every frame), `next` one line, read the driver's
# state there, run on to the next frame's batch, `finish` it and kill the firmware. Their results
# are checked exactly: symbols, stepping, breakpoints and reads from the live firmware all work,
# and afterwards neither the harness nor QEMU is left. Then a QEMU that never comes up: debug.sh
# must say so and fail, not hang.
source "$(dirname "$0")/../lib.sh"
need GPUSIM BUILD
elf="$BUILD/fw-test/tetra.elf"
need_file "$elf"
command -v gdb-multiarch >/dev/null || fail "gdb-multiarch not installed (tools/setup.sh installs it)"
work=$(fresh_dir cosim-debug-gdb)

# check_at: "check: at FUNCTION FILE:LINE" for the selected frame.
cat >"$work/commands.gdb" <<'EOF'
define check_at
  python f = gdb.selected_frame(); s = f.find_sal(); print("check: at %s %s:%d" % (f.name(), s.symtab.filename, s.line))
end
break main
continue
check_at
step
check_at
break gpu_submit_batch
continue
check_at
next
check_at
printf "check: first batch next_tag=%u id=0x%08x prims=%u\n", dev->next_tag, dev->info.id, batch->prim_count
up
printf "check: first batch frame_no=%u\n", frame_no
continue
printf "check: second batch next_tag=%u\n", dev->next_tag
finish
printf "check: returned %d\n", $
printf "check: second batch frame_no=%u\n", frame_no
kill
EOF
run_to "$work/gdb.out" 60 bash cosim/debug.sh --batch "$work/commands.gdb" "$GPUSIM" "$elf" "$work"
[ "$status" -eq 0 ] || fail "debug.sh with gdb in batch mode: status $status ($(tail -n 3 "$work/gdb.out" | tr '\n' ' '))"
grep '^check: ' "$work/gdb.out" >"$work/checks" || fail "no check lines from gdb ($(tail -n 3 "$work/gdb.out"))"

line() { sed -n "${1}p" "$work/checks"; }
# gdb stops at main's first statement: the QEMU build's main (no command line) is `return app_run();`.
main_line=$(grep -n '^    return app_run();$' firmware/app/main.c | cut -d: -f1)
[ -n "$main_line" ] || fail "no 'return app_run();' in firmware/app/main.c"
[ "$(line 1)" = "check: at main firmware/app/main.c:$main_line" ] || fail "break main: '$(line 1)', expected line $main_line"
[[ "$(line 2)" =~ ^check:\ at\ app_run\ firmware/app/app.c:[0-9]+$ ]] || fail "step into app_run: '$(line 2)'"
re='^check: at gpu_submit_batch firmware/gpu/gpu.c:([0-9]+)$'
[[ "$(line 3)" =~ $re ]] || fail "break gpu_submit_batch: '$(line 3)'"
at_break=${BASH_REMATCH[1]}
[[ "$(line 4)" =~ $re ]] || fail "next in gpu_submit_batch: '$(line 4)'"
[ "${BASH_REMATCH[1]}" -gt "$at_break" ] || fail "next did not move on from line $at_break: '$(line 4)'"
# The first tag is 1 (DOORBELL and DONE_SEQ start at 0), the ID is the contract's GPU_ID_VALUE, and
# the batch's primitives are those the firmware reports for frame 0 (one batch).
frame0=$(grep -m1 '^frame 0: ' "$work/uart.log") || fail "no frame 0 line in $work/uart.log"
[[ "$frame0" =~ \|\ prims\ ([0-9]+)\ batches\ 1\ \| ]] || fail "frame 0 was not one batch: $frame0"
[ "$(line 5)" = "check: first batch next_tag=1 id=0x47505530 prims=${BASH_REMATCH[1]}" ] ||
    fail "first batch: '$(line 5)' (frame 0: prims ${BASH_REMATCH[1]})"
[ "$(line 6)" = "check: first batch frame_no=0" ] || fail "'$(line 6)'"
[ "$(line 7)" = "check: second batch next_tag=2" ] || fail "'$(line 7)'"
[ "$(line 8)" = "check: returned 0" ] || fail "finish gpu_submit_batch: '$(line 8)' (GPU_OK is 0)"
[ "$(line 9)" = "check: second batch frame_no=1" ] || fail "'$(line 9)'"
expect_eq "$(wc -l <"$work/checks")" 9 "check lines"
no_qemu_left
for pid in $(pgrep -f "cosim --gdb" || true); do
    if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qxF "TEST_RUN_TAG=$TEST_RUN_TAG"; then
        fail "the harness is still running (pid $pid)"
    fi
done

# A QEMU that cannot start: the stub never listens; debug.sh must report it within its 10 s.
run_to "$work/noqemu.out" 30 bash cosim/debug.sh --batch "$work/commands.gdb" "$GPUSIM" "$elf" "$work/noqemu" \
    --qemu /nonexistent/qemu
expect_status 1 "debug.sh without a QEMU"
expect_line "GDB stub did not come up" "$work/noqemu.out"
expect_line "cannot run /nonexistent/qemu" "$work/noqemu.out"
no_qemu_left
pass "debug-gdb: main, step, breakpoint every frame, next, finish, live reads all as expected; harness and QEMU gone"
