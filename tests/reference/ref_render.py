#!/usr/bin/env python3
"""An independent renderer of scene-format.md, written from the contract
alone (plain Python, naive formulas, its own epsilon, its own reader of the
four dialects) to check whitted's images on scenes and cameras it generates
at random.

  ref_render.py SCENE OUT.ppm [--size N] [--recursion N] [--eye X,Y,Z]
                [--look X,Y,Z] [--up X,Y,Z] [--fov DEG] [--clamp level|final]
                [--no-floor] [--floor W,T] [--dialect auto|classic|spot|pyramid|nearfar]
                [--samples N] [--floor-texture WHITE[,BLACK]] [--glass I[:IOR[:KT]],...]
                [--floor-finish KA,KD,KS,KR,SHINE]
                [--mistake NAME] [--truncate]   (OUT ending .bmp: a 24-bit BMP)

--mistake NAME renders the image a student's program with that one mistake
makes (the "hidden set" of tests/reference/mistakes_check.py; NAME,NAME or
--mistake repeated: those mistakes at once): mirrored,
upside-down, transposed, red-blue, gamma (c^(1/2.2) before rounding),
white-highlight (specular not times the colour), no-shadows, light-behind
(no N.L > 0 test: diffuse max(N.L, 0), the highlight still added),
recursion-fewer, recursion-more, clamp-final (the other clamping),
no-clamp (never clamped; the byte keeps the low 8 bits), pixel-corners
(rays through the top-left corners), unit-offset (shadow and reflected rays
start at P + 1 * direction), floor-swapped (white where i + j is odd),
and a spotlight's cone as students get it wrong: spot-cos-degrees
(cos(cutoff) of the degrees), spot-no-cone (lit every way), spot-full-angle
(the cutoff taken as the full angle), spot-pi-macro (`#define PI
2*acos(0.0)` without parentheses, expanded), spot-unlit (no spotlights).
Forms written apart from whitted's own definitions of the causes (by the
review's student-style renderer): light-behind-signed (no N.L test at all:
diffuse kd N.L signed, a light behind darkens), gamma-srgb (the sRGB curve
on the float).  --truncate writes int(255 c) instead of rounding, as the
course's code does (with no-clamp: the low 8 bits of (int)(255 c)).
--also CONVERSION=OUT (truncate, gamma or gamma-srgb; repeatable) writes
the same render converted that way too, without tracing again.

The view the file gives (the dialect's field of view, nearfar's near plane,
aspect and checkerboard) applies unless an option says otherwise: --fov
replaces the field of view, --floor W,T puts the classic floor of that size
in place of the file's, --no-floor removes it.  --floor-finish gives the
floor a student's own coefficients and shininess (the checker's colours
stay).

The extensions, from README's rules: --samples N averages an N x N grid of
rays through the sub-pixel centres, each clamped; --floor-texture puts an
image (a 24-bit BMP or an 8-bit RGB PNG, read here with zlib alone) over
each white (black) cell, nearest texel, as the colour of the ambient and
diffuse terms, the highlight keeping the cell's colour; --glass makes file
objects glass (Snell's law, the side told by the normal, total internal
reflection a whole mirror, opaque shadows).
"""
import math
import struct
import sys
import zlib

EPS = 1e-4
MISTAKES = frozenset()
TRUNCATE = False
CLASSIC_FLOOR = dict(ka=0.4, kd=0.2, ks=0.2, kr=0.2, shine=1.0)


def tokens(text):
    for line in text.splitlines():
        line = line.split('#')[0].split('//')[0]
        for tok in line.split():
            if tok == '-':
                break
            yield tok


def is_number(tok):
    try:
        float(tok)
        return True
    except ValueError:
        return False


class Reader:
    """The token list with a cursor."""

    def __init__(self, toks):
        self.toks, self.pos = toks, 0

    def nxt(self):
        self.pos += 1
        return self.toks[self.pos - 1]

    def num(self):
        return float(self.nxt())

    def vec(self):
        return (self.num(), self.num(), self.num())

    def count(self):
        return int(float(self.nxt()))

    def numbers_ahead(self, start=None):
        """How many numbers follow from start (the cursor) up to the end or a word."""
        n = 0
        for t in self.toks[self.pos if start is None else start:]:
            if not is_number(t):
                break
            n += 1
        return n


