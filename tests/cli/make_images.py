#!/usr/bin/env python3
"""Writes a binary PPM's image in the other layouts that `whitted compare`
reads, and the broken files it must refuse, for tests/cli/compare.sh and the
fuzz corpus.  Written from the formats' specifications, independently of
the readers under test.

  make_images.py IN.ppm OUTDIR
"""
import os
import struct
import sys


def read_ppm(path):
    data = open(path, 'rb').read()
    magic, dims, maxval, px = data.split(b'\n', 3)
    w, h = (int(v) for v in dims.split())
    assert magic == b'P6' and maxval == b'255' and len(px) == 3 * w * h
    return w, h, px


def bmp(w, h, px, bits=24, top_down=False):
    """A BMP with a BITMAPINFOHEADER, rows padded to 4 bytes, bottom-up
    unless top_down (a negative height), pixels stored as B, G, R (, 0)."""
    bpp = bits // 8
    row_size = (w * bpp + 3) & ~3
    rows = []
    for y in range(h):
        r = bytearray()
        for x in range(w):
            i = 3 * (y * w + x)
            r += bytes((px[i + 2], px[i + 1], px[i])) + (b'\0' if bpp == 4 else b'')
        r += b'\0' * (row_size - len(r))
        rows.append(bytes(r))
    if not top_down:
        rows.reverse()
    raster = b''.join(rows)
    info = struct.pack('<IiiHHIIiiII', 40, w, -h if top_down else h, 1, bits, 0, len(raster),
                       2835, 2835, 0, 0)
    head = struct.pack('<2sIHHI', b'BM', 14 + len(info) + len(raster), 0, 0, 14 + len(info))
    return head + info + raster


def p3(w, h, px):
    out = ['P3', '# an ASCII PPM, as a student might write it', '%d %d' % (w, h), '255']
    for y in range(h):
        out.append(' '.join(str(v) for v in px[3 * w * y:3 * w * (y + 1)]))
    return ('\n'.join(out) + '\n').encode()


def main():
    w, h, px = read_ppm(sys.argv[1])
    out = sys.argv[2]
    files = {
        'bmp24.bmp': bmp(w, h, px),
        'bmp32.bmp': bmp(w, h, px, bits=32),
        'topdown.bmp': bmp(w, h, px, top_down=True),
        'ascii.ppm': p3(w, h, px),
        'p6-maxval-comment.ppm': b'P6\n# a comment\n%d %d\n255\n' % (w, h) + px,
    }
    good24 = files['bmp24.bmp']
    files['truncated.bmp'] = good24[:len(good24) - 7]
    files['header-only.bmp'] = good24[:30]
    files['truncated.ppm'] = (b'P6\n%d %d\n255\n' % (w, h) + px)[:-5]
    files['truncated-ascii.ppm'] = files['ascii.ppm'][:len(files['ascii.ppm']) // 2]
    files['bad-sample.ppm'] = b'P3\n1 1\n255\n0 300 0\n'
    files['empty.png'] = b''
    files['text.png'] = b'this is a scene file, not an image\n'
    files['bad-magic.bmp'] = b'BX' + good24[2:]
    files['rle.bmp'] = good24[:30] + struct.pack('<I', 1) + good24[34:]
    for name, data in files.items():
        with open(os.path.join(out, name), 'wb') as f:
            f.write(data)


if __name__ == '__main__':
    main()
