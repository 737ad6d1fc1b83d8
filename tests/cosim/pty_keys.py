#!/usr/bin/env python3
"""A client on the firmware's UART pseudo-terminal (gpusim cosim / socsim --uart-pty LINK), as a
serial-port program would be: waits for LINK, reads the firmware's output from its start, types
keys and reads on until the harness closes the pty. Writes everything received to TRANSCRIPT.
Plain termios, nothing but the standard library, so that the tests that use it depend on the pty
alone.

    pty_keys.py LINK TRANSCRIPT [TIMEOUT_S [MODE]]

MODE hq (the default): H once the first frame has been reported, Q once the help came back; status
0 when the help came back after H and "quit at frame" after Q. MODE h: H at once (it waits in the
UART until the frame loop reads keys; for socsim, whose short test builds may end before a key
typed after their first frame is read); status 0 when the help came back twice (boot, then H).
"""
import errno, os, select, sys, termios, time, tty

link, transcript_path = sys.argv[1], sys.argv[2]
limit = float(sys.argv[3]) if len(sys.argv) > 3 else 60.0
mode = sys.argv[4] if len(sys.argv) > 4 else "hq"
deadline = time.monotonic() + limit
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

if mode == "h":
    os.write(fd, b"h")
    read_until(b"\0never", 0, limit)
    open(transcript_path, "wb").write(got)
    print("help texts:", got.count(b"H this help"))
    sys.exit(0 if got.count(b"H this help") == 2 else 1)
ok = read_until(b"frame 0:", 0, limit)  # booted: the boot's own help is behind us
if ok:
    mark = len(got)
    os.write(fd, b"h")
    ok = read_until(b"H this help", mark, limit)
    print("help after H:", ok)
if ok:
    mark = len(got)
    os.write(fd, b"q")
    ok = read_until(b"quit at frame", mark, limit)
    print("quit after Q:", ok)
read_until(b"\0never", 0, 10)  # the rest, until the harness closes the pty
open(transcript_path, "wb").write(got)
sys.exit(0 if ok else 1)
