#!/usr/bin/env python3
"""tests/board/sink_stream.py TTY KIB FRAME_BYTES - streams KIB KiB of DATA to a board in the
link test's sink mode (docs/board.md 3 and 8: START with mode 1, then DATA frames of FRAME_BYTES
payload bytes, numbered from 1, as many in flight as the board's window of 16 allows), as fast
as the line takes them, and waits until the board's ACK names them all taken.  TTY: a tty path
(set raw here).  Written from docs/board.md alone.  Prints `sink: N frames, B payload bytes
acknowledged`; exit 0 when all were, 1 without that in 600 s, 2 on a NAK (a frame damaged or
lost on the way: on the simulated board's paced line, bytes the firmware did not take in time)."""
import os
import select
import struct
import sys
import termios
import time
import tty
import zlib


def frame(typ, seq, payload):
    head = b"EFB1" + bytes([typ, 0, 0, 0]) + struct.pack("<II", seq, len(payload))
    return head + payload + struct.pack("<I", zlib.crc32(head + payload))


def main():
    path, kib, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    termios.tcflush(fd, termios.TCIOFLUSH)
    n = (kib * 1024 + size - 1) // size
    frames = [frame(0x04, 0, struct.pack("<IIIIQ", 0, 0, 1, 0, 0))]  # START, mode 1: sink
    frames += [frame(0x01, k, bytes((k * 7 + i) & 0xFF for i in range(size))) for k in range(1, n + 1)]
    sent, acked, out, buf = 0, 0, b"", b""
    end = time.time() + 600
    while time.time() < end and acked < n + 1:
        while not out and sent < len(frames) and sent - acked < 16:  # the window: 16 frames
            out, sent = frames[sent], sent + 1
        r, w, _ = select.select([fd], [fd] if out else [], [], 0.5)
        if w:
            out = out[os.write(fd, out):]
        if r:
            buf += os.read(fd, 4096)
        while True:
            i = buf.find(b"EFB1")
            if i < 0 or len(buf) < i + 16:
                break
            typ, _, _, _, ln = struct.unpack("<BBHII", buf[i + 4:i + 16])
            if len(buf) < i + 20 + ln:
                break
            body, crc = buf[i:i + 16 + ln], struct.unpack("<I", buf[i + 16 + ln:i + 20 + ln])[0]
            buf = buf[i + 20 + ln:] if crc == zlib.crc32(body) else buf[i + 1:]
            if crc != zlib.crc32(body):
                continue
            if typ == 0x82:
                print("sink: a NAK from the board (frame %d, reason %d)" % struct.unpack("<II", body[16:24]), file=sys.stderr)
                return 2
            if typ == 0x81:
                acked = max(acked, struct.unpack("<I", body[16:20])[0])
    if acked < n + 1:
        print("sink: %d of %d frames acknowledged in 600 s" % (acked, n + 1), file=sys.stderr)
        return 1
    print("sink: %d frames, %d payload bytes acknowledged" % (n, n * size))
    return 0


if __name__ == "__main__":
    sys.exit(main())
