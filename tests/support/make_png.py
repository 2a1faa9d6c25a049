"""Writes a test PNG with the standard library only: a WIDTHxHEIGHT gradient, with the first
CHANGED pixels of its top row moved by DELTA levels in red (for `hexgait compare`'s tests).

usage: make_png.py OUT WIDTH HEIGHT [CHANGED DELTA]
"""
import struct
import sys
import zlib


def main():
    out, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    changed = int(sys.argv[4]) if len(sys.argv) > 4 else 0
    delta = int(sys.argv[5]) if len(sys.argv) > 5 else 0
    rows = []
    for y in range(height):
        row = bytearray([0])  # filter: none
        for x in range(width):
            r, g, b = (x * 255) // max(width - 1, 1), (y * 255) // max(height - 1, 1), 128
            if y == 0 and x < changed:
                r = r + delta if r + delta <= 255 else r - delta  # moved by exactly DELTA
            row += bytes([r, g, b])
        rows.append(bytes(row))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    with open(out, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))


main()
