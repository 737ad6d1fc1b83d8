#!/usr/bin/env python3
"""mesh_upload: send a mesh file (.gmsh, docs/mesh-format.md) to the running firmware over its UART,
by the protocol of docs/upload-protocol.md — to a board's serial port or to a co-simulation's
pseudo-terminal (`gpusim cosim --uart-pty LINK`, `socsim --uart-pty LINK`).

    mesh_upload.py PORT FILE.gmsh [--baud 115200] [--chunk 256] [--window 4] [--timeout S]
                   [--retries N] [--session N] [--quiet] [--log FILE] [fault injection ...]

BEGIN first (alone: DATA before an accepted BEGIN would only be refused), then the DATA frames with
at most --window of them unacknowledged, then COMMIT once every chunk is acknowledged (a COMMIT
before that is refused for good). A frame is sent again on its `@up nak`, when a frame sent after
it is acknowledged (the receiver answers in the order frames arrive, so it was lost), or after
--timeout seconds without an answer beyond what its bytes take at the receiver's measured rate; a
`@up nak crc` or `nak big`, which names no frame, resends the one unacknowledged frame when there is
only one. After --retries resends of one frame the transfer is given up (ABORT).

Exit status: 0 on `@up ok` for this session; 1 on `@up reject` (printed), `@up abandoned`, retries
exhausted or the port closing; 2 on a usage error (options, a missing file, a file that is not a
.gmsh); 3 after --abandon-after K, deliberately.

The pure parts — frame encoding, the response parser, the window state machine (Transfer), the
fault injector — take and return plain data; only main() and open_port() touch a serial port, and
run() works with any object that has write(bytes) and read(n) (tests/tools/test_mesh_upload.py
drives it with a fake port).
"""
import argparse
import os
import random
import struct
import sys
import time
import zlib

# ---- frames (docs/upload-protocol.md, "Frames") ------------------------------------------------
SOF0, SOF1 = 0xA5, 0xC3
BEGIN, DATA, COMMIT, ABORT = 1, 2, 3, 4
MAX_PAYLOAD = 516
CHUNK_MIN, CHUNK_MAX = 64, 512
MESH_MAGIC = b"GMSH"


def encode_frame(ftype, session, seq, payload=b""):
    """One frame: SOF0 SOF1, then type, session, seq, len, payload, and the CRC-32 of those."""
    if len(payload) > MAX_PAYLOAD:
        raise ValueError("payload of %d bytes, at most %d" % (len(payload), MAX_PAYLOAD))
    body = struct.pack("<BBHH", ftype, session, seq, len(payload)) + payload
    return bytes([SOF0, SOF1]) + body + struct.pack("<I", zlib.crc32(body) & 0xFFFFFFFF)


def begin_payload(data, chunk):
    return struct.pack("<IIH", len(data), zlib.crc32(data) & 0xFFFFFFFF, chunk)


def data_payload(offset, piece):
    return struct.pack("<I", offset) + piece


def chunk_count(size, chunk):
    return (size + chunk - 1) // chunk


def build_frames(data, session, chunk):
    """The transfer's frames in order: (seq, type, file bytes carried, frame bytes)."""
    frames = [(0, BEGIN, 0, encode_frame(BEGIN, session, 0, begin_payload(data, chunk)))]
    n = chunk_count(len(data), chunk)
    for k in range(n):
        piece = data[k * chunk:(k + 1) * chunk]
        frames.append((k + 1, DATA, len(piece), encode_frame(DATA, session, k + 1, data_payload(k * chunk, piece))))
    frames.append((n + 1, COMMIT, 0, encode_frame(COMMIT, session, n + 1)))
    return frames


# ---- responses (docs/upload-protocol.md, "Responses") ------------------------------------------
class Response:
    """A parsed `@up` line. kind: ack, nak, reject, ok, abandoned; session and seq are None where the
    line names none (`nak crc`, `nak big N`); reason is the nak's or reject's word; text the rest."""

    def __init__(self, kind, session=None, seq=None, reason="", text=""):
        self.kind, self.session, self.seq, self.reason, self.text = kind, session, seq, reason, text

    def __eq__(self, other):
        return isinstance(other, Response) and vars(self) == vars(other)

    def __repr__(self):
        return "Response(%r)" % vars(self)


