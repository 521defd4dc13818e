#!/usr/bin/env python3
"""tests/board/identify.py ADDR - asks a board on a byte stream for identify (docs/board.md 3.1
and 5.5: a 0x10 control frame, the 0x90 reply with the same tag) and prints its fields, one
`name value` a line.  ADDR: unix:PATH (a socket) or a tty path (set raw here).  Written from
docs/board.md alone, as an independent reader of what the firmware answers.  Exit 0 with the
reply, 1 without one in 120 s (a simulated board is slow), 2 on a malformed one."""
import os
import select
import socket
import struct
import sys
import termios
import time
import tty
import zlib


def main():
    addr = sys.argv[1]
    if addr.startswith("unix:"):
        s = socket.socket(socket.AF_UNIX)
        s.connect(addr[5:])
        fd = s.fileno()
    else:
        fd = os.open(addr, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(fd)
        termios.tcflush(fd, termios.TCIOFLUSH)
    tag = 0x5A17
    head = b"EFB1" + bytes([0x10, 0, 0, 0]) + struct.pack("<II", tag, 0)
    os.write(fd, head + struct.pack("<I", zlib.crc32(head)))
    buf = b""
    end = time.time() + 120
    while time.time() < end:
        i = buf.find(b"EFB1")
        if i >= 0 and len(buf) >= i + 16:
            typ, flags, res, seq, ln = struct.unpack("<BBHII", buf[i + 4:i + 16])
            if len(buf) >= i + 20 + ln:
                frame = buf[i:i + 16 + ln]
                crc, = struct.unpack("<I", buf[i + 16 + ln:i + 20 + ln])
                if typ == 0x90 and seq == tag:
                    if crc != zlib.crc32(frame) or ln != 48 or frame[16:20] != b"EFB1":
                        print("identify: a malformed reply", file=sys.stderr)
                        return 2
                    p = frame[16:]
                    ver, window, caps, ifaces, samples, w, h, e = struct.unpack("<HHIIIIII", p[4:32])
                    print("version", ver)
                    print("window", window)
                    print("capabilities", caps)
                    print("interfaces", hex(ifaces))
                    print("samples", " ".join(str(1 << k) for k in range(32) if samples >> k & 1))
                    print("width_max", w)
                    print("height_max", h)
                    print("edges_max", e)
                    print("serial", p[32:48].rstrip(b"\0").decode("ascii", "replace"))
                    return 0
                buf = buf[i + 20 + ln:] if crc == zlib.crc32(frame) else buf[i + 1:]
                continue
        r, _, _ = select.select([fd], [], [], 0.5)
        if r:
            buf += os.read(fd, 4096)
    print("identify: no reply", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
