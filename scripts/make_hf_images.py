#!/usr/bin/env python3
"""Writes the height field images scenes/shape_height_field.pov reads: an 8-bit and a
16-bit grey PNG of smooth hills, computed here (no image library needed)."""
import math
import struct
import zlib
from pathlib import Path


def png_grey(path, width, height, rows, bits):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    fmt = ">%dH" % width if bits == 16 else "%dB" % width
    raw = b"".join(b"\x00" + struct.pack(fmt, *row) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bits, 0, 0, 0, 0)
    Path(path).write_bytes(
        b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    )


def hills(u, v):
    h = 0.55 * math.exp(-((u - 0.3) ** 2 + (v - 0.35) ** 2) / 0.03)
    h += 0.4 * math.exp(-((u - 0.72) ** 2 + (v - 0.65) ** 2) / 0.05)
    h += 0.05 * math.sin(9 * u) * math.cos(7 * v) + 0.06
    return min(max(h, 0.0), 1.0)


def ridges(u, v):
    h = 0.5 + 0.35 * math.sin(6.0 * u + 2.0 * v) * math.cos(4.0 * v)
    h *= 1.0 - 0.6 * ((u - 0.5) ** 2 + (v - 0.5) ** 2)
    return min(max(h, 0.0), 1.0)


def grid(f, w, h, top):
    return [[round(f(i / (w - 1), j / (h - 1)) * top) for i in range(w)] for j in range(h)]


out = Path(__file__).resolve().parent.parent / "scenes" / "images"
out.mkdir(exist_ok=True)
png_grey(out / "hf_hills8.png", 33, 29, grid(hills, 33, 29, 255), 8)
png_grey(out / "hf_ridges16.png", 65, 49, grid(ridges, 65, 49, 65535), 16)