def parse_response(line):
    """The Response of one line of the firmware's output, or None if it is not a well-formed `@up`
    line (the frame lines, key echoes and anything garbled are not the tool's business)."""
    line = line.rstrip("\r\n")
    if not line.startswith("@up "):
        return None
    words = line[4:].split()
    try:
        kind = words[0]
        if kind == "ack" and len(words) == 3:
            return Response("ack", int(words[1]), int(words[2]))
        if kind == "nak" and len(words) >= 2 and words[1] == "crc":
            return Response("nak", reason="crc")
        if kind == "nak" and len(words) == 3 and words[1] == "big":
            return Response("nak", reason="big", text=words[2])
        if kind == "nak" and len(words) == 4:
            return Response("nak", int(words[1]), int(words[2]), words[3])
        if kind == "reject" and len(words) >= 3:
            rest = line[4:].split(None, 2)[2]
            reason, _, text = rest.partition(":")
            return Response("reject", int(words[1]), reason=reason.strip(), text=text.strip())
        if kind == "ok" and len(words) >= 2:
            return Response("ok", int(words[1]), text=" ".join(words[2:]))
        if kind == "abandoned" and len(words) >= 2:
            return Response("abandoned", int(words[1]), text=" ".join(words[2:]))
    except (IndexError, ValueError):
        return None
    return None


# ---- the window state machine -------------------------------------------------------------------
class TransferFailed(Exception):
    pass


