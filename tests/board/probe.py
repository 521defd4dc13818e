#!/usr/bin/env python3
"""tests/board/probe.py unix:PATH - the board's answers to what no correct host sends: malformed
and refused START frames, DATA and END that break the run's rules, a lost frame seen twice, and
the status record's counters (docs/board.md sections 2, 3, 4.1, 4.2, 4.4, 4.5, 5.5).  Written from
docs/board.md alone (standard library; the CRC is zlib.crc32), as tests/board/identify.py and
tests/host/pyboard.py are: an independent reader of what the board engine answers (issue 27: the
engine's mutants that edgeflag-host's own runs cannot reach).  Every case starts with a reset
control frame.  Prints "ok - ..." or "FAIL - ..." per check, then "N passed, M failed"; exit 0
only if nothing failed."""
import socket
import struct
import sys
import time
import zlib

T_START, T_DATA, T_END, T_ACKR = 0x04, 0x01, 0x02, 0x03
T_ACK, T_NAK, T_RESULT, T_DONE, T_ERROR = 0x81, 0x82, 0x83, 0x84, 0x85
DIGEST, SELECT = 1, 2


def frame(typ, seq, payload=b"", flags=0):
    head = b"EFB1" + struct.pack("<BBHII", typ, flags, 0, seq, len(payload)) + payload
    return head + struct.pack("<I", zlib.crc32(head))


class Board:
    def __init__(self, addr):
        self.s = socket.socket(socket.AF_UNIX)
        self.s.connect(addr)
        self.buf = b""
        self.tag = 0x7000
        self.bad_flags = []      # board frames whose flags are not 0 (none defined board -> host)

    def send(self, data):
        self.s.sendall(data)

    def frames(self, wait, stop=(T_ERROR, T_DONE, T_NAK, T_ACK)):
        """every whole frame that arrives within `wait` seconds, or until 0.3 s after a frame of
        a type in `stop` (a second one, a NAK storm, would arrive by then)"""
        out = []
        end = time.time() + wait
        while time.time() < end:
            self.s.settimeout(max(0.01, end - time.time()))
            try:
                d = self.s.recv(65536)
            except socket.timeout:
                break
            if not d:
                break
            self.buf += d
            while True:
                i = self.buf.find(b"EFB1")
                if i < 0 or len(self.buf) < i + 16:
                    break
                typ, flags, _, seq, ln = struct.unpack("<BBHII", self.buf[i + 4:i + 16])
                if len(self.buf) < i + 20 + ln:
                    break
                f = self.buf[i:i + 16 + ln]
                crc, = struct.unpack("<I", self.buf[i + 16 + ln:i + 20 + ln])
                if crc != zlib.crc32(f):
                    self.buf = self.buf[i + 1:]
                    continue
                self.buf = self.buf[i + 20 + ln:]
                if flags:
                    self.bad_flags.append((typ, flags))
                out.append((typ, seq, f[16:]))
                if typ in stop:
                    end = min(end, time.time() + (0.3 if stop != (typ,) else 0.0))
        return out

    def control(self, typ):
        """a control request (0x10 identify, 0x11 status, 0x12 reset): its reply's payload"""
        self.tag += 1
        self.send(frame(typ, self.tag))
        end = time.time() + 60
        while time.time() < end:
            for t, seq, p in self.frames(1.0, stop=(typ | 0x80,)):
                if t == typ | 0x80 and seq == self.tag:
                    return p
        raise SystemExit("probe: no reply to control request 0x%02x" % typ)

    def reset(self):
        self.control(0x12)
        self.buf = b""


passed = failed = 0


def check(ok, what, got=""):
    global passed, failed
    if ok:
        passed += 1
        print("ok - " + what)
    else:
        failed += 1
        print("FAIL - %s%s" % (what, ": got " + str(got) if got != "" else ""))


def start_payload(ifaces, samples, mode, kib=0, cmds=0):
    return struct.pack("<IIIIQ", ifaces, samples, mode, kib, cmds)


def errors_of(fs):
    return [(struct.unpack("<I", p[:4])[0], p[4:].decode("ascii", "replace")) for t, _, p in fs if t == T_ERROR]


