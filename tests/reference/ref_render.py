#!/usr/bin/env python3
"""An independent renderer of scene-format.md, written from the contract
alone (plain Python, naive formulas, its own epsilon) to check whitted's
images on scenes and cameras it generates at random.

  ref_render.py SCENE OUT.ppm [--size N] [--recursion N] [--eye X,Y,Z]
                [--look X,Y,Z] [--up X,Y,Z] [--fov DEG] [--clamp level|final]
                [--no-floor]
"""
import math
import sys

EPS = 1e-4


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


def parse(path):
    toks = list(tokens(open(path).read()))
    pos = [0]

    def nxt():
        pos[0] += 1
        return toks[pos[0] - 1]

    def num():
        return float(nxt())

    def vec():
        return (num(), num(), num())

    rec = int(float(nxt()))
    size = int(float(nxt()))
    objs = []
    for _ in range(int(float(nxt()))):
        kind = nxt()
        if kind == 'sphere':
            geo = (vec(), num())
        elif kind == 'triangle':
            geo = (vec(), vec(), vec())
        elif kind == 'general':
            geo = ([num() for _ in range(10)], vec(), vec())
        else:
            raise SystemExit('unknown ' + kind)
        colour = vec()
        ka, kd, ks, kr = num(), num(), num(), num()
        objs.append(dict(kind=kind, geo=geo, colour=colour, ka=ka, kd=kd, ks=ks,
                         kr=kr, shine=num()))
    nlights = int(float(nxt()))
    rest = toks[pos[0]:]
    count = 0
    for t in rest:
        if not is_number(t):
            break
        count += 1
    with_colour = not (nlights > 0 and count == 3 * nlights)
    lights = []
    for _ in range(nlights):
        p = vec()
        c = vec() if with_colour else (1.0, 1.0, 1.0)
        lights.append((p, c))
    return rec, size, objs, lights


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def add(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def mul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    n = math.sqrt(dot(a, a))
    return mul(a, 1.0 / n) if n > 0 else a


def hit_object(o, org, d):
    """The nearest t > EPS where the ray meets the object, or None."""
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
        half, tile = o['geo']
        if d[2] == 0:
            return None
        t = -org[2] / d[2]
        if t <= EPS:
            return None
        x, y = org[0] + t * d[0], org[1] + t * d[1]
        if -half <= x < half and -half <= y < half:
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


def colour_at(o, p):
    if o['kind'] != 'floor':
        return o['colour']
    half, tile = o['geo']
    i = math.floor((p[0] + half) / tile)
    j = math.floor((p[1] + half) / tile)
    return (1.0, 1.0, 1.0) if (i + j) % 2 == 0 else (0.0, 0.0, 0.0)


def nearest(objs, org, d):
    best, best_t = None, math.inf
    for o in objs:
        t = hit_object(o, org, d)
        if t is not None and t < best_t:
            best, best_t = o, t
    return best, best_t


def shade(objs, lights, org, d, level, rec, clamp_each):
    o, t = nearest(objs, org, d)
    if o is None:
        return (0.0, 0.0, 0.0)
    p = add(org, mul(d, t))
    col = colour_at(o, p)
    c = mul(col, o['ka'])
    n = normal(o, p)
    if dot(n, d) > 0:
        n = mul(n, -1)
    r = sub(d, mul(n, 2 * dot(d, n)))
    for lp, lc in lights:
        tl = sub(lp, p)
        dist = math.sqrt(dot(tl, tl))
        l = mul(tl, 1.0 / dist)
        sorg = add(p, mul(l, EPS))
        blocked = False
        for ob in objs:
            tb = hit_object(ob, sorg, l)
            if tb is not None and tb < dist:
                blocked = True
                break
        if blocked:
            continue
        nl = dot(n, l)
        if nl > 0:
            c = add(c, tuple(lc[i] * o['kd'] * nl * col[i] for i in range(3)))
            rl = dot(r, l)
            if rl > 0:
                s = o['ks'] * rl ** o['shine']
                c = add(c, tuple(lc[i] * s * col[i] for i in range(3)))
    if level < rec:
        ref = shade(objs, lights, add(p, mul(r, EPS)), r, level + 1, rec, clamp_each)
        c = add(c, mul(ref, o['kr']))
    if clamp_each:
        c = tuple(min(1.0, max(0.0, v)) for v in c)
    return c


def main(argv):
    args = {'--size': None, '--recursion': None, '--eye': '0,-200,10', '--look': '0,0,0',
            '--up': '0,0,1', '--fov': '80', '--clamp': 'level'}
    pos, no_floor, i = [], False, 1
    while i < len(argv):
        if argv[i] == '--no-floor':
            no_floor = True
        elif argv[i] in args:
            args[argv[i]] = argv[i + 1]
            i += 1
        else:
            pos.append(argv[i])
        i += 1
    rec, size, objs, lights = parse(pos[0])
    if args['--size']:
        size = int(args['--size'])
    if args['--recursion']:
        rec = int(args['--recursion'])
    if not no_floor:
        objs.append(dict(kind='floor', geo=(500.0, 20.0), colour=(1, 1, 1), ka=0.4, kd=0.2,
                         ks=0.2, kr=0.2, shine=1.0))
    eye = tuple(float(v) for v in args['--eye'].split(','))
    look = tuple(float(v) for v in args['--look'].split(','))
    upv = tuple(float(v) for v in args['--up'].split(','))
    fwd = unit(sub(look, eye))
    right = unit(cross(fwd, upv))
    up = cross(right, fwd)
    h = math.tan(math.radians(float(args['--fov'])) / 2)
    out = bytearray()
    for py in range(size):
        for px in range(size):
            u = ((px + 0.5) / size * 2 - 1) * h
            v = (1 - (py + 0.5) / size * 2) * h
            d = unit(add(fwd, add(mul(right, u), mul(up, v))))
            c = shade(objs, lights, eye, d, 1, rec, args['--clamp'] == 'level')
            out += bytes(int(round(255 * min(1.0, max(0.0, ch)))) for ch in c)
    with open(pos[1], 'wb') as f:
        f.write(b'P6\n%d %d\n255\n' % (size, size) + bytes(out))


if __name__ == '__main__':
    main(sys.argv)