def material(rd, obj):
    obj['colour'] = rd.vec()
    obj['ka'], obj['kd'], obj['ks'], obj['kr'] = rd.num(), rd.num(), rd.num(), rd.num()
    obj['shine'] = rd.num()
    return obj


def pyramid_solid(x0, y0, z0, b, h):
    """The closed pyramid over the square [x0, x0+b] x [y0, y0+b] at height
    z0 with its apex above the square's centre, as five half-spaces
    n . p <= d with n outward and unit."""
    apex = (x0 + b / 2, y0 + b / 2, z0 + h)
    corners = [(x0, y0, z0), (x0 + b, y0, z0), (x0 + b, y0 + b, z0), (x0, y0 + b, z0)]
    inside = (x0 + b / 2, y0 + b / 2, z0 + h / 4)
    planes = [((0.0, 0.0, -1.0), -z0)]
    for i in range(4):
        a, c = corners[i], corners[(i + 1) % 4]
        n = unit(cross(sub(c, a), sub(apex, a)))
        if dot(n, sub(inside, a)) > 0:
            n = mul(n, -1)
        planes.append((n, dot(n, a)))
    return planes


def cube_solid(x0, y0, z0, s):
    return [((-1.0, 0.0, 0.0), -x0), ((1.0, 0.0, 0.0), x0 + s),
            ((0.0, -1.0, 0.0), -y0), ((0.0, 1.0, 0.0), y0 + s),
            ((0.0, 0.0, -1.0), -z0), ((0.0, 0.0, 1.0), z0 + s)]


def classic_object(rd, kind, dialect):
    if kind == 'sphere':
        return material(rd, dict(kind='sphere', geo=(rd.vec(), rd.num())))
    if kind == 'triangle':
        return material(rd, dict(kind='triangle', geo=(rd.vec(), rd.vec(), rd.vec())))
    if kind == 'general':
        return material(rd, dict(kind='general', geo=([rd.num() for _ in range(10)], rd.vec(),
                                                        rd.vec())))
    if kind == 'pyramid' and dialect in ('auto', 'pyramid'):
        (x, y, z), b, h = rd.vec(), rd.num(), rd.num()
        return material(rd, dict(kind='solid', geo=pyramid_solid(x, y, z, b, h)))
    raise SystemExit('unknown object %s in the %s dialect' % (kind, dialect))


def parse_classic_family(rd, dialect):
    """classic, spot and pyramid: the same layout up to the point lights."""
    rec, size = rd.count(), rd.count()
    objs = [classic_object(rd, rd.nxt(), dialect) for _ in range(rd.count())]
    if dialect == 'auto':
        dialect = 'pyramid' if any(o['kind'] == 'solid' for o in objs) else 'auto'
    nlights = rd.count()
    ahead = rd.numbers_ahead()
    with_colour = not (nlights > 0 and ahead == 3 * nlights)
    lights = []
    for _ in range(nlights):
        p = rd.vec()
        c = rd.vec() if with_colour else (1.0, 1.0, 1.0)
        lights.append(dict(pos=p, colour=c, falloff=0.0, cutoff=None))
    if dialect == 'auto':
        rest = rd.numbers_ahead()
        spot = (with_colour and rest > 0 and
                rest == 1 + 10 * int(float(rd.toks[rd.pos])))
        dialect = 'spot' if spot else 'classic'
    if dialect == 'spot':
        for _ in range(rd.count()):
            p, c, axis, cut = rd.vec(), rd.vec(), rd.vec(), rd.num()
            lights.append(dict(pos=p, colour=c, falloff=0.0, axis=axis, cutoff=cut))
    view = dict(dialect=dialect, fov=90.0 if dialect == 'pyramid' else 80.0, near=0.0, aspect=0.0,
                floor=dict(width=1000.0, cell=30.0 if dialect == 'pyramid' else 20.0,
                           **CLASSIC_FLOOR))
    return max(rec, 1), size, objs, lights, view


def nearfar_fits(rd, start, n, points, colour):
    """Whether n numbers from start are exactly the point lights and the
    spotlights, with or without colour lines."""
    per_point, per_spot = (7, 11) if colour else (4, 8)
    k = points * per_point
    if n <= k or not is_number(rd.toks[start + k]):
        return False
    spots = float(rd.toks[start + k])
    return spots == int(spots) and n == k + 1 + per_spot * int(spots)


