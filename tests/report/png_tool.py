#!/usr/bin/env python3
"""Decodes 8-bit PNG files with the standard library only (zlib) and prints what the report
tests check: size, channels, mean and standard deviation of the luminance, and the share of
pixels that are not black.

Usage: png_tool.py FILE...          one line per file: FILE W H CHANNELS MEAN STDDEV NONBLACK
       png_tool.py --same A.png B.png  exits 0 when both decode to the same pixels
"""
import math
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type -> channels (8-bit, no palette)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def decode(path):
    """Returns (width, height, channels, rows) with rows a list of bytearrays."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in CHANNELS or interlace:
        raise ValueError(f"{path}: only 8-bit, non-interlaced, non-palette PNGs are read")
    nc = CHANNELS[colour]
    raw = zlib.decompress(idat)
    stride = width * nc
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - nc] if i >= nc else 0
            b = prev[i]
            c = prev[i - nc] if i >= nc else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                line[i] = (line[i] + paeth(a, b, c)) & 255
        rows.append(line)
        prev = line
    return width, height, nc, rows


def summary(path):
    width, height, nc, rows = decode(path)
    colour = 3 if nc >= 3 else 1
    total = total2 = nonblack = 0
    for row in rows:
        for x in range(width):
            px = row[x * nc:x * nc + colour]
            lum = sum(px) / colour
            total += lum
            total2 += lum * lum
            nonblack += any(px)
    n = width * height
    mean = total / n
    std = math.sqrt(max(total2 / n - mean * mean, 0.0))
    return width, height, nc, mean, std, nonblack / n


def main():
    if sys.argv[1:2] == ["--same"]:
        a, b = decode(sys.argv[2]), decode(sys.argv[3])
        same = a[:3] == b[:3] and a[3] == b[3]
        print(f"{sys.argv[2]} and {sys.argv[3]}: {'same pixels' if same else 'different'}")
        sys.exit(0 if same else 1)
    for path in sys.argv[1:]:
        w, h, nc, mean, std, nonblack = summary(path)
        print(f"{path} {w} {h} {nc} {mean:.3f} {std:.3f} {nonblack:.4f}")


if __name__ == "__main__":
    main()
