#!/usr/bin/env python3
"""The real renders: what `whitted compare` says of the images students
committed beside their scene files.

usage: real_set.py WHITTED DIR [DIR ...] [--only ID,ID...]

Each DIR holds ID.png (or .bmp), ID-scene.txt and cameras.txt, one line
an image: its ID and the camera options the student's program starts
from (students move the camera before they capture, so the camera of the
image is often another one).  For each image and each whitted given, one
`compare -q --json` and a line: the verdict, whether a camera was found
(and where), the best explanation's causes and PSNR, and the time; then
the tally: how many reach 25 dB.  What a person sees in each image is in
the DIR's README.md, to set beside what whitted says.

Not a test (it takes minutes): the measure behind docs/validation.md's
figures on real renders, kept here to be run again.
"""
import json
import os
import subprocess
import sys
import time


def images(folder):
    with open(os.path.join(folder, 'cameras.txt')) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            ident, opts = words[0], words[1:]
            image = next((os.path.join(folder, ident + ext) for ext in ('.png', '.bmp')
                          if os.path.exists(os.path.join(folder, ident + ext))), None)
            yield ident, image, os.path.join(folder, ident + '-scene.txt'), opts


def main(argv):
    args = argv[1:]
    only = None
    if '--only' in args:
        k = args.index('--only')
        only = set(args[k + 1].split(','))
        del args[k:k + 2]
    if len(args) < 2:
        sys.stderr.write(__doc__)
        return 2
    whitted, folders = args[0], args[1:]
    reached = total = 0
    for folder in folders:
        for ident, image, scene, opts in images(folder):
            if only and ident not in only:
                continue
            start = time.time()
            p = subprocess.run([whitted, 'compare', '-q', '--json', scene, image] + opts,
                               capture_output=True, text=True)
            secs = time.time() - start
            try:
                j = json.loads(p.stdout)
            except ValueError:
                print('%-6s exit %d: %s' % (ident, p.returncode, p.stderr.strip()[:200]))
                total += 1
                continue
            cam = j.get('camera', {})
            best = j.get('best', {})
            psnr = best.get('psnr')
            psnr = 99.0 if psnr is None else psnr
            where = 'camera found' if cam.get('moved') else (
                'floor alone, not taken' if cam.get('floor_alone') else 'no camera')
            print('%-6s %-8s %-24s %6.2f dB  %-60s %5.1fs' % (
                ident, j.get('verdict'), where, psnr, '+'.join(best.get('causes', [])) or '-', secs))
            total += 1
            reached += psnr >= 25.0
    print('best explanation >= 25 dB: %d of %d' % (reached, total))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