def parse_nearfar(rd):
    near, far, fovy, aspect = rd.num(), rd.num(), rd.num(), rd.num()
    rec, size, cell = rd.count(), rd.count(), rd.num()
    ka, kd, kr = rd.num(), rd.num(), rd.num()
    objs = []
    for _ in range(rd.count()):
        kind = rd.nxt()
        if kind == 'sphere':
            o = dict(kind='sphere', geo=(rd.vec(), rd.num()))
        elif kind == 'pyramid':
            (x, y, z), w, h = rd.vec(), rd.num(), rd.num()
            o = dict(kind='solid', geo=pyramid_solid(x - w / 2, y - w / 2, z, w, h))
        elif kind == 'cube':
            (x, y, z), s = rd.vec(), rd.num()
            o = dict(kind='solid', geo=cube_solid(x, y, z, s))
        else:
            raise SystemExit('unknown object %s in the nearfar dialect' % kind)
        objs.append(material(rd, o))
    points = rd.count()
    n = rd.numbers_ahead()
    colour = not nearfar_fits(rd, rd.pos, n, points, False) and \
        nearfar_fits(rd, rd.pos, n, points, True)
    lights = []
    for _ in range(points):
        p = rd.vec()
        c = rd.vec() if colour else (1.0, 1.0, 1.0)
        lights.append(dict(pos=p, colour=c, falloff=rd.num(), cutoff=None))
    for _ in range(rd.count()):
        p = rd.vec()
        c = rd.vec() if colour else (1.0, 1.0, 1.0)
        fall, look, cut = rd.num(), rd.vec(), rd.num()
        lights.append(dict(pos=p, colour=c, falloff=fall, axis=sub(look, p), cutoff=cut))
    view = dict(dialect='nearfar', fov=fovy, near=near, aspect=aspect,
                floor=dict(width=math.inf, cell=cell, ka=ka, kd=kd, ks=0.0, kr=kr, shine=1.0))
    return max(rec, 1), size, objs, lights, view


def parse(path, dialect='auto'):
    rd = Reader(list(tokens(open(path, encoding='utf-8-sig').read())))
    if dialect == 'auto':
        lead = rd.numbers_ahead(0)
        # A third number of 0 is classic's object count of 0, never
        # nearfar's FOVY (scene-format.md, "The dialects", rule 1).
        if lead >= 3 and float(rd.toks[2]) == 0.0:
            lead = -1
        if lead == 11:
            dialect = 'nearfar'
        elif lead == len(rd.toks) and lead >= 11:
            try:
                parse_nearfar(Reader(rd.toks))
                dialect = 'nearfar'
            except (IndexError, ValueError):
                pass
    if dialect == 'nearfar':
        return parse_nearfar(rd)
    return parse_classic_family(rd, dialect)


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(dot(a, a))
    return mul(a, 1.0 / n) if n > 0 else a


def solid_hit(planes, org, d):
    """Cyrus-Beck: the ray's interval inside every half-space, with the
    planes it enters and leaves through; the nearest of the two ends in
    front of the ray, or None."""
    t0, t1, p0, p1 = -math.inf, math.inf, None, None
    for n, dd in planes:
        den = dot(n, d)
        num = dd - dot(n, org)
        if den == 0:
            if num < 0:
                return None
            continue
        t = num / den
        if den < 0:
            if t > t0:
                t0, p0 = t, n
        elif t < t1:
            t1, p1 = t, n
    if t0 > t1:
        return None
    if t0 > EPS:
        return t0, p0
    if t1 > EPS:
        return t1, p1
    return None


def hit_object(o, org, d):
    """The nearest t > EPS where the ray meets the object, or None."""
    h = hit_with_normal(o, org, d)
    return None if h is None else h[0]


def hit_with_normal(o, org, d):
    """(t, the face's normal for a solid or None), or None for a miss."""
    k = o['kind']
    if k == 'solid':
        return solid_hit(o['geo'], org, d)
    t = hit_curved(o, org, d)
    return None if t is None else (t, None)


