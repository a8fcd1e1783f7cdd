#!/usr/bin/env python3
"""Renders random scenes and cameras with whitted and with the independent
reference renderer (ref_render.py) and compares them: PSNR >= 60 dB, at
most 0.2% of pixels off by more than 2 levels and 0.02% by more than 8.
Every third scene has 9 to 12 coloured lights (more than the renderer's
batch of 8 lights: real course files have 9), and every third is rendered
at SIZE + 7 pixels, so that the renderer's 16x16 blocks are cut at the
right and bottom edges (for any SIZE that is a multiple of 16, such as
make check's 80, the others have no partial block).

COUNT classic scenes come first (the same for a SEED as before the
dialects), then COUNT / 3 random scenes of each other dialect, written in
its own format (spot: spotlights of every width from 5 to 180 degrees;
pyramid: pyramids and spheres, white lights; nearfar: its header's near
plane, aspect and checkerboard, cubes and pyramids, lights that fall off),
half of them read with --dialect and half detected, then the scenes of
scenes/ and tests/scenes/ that are not classic (falloff.txt among them,
which POV-Ray cannot render exactly), each at its own view.

  random_check.py WHITTED [COUNT] [SEED] [SIZE]
"""
import glob
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
    # The cross terms E (xz) and F (yz) as well as D (xy): each its own
    # term of the equation and of the gradient.
    if kind != 'plane' and r.random() < 0.3:
        coef[4] = r.uniform(-0.3, 0.3)
    if kind != 'plane' and r.random() < 0.3:
        coef[5] = r.uniform(-0.3, 0.3)
    ext = [r.choice([0, r.uniform(10, 40)]) for _ in range(3)]
    ref = [cx - r.uniform(0, 20), cy - r.uniform(0, 20), cz - r.uniform(0, 20)]
    if kind == 'plane':
        ext = [r.uniform(20, 40), r.uniform(20, 40), 0]
    return ('general\n' + ' '.join('%.6g' % v for v in coef) + '\n' +
            ' '.join('%.4g' % v for v in ref) + ' ' + ' '.join('%.4g' % v for v in ext) + '\n' +
            rnd_material(r))


def rnd_classic_objects(r, most, sphere_below, triangle_below):
    """1 to `most` classic objects: a draw below sphere_below a sphere,
    below triangle_below a triangle, else a quadric."""
    objs = []
    for _ in range(r.randint(1, most)):
        k = r.random()
        if k < sphere_below:
            p = rnd_point(r, 50, 5, 50)
            objs.append('sphere\n%.3f %.3f %.3f\n%.3f\n' % (p + (r.uniform(3, 20),)) + rnd_material(r))
        elif k < triangle_below:
            c = rnd_point(r, 50, 0, 50)
            verts = [tuple(c[i] + r.uniform(-25, 25) for i in range(3)) for _ in range(3)]
            objs.append('triangle\n' + ''.join('%.3f %.3f %.3f\n' % v for v in verts) + rnd_material(r))
        else:
            objs.append(rnd_quadric(r))
    return objs


def rnd_scene(r, many_lights=False):
    objs = rnd_classic_objects(r, 8, 0.4, 0.75)
    if many_lights:
        # Dim and each of its own colour, so that the sum does not just
        # clamp to white and a light shaded with another's colour shows.
        nl, coloured, scale = r.randint(9, 12), True, 0.3
    else:
        nl, coloured, scale = r.randint(1, 4), r.random() < 0.8, 1.0
    lights = ''
    for _ in range(nl):
        lights += '%.2f %.2f %.2f\n' % rnd_point(r, 120, 20, 150)
        if coloured:
            lights += ' '.join('%.2f' % (scale * r.random()) for _ in range(3)) + '\n'
    return '%d\n%d\n%d\n%s%d\n%s' % (r.randint(1, 5), 64, len(objs), '\n'.join(objs), nl, lights), nl


def rnd_light_colour(r, scale=1.0):
    return ' '.join('%.2f' % (scale * r.random()) for _ in range(3)) + '\n'


def rnd_cutoff(r):
    return r.choice([r.uniform(5, 40), r.uniform(40, 89), 90.0, r.uniform(91, 170), 180.0])


