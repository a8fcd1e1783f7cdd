#!/usr/bin/env python3
"""The moved-camera set: how often `whitted compare`, given no camera,
finds the camera a render was taken from and names the mistake on top.

usage: moved_set.py [--seed S] [--cameras N] [--size PX] [--mistakes M,...]
                    [--reach R] [--out DIR] WHITTED [WHITTED2 ...] -- SCENE [SCENE ...]

For each scene, N cameras moved the way the course's keyboard moves them
(from the file's default eye 0,-200,10: walked up to about 60 units
sideways, 90 forward and 60 up, each times R, default 1: R 1.3 walks up
to about 160 units; turned up to 15 degrees, half of them
rolled up to 8 degrees, fov 60 to 100), and for each camera one render a
mistake (ref_render.py's --mistake names; "none" for a correct render)
by the independent renderer (tests/reference/ref_render.py).  Each
whitted given compares every image (`compare -q --json -s PX`, no
camera) and prints, per image and per whitted: the verdict, the first
cause, whether the camera moved, the best explanation's PSNR and the
time; a mistake whose image passes the gate against the correct one
from that camera (nothing it changes is in view) is left out and
counted, as tests/reference/mistakes_check.py does.  Then the tally per
whitted: correct renders called a match, the mistake named first, and
the best explanation (camera and causes) at >= 35 dB.

Not a test (it takes minutes): the measure behind docs/validation.md's
figures on pulled passes, kept here to be run again.  The images are
cached in --out (default /tmp/whitted-moved-set) by name.
"""
import json
import math
import os
import random
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, 'ref_render.py')
sys.path.insert(0, HERE)
from mistakes_check import gate, read_ppm  # noqa: E402


def render(opts, scene, name, c, cam, mistake, size):
    """The image of one camera and mistake, rendered once into the cache."""
    seed = opts['--seed'] if float(opts['--reach']) == 1.0 else '%s-r%s' % (opts['--seed'], opts['--reach'])
    img = os.path.join(opts['--out'], '%s-%s-%d-%s-%s.ppm' % (name, seed, c, mistake, size))
    if not os.path.exists(img):
        extra = [] if mistake == 'none' else ['--mistake', mistake]
        subprocess.run([sys.executable, REF, scene, img, '--size', size] + extra + cam, check=True)
    return img


def cameras(seed, n, reach=1.0):
    r = random.Random(seed)
    out = []
    for _ in range(n):
        eye = [reach * r.uniform(-60, 60), -200 + reach * r.uniform(-30, 90), 10 + reach * r.uniform(0, 60)]
        d = [-eye[0], -eye[1], 15 - eye[2]]
        length = math.sqrt(sum(c * c for c in d))
        x, y, z = (c / length for c in d)
        yaw = math.radians(r.uniform(-15, 15))
        pitch = math.radians(r.uniform(-10, 10))
        x, y = x * math.cos(yaw) - y * math.sin(yaw), x * math.sin(yaw) + y * math.cos(yaw)
        z += math.sin(pitch)
        look = [eye[0] + 100 * x, eye[1] + 100 * y, eye[2] + 100 * z]
        roll = math.radians(r.uniform(-8, 8)) if r.random() < 0.5 else 0.0
        up = [math.sin(roll), 0.0, math.cos(roll)]
        fov = r.uniform(60, 100)
        out.append(['--eye', '%.4f,%.4f,%.4f' % tuple(eye), '--look', '%.4f,%.4f,%.4f' % tuple(look),
                    '--up', '%.4f,%.4f,%.4f' % tuple(up), '--fov', '%.3f' % fov])
    return out


def main(argv):
    opts = {'--seed': '7', '--cameras': '4', '--size': '256', '--reach': '1',
            '--mistakes': 'none,floor-swapped,gamma', '--out': '/tmp/whitted-moved-set'}
    args = argv[1:]
    while args and args[0] in opts:
        opts[args[0]] = args[1]
        args = args[2:]
    if '--' not in args or args.index('--') == 0 or args.index('--') == len(args) - 1:
        sys.stderr.write(__doc__)
        return 2
    cut = args.index('--')
    binaries, scenes = args[:cut], args[cut + 1:]
    size = opts['--size']
    os.makedirs(opts['--out'], exist_ok=True)
    cams = cameras(int(opts['--seed']), int(opts['--cameras']), float(opts['--reach']))
    tally = {w: {'match': [0, 0], 'named': [0, 0], 'best35': [0, 0]} for w in binaries}
    unseen = {}
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        for c, cam in enumerate(cams, 1):
            for mistake in opts['--mistakes'].split(','):
                img = render(opts, scene, name, c, cam, mistake, size)
                line = '%-16s %d %-14s' % (name, c, mistake)
                if mistake != 'none' and gate(read_ppm(render(opts, scene, name, c, cam, 'none', size))[2],
                                              read_ppm(img)[2]):
                    # Not visible from this camera (no light behind a
                    # surface in view): left out, as mistakes_check does.
                    unseen[mistake] = unseen.get(mistake, 0) + 1
                    print(line + '  not visible from this camera', flush=True)
                    continue
                for w in binaries:
                    t0 = time.time()
                    p = subprocess.run([w, 'compare', '-q', '--json', '-s', size, scene, img],
                                       capture_output=True, text=True)
                    dt = time.time() - t0
                    try:
                        j = json.loads(p.stdout)
                    except ValueError:
                        line += '  error(%d)' % p.returncode
                        continue
                    first = '+'.join(j['first']) or '-'
                    best = j['best']['psnr']
                    best = math.inf if best is None else best
                    t = tally[w]
                    if mistake == 'none':
                        t['match'][1] += 1
                        t['match'][0] += j['verdict'] == 'match'
                    else:
                        t['named'][1] += 1
                        t['named'][0] += first == mistake
                        t['best35'][1] += 1
                        t['best35'][0] += best >= 35 and mistake in j['best']['causes']
                    line += '  %s/%s/%s/%.1f/%.1fs' % (j['verdict'], first,
                                                       'moved' if j['camera']['moved'] else 'given',
                                                       min(best, 99.0), dt)
                print(line, flush=True)
    if unseen:
        print('not visible, left out: ' + ', '.join('%s %d' % kv for kv in sorted(unseen.items())))
    for w in binaries:
        t = tally[w]
        print('%s: correct called a match %d/%d; mistake named first %d/%d; camera and mistake >= 35 dB %d/%d'
              % (w, t['match'][0], t['match'][1], t['named'][0], t['named'][1], t['best35'][0], t['best35'][1]))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
