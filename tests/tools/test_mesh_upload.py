#!/usr/bin/env python3
"""Unit tests of tools/mesh_upload.py's pure parts: the frame bytes against vectors written out by
hand from docs/upload-protocol.md (the CRCs checked by a bitwise CRC-32 here, not zlib's), the
response parser, and the window state machine driven through run() by a fake port — a small
receiver written for this test that answers as the protocol says and can be told to lose, refuse
or repeat answers. Run with python3 (pyserial is only needed by the last group, which opens a real
pseudo-terminal)."""
import io
import os
import struct
import sys
import tempfile
import threading
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import mesh_upload as mu  # noqa: E402


def crc32_bitwise(data):
    """CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), one bit at a time: an implementation
    independent of zlib's, to check the tool's frames against."""
    crc = 0xFFFFFFFF
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = (crc >> 1) ^ (0xEDB88320 if crc & 1 else 0)
    return crc ^ 0xFFFFFFFF


# A 300-byte "file" (the frame layer does not look inside it): chunks of 256 and 44 bytes.
FILE = bytes((i * 7) & 0xFF for i in range(300))


class CrcReference(unittest.TestCase):
    def test_check_value(self):
        # The CRC-32 check value every description of the polynomial quotes.
        self.assertEqual(crc32_bitwise(b"123456789"), 0xCBF43926)

    def test_file_crc(self):
        self.assertEqual(crc32_bitwise(FILE), 0xE000B1FB)


class Frames(unittest.TestCase):
    def test_commit(self):
        # type 3, session 7, seq 3 (two chunks + 1), len 0; CRC over 03 07 03 00 00 00.
        body = bytes([0x03, 0x07, 0x03, 0x00, 0x00, 0x00])
        self.assertEqual(crc32_bitwise(body), 0x97C3A0F3)
        want = bytes([0xA5, 0xC3]) + body + bytes([0xF3, 0xA0, 0xC3, 0x97])
        self.assertEqual(mu.encode_frame(mu.COMMIT, 7, 3), want)

    def test_begin(self):
        # type 1, session 7, seq 0, len 10; total 300 = 0x012C, total CRC 0xE000B1FB, chunk 256.
        body = bytes([0x01, 0x07, 0x00, 0x00, 0x0A, 0x00,
                      0x2C, 0x01, 0x00, 0x00, 0xFB, 0xB1, 0x00, 0xE0, 0x00, 0x01])
        self.assertEqual(crc32_bitwise(body), 0xFDE8E2EA)
        want = bytes([0xA5, 0xC3]) + body + bytes([0xEA, 0xE2, 0xE8, 0xFD])
        self.assertEqual(mu.encode_frame(mu.BEGIN, 7, 0, mu.begin_payload(FILE, 256)), want)

    def test_last_data(self):
        # type 2, session 7, seq 2 (chunk 1), len 4 + 44 = 48 = 0x30, offset 256, the last 44 bytes.
        body = bytes([0x02, 0x07, 0x02, 0x00, 0x30, 0x00, 0x00, 0x01, 0x00, 0x00]) + FILE[256:]
        self.assertEqual(crc32_bitwise(body), 0x06E650B9)
        want = bytes([0xA5, 0xC3]) + body + bytes([0xB9, 0x50, 0xE6, 0x06])
        self.assertEqual(mu.encode_frame(mu.DATA, 7, 2, mu.data_payload(256, FILE[256:])), want)

    def test_build_frames(self):
        frames = mu.build_frames(FILE, 7, 256)
        self.assertEqual([(s, t, n) for s, t, n, _ in frames],
                         [(0, mu.BEGIN, 0), (1, mu.DATA, 256), (2, mu.DATA, 44), (3, mu.COMMIT, 0)])
        self.assertEqual(len(frames[1][3]), 12 + 4 + 256)  # the protocol's overhead: 12 + offset
        self.assertEqual(frames[1][3][8:12], bytes(4))       # offset 0
        self.assertEqual(frames[1][3][12:-4], FILE[:256])

    def test_exact_multiple(self):
        frames = mu.build_frames(bytes(512), 1, 256)
        self.assertEqual([s for s, _, _, _ in frames], [0, 1, 2, 3])
        self.assertEqual([n for _, _, n, _ in frames], [0, 256, 256, 0])

    def test_payload_limit(self):
        self.assertEqual(len(mu.encode_frame(mu.DATA, 1, 1, bytes(516))), 528)
        with self.assertRaises(ValueError):
            mu.encode_frame(mu.DATA, 1, 1, bytes(517))