def rnd_spot_scene(r):
    """classic's objects and coloured point lights, then spotlights aimed
    near the objects."""
    objs = rnd_classic_objects(r, 6, 0.5, 0.85)
    nl = r.randint(0, 3)
    lights = ''.join('%.2f %.2f %.2f\n' % rnd_point(r, 120, 20, 150) + rnd_light_colour(r, 0.5)
                     for _ in range(nl))
    ns = r.randint(1, 3)
    spots = ''
    for _ in range(ns):
        pos = rnd_point(r, 120, 20, 150)
        aim = rnd_point(r, 40, 0, 30)
        axis = tuple(aim[i] - pos[i] + r.uniform(-20, 20) for i in range(3))
        spots += ('%.2f %.2f %.2f\n' % pos + rnd_light_colour(r) + '%.3f %.3f %.3f\n' % axis +
                  '%.3f\n' % rnd_cutoff(r))
    return ('%d\n%d\n%d\n%s%d\n%s%d\n%s' % (r.randint(1, 5), 64, len(objs), '\n'.join(objs), nl,
                                          lights, ns, spots), nl + ns)


def rnd_pyramid_scene(r):
    """Spheres and pyramids (lowest corner, base, height), white lights."""
    objs = []
    for _ in range(r.randint(1, 7)):
        if r.random() < 0.6:
            x, y, z = rnd_point(r, 60, 0, 30)
            objs.append('pyramid\n%.3f %.3f %.3f\n%.3f %.3f\n' %
                        (x, y, z, r.uniform(10, 50), r.uniform(10, 60)) + rnd_material(r))
        else:
            p = rnd_point(r, 50, 5, 50)
            objs.append('sphere\n%.3f %.3f %.3f\n%.3f\n' % (p + (r.uniform(3, 20),)) + rnd_material(r))
    nl = r.randint(1, 4)
    lights = ''.join('%.2f %.2f %.2f\n' % rnd_point(r, 120, 20, 150) for _ in range(nl))
    return '%d\n%d\n%d\n%s%d\n%s' % (r.randint(1, 5), 64, len(objs), '\n'.join(objs), nl, lights), nl


def rnd_falloff(r):
    return r.choice([0.0, r.uniform(1e-6, 4e-5), r.uniform(1e-7, 5e-6)])


def rnd_nearfar_scene(r):
    """The nearfar header, spheres, pyramids (base centre, width, height)
    and cubes (corner, side), lights x y z falloff and spotlights aimed at
    a point."""
    fovy = r.uniform(40, 90)
    aspect = r.uniform(0.5, min(1.8, 170.0 / fovy))
    head = '%.3f 1000 %.3f %.3f\n%d\n%d\n%.2f\n%.2f %.2f %.2f\n' % (
        r.uniform(0.5, 30), fovy, aspect, r.randint(1, 4), 64, r.uniform(10, 50),
        r.uniform(0, 0.5), r.uniform(0, 0.8), r.uniform(0, 0.6))
    objs = []
    for _ in range(r.randint(1, 7)):
        k = r.random()
        if k < 0.35:
            p = rnd_point(r, 50, 5, 50)
            objs.append('sphere\n%.3f %.3f %.3f\n%.3f\n' % (p + (r.uniform(3, 20),)) + rnd_material(r))
        elif k < 0.7:
            x, y, z = rnd_point(r, 60, 0, 30)
            objs.append('pyramid\n%.3f %.3f %.3f\n%.3f %.3f\n' %
                        (x, y, z, r.uniform(10, 50), r.uniform(10, 60)) + rnd_material(r))
        else:
            x, y, z = rnd_point(r, 60, 0, 30)
            objs.append('cube\n%.3f %.3f %.3f\n%.3f\n' % (x, y, z, r.uniform(5, 40)) + rnd_material(r))
    npt, ns = r.randint(0, 3), r.randint(0, 2)
    if npt + ns == 0:
        npt = 1
    lights = ''.join('%.2f %.2f %.2f\n%.8g\n' % (rnd_point(r, 120, 20, 150) + (rnd_falloff(r),))
                     for _ in range(npt))
    spots = ''
    for _ in range(ns):
        spots += '%.2f %.2f %.2f\n%.8g\n' % (rnd_point(r, 120, 20, 150) + (rnd_falloff(r),))
        spots += '%.2f %.2f %.2f %.3f\n' % (rnd_point(r, 40, 0, 30) + (rnd_cutoff(r),))
    return '%s%d\n%s%d\n%s%d\n%s' % (head, len(objs), '\n'.join(objs), npt, lights, ns, spots), npt + ns


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