def cmd(op, a=0, b_=0, c=0, d=0):
    """a command: 13 bytes, least significant first (docs/board.md 2)"""
    return (d | c << 24 | b_ << 48 | a << 72 | op << 96).to_bytes(13, "little")


def records(data):
    """the vectors.bin records of RESULT payloads (section 4.3): (interface, bytes)"""
    out, o = [], 0
    while o + 10 <= len(data):
        n = 10 + data[o + 1]
        out.append((data[o], data[o:o + n]))
        o += n
    return out


def dut_run(b, ifaces, samples, flags, extra, cmds):
    """a mode-0 run of the cmd interface: START, one DATA, END; every numbered board frame is
    acknowledged as it comes (ACKR naming the next).  Its RESULT payloads, DONE's fields, ERROR."""
    b.reset()
    ncmd = len(cmds) // 13
    b.send(frame(T_START, 0, start_payload(1, samples, 0, 0, ncmd) + extra, flags) +
           frame(T_DATA, 1, cmds) + frame(T_END, 2))
    got, res, done, err = set(), b"", None, None
    end = time.time() + 60
    while time.time() < end and done is None and err is None:
        for t, seq, p in b.frames(1.0, stop=(T_DONE, T_ERROR, T_RESULT)):
            if t in (T_RESULT, T_DONE, T_ERROR) and seq not in got:
                got.add(seq)
                if t == T_RESULT:
                    res += p
                elif t == T_DONE:
                    done = struct.unpack("<QQQII", p)
                else:
                    err = (struct.unpack("<I", p[:4])[0], p[4:])
                b.send(frame(T_ACKR, 0, struct.pack("<I", seq + 1)))
    return {"results": res, "done": done or (None,) * 5, "error": err}


