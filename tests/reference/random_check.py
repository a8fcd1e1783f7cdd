#!/usr/bin/env python3
"""Renders random scenes and cameras with whitted and with the independent
reference renderer (ref_render.py) and compares them: PSNR >= 60 dB, at
most 0.2% of pixels off by more than 2 levels and 0.02% by more than 8.

  random_check.py WHITTED [COUNT] [SEED] [SIZE]
"""
import math
import os
import random
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def rnd_material(r):
    col = ' '.join('%.3f' % r.random() for _ in range(3))
    coef = '%.2f %.2f %.2f %.2f' % (r.uniform(0, 0.5), r.uniform(0, 0.8),
                                    r.uniform(0, 0.8), r.uniform(0, 0.6))
    return '%s\n%s\n%d\n' % (col, coef, r.choice([1, 2, 5, 10, 30, 100]))


def rnd_point(r, spread=60.0, zmin=0.0, zmax=60.0):
    return (r.uniform(-spread, spread), r.uniform(-spread, spread), r.uniform(zmin, zmax))


def rnd_quadric(r):
    cx, cy, cz = rnd_point(r, 40, 5, 40)
    kind = r.choice(['ellipsoid', 'cylinder', 'hyperboloid', 'plane', 'cone'])
    a, b, c = (r.uniform(0.5, 2.0) for _ in range(3))
    if kind == 'ellipsoid':
        A, B, C, J0 = 1 / a ** 2, 1 / b ** 2, 1 / c ** 2, -r.uniform(60, 200)
    elif kind == 'cylinder':
        A, B, C, J0 = 1.0, 1.0, 0.0, -r.uniform(30, 150)
    elif kind == 'hyperboloid':
        A, B, C, J0 = 1.0, 1.0, -1.0, -r.uniform(20, 100)
    elif kind == 'cone':
        A, B, C, J0 = 1.0, 1.0, -0.5, 0.0
    else:
        A, B, C, J0 = 0.0, 0.0, 0.0, 0.0
    # Translate the quadric centred at the origin to (cx, cy, cz).
    if kind == 'plane':
        G, H, I = r.uniform(-1, 1), r.uniform(-1, 1), 1.0
        J = -(G * cx + H * cy + I * cz)
    else:
        G, H, I = -2 * A * cx, -2 * B * cy, -2 * C * cz
        J = A * cx * cx + B * cy * cy + C * cz * cz + J0
    coef = [A, B, C, 0.0, 0.0, 0.0, G, H, I, J]
    if kind != 'plane' and r.random() < 0.3:
        coef[3] = r.uniform(-0.3, 0.3)
    ext = [r.choice([0, r.uniform(10, 40)]) for _ in range(3)]
    ref = [cx - r.uniform(0, 20), cy - r.uniform(0, 20), cz - r.uniform(0, 20)]
    if kind == 'plane':
        ext = [r.uniform(20, 40), r.uniform(20, 40), 0]
    return ('general\n' + ' '.join('%.6g' % v for v in coef) + '\n' +
            ' '.join('%.4g' % v for v in ref) + ' ' + ' '.join('%.4g' % v for v in ext) + '\n' +
            rnd_material(r))


def rnd_scene(r):
    objs = []
    for _ in range(r.randint(1, 8)):
        k = r.random()
        if k < 0.4:
            p = rnd_point(r, 50, 5, 50)
            objs.append('sphere\n%.3f %.3f %.3f\n%.3f\n' % (p + (r.uniform(3, 20),)) + rnd_material(r))
        elif k < 0.75:
            c = rnd_point(r, 50, 0, 50)
            verts = [tuple(c[i] + r.uniform(-25, 25) for i in range(3)) for _ in range(3)]
            objs.append('triangle\n' + ''.join('%.3f %.3f %.3f\n' % v for v in verts) + rnd_material(r))
        else:
            objs.append(rnd_quadric(r))
    nl = r.randint(1, 4)
    coloured = r.random() < 0.8
    lights = ''
    for _ in range(nl):
        lights += '%.2f %.2f %.2f\n' % rnd_point(r, 120, 20, 150)
        if coloured:
            lights += ' '.join('%.2f' % r.random() for _ in range(3)) + '\n'
    return '%d\n%d\n%d\n%s%d\n%s' % (r.randint(1, 5), 64, len(objs), '\n'.join(objs), nl, lights)


def rnd_camera(r):
    dist = r.uniform(120, 260)
    az = r.uniform(0, 2 * math.pi)
    el = r.uniform(0.05, 0.9)
    eye = (dist * math.cos(az) * math.cos(el), dist * math.sin(az) * math.cos(el),
           dist * math.sin(el) + 5)
    look = rnd_point(r, 20, 0, 30)
    up = (r.uniform(-0.4, 0.4), r.uniform(-0.4, 0.4), 1.0)
    fov = r.uniform(30, 100)
    return ['--eye', '%.4f,%.4f,%.4f' % eye, '--look', '%.4f,%.4f,%.4f' % look,
            '--up', '%.3f,%.3f,%.3f' % up, '--fov', '%.3f' % fov]


def pixels(path):
    data = open(path, 'rb').read()
    return data.split(b'\n', 3)[3]


def compare(a, b):
    diffs = [abs(x - y) for x, y in zip(a, b)]
    n = len(diffs) // 3
    px = [max(diffs[3 * i:3 * i + 3]) for i in range(n)]
    mse = sum(d * d for d in diffs) / len(diffs)
    psnr = math.inf if mse == 0 else 10 * math.log10(255 * 255 / mse)
    return psnr, max(diffs), 100.0 * sum(p > 2 for p in px) / n, 100.0 * sum(p > 8 for p in px) / n


def main():
    whitted = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    size = sys.argv[4] if len(sys.argv) > 4 else '64'
    r = random.Random(seed)
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(count):
            scene = os.path.join(tmp, 'random%02d.txt' % k)
            with open(scene, 'w') as f:
                f.write(rnd_scene(r))
            cam = rnd_camera(r) if k % 4 else []
            extra = cam + ['--size', size] + (['--clamp', 'final'] if r.random() < 0.3 else [])
            wout, rout = os.path.join(tmp, 'w.ppm'), os.path.join(tmp, 'r.ppm')
            subprocess.run([whitted, '-q', '-o', wout, scene] + extra, check=True)
            subprocess.run([sys.executable, os.path.join(HERE, 'ref_render.py'), scene, rout] + extra,
                           check=True)
            wpix = pixels(wout)
            psnr, mx, p2, p8 = compare(wpix, pixels(rout))
            mean = sum(wpix) / len(wpix)
            ok = psnr >= 60 and p2 <= 0.2 and p8 <= 0.02
            print('refcheck: scene %2d  mean level %5.1f  PSNR %6.1f dB  max %3d  >2: %.3f%%  >8: %.3f%%  %s' %
                  (k, mean, psnr, mx, p2, p8, 'ok' if ok else 'FAIL'))
            if ok:
                passed += 1
            else:
                failed += 1
                keep = os.path.join(os.getcwd(), 'build', 'refcheck-fail-%02d.txt' % k)
                os.makedirs(os.path.dirname(keep), exist_ok=True)
                with open(keep, 'w') as f:
                    f.write(open(scene).read())
                print('refcheck:   scene kept in %s, options: %s' % (keep, ' '.join(extra)))
    print('refcheck: %d passed, %d failed' % (passed, failed))
    sys.exit(1 if failed else 0)


main()
