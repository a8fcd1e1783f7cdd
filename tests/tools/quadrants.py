#!/usr/bin/env python3
"""Checks which colour fills each quadrant of an image, for povcheck's
camera check (which must not trust any program's idea of the camera).

  quadrants.py IMAGE.ppm TOP_LEFT TOP_RIGHT BOTTOM_LEFT BOTTOM_RIGHT

Each colour is R,G,B in 0..255.  A quadrant passes when at least 2% of its
pixels are its colour (each channel within 8 levels) and none is the
colour of another quadrant.  Prints one line; exits 0 when all four pass,
1 otherwise (or when the image cannot be read).
"""
import sys


def read_ppm(path):
    data = open(path, 'rb').read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b'#':
            while data[pos:pos + 1] not in (b'\n', b''):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b'P6' or int(fields[3]) != 255:
        raise ValueError('%s: not an 8-bit binary PPM' % path)
    w, h = int(fields[1]), int(fields[2])
    return w, h, data[pos + 1:pos + 1 + 3 * w * h]


def main(argv):
    if len(argv) != 6:
        sys.stderr.write(__doc__)
        return 2
    try:
        w, h, px = read_ppm(argv[1])
    except (OSError, ValueError) as e:
        print('quadrants: %s' % e)
        return 1
    want = [tuple(int(v) for v in c.split(',')) for c in argv[2:6]]
    names = ['top left', 'top right', 'bottom left', 'bottom right']
    counts = [[0] * 4 for _ in range(4)]    # counts[quadrant][colour]
    for y in range(h):
        for x in range(w):
            if 2 * x + 1 == w or 2 * y + 1 == h:
                continue    # the middle row or column of an odd size
            q = (2 if 2 * y >= h else 0) + (1 if 2 * x >= w else 0)
            p = px[3 * (y * w + x):3 * (y * w + x) + 3]
            for k, c in enumerate(want):
                if all(abs(p[i] - c[i]) <= 8 for i in range(3)):
                    counts[q][k] += 1
    area = (w // 2) * (h // 2)
    bad = []
    for q in range(4):
        if counts[q][q] < 0.02 * area:
            bad.append('%s has %d pixels of %s (expected at least %d)' %
                       (names[q], counts[q][q], argv[2 + q], int(0.02 * area + 0.999)))
        for k in range(4):
            if k != q and counts[q][k]:
                bad.append('%s has %d pixels of %s, the %s colour' %
                           (names[q], counts[q][k], argv[2 + k], names[k]))
    if bad:
        print('quadrants: %s: %s' % (argv[1], '; '.join(bad)))
        return 1
    print('quadrants: %s: ok (%s)' % (argv[1], ', '.join('%d' % counts[q][q] for q in range(4))))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
