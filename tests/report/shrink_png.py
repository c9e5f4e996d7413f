#!/usr/bin/env python3
"""Shrinks a screenshot for the docs with the standard library only: scales it down by an
integer factor (box filter, optional), posterizes each channel to LEVELS values and writes an
RGB PNG with the Paeth filter and zlib level 9.

Usage: shrink_png.py IN.png OUT.png [FACTOR [LEVELS]]   (defaults: 1, 48)
"""
import struct
import sys
import zlib

from png_tool import decode


def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(
        ">I", zlib.crc32(kind + body) & 0xFFFFFFFF)


def main():
    src, dst = sys.argv[1], sys.argv[2]
    factor = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    levels = int(sys.argv[4]) if len(sys.argv) > 4 else 48
    width, height, nc, rows = decode(src)
    w, h = width // factor, height // factor
    step = 255.0 / (levels - 1)
    out_rows = []
    for y in range(h):
        line = bytearray(w * 3)
        for x in range(w):
            for c in range(3):
                total = 0
                for dy in range(factor):
                    row = rows[y * factor + dy]
                    for dx in range(factor):
                        total += row[(x * factor + dx) * nc + (c if nc >= 3 else 0)]
                v = total / (factor * factor)
                line[x * 3 + c] = min(255, int(round(round(v / step) * step)))
        out_rows.append(line)
    raw = bytearray()
    prev = bytearray(w * 3)
    for line in out_rows:  # Paeth filter
        raw.append(4)
        for i in range(len(line)):
            a = line[i - 3] if i >= 3 else 0
            b = prev[i]
            c = prev[i - 3] if i >= 3 else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            raw.append((line[i] - pred) & 255)
        prev = line
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")
    open(dst, "wb").write(png)
    print(f"{dst}: {w}x{h}, {len(png)} bytes")


if __name__ == "__main__":
    main()
