#!/bin/bash
# The HTML report of `whitted grade` in a real browser: headless Chromium
# (Debian's chromium, no network: the report is self-contained) loads it,
# the page's own script records on <body> how many images decoded, and the
# dumped DOM must show every row with its verdict and cause, every image
# loaded at its size (reference and submission 40 wide, the difference 80),
# and the unreadable image's row without images.  A screenshot of the page
# is kept in build/test-output/reportcheck/ for a human to look at.
SUITE=reportcheck
. "$(dirname "$0")/lib.sh"
[ -n "$1" ] && W=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
CHROMIUM=$(command -v chromium || command -v chromium-browser)
if [ -z "$CHROMIUM" ]; then
	echo "reportcheck: NOT RUN: chromium is not installed (make deps)"
	echo "reportcheck: 0 passed, 1 failed, 0 skipped"
	exit 1
fi
OUT=$ROOT/build/test-output/reportcheck
mkdir -p "$OUT"
SCENE=$ROOT/scenes/scene.txt
I=$T/img
mkdir -p "$I"
"$W" -q -s 40 -o "$I/good.bmp" "$SCENE"
"$W" -q -s 40 -o "$I/good.ppm" "$SCENE"
"$W" -q -s 40 -o "$I/other.png" "$ROOT/scenes/mirrors.txt"
python3 "$ROOT/tests/cli/make_images.py" "$I/good.ppm" "$I"
# A submission with red and blue swapped, from the PPM.
python3 - "$I/good.ppm" "$I/swapped.ppm" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); m, dims, mx, px = d.split(b'\n', 3)
out = bytearray(px)
out[0::3], out[2::3] = px[2::3], px[0::3]
open(sys.argv[2], 'wb').write(b'%s\n%s\n%s\n' % (m, dims, mx) + bytes(out))
PY
run grade -q -s 40 --scene "$SCENE" -o "$T/report.html" "$I/good.bmp" "$I/swapped.ppm" \
	"$I/truncated.bmp" "$I/other.png"
check grade-exit [ "$rc" -eq 3 ]
check report-written [ -s "$T/report.html" ]

CHROME_FLAGS=(--headless --no-sandbox --disable-gpu --disable-background-networking
	--disable-component-update --no-first-run --no-default-browser-check
	--user-data-dir="$T/profile" --virtual-time-budget=5000)
timeout 120 "$CHROMIUM" "${CHROME_FLAGS[@]}" --dump-dom "file://$T/report.html" >"$T/dom.html" 2>"$T/chromium.err"
check chromium-dump [ -s "$T/dom.html" ]
check dom python3 - "$T/dom.html" <<'PY'
import re, sys
dom = open(sys.argv[1]).read()
body = re.search(r'<body([^>]*)>', dom).group(1)
images = int(re.search(r'data-images="(\d+)"', body).group(1))
loaded = int(re.search(r'data-images-loaded="(\d+)"', body).group(1))
assert images == 9 and loaded == 9, (images, loaded)
rows = re.findall(r'<tr class="row (\w+)" data-verdict="(\w+)" data-cause="([\w-]*)">', dom)
assert [v for _, v, _ in rows] == ['match', 'differs', 'unreadable', 'differs'], rows
assert rows[1][2] == 'red-blue' and rows[0][2] == rows[2][2] == '', rows
widths = {}
for tag in re.findall(r'<img [^>]*>', dom):
    cls = re.search(r'class="(\w+)"', tag).group(1)
    w = int(re.search(r'data-natural-width="(\d+)"', tag).group(1))
    widths.setdefault(cls, set()).add(w)
assert widths == {'reference': {40}, 'submitted': {40}, 'difference': {80}}, widths
assert 'matches the reference with red and blue swapped' in dom
assert 'truncated BMP' in dom
assert '1 of 4 images match' in dom
PY
timeout 120 "$CHROMIUM" "${CHROME_FLAGS[@]}" --window-size=1280,1600 --hide-scrollbars \
	--screenshot="$OUT/report.png" "file://$T/report.html" >/dev/null 2>>"$T/chromium.err"
check screenshot is_png "$OUT/report.png"
check screenshot-width [ "$(png_width "$OUT/report.png")" -eq 1280 ]
cp "$T/report.html" "$OUT/report.html"
echo "reportcheck: the report and its screenshot: $OUT/report.html, $OUT/report.png"
finish
