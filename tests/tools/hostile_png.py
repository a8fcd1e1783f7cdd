#!/usr/bin/env python3
"""Hostile PNG files for the image readers' tests (tests/cli/faults.sh,
tests/dist/run.sh) and fuzz seeds: hostile_png.py DIR [TILE.png] writes

  bomb.png          16x16 RGB whose image data inflates to 64 MiB
  bomb-tail.png     a good 16x16 image followed, in the same stream, by 8 MiB more
  short-data.png    16x16 whose data inflates to half the rows
  bad-crc.png       a good 4x4 image with one byte of its IDAT's CRC changed
  bad-crc-text.png  the same, the damage in an ancillary tEXt chunk
  huge-65535.png    IHDR 65535x65535 (with a little data)
  huge-wide.png     IHDR (2^31-1)x1
  huge-30000.png    a valid 30000x30000 grey image (about 870 KB)
  claims-16384.png  a 400-byte file whose header claims 16384x16384
  truncated.png     a good 4x4 image cut in its IDAT
  no-iend.png       a good 4x4 image without IEND
  jpeg.jpg          the start of a JPEG file (SOI, APP0)

and, given a whitted tile TILE.png:

  tile-junk.png     the tile with junk after IEND
  tile-bomb.png     the tile, its data replaced by its rows and 16 MiB more
  tile-claims.png   the tile, its IHDR claiming 16384x16384 (CRC fixed)
  tile-bad-crc.png  the tile with its IDAT's CRC damaged
"""
import os
import struct
import sys
import zlib


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xffffffff)


def ihdr(w, h, depth=8, color=2, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, color, 0, 0, interlace))


SIG = b"\x89PNG\r\n\x1a\n"


def png(w, h, raw, color=2, extra=b"", level=9):
    return SIG + ihdr(w, h, color=color) + extra + chunk(b"IDAT", zlib.compress(raw, level)) + \
        chunk(b"IEND", b"")


def rows(w, h, channels=3, value=128):
    return b"".join(b"\0" + bytes([value]) * (w * channels) for _ in range(h))


def streamed(*parts):
    """One zlib stream of the parts, written piece by piece (no part in memory twice)."""
    z = zlib.compressobj(9)
    out = b"".join(z.compress(p) for p in parts)
    return out + z.flush()


def chunks_of(data):
    out, off = [], 8
    while off + 12 <= len(data):
        n = struct.unpack(">I", data[off:off + 4])[0]
        out.append((data[off + 4:off + 8], data[off + 8:off + 8 + n]))
        off += 12 + n
    return out


def rebuild(parts):
    return SIG + b"".join(chunk(k, d) for k, d in parts)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)

    def put(name, data):
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)

    zero_mb = bytes(1 << 20)
    put("bomb.png", SIG + ihdr(16, 16) + chunk(b"IDAT", streamed(*([zero_mb] * 64))) + chunk(b"IEND", b""))
    put("bomb-tail.png", SIG + ihdr(16, 16) +
        chunk(b"IDAT", streamed(rows(16, 16), *([zero_mb] * 8))) + chunk(b"IEND", b""))
    put("short-data.png", SIG + ihdr(16, 16) + chunk(b"IDAT", zlib.compress(rows(16, 8))) +
        chunk(b"IEND", b""))
    good = png(4, 4, rows(4, 4), extra=chunk(b"tEXt", b"Comment\0fine"))
    parts = chunks_of(good)
    idat = next(i for i, (k, _) in enumerate(parts) if k == b"IDAT")
    text = next(i for i, (k, _) in enumerate(parts) if k == b"tEXt")
    whole = rebuild(parts)

    def damage_crc(data, index):
        off = 8
        for i, (k, d) in enumerate(chunks_of(data)):
            if i == index:
                at = off + 8 + len(d)
                return data[:at] + bytes([data[at] ^ 0x55]) + data[at + 1:]
            off += 12 + len(d)
        raise ValueError("no chunk %d" % index)

    put("bad-crc.png", damage_crc(whole, idat))
    put("bad-crc-text.png", damage_crc(whole, text))
    put("huge-65535.png", SIG + ihdr(65535, 65535) + chunk(b"IDAT", zlib.compress(rows(16, 16))) +
        chunk(b"IEND", b""))
    put("huge-wide.png", SIG + ihdr(2 ** 31 - 1, 1) + chunk(b"IDAT", zlib.compress(rows(16, 1))) +
        chunk(b"IEND", b""))
    row = b"\0" + bytes(30000)
    put("huge-30000.png", SIG + ihdr(30000, 30000, color=0) +
        chunk(b"IDAT", streamed(*([row * 1000] * 30))) + chunk(b"IEND", b""))
    claim = SIG + ihdr(16384, 16384) + chunk(b"IDAT", zlib.compress(rows(16, 16))) + chunk(b"IEND", b"")
    put("claims-16384.png", claim + b"\0" * max(0, 400 - len(claim)))
    put("truncated.png", whole[:len(whole) - 30])
    put("no-iend.png", whole[:len(whole) - 12])
    put("jpeg.jpg", b"\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00" + bytes(64))

    if len(sys.argv) > 2:
        with open(sys.argv[2], "rb") as f:
            tile = f.read()
        tparts = chunks_of(tile)
        put("tile-junk.png", tile + b"junk after the end\n")
        hdr = next(d for k, d in tparts if k == b"IHDR")
        w, h = struct.unpack(">II", hdr[:8])
        raw = zlib.decompress(b"".join(d for k, d in tparts if k == b"IDAT"))
        bomb = streamed(raw, *([zero_mb] * 16))
        first = next(i for i, (k, _) in enumerate(tparts) if k == b"IDAT")
        kept = [(k, d) for k, d in tparts if k != b"IDAT"]
        kept.insert(first, (b"IDAT", bomb))
        put("tile-bomb.png", rebuild(kept))
        claims = [(k, struct.pack(">II", 16384, 16384) + d[8:] if k == b"IHDR" else d)
                  for k, d in tparts]
        put("tile-claims.png", rebuild(claims))
        tidat = next(i for i, (k, _) in enumerate(tparts) if k == b"IDAT")
        put("tile-bad-crc.png", damage_crc(tile, tidat))


if __name__ == "__main__":
    main()
