#!/usr/bin/env python3
"""Writes the floor textures of the tests, deterministically, with the
standard library only: white.bmp (8x8, 24-bit bottom-up as the handouts ship
them), black.png (5x4, 8-bit RGB) and white.png (white.bmp's pixels as PNG);
and the other forms whitted accepts, which scene2pov must hand POV-Ray as
the texels whitted decodes: white-rgba.png (white's pixels with a varying
alpha, which whitted ignores), white-xrgb.bmp (32-bit rows, the fourth byte
0) and black-topdown.bmp (black's pixels, rows top-down: a negative height).
Each has a different colour in each corner, so that a texture turned or
mirrored shows.  Run from anywhere: python3 make_textures.py [DIR]."""
import os
import struct
import sys
import zlib


def white_pixels():
    rows = []
    for y in range(8):  # y = 0 is the top row
        row = []
        for x in range(8):
            if x < 4 and y < 4:
                c = (250, 60, 40)     # top left: red
            elif y < 4:
                c = (60, 230, 60)     # top right: green
            elif x < 4:
                c = (50, 80, 240)     # bottom left: blue
            else:
                c = (240, 230, 200)   # bottom right: cream
            if (x + y) % 3 == 0:
                c = tuple(v // 2 for v in c)
            row.append(c)
        rows.append(row)
    return rows


def black_pixels():
    return [[(20 + 40 * x, 10 + 30 * y, 90 - 15 * x) for x in range(5)] for y in range(4)]


def write_bmp(path, rows, bpp=24, topdown=False):
    h, w = len(rows), len(rows[0])
    pad = (4 - bpp // 8 * w % 4) % 4
    extra = b"\0" if bpp == 32 else b""
    data = b"".join(b"".join(bytes((b, g, r)) + extra for r, g, b in row) + b"\0" * pad
                    for row in (rows if topdown else reversed(rows)))
    head = struct.pack("<2sIHHI", b"BM", 54 + len(data), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, w, -h if topdown else h, 1, bpp, 0, len(data),
                       2835, 2835, 0, 0)
    with open(path, "wb") as f:
        f.write(head + info + data)


def write_png(path, rows, alpha=False):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + b"".join(bytes(c) + (bytes(((x * 53 + y * 31) % 256,)) if alpha else b"")
                                     for x, c in enumerate(row)) for y, row in enumerate(rows))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6 if alpha else 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    write_bmp(os.path.join(out, "white.bmp"), white_pixels())
    write_png(os.path.join(out, "white.png"), white_pixels())
    write_png(os.path.join(out, "black.png"), black_pixels())
    write_png(os.path.join(out, "white-rgba.png"), white_pixels(), alpha=True)
    write_bmp(os.path.join(out, "white-xrgb.bmp"), white_pixels(), bpp=32)
    write_bmp(os.path.join(out, "black-topdown.bmp"), black_pixels(), topdown=True)


if __name__ == "__main__":
    main()
