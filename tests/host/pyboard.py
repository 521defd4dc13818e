#!/usr/bin/env python3
"""pyboard.py - an edgeflag board written from docs/board.md alone (sections 2-4 and 5.5), as an
independent oracle for edgeflag-host's socket transport and its protocol code: it shares no code
with host/ (Python standard library only; the CRC is zlib.crc32).

It listens on a unix socket (--unix PATH) or on 127.0.0.1 (--tcp PORT, 0 = any free port,
written to --port-file), serves one connection at a time and keeps its run across connections
(capability bit 1, resume).  Its DUT replays an expected vectors.bin (--vectors): every command
received must equal the file's next cmd record (else ERROR 16), and at each FRAME_END it returns
the file's records of the interfaces START asked for, in file order, up to the file's next cmd
record (the rest at END), so a correct host gets results that pass `edgeflag check`.  START's
link-test modes (sink, loopback, source) are those of docs/board.md section 8.

Faults (each flag may repeat; N counts from 1):
  --drop N            drop the Nth numbered host frame (START/DATA/END, every copy counts)
  --corrupt N         flip a byte of the Nth numbered host frame
  --drop-reply N      do not send the Nth numbered board frame copy (RESULT/DONE/ERROR)
  --corrupt-reply N   flip a byte of the Nth numbered board frame copy
  --disconnect N      close the connection when the Nth numbered host frame arrives (not taken)
  --disconnect-reply N  close the connection instead of sending the Nth numbered board frame copy
  --stall N           from the Nth numbered host frame on, take nothing and say nothing until
                      the connection closes
  --reset N           reset (section 3.1) before taking the Nth numbered host frame
  --protocol V        identify answers protocol version V
  --not-ours          identify answers without the magic
  --mute              accepts connections and never answers anything (not even identify)
  --data-kib K        identify's largest DATA payload, in KiB (capabilities bits 16-23, table 3.1);
                      the stats' data_max is the largest DATA payload taken
--limits W,H,E makes identify state W_MAX, H_MAX and E_MAX (default 16384,16384,4194304): the board
a `edgeflag-host identify --save` test reads (the replay DUT does not check them).
--stats FILE gets one line of counters (JSON) after every connection and every DONE/ERROR.
"""
import argparse
import json
import os
import select
import signal
import socket
import struct
import sys
import zlib

MAGIC = b"EFB1"
HDR, TRL, PAYLOAD_MAX, RESULT_MAX = 16, 4, 65536, 32768
T_DATA, T_END, T_ACKR, T_START = 0x01, 0x02, 0x03, 0x04
T_ACK, T_NAK, T_RESULT, T_DONE, T_ERROR = 0x81, 0x82, 0x83, 0x84, 0x85
T_IDENT, T_STATUS, T_RESET = 0x10, 0x11, 0x12
NAK_DAMAGED, NAK_GAP, NAK_UNKNOWN, NAK_PLACE = 0, 1, 2, 3
CMD_BYTES = 13
IFACE_BYTES = [13, None, None, None, None, None, None]  # cmd's 100 bits; others from the file
S_IDLE, S_RUN, S_DONE, S_ERROR = 0, 1, 2, 3
VEC_MAGIC = b"\x89EFV\r\n\x1a\n"
SOURCE_BYTES = bytes(i & 0xFF for i in range(RESULT_MAX))   # source mode's payload (any bytes do)


def frame(ftype, seq, payload=b"", flags=0):
    head = MAGIC + struct.pack("<BBHII", ftype, flags, 0, seq, len(payload)) + payload
    return head + struct.pack("<I", zlib.crc32(head))


def parse(buf):
    """('ok', type, flags, seq, payload, size) | ('more',) | ('bad',) for the bytes at buf[0:]."""
    n = len(buf)
    if buf[:min(n, 4)] != MAGIC[:min(n, 4)]:
        return ("bad",)
    if n < HDR:
        return ("more",)
    ftype, flags, reserved, seq, length = struct.unpack_from("<BBHII", buf, 4)
    if reserved != 0 or length > PAYLOAD_MAX:
        return ("bad",)
    size = HDR + length + TRL
    if n < size:
        return ("more",)
    if zlib.crc32(bytes(buf[:HDR + length])) != struct.unpack_from("<I", buf, HDR + length)[0]:
        return ("bad",)
    return ("ok", ftype, flags, seq, bytes(buf[HDR:HDR + length]), size)