class Parser(unittest.TestCase):
    def test_lines(self):
        R = mu.Response
        cases = [
            ("@up ack 7 3", R("ack", 7, 3)),
            ("@up ack 7 3\r", R("ack", 7, 3)),
            ("@up nak 7 2 offset", R("nak", 7, 2, "offset")),
            ("@up nak 12 0 session", R("nak", 12, 0, "session")),
            ("@up nak crc", R("nak", reason="crc")),
            ("@up nak big 600", R("nak", reason="big", text="600")),
            ("@up reject 7 mesh: face 12: index 4000 out of range (vertices 1200)",
             R("reject", 7, reason="mesh", text="face 12: index 4000 out of range (vertices 1200)")),
            ("@up reject 7 incomplete: 3 of 5 chunks", R("reject", 7, reason="incomplete", text="3 of 5 chunks")),
            ("@up ok 7 faces 2 verts 4", R("ok", 7, text="faces 2 verts 4")),
            ("@up abandoned 7", R("abandoned", 7)),
            ("@up abandoned 7 (12 stray bytes ignored)", R("abandoned", 7, text="(12 stray bytes ignored)")),
        ]
        for line, want in cases:
            self.assertEqual(mu.parse_response(line), want, line)

    def test_not_responses(self):
        for line in ["frame 3: tris submitted 4", "up ack 7 3", " @up ack 7 3", "@upack 7 3", "@up ",
                     "@up ack 7", "@up ack x 3", "@up ack 7 3 4", "@up nak 7 2", "@up hello 7", "@up ok",
                     "@up abandoned", "@up reject 7"]:
            self.assertIsNone(mu.parse_response(line), line)