class Transfer:
    """What to send when, from the answers: no I/O and no clock of its own (now is passed in).

    Phases: BEGIN alone, then DATA with `window` frames unacknowledged at most, then COMMIT, which
    ends with `@up ok` (done) or `@up reject` (failed). poll(now) gives the frames to send next;
    sent(seq, now) records that one went on the wire (in wire order: the loss detection relies on
    it); on_response() takes every parsed line. A frame is resent on a nak naming it, on an ack of
    a frame sent after it, on a nak naming no frame when it is the only one unanswered, or when it
    has waited `timeout` seconds more than its bytes take at the receiver's rate, counted from the
    later of its sending and the last answer of this session (a slow receiver that keeps answering
    is not a lost frame). The rate starts as the line's (rate, bytes a second) and follows what the
    acks show (timed from a frame's first copy: an ack of a resent frame may answer either): a co-simulated
    firmware takes a few dozen bytes a frame, and a timeout shorter than a frame's service time
    would resend every frame. More than `retries` resends of one frame fail the transfer."""

    def __init__(self, data, session, chunk=256, window=4, timeout=10.0, retries=8, rate=11520.0):
        self.session, self.window, self.timeout, self.retries = session, window, timeout, retries
        self.rate = float(rate)
        self.frames = {seq: (ftype, nbytes, frame) for seq, ftype, nbytes, frame in build_frames(data, session, chunk)}
        self.total_bytes = len(data)
        self.last_seq = max(self.frames)
        self.phase = BEGIN
        self.unsent = [0]           # seqs of this phase not yet sent, in order
        self.outstanding = {}       # seq -> [wire number, time last sent, resends, time first sent]
        self.resend = []            # seqs to send again, in order
        self.acked = set()
        self.acked_bytes = 0
        self.wire_no = 0
        self.rate_samples = 0
        self.last_answer = None
        self.done = False
        self.result = None          # the ok Response
        self.counts = {"frames": 0, "retransmissions": 0, "naks": 0, "duplicate_acks": 0, "foreign": 0}

    # -- what to send
    def poll(self, now):
        """The seqs to send now: resends first (as their reasons arrived), then new ones while the
        window has room. Raises TransferFailed on a timeout past the retries."""
        if self.done:
            return []
        for seq, (_, sent_at, _, _) in sorted(self.outstanding.items(), key=lambda kv: kv[1][0]):
            since = max(sent_at, self.last_answer or sent_at)
            if now - since >= self.timeout + len(self.frame(seq)) / self.rate and seq not in self.resend:
                self._queue_resend(seq)
        out = list(self.resend)
        self.resend = []
        room = (self.window if self.phase == DATA else 1) - len(self.outstanding)
        while self.unsent and room > 0:
            out.append(self.unsent.pop(0))
            room -= 1
        return out

    def sent(self, seq, now):
        self.wire_no += 1
        entry = self.outstanding.get(seq)
        if entry is None:
            self.outstanding[seq] = [self.wire_no, now, 0, now]
        else:
            entry[0], entry[1] = self.wire_no, now
            entry[2] += 1
            self.counts["retransmissions"] += 1
        self.counts["frames"] += 1

    def frame(self, seq):
        return self.frames[seq][2]

    def _queue_resend(self, seq):
        if self.outstanding[seq][2] >= self.retries:
            raise TransferFailed("frame %d (%s) unanswered after %d retransmissions"
                                 % (seq, self.describe(seq), self.retries))
        if seq not in self.resend:
            self.resend.append(seq)

    def describe(self, seq):
        return {BEGIN: "BEGIN", DATA: "DATA", COMMIT: "COMMIT"}[self.frames[seq][0]]

    # -- what came back
    def on_response(self, r, now):
        """Takes one Response; returns True when it concerned this transfer."""
        if r.session is not None and r.session != self.session:
            self.counts["foreign"] += 1
            return False
        previous, self.last_answer = self.last_answer, now
        if r.kind == "ack":
            return self._ack(r.seq, now, previous)
        if r.kind == "nak":
            self.counts["naks"] += 1
            if r.seq is None:
                # nak crc / big name no frame, and need not be about one of ours at all (a copy, or
                # noise that looked like a SOF). With one frame unanswered it is that one's;
                # with more, a guess would add a resend to the line's backlog each time it is
                # wrong (a slow link then drowns in copies), while the frame that was mangled
                # shows itself lost anyway by the ack of the next one, or by its timeout.
                if len(self.outstanding) == 1:
                    seq = next(iter(self.outstanding))
                    if seq not in self.resend:
                        self._queue_resend(seq)
            elif r.seq in self.outstanding:
                self._queue_resend(r.seq)
            return True
        if r.kind == "reject":
            raise TransferFailed("rejected: %s: %s" % (r.reason, r.text))
        if r.kind == "abandoned":
            raise TransferFailed("the firmware abandoned the transfer (no valid frame for too long)")
        if r.kind == "ok":
            if self.phase != COMMIT:
                return False  # only a COMMIT is answered with ok
            self.done = True
            self.result = r
            return True
        return False

    def _ack(self, seq, now=0.0, previous=None):
        if seq == self.last_seq:
            # A COMMIT is answered with ok or reject; a repeated one, of a transfer already
            # committed, with an ack (its ok was lost: the model is in).
            if self.phase == COMMIT and seq in self.outstanding:
                self.done = True
                self.result = Response("ok", self.session, text="(a repeated COMMIT acknowledged)")
            return True
        entry = self.outstanding.pop(seq, None)
        if entry is None:
            self.counts["duplicate_acks"] += 1  # a resent frame's second ack, or a stray
            return True
        self.acked.add(seq)
        # The service time from the first copy's sending: for a resent frame the ack may answer
        # either copy, and the longer time errs on the safe side (a longer timeout).
        served = now - max(entry[3], previous if previous is not None else entry[3])
        if served > 0:
            sample = len(self.frame(seq)) / served
            self.rate = 0.5 * self.rate + 0.5 * sample if self.rate_samples else sample
            self.rate_samples += 1
        if seq in self.resend:
            self.resend.remove(seq)
        self.acked_bytes += self.frames[seq][1]
        # The receiver answers in wire order: whatever went out before this frame and is still
        # unanswered was lost (a dropped or mangled frame that produced no nak).
        for other, (wire, _, _, _) in list(self.outstanding.items()):
            if wire < entry[0] and other not in self.resend:
                self._queue_resend(other)
        if not self.outstanding and not self.unsent and not self.resend:
            self._next_phase()
        return True

    def _next_phase(self):
        if self.phase == BEGIN:
            self.phase = DATA
            self.unsent = list(range(1, self.last_seq))
            if not self.unsent:  # an empty file has no chunks
                self._next_phase()
        elif self.phase == DATA:
            self.phase = COMMIT
            self.unsent = [self.last_seq]