def main():
    if len(sys.argv) != 2 or not sys.argv[1].startswith("unix:"):
        raise SystemExit(__doc__)
    b = Board(sys.argv[1][5:])
    b.reset()
    ident = b.control(0x10)
    ifaces, smask = struct.unpack("<II", ident[12:20])
    samples = min(1 << k for k in range(32) if smask >> k & 1)
    good = start_payload(ifaces, samples, 0, 0, 0)

    # --- START refused (ERROR code 1: malformed; 2: what the board does not have), section 3.2, 4.5
    cases = [
        ("flags 4 (unknown)", 4, good + struct.pack("<II", 1, 0), 1, "unknown flags"),
        ("flags DIGEST|SELECT", 3, good + struct.pack("<II", 1, 0), 1, "unknown flags"),
        ("a 24-byte payload with DIGEST", DIGEST, good, 1, "wrong length"),
        ("DIGEST with windows of 0 transactions", DIGEST, good + struct.pack("<I", 0), 1, "windows of 0"),
        ("SELECT of 1,025 windows", SELECT, good + struct.pack("<II", 1, 1025) + b"\0" * 4 * 1025, 1, "malformed"),
        ("SELECT whose count is not its length", SELECT, good + struct.pack("<II", 1, 2) + struct.pack("<I", 1), 1, "malformed"),
        ("SELECT with a window twice", SELECT, good + struct.pack("<IIII", 1, 2, 5, 5), 1, "ascending"),
        ("SELECT out of order", SELECT, good + struct.pack("<IIII", 1, 2, 7, 3), 1, "ascending"),
        ("mode 4 (unknown)", 0, start_payload(ifaces, samples, 4), 1, "unknown mode"),
        ("an interface the board cannot return", 0, start_payload(ifaces | 1 << 31, samples, 0), 2, "interfaces"),
        ("12 samples per pixel", 0, start_payload(ifaces, 12, 0), 2, "sample count"),
    ]
    for name, flags, payload, code, text in cases:
        b.reset()
        b.send(frame(T_START, 0, payload, flags))
        errs = errors_of(b.frames(2.0))
        check(len(errs) == 1 and errs[0][0] == code and text in errs[0][1],
              "START %s: ERROR code %d ('...%s...')" % (name, code, text), errs)

    # the good ones next to them: SELECT of 1,024 ascending windows, DIGEST with N = 1, mode 3
    # (source) of 0 KiB: no ERROR, and END gives DONE
    for name, flags, payload in (
            ("SELECT of 1,024 ascending windows", SELECT, good + struct.pack("<II", 1, 1024) +
             b"".join(struct.pack("<I", k) for k in range(1024))),
            ("DIGEST with N = 1", DIGEST, good + struct.pack("<I", 1)),
            ("mode 3 (source) of 0 KiB", 0, start_payload(0, 0, 3))):
        b.reset()
        b.send(frame(T_START, 0, payload, flags) + frame(T_END, 1))
        fs = b.frames(2.0)
        check(not errors_of(fs) and any(t == T_DONE for t, _, _ in fs),
              "START %s and END: DONE, no ERROR" % name, [(hex(t), s) for t, s, _ in fs])

    # --- DATA and END that break the run's rules (ERROR 3 and 4, section 4.4)
    b.reset()
    b.send(frame(T_START, 0, start_payload(ifaces, samples, 0, 0, 1)) + frame(T_DATA, 1, b"\0" * 12))
    errs = errors_of(b.frames(2.0))
    check(len(errs) == 1 and errs[0][0] == 3, "DATA of 12 bytes: ERROR code 3", errs)
    b.reset()
    b.send(frame(T_START, 0, start_payload(ifaces, samples, 0, 0, 1)) + frame(T_END, 1))
    errs = errors_of(b.frames(2.0))
    check(len(errs) == 1 and errs[0][0] == 4, "END after 0 commands when START announced 1: ERROR code 4", errs)
    b.reset()
    b.send(frame(T_START, 0, start_payload(ifaces, samples, 0, 0, 0)) + frame(T_END, 1))
    fs = b.frames(2.0)
    done = [p for t, _, p in fs if t == T_DONE]
    check(len(done) == 1 and len(done[0]) == 32 and struct.unpack("<QQQII", done[0]) == (0, 0, 0, 0, 0),
          "START of 0 commands and END: DONE of 0 records, 0 bytes, 0 commands, CRCs 0", done)

    # --- a lost frame (section 4.1): one NAK (reason 1, naming E) however many frames follow it,
    # until a frame is taken again; then a new gap gets its own NAK
    b.reset()
    b.send(frame(T_START, 0, start_payload(0, 0, 1)))      # sink: DATA taken and dropped
    b.frames(1.0)
    b.send(frame(T_DATA, 3, b"\0" * 13) + frame(T_DATA, 4, b"\0" * 13))
    naks = [struct.unpack("<II", p) for t, _, p in b.frames(1.5) if t == T_NAK]
    check(naks == [(1, 1)], "two frames past a gap: one NAK (E 1, reason 1)", naks)
    b.send(frame(T_DATA, 1, b"\0" * 13))
    acks = [struct.unpack("<III", p)[0] for t, _, p in b.frames(1.5) if t == T_ACK]
    check(acks == [2], "the missing frame: taken, ACK naming 2", acks)
    b.send(frame(T_DATA, 5, b"\0" * 13))
    naks = [struct.unpack("<II", p) for t, _, p in b.frames(1.5) if t == T_NAK]
    check(naks == [(2, 1)], "a new gap after a frame was taken: a new NAK (E 2, reason 1)", naks)

    # --- the status record's counters (section 3.1) around an ERROR and ACKR (4.2)
    b.reset()
    b.send(frame(T_START, 0, start_payload(ifaces, samples, 9)))
    b.frames(1.0)
    st = b.control(0x11)
    state, nxt, made, acked = st[6], *struct.unpack("<III", st[8:20])
    check((state, nxt, made, acked) == (3, 1, 1, 0),
          "status after a refused START: state 3 (error), next 1, 1 result frame made, 0 acknowledged",
          (state, nxt, made, acked))
    b.send(frame(T_ACKR, 0, struct.pack("<I", 1)))
    b.frames(0.5)
    st = b.control(0x11)
    check(struct.unpack("<II", st[12:20]) == (1, 1), "status after ACKR naming 1: 1 made, 1 acknowledged",
          struct.unpack("<II", st[12:20]))

    # --- real runs of two commands (FRAME 4 x 4, FRAME_END; the cmd interface returned), section
    # 3.2, 4.3 to 4.5: full, digest (N = 1) and select runs must agree record for record
    cmds = cmd(1, 4, 4) + cmd(5)
    full = dut_run(b, ifaces, samples, 0, b"", cmds)
    recs = records(full["results"])
    check(full["error"] is None and len(recs) == 2 and all(r[0] == 0 for r in recs) and
          full["done"] == (2, len(full["results"]), 2, zlib.crc32(cmds), zlib.crc32(full["results"])),
          "a full run of FRAME, FRAME_END: 2 cmd records; DONE's records, bytes, commands and CRCs agree",
          (full["error"], len(recs), full["done"]))
    dig = dut_run(b, ifaces, samples, DIGEST, struct.pack("<I", 1), cmds)
    want = b"".join(struct.pack("<BBIII", 0, 0xFF, w, 1, zlib.crc32(r[1])) for w, r in enumerate(recs))
    check(dig["error"] is None and dig["results"] == want and dig["done"][0] == 2,
          "a digest run (N = 1): one digest record per cmd transaction, the CRC of the full run's record",
          (dig["error"], dig["results"].hex(), dig["done"]))
    for name, sel, n in (("window 0 of cmd", [0], 1), ("window 1 of cmd", [1], 1), ("no window", [], 0)):
        r = dut_run(b, ifaces, samples, SELECT, struct.pack("<II", 1, len(sel)) +
                    b"".join(struct.pack("<I", w) for w in sel), cmds)
        check(r["error"] is None and r["results"] == b"".join(recs[w][1] for w in sel) and r["done"][0] == n,
              "a select run of %s: exactly those records, DONE counts %d" % (name, n),
              (r["error"], r["results"].hex(), r["done"]))
    # a run cut by a reset after its first command, then the same run whole: the DUT starts clean
    b.reset()
    b.send(frame(T_START, 0, start_payload(1, samples, 0, 0, 2)) + frame(T_DATA, 1, cmd(1, 4, 4)))
    b.frames(1.0)
    again = dut_run(b, ifaces, samples, 0, b"", cmds)
    check(again["error"] is None and again["results"] == full["results"],
          "after a run cut by a reset, the same run gives the same records", (again["error"], again["done"]))

    # --- identify's limits are the DUT's (section 3.1, 3.2): a FRAME of exactly W_MAX x 1 and of
    # 1 x H_MAX is rendered, one a pixel over either is refused by the DUT (ERROR code 16)
    wmax, hmax = struct.unpack("<II", ident[20:28])
    for w, h, ok_ in ((wmax, 1, True), (1, hmax, True), (wmax + 1, 1, False), (1, hmax + 1, False)):
        r = dut_run(b, ifaces, samples, 0, b"", cmd(1, w, h) + cmd(5))
        if ok_:
            check(r["error"] is None and r["done"][2] == 2, "a FRAME of %d x %d (identify's limits): DONE" % (w, h),
                  (r["error"], r["done"]))
        else:
            check(r["error"] is not None and r["error"][0] == 16,
                  "a FRAME of %d x %d (a pixel over identify's limits): ERROR code 16" % (w, h), r["error"])

    # --- a connection that ends in the middle of a frame (section 5.5): the board drops the part
    # it had, so the next connection's first frame is taken with no NAK
    b.reset()
    b.send(frame(T_START, 0, start_payload(0, 0, 1)))
    b.frames(1.0)
    part = frame(T_DATA, 1, b"\0" * 13)
    b.send(part[:11])
    b.s.close()
    time.sleep(0.5)
    b2 = Board(sys.argv[1][5:])
    b2.send(part)
    fs = b2.frames(1.5)
    check([t for t, _, _ in fs] == [T_ACK] and struct.unpack("<III", fs[0][2])[0] == 2,
          "a frame cut by the end of a connection, sent whole on the next: taken (ACK 2), no NAK",
          [(hex(t), p.hex()) for t, _, p in fs])
    b2.bad_flags += b.bad_flags
    b = b2

    check(not b.bad_flags, "every board frame has flags 0 (docs/board.md 2: no flag is defined board -> host)",
          b.bad_flags)
    print("%d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