class Check:
    """Renders one scene both ways and prints its row."""

    def __init__(self, whitted, tmp):
        self.whitted, self.tmp = whitted, tmp
        self.passed = self.failed = 0

    def run(self, label, scene, extra, lights):
        wout, rout = os.path.join(self.tmp, 'w.ppm'), os.path.join(self.tmp, 'r.ppm')
        subprocess.run([self.whitted, '-q', '-o', wout, scene] + extra, check=True)
        subprocess.run([sys.executable, os.path.join(HERE, 'ref_render.py'), scene, rout] + extra,
                       check=True)
        wpix = pixels(wout)
        psnr, mx, p2, p8 = compare(wpix, pixels(rout))
        mean = sum(wpix) / len(wpix)
        ok = psnr >= 60 and p2 <= 0.2 and p8 <= 0.02
        size = extra[extra.index('--size') + 1] if '--size' in extra else '-'
        print('refcheck: %-14s %2s lights  %3s px  mean level %5.1f  PSNR %6.1f dB  max %3d  '
              '>2: %.3f%%  >8: %.3f%%  %s' % (label, lights, size, mean, psnr, mx, p2, p8,
                                              'ok' if ok else 'FAIL'))
        if ok:
            self.passed += 1
            return
        self.failed += 1
        keep = os.path.join(os.getcwd(), 'build', 'refcheck-fail-%s.txt' % label.replace(' ', '-'))
        os.makedirs(os.path.dirname(keep), exist_ok=True)
        with open(keep, 'w') as f:
            f.write(open(scene).read())
        print('refcheck:   scene kept in %s, options: %s' % (keep, ' '.join(extra)))


def dialect_of(path):
    """The dialect ref_render.py reads path as."""
    sys.path.insert(0, HERE)
    import ref_render
    return ref_render.parse(path)[4]['dialect']


def main():
    whitted = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    size = sys.argv[4] if len(sys.argv) > 4 else '64'
    r = random.Random(seed)
    with tempfile.TemporaryDirectory() as tmp:
        check = Check(whitted, tmp)
        for k in range(count):
            scene = os.path.join(tmp, 'random%02d.txt' % k)
            text, lights = rnd_scene(r, many_lights=k % 3 == 2)
            with open(scene, 'w') as f:
                f.write(text)
            cam = rnd_camera(r) if k % 4 else []
            px = str(int(size) + 7) if k % 3 == 1 else size
            extra = cam + ['--size', px] + (['--clamp', 'final'] if r.random() < 0.3 else [])
            check.run('scene %2d' % k, scene, extra, lights)
        # The dialects' own random scenes, from a generator of their own, so
        # that the classic scenes above stay those of earlier runs.
        r = random.Random(seed * 7919 + 12)
        makers = (('spot', rnd_spot_scene), ('pyramid', rnd_pyramid_scene),
                  ('nearfar', rnd_nearfar_scene))
        for name, make in makers:
            for k in range(max(1, count // 3)):
                scene = os.path.join(tmp, '%s%02d.txt' % (name, k))
                text, lights = make(r)
                with open(scene, 'w') as f:
                    f.write(text)
                cam = rnd_camera(r) if k % 4 else []
                # Not an odd size with the default camera: its middle row
                # then looks along y = 0, a line between checkerboard
                # cells, where rounding picks either cell.
                px = str(int(size) + 7) if k % 3 == 1 and cam else size
                extra = cam + ['--size', px] + (['--clamp', 'final'] if r.random() < 0.3 else [])
                if k % 2:
                    extra += ['--dialect', name]
                check.run('%s %2d' % (name, k), scene, extra, lights)
        fixed = sorted(glob.glob(os.path.join(HERE, '..', '..', 'scenes', '*.txt')) +
                       glob.glob(os.path.join(HERE, '..', 'scenes', '*.txt')))
        # The course's own files of every dialect, copied into tests/data
        # (each must be there): the handouts' scenes, falloff included.
        course_dir = os.path.join(HERE, '..', 'data', 'course-files')
        course = ['munzer2', 'sadathossain01', 'an-akhand', 'rafid013', 'tanjeem29',
                  'akib1689', 'ishtiaqniloy']
        for name in course:
            scene = os.path.join(course_dir, name + '.txt')
            if not os.path.isfile(scene):
                print('refcheck: %s is missing' % scene)
                check.failed += 1
                continue
            check.run(name[:14], scene, ['--size', size], '-')
        for scene in fixed:
            if dialect_of(scene) != 'classic':
                opts = ['--no-floor'] if 'quadrants' in scene else []
                check.run(os.path.basename(scene)[:-4][:14], scene, ['--size', size] + opts, '-')
    print('refcheck: %d passed, %d failed, 0 skipped' % (check.passed, check.failed))
    sys.exit(1 if check.failed else 0)


main()