def resync(buf):
    """Offset of the next "EFB1" (or a prefix of it at the end) after buf[0]."""
    i = 1
    while True:
        i = buf.find(b"E", i)
        if i < 0:
            return len(buf)
        tail = bytes(buf[i:i + 4])
        if tail == MAGIC[:len(tail)]:
            return i
        i += 1


class Vectors:
    """The expected vectors.bin (docs/vectors.md section 4), checked as a reader must."""

    def __init__(self, path):
        data = open(path, "rb").read()
        if len(data) < 104 or data[:8] != VEC_MAGIC:
            sys.exit("pyboard: %s: not a vectors.bin" % path)
        ver, hsize, self.samples = struct.unpack_from("<HHB", data, 8)
        if ver != 1 or hsize != 104 or zlib.crc32(data[:100]) != struct.unpack_from("<I", data, 100)[0]:
            sys.exit("pyboard: %s: bad header" % path)
        self.mask = struct.unpack_from("<I", data, 32)[0]
        if zlib.crc32(data[104:]) != struct.unpack_from("<I", data, 96)[0]:
            sys.exit("pyboard: %s: records CRC differs" % path)
        self.records = []          # (iface, whole record bytes)
        self.cmd_index = []        # index in records of every cmd record
        pos = 104
        while pos < len(data):
            if pos + 10 > len(data):
                sys.exit("pyboard: %s: record at byte %d cut short" % (path, pos))
            iface, length = data[pos], data[pos + 1]
            if iface > 6 or pos + 10 + length > len(data):
                sys.exit("pyboard: %s: bad record at byte %d" % (path, pos))
            if iface == 0:
                self.cmd_index.append(len(self.records))
            self.records.append((iface, data[pos:pos + 10 + length]))
            pos += 10 + length