class FakeReceiver:
    """The firmware's side as the protocol describes it, over write()/read(): frames are found by
    their SOF, checked (len, CRC), answered one line each; bytes outside frames are skipped. Hooks:
    lose  {seq: n}  the first n copies of frame seq vanish without an answer
    nak   {seq: n}  the first n copies are answered `@up nak S Q offset`
    repeat_acks     every ack is printed twice
    silent          nothing is ever answered
    throttle        bytes taken from the line per read (None: all at once), a slow firmware
    clock           advanced by step on every read (the fake's notion of time passing)."""

    def __init__(self, clock=None, step=0.05):
        self.buf = b""
        self.out = b""
        self.lose, self.nak, self.repeat_acks, self.silent = {}, {}, False, False
        self.clock, self.step = clock, step
        self.session = None
        self.staging = None
        self.chunks = set()
        self.received = []  # (type, seq) of every good frame, in order
        self.closed = False
        self.throttle = None
        self.line = b""  # written, not yet taken (throttle)

    # the port's side
    def write(self, data):
        self.line += data
        self._take()

    def _take(self):
        n = len(self.line) if self.throttle is None else self.throttle
        self.buf += self.line[:n]
        self.line = self.line[n:]
        self._parse()

    def read(self, n):
        if self.clock is not None:
            self.clock.t += self.step
        if self.throttle is not None:
            self._take()
        if self.closed and not self.out:
            raise OSError(5, "Input/output error")
        data, self.out = self.out[:n], self.out[n:]
        return data

    def say(self, line):
        if not self.silent:
            self.out += (line + "\r\n").encode()

    def _parse(self):
        while True:
            i = self.buf.find(bytes([mu.SOF0, mu.SOF1]))
            if i < 0:
                self.buf = self.buf[-1:] if self.buf[-1:] == bytes([mu.SOF0]) else b""
                return
            self.buf = self.buf[i:]
            if len(self.buf) < 8:
                return
            ftype, session, seq, length = struct.unpack("<BBHH", self.buf[2:8])
            if length > mu.MAX_PAYLOAD:
                self.say("@up nak big %d" % length)
                self.buf = self.buf[2:]
                continue
            if len(self.buf) < 12 + length:
                return
            frame, rest = self.buf[:12 + length], self.buf[12 + length:]
            if struct.unpack("<I", frame[-4:])[0] != crc32_bitwise(frame[2:-4]):
                self.say("@up nak crc")
                self.buf = self.buf[2:]  # resynchronise on the next SOF
                continue
            self.buf = rest
            self._frame(ftype, session, seq, frame[8:-4])

    def _frame(self, ftype, session, seq, payload):
        if self.lose.get(seq, 0) > 0:
            self.lose[seq] -= 1
            return
        self.received.append((ftype, seq))
        if self.nak.get(seq, 0) > 0:
            self.nak[seq] -= 1
            self.say("@up nak %d %d offset" % (session, seq))
            return
        if ftype == mu.BEGIN:
            total, self.total_crc, self.chunk = struct.unpack("<IIH", payload)
            self.session, self.staging, self.chunks = session, bytearray(total), set()
            return self._ack(session, seq)
        if self.session != session:
            return self.say("@up nak %d %d %s" % (session, seq, "state" if self.session is None else "session"))
        if ftype == mu.DATA:
            offset = struct.unpack("<I", payload[:4])[0]
            self.staging[offset:offset + len(payload) - 4] = payload[4:]
            self.chunks.add(offset // self.chunk)
            return self._ack(session, seq)
        if ftype == mu.COMMIT:
            need = mu.chunk_count(len(self.staging), self.chunk)
            self.session = None
            if len(self.chunks) != need:
                return self.say("@up reject %d incomplete: %d of %d chunks" % (session, len(self.chunks), need))
            if crc32_bitwise(bytes(self.staging)) != self.total_crc:
                return self.say("@up reject %d crc: file CRC differs" % session)
            return self.say("@up ok %d faces 1 verts 3" % session)

    def _ack(self, session, seq):
        self.say("@up ack %d %d" % (session, seq))
        if self.repeat_acks:
            self.say("@up ack %d %d" % (session, seq))


class Clock:
    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


def transfer_over(rx, clock, data=FILE, chunk=64, window=4, timeout=1.0, retries=3, faults=None, **kw):
    t = mu.Transfer(data, 7, chunk, window, timeout, retries)
    status = mu.run(rx, t, faults, clock=clock, idle_sleep=0, **kw)
    return t, status


class Window(unittest.TestCase):
    def fault_transfer(self, frames, step=0.05, timeout=1.0, **hooks):
        """`frames` 64-byte DATA frames through a window of 4 to a FakeReceiver advancing its clock
        by step, with the given hooks (lose, nak, throttle, repeat_acks); the transfer must
        succeed. Returns (transfer, receiver, clock)."""
        clock = Clock()
        rx = FakeReceiver(clock, step=step)
        for name, value in hooks.items():
            assert hasattr(rx, name), name
            setattr(rx, name, value)
        t, status = transfer_over(rx, clock, data=bytes(64 * frames), window=4, timeout=timeout)
        self.assertEqual(status, 0)
        return t, rx, clock

    def test_clean(self):
        clock = Clock()
        rx = FakeReceiver(clock)
        t, status = transfer_over(rx, clock, chunk=256)
        self.assertEqual(status, 0)
        self.assertTrue(t.done)
        self.assertEqual(t.result.text, "faces 1 verts 3")
        self.assertEqual(bytes(rx.staging), FILE)
        self.assertEqual(rx.received, [(mu.BEGIN, 0), (mu.DATA, 1), (mu.DATA, 2), (mu.COMMIT, 3)])
        self.assertEqual(t.counts["retransmissions"], 0)
        self.assertEqual(t.acked_bytes, len(FILE))

    def test_window_limit(self):
        # No answers but BEGIN's: exactly `window` DATA frames go out, then nothing until an ack.
        t = mu.Transfer(bytes(64 * 10), 9, 64, window=3, timeout=100, retries=1)
        self.assertEqual(t.poll(0), [0])
        t.sent(0, 0)
        self.assertEqual(t.poll(0), [])  # BEGIN alone
        t.on_response(mu.Response("ack", 9, 0), 0)
        out = t.poll(0)
        self.assertEqual(out, [1, 2, 3])
        for s in out:
            t.sent(s, 0)
        self.assertEqual(t.poll(1), [])
        t.on_response(mu.Response("ack", 9, 1), 1)
        self.assertEqual(t.poll(1), [4])

    def test_nak_retransmits(self):
        # A nak for the last DATA frame: no later ack shows it lost, only the nak.
        t, rx, clock = self.fault_transfer(6, timeout=1000.0, nak={6: 1})
        self.assertEqual(t.counts["naks"], 1)
        self.assertEqual(t.counts["retransmissions"], 1)
        self.assertEqual([q for f, q in rx.received if q == 6], [6, 6])
        self.assertLess(clock.t, 1000.0)  # by the nak, not the timeout

    def test_lost_frame_resent_when_a_later_one_is_acked(self):
        t, rx, clock = self.fault_transfer(6, timeout=1000.0, lose={2: 1})
        self.assertEqual(t.counts["retransmissions"], 1)
        self.assertLess(clock.t, 1000.0)  # not by the timeout

    def test_timeout_retransmits(self):
        # The last DATA frame's loss shows by nothing but silence: resent after the timeout.
        t, rx, clock = self.fault_transfer(6, step=0.05, timeout=2.0, lose={6: 1})
        self.assertEqual(t.counts["retransmissions"], 1)
        self.assertGreaterEqual(clock.t, 2.0)

    def test_slow_receiver_no_resends(self):
        # 2 bytes a read, 0.05 s a read: 40 bytes/s, so a DATA frame of 80 bytes takes 2 s, more
        # than the timeout: the rate learnt from BEGIN's ack must keep the window from resending.
        t, rx, clock = self.fault_transfer(6, step=0.05, throttle=2)
        self.assertEqual(t.counts["retransmissions"], 0)
        self.assertLess(t.rate, 60)
        self.assertGreater(clock.t, 10.0)  # it was slow: 550 bytes at 40 bytes/s

    def test_duplicate_acks_ignored(self):
        t, rx, clock = self.fault_transfer(6, repeat_acks=True)
        self.assertEqual(t.counts["retransmissions"], 0)
        self.assertEqual(t.counts["duplicate_acks"], 7)  # BEGIN and six DATA, each acked twice
        self.assertEqual(t.acked_bytes, 64 * 6)

    def test_foreign_session_ignored(self):
        t = mu.Transfer(FILE, 7, 256, 4, 100, 1)
        t.poll(0)
        t.sent(0, 0)
        self.assertFalse(t.on_response(mu.Response("ack", 8, 0), 0))
        self.assertEqual(t.phase, mu.BEGIN)
        self.assertTrue(t.on_response(mu.Response("ack", 7, 0), 0))
        self.assertEqual(t.phase, mu.DATA)

    def test_ok_only_answers_commit(self):
        t = mu.Transfer(bytes(64 * 2), 7, 64, 4, 100, 1)
        t.sent(t.poll(0)[0], 0)
        t.on_response(mu.Response("ack", 7, 0), 0)
        self.assertFalse(t.on_response(mu.Response("ok", 7, text="faces 1 verts 3"), 0))
        self.assertFalse(t.done)

    def test_unnamed_nak(self):
        # With several frames unanswered a nak crc names none of them: nothing is resent until the
        # next ack shows which one was lost. With one unanswered, it is that one's.
        t = mu.Transfer(bytes(64 * 4), 7, 64, 4, 100, 2)
        t.sent(t.poll(0)[0], 0)
        t.on_response(mu.Response("nak", reason="crc"), 0)
        self.assertEqual(t.poll(0), [0])  # BEGIN, alone
        t.sent(0, 0)
        t.on_response(mu.Response("ack", 7, 0), 0)
        for s in t.poll(0):
            t.sent(s, 0)
        t.on_response(mu.Response("ack", 7, 1), 0)
        t.on_response(mu.Response("nak", reason="crc"), 0)
        self.assertEqual(t.poll(0), [])
        t.on_response(mu.Response("ack", 7, 3), 0)
        self.assertEqual(t.poll(0), [2])
        self.assertEqual(t.counts["naks"], 2)

    def test_retries_exhausted(self):
        clock = Clock()
        rx = FakeReceiver(clock, step=0.5)
        rx.silent = True
        with self.assertRaises(mu.TransferFailed) as e:
            transfer_over(rx, clock, timeout=1.0, retries=2)
        self.assertIn("BEGIN", str(e.exception))
        self.assertEqual(rx.received, [(mu.BEGIN, 0)] * 3)  # the first copy and two resends

    def test_reject(self):
        t = mu.Transfer(FILE, 7, 256, 4, 100, 1)
        with self.assertRaises(mu.TransferFailed) as e:
            t.on_response(mu.parse_response("@up reject 7 capacity: 300 bytes, buffer 200"), 0)
        self.assertIn("capacity", str(e.exception))

    def test_port_closed(self):
        clock = Clock()
        rx = FakeReceiver(clock)
        rx.silent = True
        rx.closed = True
        with self.assertRaises(mu.PortClosed):
            transfer_over(rx, clock)

    def test_commit_only_after_every_ack(self):
        t, rx, clock = self.fault_transfer(3, lose={1: 2})
        kinds = [f for f, _ in rx.received]
        self.assertEqual(kinds.count(mu.COMMIT), 1)
        self.assertEqual(kinds[-1], mu.COMMIT)

    def test_progress_lines(self):
        clock = Clock()
        out = io.StringIO()
        data = bytes(64 * 20)
        transfer_over(FakeReceiver(clock), clock, data=data, progress=mu.Progress(len(data), False, out))
        lines = out.getvalue().splitlines()
        self.assertEqual(len(lines), 10)
        self.assertIn("100%", lines[-1])


class Injection(unittest.TestCase):
    """Every fault the tool can inject, against the fake receiver: the transfer still completes,
    the staged file is the file, and each fault was counted."""

    def run_with(self, seed=1, data=None, **faults):
        clock = Clock()
        rx = FakeReceiver(clock)
        data = data if data is not None else bytes((i * 13 + 5) & 0x7F for i in range(64 * 30))
        f = mu.Faults(seed, **faults)
        t, status = transfer_over(rx, clock, data=data, window=4, timeout=1.0, retries=20, faults=f)
        self.assertEqual(status, 0)
        self.assertEqual(bytes(rx.staging), data)
        return t, f, rx

    def test_each_fault(self):
        for kind in ("corrupt", "drop", "duplicate", "reorder", "garbage"):
            with self.subTest(kind=kind):
                t, f, _ = self.run_with(**{kind: 0.3})
                self.assertGreater(f.counts[kind], 0)
                if kind in ("corrupt", "drop"):
                    self.assertGreater(t.counts["retransmissions"], 0)

    def test_keys_truncate_oversize(self):
        t, f, rx = self.run_with(keys="hjkl", truncate_frame=3, oversize=True)
        self.assertEqual(f.counts["keys"], 4)
        self.assertEqual(f.counts["truncate"], 1)
        self.assertEqual(f.counts["oversize"], 1)
        self.assertGreater(t.counts["retransmissions"], 0)  # the truncated frame, at least

    def test_oversize_answer_is_not_a_loss(self):
        # The receiver's `nak big 600` answers the injected header, not BEGIN: nothing is resent.
        t, f, _ = self.run_with(oversize=True)
        self.assertEqual(f.counts["oversize"], 1)
        self.assertEqual(t.counts["naks"], 0)
        self.assertEqual(t.counts["retransmissions"], 0)

    def test_seeded(self):
        a = self.run_with(seed=5, corrupt=0.2, drop=0.2)[1].counts
        b = self.run_with(seed=5, corrupt=0.2, drop=0.2)[1].counts
        self.assertEqual(a, b)

    def test_abandon_after(self):
        clock = Clock()
        rx = FakeReceiver(clock)
        t = mu.Transfer(bytes(64 * 10), 7, 64, 4, 1.0, 3)
        status = mu.run(rx, t, clock=clock, idle_sleep=0, abandon_after=5)
        self.assertEqual(status, 3)
        kinds = [f for f, _ in rx.received]
        self.assertEqual(kinds.count(mu.DATA), 5)
        self.assertNotIn(mu.COMMIT, kinds)
        self.assertNotIn(mu.ABORT, kinds)


class Usage(unittest.TestCase):
    def test_exit_2(self):
        with tempfile.TemporaryDirectory() as d:
            good = os.path.join(d, "m.gmsh")
            with open(good, "wb") as f:
                f.write(b"GMSH" + bytes(60))
            bad = os.path.join(d, "x.gmsh")
            with open(bad, "wb") as f:
                f.write(b"PNG!" + bytes(60))
            devnull = open(os.devnull, "w")
            old = sys.stderr
            sys.stderr = devnull
            try:
                for argv in ([d + "/tty", d + "/missing.gmsh"], [d + "/tty", bad], [d + "/tty", good, "--chunk", "32"],
                             [d + "/tty", good, "--window", "0"], [d + "/tty", good, "--session", "0"],
                             [d + "/tty", good, "--drop", "1.5"], [d + "/tty", good, "--keys", "\u00e9"], [d + "/tty"]):
                    self.assertEqual(mu.main(argv), 2, argv)
            finally:
                sys.stderr = old
                devnull.close()


@unittest.skipUnless(sys.platform.startswith("linux"), "a Linux pty")
class SerialEdge(unittest.TestCase):
    """main() on a real pseudo-terminal, the fake receiver on its master: pyserial, the line
    splitting, the exit status and the summary line."""

    def test_main_over_a_pty(self):
        try:
            import serial  # noqa: F401
        except ImportError:
            self.skipTest("no pyserial (Debian's python3-serial; run with /usr/bin/python3)")
        master, slave = os.openpty()
        rx = FakeReceiver()
        stop = threading.Event()

        def serve():
            while not stop.is_set():
                import select
                if select.select([master], [], [], 0.02)[0]:
                    try:
                        rx.write(os.read(master, 4096))
                    except OSError:
                        return
                out = rx.read(4096)
                if out:
                    os.write(master, b"frame 1: noise the tool must skip\r\n" + out)

        # An answer left from an earlier run, waiting in the pty: the tool must discard it on opening.
        os.write(master, b"@up reject 42 crc: an old session's answer\r\n")
        th = threading.Thread(target=serve, daemon=True)
        th.start()
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.gmsh")
            data = b"GMSH" + bytes(range(256)) * 3
            with open(path, "wb") as f:
                f.write(data)
            log = os.path.join(d, "log")
            out = io.StringIO()
            old = sys.stdout
            sys.stdout = out
            try:
                status = mu.main([os.ttyname(slave), path, "--session", "42", "--chunk", "128", "--log", log,
                                  "--timeout", "2"])
            finally:
                sys.stdout = old
                stop.set()
                th.join()
                os.close(master)
                os.close(slave)
            self.assertEqual(status, 0, out.getvalue())
            self.assertEqual(bytes(rx.staging), data)
            text = out.getvalue()
            self.assertIn("accepted: @up ok 42", text)
            summary = text.splitlines()[-1]
            # 772 bytes: BEGIN 22, six DATA frames of 128 (16 + 128 each) and one of 4 (16 + 4),
            # COMMIT 12: 22 + 6 * 144 + 20 + 12 = 918.
            self.assertIn("772 bytes; on the wire 918 bytes", summary)
            self.assertIn("9 frames sent, 0 retransmissions", summary)
            with open(log) as f:
                self.assertIn("frame 1: noise the tool must skip\n", f.read())


if __name__ == "__main__":
    unittest.main()