def hit_curved(o, org, d):
    k = o['kind']
    if k == 'sphere':
        c, r = o['geo']
        oc = sub(org, c)
        b = dot(oc, d)
        disc = b * b - (dot(oc, oc) - r * r)
        if disc < 0:
            return None
        s = math.sqrt(disc)
        for t in (-b - s, -b + s):
            if t > EPS:
                return t
        return None
    if k == 'triangle':
        a, b, c = o['geo']
        # Solve org + t d = a + u (b - a) + v (c - a) by Cramer's rule.
        e1, e2 = sub(b, a), sub(c, a)
        n = cross(e1, e2)
        den = dot(n, d)
        if den == 0:
            return None
        t = dot(n, sub(a, org)) / den
        if t <= EPS:
            return None
        p = add(org, mul(d, t))
        # Inside when p is on the inner side of every edge.
        for v0, v1 in ((a, b), (b, c), (c, a)):
            if dot(cross(sub(v1, v0), sub(p, v0)), n) < 0:
                return None
        return t
    if k == 'general':
        (A, B, C, D, E, F, G, H, I, J), ref, ext = o['geo']
        ox, oy, oz = org
        dx, dy, dz = d
        qa = A*dx*dx + B*dy*dy + C*dz*dz + D*dx*dy + E*dx*dz + F*dy*dz
        qb = (2*A*ox*dx + 2*B*oy*dy + 2*C*oz*dz + D*(ox*dy + oy*dx) + E*(ox*dz + oz*dx)
              + F*(oy*dz + oz*dy) + G*dx + H*dy + I*dz)
        qc = (A*ox*ox + B*oy*oy + C*oz*oz + D*ox*oy + E*ox*oz + F*oy*oz + G*ox + H*oy
              + I*oz + J)
        if qa == 0:
            roots = [] if qb == 0 else [-qc / qb]
        else:
            disc = qb * qb - 4 * qa * qc
            if disc < 0:
                return None
            s = math.sqrt(disc)
            roots = sorted([(-qb - s) / (2 * qa), (-qb + s) / (2 * qa)])
        for t in roots:
            if t <= EPS:
                continue
            p = add(org, mul(d, t))
            ok = True
            for axis in range(3):
                if ext[axis] != 0 and not (ref[axis] <= p[axis] <= ref[axis] + ext[axis]):
                    ok = False
            if ok:
                return t
        return None
    if k == 'floor':
        half = o['width'] / 2
        if d[2] == 0:
            return None
        t = -org[2] / d[2]
        if t <= EPS:
            return None
        x, y = org[0] + t * d[0], org[1] + t * d[1]
        if half == math.inf or (-half <= x < half and -half <= y < half):
            return t
        return None
    raise ValueError(k)


def normal(o, p):
    k = o['kind']
    if k == 'sphere':
        return unit(sub(p, o['geo'][0]))
    if k == 'triangle':
        a, b, c = o['geo']
        return unit(cross(sub(b, a), sub(c, a)))
    if k == 'general':
        (A, B, C, D, E, F, G, H, I, J), _, _ = o['geo']
        x, y, z = p
        return unit((2*A*x + D*y + E*z + G, 2*B*y + D*x + F*z + H, 2*C*z + E*x + F*y + I))
    return (0.0, 0.0, 1.0)