class Board:
    def __init__(self, args):
        self.a = args
        self.vec = Vectors(args.vectors) if args.vectors else None
        self.window = args.window
        self.iface_mask = (self.vec.mask if self.vec else 0x7f)
        self.samples_mask = (1 << {8: 3, 16: 4, 32: 5}[self.vec.samples]) if self.vec else 0x38
        self.host_frames = 0       # numbered host frames seen (fault counter), across connections
        self.board_frames = 0      # numbered board frame copies sent (fault counter)
        self.stalled = False
        self.drop_conn = False
        self.reset_state()

    # --- section 3.1: reset -------------------------------------------------------------------
    def reset_state(self):
        self.state = S_IDLE
        self.E = 0                 # next host frame expected
        self.kept = {}             # result seq -> frame bytes, until acknowledged
        self.res_made = 0
        self.res_acked = 0
        self.res_next_send = 0
        self.res_sent_max = 0      # one past the highest result frame ever sent
        self.input_crc = 0
        self.results_crc = 0
        self.result_bytes = 0
        self.cmds = 0
        self.records = 0
        self.nak_sent = False      # one NAK until a frame is taken again
        self.mode = 0
        self.want = 0
        self.announced = 0
        self.cmd_pos = 0           # replay: index into vec.cmd_index of the next command
        self.emit_pos = 0          # replay: next record of the file to consider returning
        self.out = bytearray()     # bytes queued for the host
        self.stats = {"taken": 0, "dup": 0, "gap": 0, "bad": 0, "naks": 0, "resets": 0, "data_max": 0}

    # --- output -------------------------------------------------------------------------------
    def make_result(self, ftype, payload):
        seq = self.res_made
        self.res_made += 1
        self.kept[seq] = frame(ftype, seq, payload)
        if ftype == T_RESULT:
            self.results_crc = zlib.crc32(payload, self.results_crc)
            self.result_bytes += len(payload)
        if ftype in (T_DONE, T_ERROR):
            self.state = S_DONE if ftype == T_DONE else S_ERROR
            self.write_stats()

    def pump(self):
        """Sends kept result frames while fewer than window are unacknowledged (section 4.2)."""
        while self.res_next_send < self.res_made and self.res_next_send < self.res_acked + self.window:
            f = self.kept[self.res_next_send]
            self.res_next_send += 1
            self.res_sent_max = max(self.res_sent_max, self.res_next_send)
            self.board_frames += 1
            n = self.board_frames
            if n in self.a.disconnect_reply:
                self.drop_conn = True
                return
            if n in self.a.drop_reply:
                continue
            if n in self.a.corrupt_reply:
                f = bytearray(f)
                f[len(f) // 2] ^= 0x5A
                f = bytes(f)
            self.out += f

    def fail(self, code, text):
        self.make_result(T_ERROR, struct.pack("<I", code) + text.encode("ascii")[:200])

    def nak(self, reason):
        if not self.nak_sent:
            self.out += frame(T_NAK, 0, struct.pack("<II", self.E, reason))
            self.nak_sent = True
            self.stats["naks"] += 1

    # --- section 3.1 / 5.5: identify and status -----------------------------------------------
    def identify(self):
        magic = b"USB\0" if self.a.not_ours else MAGIC
        serial = self.a.serial.encode("ascii")[:16].ljust(16, b"\0")
        caps = 7 | (self.a.data_kib & 0xFF) << 16   # bits 16-23: the largest DATA payload in KiB (table 3.1)
        return magic + struct.pack("<HHIIIIII", self.a.protocol, self.window, caps, self.iface_mask,
                                   self.samples_mask, *self.a.limits) + serial

    def status(self):
        return MAGIC + struct.pack("<HBBIIIIQQ", 1, self.state, 0, self.E, self.res_made, self.res_acked,
                                   self.input_crc, self.cmds, self.records)

    # --- section 3.2: a run -------------------------------------------------------------------
    def start(self, p):
        self.state = S_RUN
        if len(p) != 24:
            return self.fail(1, "START payload is %d bytes, not 24" % len(p))
        want, samples, mode, kib, count = struct.unpack("<IIIIQ", p)
        self.want, self.mode, self.announced = want, mode, count
        if mode > 3:
            return self.fail(1, "START mode %d" % mode)
        if mode != 0:
            want = self.want = 0   # link tests: interfaces and samples are not used (board.md 3.2)
        elif want & ~self.iface_mask or samples not in (8, 16, 32) or \
                not self.samples_mask & (1 << {8: 3, 16: 4, 32: 5}[samples]):
            return self.fail(2, "START asks for interfaces 0x%x / %d samples" % (want, samples))
        if mode == 0 and not self.vec:
            return self.fail(2, "no DUT: pyboard was started without --vectors")
        if mode == 3:
            left = kib * 1024
            while left:
                n = min(left, RESULT_MAX)
                self.make_result(T_RESULT, SOURCE_BYTES[:n])
                left -= n

    def emit_upto(self, end):
        batch = bytearray()
        while self.emit_pos < end:
            iface, rec = self.vec.records[self.emit_pos]
            self.emit_pos += 1
            if not self.want & (1 << iface):
                continue
            if len(batch) + len(rec) > RESULT_MAX:
                self.make_result(T_RESULT, bytes(batch))
                batch = bytearray()
            batch += rec
            self.records += 1
        if batch:
            self.make_result(T_RESULT, bytes(batch))

    def data(self, p):
        if self.mode == 1:
            return
        if self.mode == 2:
            self.make_result(T_RESULT, p)               # section 8: the payload as it came
            return
        if self.mode == 3:
            return
        if len(p) % CMD_BYTES:
            return self.fail(3, "DATA payload of %d bytes is not whole commands" % len(p))
        for i in range(0, len(p), CMD_BYTES):
            cmd = p[i:i + CMD_BYTES]
            n = self.cmds
            if self.cmd_pos >= len(self.vec.cmd_index):
                return self.fail(16, "command %d: the vectors file has only %d" % (n, len(self.vec.cmd_index)))
            rec = self.vec.records[self.vec.cmd_index[self.cmd_pos]][1]
            if rec[10:] != cmd:
                return self.fail(16, "command %d differs from the vectors file's" % n)
            self.cmd_pos += 1
            self.cmds += 1
            if cmd[12] & 0x0F == 5:                      # FRAME_END: this frame's transactions
                nxt = self.vec.cmd_index[self.cmd_pos] if self.cmd_pos < len(self.vec.cmd_index) \
                    else len(self.vec.records)
                self.emit_upto(nxt)

    def end(self):
        if self.mode == 0:
            if self.cmds != self.announced:
                return self.fail(4, "END after %d commands, START announced %d" % (self.cmds, self.announced))
            self.emit_upto(len(self.vec.records))
        self.make_result(T_DONE, struct.pack("<QQQII", self.records, self.result_bytes, self.cmds,
                                             self.input_crc, self.results_crc))

    # --- section 4.1: one good frame ----------------------------------------------------------
    def numbered(self, ftype, seq, payload):
        """Returns 'taken', 'dup' or None; the checks in section 4.1's order."""
        if seq < self.E:
            self.stats["dup"] += 1
            return "dup"
        if seq > self.E:
            self.stats["gap"] += 1
            self.nak(NAK_GAP)
            return None
        if (seq == 0) != (ftype == T_START) or (ftype != T_START and self.state != S_RUN):
            self.nak(NAK_PLACE)
            return None
        self.E += 1
        self.nak_sent = False
        self.stats["taken"] += 1
        if ftype == T_START:
            self.start(payload)
        elif ftype == T_DATA:
            self.input_crc = zlib.crc32(payload, self.input_crc)
            self.stats["data_max"] = max(self.stats["data_max"], len(payload))
            self.data(payload)
        else:
            self.end()
        return "taken"

    def rx(self, buf):
        """Handles every whole frame at the start of buf; returns the bytes used."""
        pos, ack, corrupted = 0, False, False
        while pos < len(buf) and not self.drop_conn and not self.stalled:
            r = parse(memoryview(buf)[pos:])
            if r[0] == "more":
                break
            if r[0] == "bad":
                self.stats["bad"] += 1
                pos += resync(buf[pos:])
                self.nak(NAK_DAMAGED)
                continue
            _, ftype, flags, seq, payload, size = r
            pos += size
            if ftype in (T_IDENT, T_STATUS, T_RESET) and not payload:
                if ack:                                  # stream order: what came before first
                    self.out += frame(T_ACK, 0, struct.pack("<III", self.E, self.window, self.res_made))
                    ack = False
                self.pump()
                if ftype == T_IDENT:
                    self.out += frame(0x90, seq, self.identify())
                elif ftype == T_STATUS:
                    self.out += frame(0x91, seq, self.status())
                else:
                    self.do_reset()
                    self.out += frame(0x92, seq)
                continue
            if ftype == T_ACKR and len(payload) == 4:
                nxt = struct.unpack("<I", payload)[0]
                if nxt > self.res_sent_max:                 # section 4.2: only what was sent
                    nxt = self.res_sent_max
                if nxt > self.res_acked:
                    for s in range(self.res_acked, nxt):
                        self.kept.pop(s, None)
                    self.res_acked = nxt
                if self.res_next_send < self.res_acked:
                    self.res_next_send = self.res_acked
                if flags & 1:
                    self.res_next_send = max(nxt, self.res_acked)
                continue
            if ftype not in (T_START, T_DATA, T_END):
                self.nak(NAK_UNKNOWN)
                continue
            self.host_frames += 1
            n = self.host_frames
            if n in self.a.disconnect:
                self.drop_conn = True
                break
            if n in self.a.stall:
                self.stalled = True
                break
            if n in self.a.drop:
                continue
            if n in self.a.corrupt and not corrupted:
                start = pos - size                       # flip a byte in what arrived, parse it again
                buf[start + size // 2] ^= 0xA5
                pos, corrupted = start, True            # (the copy counted: the fault fires once)
                continue
            if n in self.a.reset:
                self.do_reset()
            if self.numbered(ftype, seq, payload):
                ack = True
        if ack:
            self.out += frame(T_ACK, 0, struct.pack("<III", self.E, self.window, self.res_made))
        self.pump()
        return pos

    def do_reset(self):
        resets = self.stats["resets"] + 1
        self.reset_state()
        self.stats["resets"] = resets

    def write_stats(self):
        if not self.a.stats:
            return
        s = dict(self.stats, E=self.E, state=self.state, cmds=self.cmds, records=self.records,
                 input_crc=self.input_crc, results_made=self.res_made, results_acked=self.res_acked,
                 host_frames=self.host_frames, board_frames=self.board_frames)
        with open(self.a.stats, "a") as f:
            f.write(json.dumps(s, sort_keys=True) + "\n")

    # --- the connection loop ------------------------------------------------------------------
    def serve(self, conn):
        conn.setblocking(False)
        inbuf = bytearray()
        self.drop_conn = False
        self.stalled = self.a.mute
        while True:
            want_w = [conn] if self.out else []
            r, w, _ = select.select([conn], want_w, [], 1.0)
            if r:
                try:
                    chunk = conn.recv(1 << 20)
                except (ConnectionResetError, BlockingIOError):
                    chunk = b""
                if not chunk:
                    break
                if self.stalled:
                    continue
                inbuf += chunk
                used = self.rx(inbuf)
                del inbuf[:used]
                if self.drop_conn:
                    break
            if w and self.out and not self.stalled:
                try:
                    n = conn.send(self.out)
                except (BlockingIOError, InterruptedError):
                    n = 0
                except (BrokenPipeError, ConnectionResetError):
                    break
                del self.out[:n]
            if self.stalled:
                self.out.clear()
        conn.close()
        # section 5.5: a partial frame and unsent output are dropped, the run is kept
        self.out.clear()
        self.res_next_send = self.res_acked
        self.stalled = False
        self.write_stats()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--unix", metavar="PATH")
    g.add_argument("--tcp", metavar="PORT", type=int)
    ap.add_argument("--port-file")
    ap.add_argument("--vectors", help="the expected vectors.bin (the replay DUT); without it: link tests only")
    ap.add_argument("--window", type=int, default=16)
    ap.add_argument("--serial", default="EFPY0001")
    ap.add_argument("--protocol", type=int, default=1)
    ap.add_argument("--not-ours", action="store_true")
    ap.add_argument("--mute", action="store_true")
    ap.add_argument("--stats")
    ap.add_argument("--data-kib", type=int, default=0, metavar="K",
                    help="identify's largest DATA payload in KiB (1-63; 0: 64 KiB); stats' data_max is the largest taken")
    ap.add_argument("--limits", type=lambda v: [int(x) for x in v.split(",")], default=[16384, 16384, 1 << 22],
                    metavar="W,H,E", help="the W_MAX, H_MAX, E_MAX identify states (the replay DUT does not check them)")
    for name in ("drop", "corrupt", "drop-reply", "corrupt-reply", "disconnect", "disconnect-reply", "stall",
                 "reset"):
        ap.add_argument("--" + name, type=int, action="append", default=[], metavar="N")
    args = ap.parse_args()
    board = Board(args)
    if args.unix:
        if os.path.exists(args.unix):
            os.unlink(args.unix)
        ls = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        ls.bind(args.unix)
    else:
        ls = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        ls.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        ls.bind(("127.0.0.1", args.tcp))
    ls.listen(4)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    if args.port_file:
        tmp = args.port_file + ".tmp"
        with open(tmp, "w") as f:
            f.write("%d\n" % ls.getsockname()[1] if not args.unix else "0\n")
        os.rename(tmp, args.port_file)
    try:
        while True:
            conn, _ = ls.accept()
            if not args.unix:
                conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            board.serve(conn)
    finally:
        if args.unix and os.path.exists(args.unix):
            os.unlink(args.unix)


if __name__ == "__main__":
    main()
