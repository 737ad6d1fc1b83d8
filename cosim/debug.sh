#!/usr/bin/env bash
# The firmware under a debugger: `gpusim cosim --gdb PORT` in the background (QEMU's GDB stub, the
# firmware halted at reset, the GPU co-simulated as in `make run`), then gdb-multiarch in the
# foreground with the ELF's symbols, connected to the stub, running a gdb command file: by default
# cosim/debug.gdb (break at main, continue: the user lands at main). When gdb ends, so does the
# co-simulation (SIGTERM; QEMU dies with the harness).
#
#   cosim/debug.sh [--batch FILE] GPUSIM ELF OUTDIR [COSIM OPTION]...
#     --batch FILE  gdb in batch mode running FILE instead of cosim/debug.gdb (tests/cosim/debug_gdb.sh);
#                   the exit status is gdb's
#     OUTDIR        gets frames/ (the PNGs, emptied first), uart.log and debug-cosim.log (the
#                   harness's output: the firmware's UART, its errors)
#   DEBUG_PORT=N    the stub's port (default: a free one, picked here); GDB=... another gdb
#
# gdb connects only once QEMU listens (the port is polled, for at most 10 s); if the harness ends or
# the port never opens, the log's tail is shown and the status is 1.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
batch=""
if [ "${1:-}" = "--batch" ]; then
    batch="${2:?--batch needs a gdb command file}"
    shift 2
fi
[ $# -ge 3 ] || { echo "usage: cosim/debug.sh [--batch FILE] GPUSIM ELF OUTDIR [COSIM OPTION]..." >&2; exit 2; }
gpusim="$1" elf="$2" out="$3"
shift 3
gdb="${GDB:-gdb-multiarch}"
command -v "$gdb" >/dev/null || { echo "debug: $gdb not found (tools/setup.sh installs gdb-multiarch)" >&2; exit 1; }

# A free port: the kernel's choice for a socket bound to port 0 (free again once it is closed).
port="${DEBUG_PORT:-$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')}"
log="$out/debug-cosim.log"
# The stub is ready once a LISTEN socket (state 0A) on 127.0.0.1:port shows in /proc/net/tcp.
hex_port=$(printf '%04X' "$port")
listening() { grep -q "^ *[0-9]*: 0100007F:$hex_port 00000000:0000 0A " /proc/net/tcp; }
if listening; then
    echo "debug: port $port is in use (DEBUG_PORT=$port): choose another one, or none" >&2
    exit 1
fi
mkdir -p "$out"
rm -rf "$out/frames"

# A session of its own (setsid), so that Ctrl-C in gdb (interrupt the firmware) does not reach the
# harness; stdin /dev/null, so that the terminal stays gdb's.
setsid "$gpusim" cosim --gdb "$port" --fw "$elf" --frames "$out/frames" --uart-log "$out/uart.log" "$@" \
    </dev/null >"$log" 2>&1 &
harness=$!
stop() {
    if kill -0 "$harness" 2>/dev/null; then
        kill -TERM "$harness" 2>/dev/null || true
        for _ in $(seq 50); do
            kill -0 "$harness" 2>/dev/null || break
            sleep 0.1
        done
        kill -KILL "$harness" 2>/dev/null || true
    fi
    wait "$harness" 2>/dev/null || true
    [ -n "$batch" ] || echo "debug: co-simulation stopped"
}
trap stop EXIT
[ -n "$batch" ] || echo "debug: co-simulation in the background: frames in $out/frames, its output (UART, errors) in $log"

# Wait until QEMU listens, for at most 10 s, or until the harness has ended.
for _ in $(seq 100); do
    listening && break
    kill -0 "$harness" 2>/dev/null || break
    sleep 0.1
done
if ! listening; then
    echo "debug: QEMU's GDB stub did not come up on port $port; the end of $log:" >&2
    tail -n 20 "$log" >&2
    exit 1
fi

gdb_args=(-q -ex "set architecture riscv:rv32" -ex "target remote 127.0.0.1:$port")
if [ -n "$batch" ]; then
    "$gdb" -batch -nx "${gdb_args[@]}" -x "$batch" "$elf"  # -nx: no ~/.gdbinit, the same for everyone
else
    "$gdb" "${gdb_args[@]}" -x "$here/debug.gdb" "$elf"
fi