def read_texture(path):
    """(width, height, rows of (r, g, b) top to bottom) of a 24-bit BMP or
    an 8-bit RGB, non-interlaced PNG."""
    data = open(path, 'rb').read()
    if data[:2] == b'BM':
        off, = struct.unpack_from('<I', data, 10)
        w, h, _, bpp, comp = struct.unpack_from('<iiHHI', data, 18)
        assert bpp == 24 and comp == 0, 'only 24-bit uncompressed BMP'
        stride = (3 * w + 3) // 4 * 4
        rows = []
        for y in range(abs(h)):
            base = off + y * stride
            rows.append([(data[base + 3 * x + 2], data[base + 3 * x + 1], data[base + 3 * x])
                         for x in range(w)])
        return w, abs(h), (rows[::-1] if h > 0 else rows)
    assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG or BMP'
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack_from('>I4s', data, pos)
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', body)
            assert depth == 8 and ctype == 2 and interlace == 0, 'only 8-bit RGB PNG'
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(3 * w)
    for y in range(h):
        f, line = raw[y * (3 * w + 1)], bytearray(raw[y * (3 * w + 1) + 1:(y + 1) * (3 * w + 1)])
        for x in range(3 * w):
            a = line[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            pred = [0, a, b, (a + b) // 2, 0][f]
            if f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            line[x] = (line[x] + pred) & 255
        rows.append([tuple(line[3 * x:3 * x + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def cell_of(o, p):
    cell = o['cell']
    if o['width'] == math.inf:
        return p[0] / cell, p[1] / cell
    half = o['width'] / 2
    return (p[0] + half) / cell, (p[1] + half) / cell


def cell_colour(o, p):
    cx, cy = cell_of(o, p)
    white = (math.floor(cx) + math.floor(cy)) % 2 == 0
    if 'floor-swapped' in MISTAKES:
        white = not white
    return (1.0, 1.0, 1.0) if white else (0.0, 0.0, 0.0)


def colour_at(o, p):
    if o['kind'] != 'floor':
        return o['colour']
    plain = cell_colour(o, p)
    tex = o.get('textures', [None, None])[0 if plain[0] > 0.5 else 1]
    if tex is None:
        return plain
    w, h, rows = tex
    cx, cy = cell_of(o, p)
    u, v = cx - math.floor(cx), cy - math.floor(cy)
    col = min(w - 1, int(u * w))
    row = min(h - 1, h - 1 - int(v * h))
    return tuple(ch / 255.0 for ch in rows[max(0, row)][col])


def nearest(objs, org, d):
    """The nearest object, its t and, for a solid, the normal of the face hit."""
    best, best_t, best_n = None, math.inf, None
    for o in objs:
        h = hit_with_normal(o, org, d)
        if h is not None and h[0] < best_t:
            best, (best_t, best_n) = o, h
    return best, best_t, best_n


def in_cone(light, p):
    """The angle between p - position and the axis is at most the cutoff
    (or, with a spot-* mistake, what a student's cone test says)."""
    if light['cutoff'] is None:
        return True
    if 'spot-unlit' in MISTAKES:
        return False
    if 'spot-no-cone' in MISTAKES:
        return True
    v, a = unit(sub(p, light['pos'])), unit(light['axis'])
    cosine = max(-1.0, min(1.0, dot(v, a)))
    if 'spot-cos-degrees' in MISTAKES:
        return cosine >= math.cos(light['cutoff'])      # cos() given degrees
    if 'spot-full-angle' in MISTAKES:
        return math.degrees(math.acos(cosine)) <= light['cutoff'] / 2
    if 'spot-pi-macro' in MISTAKES:
        # acos(c) * 180 / PI with `#define PI 2*acos(0.0)`, expanded as
        # the C preprocessor does: acos(c) * 180 / 2 * acos(0.0).
        return math.acos(cosine) * 180 / 2 * math.acos(0.0) <= light['cutoff']
    return math.degrees(math.acos(cosine)) <= light['cutoff']


def shade(objs, lights, org, d, level, rec, clamp_each):
    o, t, n = nearest(objs, org, d)
    if o is None:
        return (0.0, 0.0, 0.0)
    p = add(org, mul(d, t))
    col = colour_at(o, p)
    spec_col = cell_colour(o, p) if o['kind'] == 'floor' else col
    c = mul(col, o['ka'])
    if n is None:
        n = normal(o, p)
    inside = dot(n, d) > 0
    if inside:
        n = mul(n, -1)
    r = sub(d, mul(n, 2 * dot(d, n)))
    for light in lights:
        lp, lc = light['pos'], light['colour']
        tl = sub(lp, p)
        dist = math.sqrt(dot(tl, tl))
        l = mul(tl, 1.0 / dist)
        nl = dot(n, l)
        if (nl <= 0 and not MISTAKES & {'light-behind', 'light-behind-signed'}) or \
                not in_cone(light, p):
            continue
        unit_start = 'unit-offset' in MISTAKES
        sorg = add(p, mul(l, 1.0 if unit_start else EPS))
        reach = dist - 1.0 if unit_start else dist
        blocked = False
        for ob in objs if 'no-shadows' not in MISTAKES else []:
            tb = hit_object(ob, sorg, l)
            if tb is not None and tb < reach:
                blocked = True
                break
        if blocked:
            continue
        a = math.exp(-dist * dist * light['falloff'])
        lam = nl if 'light-behind-signed' in MISTAKES else max(nl, 0.0)
        c = add(c, tuple(a * lc[i] * o['kd'] * lam * col[i] for i in range(3)))
        rl = dot(r, l)
        if rl > 0:
            s = a * o['ks'] * rl ** o['shine']
            tint = (1.0, 1.0, 1.0) if 'white-highlight' in MISTAKES else spec_col
            c = add(c, tuple(lc[i] * s * tint[i] for i in range(3)))
    kt, kr, through = o.get('kt', 0.0), o['kr'], None
    if level < rec and kt > 0:
        # Snell: sin t = eta sin i, eta = 1/IOR entering, IOR leaving.
        eta = o['ior'] if inside else 1.0 / o['ior']
        cos_i = -dot(d, n)
        sin2_t = eta * eta * (1 - cos_i * cos_i)
        if sin2_t > 1:
            kr, kt = 1.0, 0.0
        else:
            through = unit(add(mul(d, eta), mul(n, eta * cos_i - math.sqrt(1 - sin2_t))))
    if level < rec and kr > 0:
        start = 1.0 if 'unit-offset' in MISTAKES else EPS
        ref = shade(objs, lights, add(p, mul(r, start)), r, level + 1, rec, clamp_each)
        c = add(c, mul(ref, kr))
    if through is not None and kt > 0:
        tr = shade(objs, lights, add(p, mul(through, EPS)), through, level + 1, rec, clamp_each)
        c = add(c, mul(tr, kt))
    if clamp_each:
        c = tuple(min(1.0, max(0.0, v)) for v in c)
    return c


def pixel_byte(ch):
    """round(255 c) of the clamped channel, or as the mistake stores it;
    with --truncate int(255 c), as C's conversion to unsigned char does."""
    if 'no-clamp' in MISTAKES:
        if TRUNCATE:
            return int(255 * ch) & 255
        return int(round(255 * ch)) & 255 if ch > 0 else 0
    ch = min(1.0, max(0.0, ch))
    if 'gamma' in MISTAKES:
        ch = ch ** (1 / 2.2)
    elif 'gamma-srgb' in MISTAKES:
        ch = 12.92 * ch if ch <= 0.0031308 else 1.055 * ch ** (1 / 2.4) - 0.055
    return int(255 * ch) if TRUNCATE else int(round(255 * ch))


def main(argv):
    args = {'--size': None, '--recursion': None, '--eye': '0,-200,10', '--look': '0,0,0',
            '--up': '0,0,1', '--fov': None, '--clamp': 'level', '--floor': None,
            '--dialect': 'auto', '--samples': '1', '--floor-texture': None, '--glass': None,
            '--floor-finish': None}
    global MISTAKES, TRUNCATE
    pos, no_floor, i, also = [], False, 1, []
    while i < len(argv):
        if argv[i] == '--mistake':
            MISTAKES = MISTAKES | frozenset(argv[i + 1].split(','))
            i += 1
        elif argv[i] == '--truncate':
            TRUNCATE = True
        elif argv[i] == '--also':
            also.append(argv[i + 1].split('=', 1))
            i += 1
        elif argv[i] == '--no-floor':
            no_floor = True
        elif argv[i] in args:
            args[argv[i]] = argv[i + 1]
            i += 1
        else:
            pos.append(argv[i])
        i += 1
    rec, size, objs, lights, view = parse(pos[0], args['--dialect'])
    if args['--size']:
        size = int(args['--size'])
    if args['--recursion']:
        rec = int(args['--recursion'])
    if 'recursion-fewer' in MISTAKES:
        rec -= 1
    elif 'recursion-more' in MISTAKES:
        rec += 1
    clamp_each = args['--clamp'] == 'level'
    if 'clamp-final' in MISTAKES:
        clamp_each = not clamp_each
    elif 'no-clamp' in MISTAKES:
        clamp_each = False
    floor = view['floor']
    if args['--floor']:
        w, cell = (float(v) for v in args['--floor'].split(','))
        floor = dict(width=w, cell=cell, **CLASSIC_FLOOR)
    if args['--floor-finish']:
        k = [float(v) for v in args['--floor-finish'].split(',')]
        floor = dict(floor, ka=k[0], kd=k[1], ks=k[2], kr=k[3], shine=k[4])
    for item in (args['--glass'].split(',') if args['--glass'] else []):
        f = item.split(':')
        o = objs[int(f[0]) - 1]
        o['ior'] = float(f[1]) if len(f) > 1 else 1.5
        o['kt'] = float(f[2]) if len(f) > 2 else 0.8
    if not no_floor:
        objs.append(dict(kind='floor', colour=(1, 1, 1), **floor))
        if args['--floor-texture']:
            names = args['--floor-texture'].split(',')
            objs[-1]['textures'] = [read_texture(nm) if nm else None
                                    for nm in (names + [''])[:2]]
    eye = tuple(float(v) for v in args['--eye'].split(','))
    look = tuple(float(v) for v in args['--look'].split(','))
    upv = tuple(float(v) for v in args['--up'].split(','))
    fwd = unit(sub(look, eye))
    right = unit(cross(fwd, upv))
    up = cross(right, fwd)
    fovy = float(args['--fov']) if args['--fov'] else view['fov']
    # The image plane at distance near (1 when there is none: the rays'
    # directions are the same), height 2 near tan(fovy / 2), width
    # 2 near tan(fovx / 2) with fovx = aspect fovy, or fovy when aspect is 0.
    fovx = view['aspect'] * fovy if view['aspect'] > 0 else fovy
    h = math.tan(math.radians(fovy) / 2)
    wx = math.tan(math.radians(fovx) / 2)
    near = view['near']
    centre = 0.0 if 'pixel-corners' in MISTAKES else 0.5
    n = int(args['--samples'])
    rows = []
    for py in range(size):
        row = []
        for px in range(size):
            total = (0.0, 0.0, 0.0)
            for j in range(n):
                for i in range(n):
                    u = ((px + (i + centre) / n) / size * 2 - 1) * wx
                    v = (1 - (py + (j + centre) / n) / size * 2) * h
                    through = add(fwd, add(mul(right, u), mul(up, v)))
                    org = add(eye, mul(through, near)) if near > 0 else eye
                    c = shade(objs, lights, org, unit(through), 1, rec, clamp_each)
                    # Each of several samples is clamped before the mean (the
                    # one sample of a pixel is left to pixel_byte, so that
                    # the no-clamp mistake still wraps).
                    total = add(total, c if n == 1 else tuple(min(1.0, max(0.0, ch)) for ch in c))
            row.append(mul(total, 1.0 / (n * n)))
        rows.append(row)
    write_image(pos[1], rows)
    # --also CONVERSION=OUT: the same colours written another way.
    for conv, path in also:
        TRUNCATE = conv == 'truncate'
        if conv != 'truncate':
            MISTAKES = frozenset([conv])
        write_image(path, rows)


def write_image(path, floats):
    rows = [[tuple(pixel_byte(ch) for ch in c) for c in r] for r in floats]
    size = len(rows)
    if 'mirrored' in MISTAKES:
        rows = [r[::-1] for r in rows]
    if 'upside-down' in MISTAKES:
        rows = rows[::-1]
    if 'transposed' in MISTAKES:
        rows = [list(col) for col in zip(*rows)]
    if 'red-blue' in MISTAKES:
        rows = [[(p[2], p[1], p[0]) for p in r] for r in rows]
    if path.endswith('.bmp'):
        write_bmp(path, rows)
        return
    out = bytearray()
    for r in rows:
        for p in r:
            out += bytes(p)
    with open(path, 'wb') as f:
        f.write(b'P6\n%d %d\n255\n' % (size, size) + bytes(out))


def write_bmp(path, rows):
    """A 24-bit BMP as the course's bitmap code writes it: BGR, the rows
    bottom-up, each padded to a multiple of 4 bytes."""
    h, w = len(rows), len(rows[0])
    pad = (4 - 3 * w % 4) % 4
    data = bytearray()
    for r in reversed(rows):
        for p in r:
            data += bytes((p[2], p[1], p[0]))
        data += b'\0' * pad
    head = b'BM' + struct.pack('<IHHI', 54 + len(data), 0, 0, 54)
    info = struct.pack('<IiiHHIIiiII', 40, w, h, 1, 24, 0, len(data), 2835, 2835, 0, 0)
    with open(path, 'wb') as f:
        f.write(head + info + bytes(data))


if __name__ == '__main__':
    main(sys.argv)
