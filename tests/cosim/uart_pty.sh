#!/usr/bin/env bash
# The UART as a pseudo-terminal (gpusim cosim --uart-pty): a client on the pty, as a serial-port
# program would be, types H and then Q. The firmware must print its help in answer (twice in the
# log: at boot and on H), quit early at Q with status 0, the summary must count the client's two
# bytes, and the client must have received the firmware's whole output: its transcript, '\r'
# dropped, equals the UART log byte for byte.
source "$(dirname "$0")/../lib.sh"
need GPUSIM FW_ELF BUILD
need_file "$GPUSIM" "$FW_ELF"
work=$(fresh_dir cosim-uart-pty)
link="$work/tty"

# FW_ELF renders 24 frames (about 35 s here): time enough to type before it ends by itself.
timeout 120 "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --uart-log "$work/uart.log" \
    --summary "$work/summary" --uart-pty "$link" >"$work/out" 2>&1 &
sim=$!

# The client: plain termios, nothing but the standard library, so that the test depends on the
# pty alone. Status 0 when the help came back after H and "quit at frame" after Q.
client=0
python3 - "$link" "$work/transcript" >"$work/client.out" 2>&1 <<'PY' || client=$?
import errno, os, select, sys, termios, time, tty

link, transcript_path = sys.argv[1], sys.argv[2]
deadline = time.monotonic() + 60
while not os.path.exists(link):
    if time.monotonic() > deadline:
        sys.exit("no pty at " + link)
    time.sleep(0.05)
fd = os.open(link, os.O_RDWR | os.O_NOCTTY)
tty.setraw(fd, termios.TCSANOW)  # not the default TCSAFLUSH: it would discard the boot lines
got = b""

def read_until(marker, start, limit):
    """Reads into got until marker appears at or after offset start; False on timeout or hang-up."""
    global got
    end = time.monotonic() + limit
    while got.find(marker, start) < 0:
        left = end - time.monotonic()
        if left <= 0:
            return False
        if select.select([fd], [], [], left)[0]:
            try:
                data = os.read(fd, 4096)
            except OSError as e:
                if e.errno == errno.EIO:
                    return False
                raise
            if not data:
                return False
            got += data
    return True

ok = read_until(b"frame 0:", 0, 60)  # booted: the boot's own help is behind us
if ok:
    mark = len(got)
    os.write(fd, b"h")
    ok = read_until(b"H this help", mark, 30)
    print("help after H:", ok)
if ok:
    mark = len(got)
    os.write(fd, b"q")
    ok = read_until(b"quit at frame", mark, 30)
    print("quit after Q:", ok)
read_until(b"\0never", 0, 10)  # the rest, until the harness closes the pty
open(transcript_path, "wb").write(got)
sys.exit(0 if ok else 1)
PY
status=0
wait "$sim" || status=$?
cat "$work/client.out"
tail -n 3 "$work/out"
expect_status 0 "the co-simulation"
[ "$client" -eq 0 ] || fail "the pty client did not get its answers (client.out above)"
expect_line "^cosim: UART on $link \(/dev/pts/[0-9]+\)$" "$work/out"
[ ! -e "$link" ] || fail "the link $link is still there after the run"
expect_eq "$(count 'H this help' "$work/uart.log")" 2 "help texts in the log (boot and H)"
quit_frame=$(sed -n 's/^quit at frame \([0-9]*\).*/\1/p' "$work/uart.log")
[ -n "$quit_frame" ] && [ "$quit_frame" -lt 23 ] || fail "no early quit in the log (frame '$quit_frame')"
expect_eq "$(summary uart_pty_in "$work/summary")" 2 "bytes from the pty (summary)"
expect_eq "$(summary uart_pty_dropped "$work/summary")" 0 "bytes dropped (summary)"
tr -d '\r' <"$work/transcript" >"$work/transcript.lf"
cmp -s "$work/transcript.lf" "$work/uart.log" || fail "the pty's transcript differs from the UART log"
no_qemu_left
pass "uart-pty: H and Q typed through $(basename "$link"), help and quit at frame $quit_frame came back, $(wc -c <"$work/transcript") bytes received"