# ---- fault injection ----------------------------------------------------------------------------
class Faults:
    """Deliberate damage on the way out, for the receiver's tests; every fault it commits is counted.
    Probabilities are per transmitted frame; garbage and keys go between frames."""

    KINDS = ("corrupt", "drop", "duplicate", "reorder", "garbage", "keys", "truncate", "oversize")

    def __init__(self, seed=None, corrupt=0.0, drop=0.0, duplicate=0.0, reorder=0.0, garbage=0.0, keys="",
                 truncate_frame=None, oversize=False):
        self.rng = random.Random(seed)
        self.p = {"corrupt": corrupt, "drop": drop, "duplicate": duplicate, "reorder": reorder, "garbage": garbage}
        self.keys = list(keys)
        self.truncate_frame = truncate_frame
        self.oversize = oversize
        self.counts = {k: 0 for k in self.KINDS}

    def _hit(self, kind):
        return self.p[kind] > 0 and self.rng.random() < self.p[kind]

    def preamble(self, session):
        """Bytes to send before the transfer: the --oversize frame (a header whose len is 600)."""
        if not self.oversize:
            return b""
        self.counts["oversize"] += 1
        return bytes([SOF0, SOF1]) + struct.pack("<BBHH", BEGIN, session, 0, 600)

    def expected_unnamed_naks(self):
        return self.counts["oversize"]

    def apply(self, batch):
        """batch: [(seq, frame bytes)] in send order. Returns [(seq or None, bytes)] in wire order,
        seq None for what is not a frame of the transfer (garbage, keys, a truncated copy)."""
        out = []
        held = None
        for seq, frame in batch:
            pieces = []
            if self.truncate_frame is not None and seq == self.truncate_frame:
                self.truncate_frame = None
                self.counts["truncate"] += 1
                pieces.append((seq, frame[:len(frame) // 2]))  # "sent": the window resends it
            elif self._hit("drop"):
                self.counts["drop"] += 1
                pieces.append((seq, b""))  # "sent" as far as the window knows
            else:
                if self._hit("corrupt"):
                    self.counts["corrupt"] += 1
                    bit = self.rng.randrange(len(frame) * 8)
                    frame = bytearray(frame)
                    frame[bit // 8] ^= 1 << (bit % 8)
                    frame = bytes(frame)
                pieces.append((seq, frame))
                if self._hit("duplicate"):
                    self.counts["duplicate"] += 1
                    pieces.append((None, frame))
            if self._hit("garbage"):
                self.counts["garbage"] += 1
                n = self.rng.randint(1, 40)
                pieces.append((None, bytes(self.rng.randint(0x80, 0xFF) for _ in range(n))))
            if self.keys:
                self.counts["keys"] += 1
                pieces.append((None, self.keys.pop(0).encode("ascii")))
            if held is not None:
                out.extend(pieces)
                out.extend(held)
                held = None
                self.counts["reorder"] += 1
            elif self._hit("reorder"):
                held = pieces
            else:
                out.extend(pieces)
        if held is not None:
            out.extend(held)  # nothing came after it in this batch: no swap, none counted
        return out


# ---- the loop: any port with write(bytes) and read(n) -------------------------------------------
class PortClosed(Exception):
    pass


class Progress:
    """One line per tenth of the file acknowledged, unless quiet."""

    def __init__(self, total, quiet, out=None):
        self.total, self.quiet, self.out, self.step = max(total, 1), quiet, out, 0

    def update(self, acked):
        tenth = acked * 10 // self.total
        if tenth > self.step:
            self.step = tenth
            if not self.quiet:
                print("mesh_upload: %3d%% (%d of %d bytes acknowledged)" % (tenth * 10, acked, self.total),
                      file=self.out or sys.stdout, flush=True)


class Stats:
    def __init__(self):
        self.wire_bytes = 0
        self.start = time.monotonic()


def run(port, transfer, faults=None, clock=time.monotonic, log=None, progress=None, abandon_after=None,
        stats=None, idle_sleep=0.002):
    """Drives transfer over port until done. Returns 0 on ok, 3 after abandon_after DATA frames;
    raises TransferFailed (reject, abandoned, retries) or PortClosed."""
    faults = faults or Faults()
    stats = stats or Stats()
    rx = b""
    unnamed_to_swallow = 0

    def write(data):
        if data:
            port.write(data)
            stats.wire_bytes += len(data)

    pre = faults.preamble(transfer.session)
    if pre:
        write(pre)
        unnamed_to_swallow = faults.expected_unnamed_naks()
    data_sent = 0
    while not transfer.done:
        now = clock()
        batch = [(seq, transfer.frame(seq)) for seq in transfer.poll(now)]
        if abandon_after is not None:
            kept = []
            for seq, frame in batch:
                if transfer.frames[seq][0] == DATA and seq not in transfer.outstanding:
                    if data_sent >= abandon_after:
                        break
                    data_sent += 1
                kept.append((seq, frame))
            batch = kept
        if batch:
            wire = faults.apply(batch)
            for seq, piece in wire:
                write(piece)
                if seq is not None:
                    transfer.sent(seq, clock())
            if abandon_after is not None and data_sent >= abandon_after:
                return 3
        try:
            chunk = port.read(4096)
        except Exception as e:  # pyserial's SerialException, OSError (EIO) on a closed pty
            raise PortClosed(str(e))
        if chunk is None:
            raise PortClosed("the port was closed")
        if not chunk:
            if idle_sleep:
                time.sleep(idle_sleep)
            continue
        rx += chunk
        while b"\n" in rx:
            raw, rx = rx.split(b"\n", 1)
            line = raw.decode("ascii", "replace").rstrip("\r")
            if log is not None:
                log.write(line + "\n")
            r = parse_response(line)
            if r is None:
                continue
            if r.kind == "nak" and r.seq is None and r.reason == "big" and unnamed_to_swallow > 0:
                unnamed_to_swallow -= 1  # the answer to --oversize's frame, not a lost one of ours
                continue
            transfer.on_response(r, clock())
            if progress is not None:
                progress.update(transfer.acked_bytes)
    return 0


def summary_line(path, transfer, faults, stats, baud):
    elapsed = time.monotonic() - stats.start
    wire_s = stats.wire_bytes * 10.0 / baud
    file_s = transfer.total_bytes * 10.0 / baud
    c = transfer.counts
    overhead = ("%.1f %% overhead" % (100.0 * (stats.wire_bytes - transfer.total_bytes) / transfer.total_bytes)
                if stats.wire_bytes >= transfer.total_bytes > 0 else "incomplete")
    text = ("mesh_upload: %s: %d bytes; on the wire %d bytes (%s), %d frames sent, "
            "%d retransmissions, %d naks, %d duplicate acks; %.2f s; the wire bytes take %.2f s at %d baud "
            "(the file alone %.2f s)"
            % (os.path.basename(path), transfer.total_bytes, stats.wire_bytes, overhead, c["frames"],
               c["retransmissions"], c["naks"], c["duplicate_acks"], elapsed, wire_s, baud, file_s))
    injected = ", ".join("%s %d" % (k, v) for k, v in faults.counts.items() if v)
    if injected:
        text += "; injected: " + injected
    return text


# ---- the serial edge ----------------------------------------------------------------------------
def open_port(path, baud):
    import serial  # pyserial (Debian's python3-serial): only the edge needs it
    port = serial.serial_for_url(path, baudrate=baud, timeout=0.02, write_timeout=30)
    # What the firmware printed before (old sessions' answers) is stale. pyserial flushes on opening
    # too; this says so where the tool relies on it.
    port.reset_input_buffer()
    return port


class UsageError(Exception):
    pass


def probability(text):
    p = float(text)
    if not 0.0 <= p <= 1.0:
        raise argparse.ArgumentTypeError("a probability is 0 .. 1, not %s" % text)
    return p


def parse_args(argv):
    ap = argparse.ArgumentParser(
        prog="mesh_upload.py", description="Send a .gmsh model to the running firmware over its UART "
        "(docs/upload-protocol.md).", epilog="Exit status: 0 ok, 1 refused or failed, 2 usage, 3 --abandon-after.")
    ap.add_argument("port", help="serial device (/dev/ttyUSB0) or a co-simulation's --uart-pty link")
    ap.add_argument("file", help="the model, as tools/meshconv writes it")
    ap.add_argument("--baud", type=int, default=115200)
    ap.add_argument("--chunk", type=int, default=256, help="file bytes per DATA frame, %d..%d" % (CHUNK_MIN, CHUNK_MAX))
    ap.add_argument("--window", type=int, default=4, help="DATA frames unacknowledged at most")
    ap.add_argument("--timeout", type=float, default=10.0,
                    help="seconds a frame may wait for its answer beyond what its bytes take at the receiver's "
                    "measured rate, before it is sent again (default 10: a co-simulated frame takes about a "
                    "second of wall time, and answers come at frame ends)")
    ap.add_argument("--retries", type=int, default=8, help="resends of one frame before giving up")
    ap.add_argument("--session", type=int, help="1..255 (default: from the process id)")
    ap.add_argument("--quiet", action="store_true", help="no progress lines")
    ap.add_argument("--log", help="keep every line the firmware printed in FILE")
    g = ap.add_argument_group("fault injection (tests of the receiver)")
    g.add_argument("--inject-seed", type=int, help="seed of the faults' random choices")
    g.add_argument("--corrupt", type=probability, default=0.0, help="flip a random bit of a frame, probability P")
    g.add_argument("--drop", type=probability, default=0.0, help="leave a frame out, probability P")
    g.add_argument("--duplicate", type=probability, default=0.0, help="send a frame twice, probability P")
    g.add_argument("--reorder", type=probability, default=0.0, help="swap a frame with the next, probability P")
    g.add_argument("--garbage", type=probability, default=0.0, help="1..40 random bytes >= 0x80 after a frame")
    g.add_argument("--keys", default="", help="type these ASCII keys between frames, one per gap")
    g.add_argument("--truncate-frame", type=int, metavar="K", help="send only the first half of frame seq K, once")
    g.add_argument("--oversize", action="store_true", help="first send a frame header whose len is 600")
    g.add_argument("--abandon-after", type=int, metavar="K", help="stop after K DATA frames, no COMMIT or ABORT")
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        raise UsageError(None) if e.code else e
    if not CHUNK_MIN <= a.chunk <= CHUNK_MAX:
        raise UsageError("--chunk %d: %d..%d" % (a.chunk, CHUNK_MIN, CHUNK_MAX))
    if a.window < 1 or a.retries < 0 or a.timeout <= 0 or a.baud <= 0:
        raise UsageError("--window >= 1, --retries >= 0, --timeout > 0, --baud > 0")
    if a.session is not None and not 1 <= a.session <= 255:
        raise UsageError("--session %d: 1..255" % a.session)
    if a.abandon_after is not None and a.abandon_after < 0:
        raise UsageError("--abandon-after K: K >= 0")
    if any(ord(c) >= 0x80 for c in a.keys):
        raise UsageError("--keys: ASCII only (bytes >= 0x80 are the protocol's)")
    return a


def read_mesh(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise UsageError("%s: %s" % (path, e.strerror))
    if data[:4] != MESH_MAGIC:
        raise UsageError("%s: not a mesh file (no GMSH magic; tools/meshconv writes them)" % path)
    return data


def main(argv=None):
    try:
        a = parse_args(sys.argv[1:] if argv is None else argv)
        data = read_mesh(a.file)
    except UsageError as e:
        if e.args and e.args[0]:
            print("mesh_upload: %s" % e.args[0], file=sys.stderr)
        return 2
    session = a.session if a.session is not None else os.getpid() % 255 + 1
    transfer = Transfer(data, session, a.chunk, a.window, a.timeout, a.retries, a.baud / 10.0)
    faults = Faults(a.inject_seed, a.corrupt, a.drop, a.duplicate, a.reorder, a.garbage, a.keys,
                    a.truncate_frame, a.oversize)
    stats = Stats()
    log = open(a.log, "w") if a.log else None
    port = None
    status = 1
    try:
        port = open_port(a.port, a.baud)
        if not a.quiet:
            print("mesh_upload: %s -> %s, session %d, %d chunks of %d bytes, window %d"
                  % (a.file, a.port, session, chunk_count(len(data), a.chunk), a.chunk, a.window), flush=True)
        status = run(port, transfer, faults, log=log, progress=Progress(len(data), a.quiet),
                     abandon_after=a.abandon_after, stats=stats)
        if status == 0:
            print("mesh_upload: accepted: @up ok %d %s" % (session, transfer.result.text), flush=True)
        else:
            print("mesh_upload: abandoned after %d DATA frames, deliberately (no COMMIT, no ABORT)"
                  % a.abandon_after, flush=True)
    except TransferFailed as e:
        print("mesh_upload: failed: %s" % e, file=sys.stderr, flush=True)
        if port is not None and "rejected" not in str(e) and "abandoned" not in str(e):
            try:  # the firmware can drop the transfer now instead of at its timeout
                port.write(encode_frame(ABORT, session, 0))
            except Exception:
                pass
    except PortClosed as e:
        print("mesh_upload: the port closed: %s" % e, file=sys.stderr, flush=True)
    except OSError as e:  # the port cannot be opened or written (pyserial's SerialException is one)
        print("mesh_upload: %s: %s" % (a.port, e), file=sys.stderr, flush=True)
    except ImportError:
        print("mesh_upload: no pyserial: install python3-serial and run this with the system python3",
              file=sys.stderr, flush=True)
    finally:
        if log is not None:
            log.close()
        if port is not None:
            port.close()
    print(summary_line(a.file, transfer, faults, stats, a.baud), flush=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
