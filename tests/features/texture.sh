#!/bin/sh
# --floor-texture end to end: pixel values of a floor seen from straight
# above, computed here from the handout's rule (texel times ambient and
# diffuse, the highlight the cell's colour: white, or none on a black cell)
# for a BMP and a PNG on the classic and the nearfar floor; BMP and PNG of
# the same pixels give the same image; tiles of other pixels under the same
# name are refused by the merge; the errors (a missing, an empty, a
# truncated or a non-image file: exit 1 naming it, no output; a bad value
# or --no-floor: exit 2); the default unchanged; an RGBA PNG, an XRGB and
# a top-down BMP read as their opaque pixels, and scene2pov's PNGs of the
# texels (removed when it fails).  Ends with "texture: N
# passed, N failed, N skipped".
set -u
. "$(dirname "$0")/lib.sh"
T=$top/tests/textures

# A 2x2 image of four points of the floor, (11, 32) (31, 32) / (11, 12)
# (31, 12), seen from above with the one light at the eye: 0.2 tan(fov/2)
# puts the pixel centres 10 units either side of the eye's foot.
printf '1\n2\n\n0\n\n1\n21 22 100\n1 1 1\n' >"$tmp/empty.txt"
view="--eye 21,22,100 --look 21,22,0 --up 0,1,0 --fov 22.619864948040426"

# expect NAME PPM KA KD KS WIDTH CELL OFFSET: the pixels against the rule,
# with the floor's cell (0, 0) at OFFSET (w/2 classic, 0 nearfar).
expect() {
	python3 - "$@" "$T" <<'PY' || return 1
import math, sys, struct
name, ppm, ka, kd, ks, width, cell, off, tdir = sys.argv[1:]
ka, kd, ks, cell, off = float(ka), float(kd), float(ks), float(cell), float(off)
def texture(kind):
    if kind == "white":  # tests/textures/make_textures.py's white pixels
        def px(x, y):
            c = [(250, 60, 40), (60, 230, 60), (50, 80, 240), (240, 230, 200)][(y >= 4) * 2 + (x >= 4)]
            return tuple(v // 2 for v in c) if (x + y) % 3 == 0 else c
        return 8, 8, px
    return 5, 4, lambda x, y: (20 + 40 * x, 10 + 30 * y, 90 - 15 * x)
data = open(ppm, "rb").read()
body = data[len(data) - 12:]
eye = (21.0, 22.0, 100.0)
want = []
for (x, y) in [(11, 32), (31, 32), (11, 12), (31, 12)]:
    cx, cy = (x + off) / cell, (y + off) / cell
    i, j = math.floor(cx), math.floor(cy)
    white = (i + j) % 2 == 0
    w, h, px = texture("white" if white else "black")
    col, row = int((cx - i) * w), h - 1 - int((cy - j) * h)
    tex = [v / 255.0 for v in px(col, row)]
    d = [x - eye[0], y - eye[1], -eye[2]]
    n = math.sqrt(sum(v * v for v in d))
    l = [-v / n for v in d]
    refl = [d[0] / n, d[1] / n, -d[2] / n]
    nl, rl = l[2], sum(a * b for a, b in zip(refl, l))
    spec = 1.0 if white else 0.0
    for t in tex:
        v = ka * t + kd * nl * t + ks * max(rl, 0.0) * spec
        want.append(int(math.floor(255 * min(max(v, 0.0), 1.0) + 0.5)))
got = list(body)
if got != want:
    print("%s: got %s, want %s" % (name, got, want))
    sys.exit(1)
PY
}

# shellcheck disable=SC2086
"$W" -q $view --floor-texture "$T/white.bmp,$T/black.png" -o "$tmp/c.ppm" "$tmp/empty.txt" &&
	expect classic "$tmp/c.ppm" 0.4 0.2 0.2 1000 20 500 && ok || bad "classic floor's pixels"
# shellcheck disable=SC2086
"$W" -q $view --floor 1000,10 --floor-texture "$T/white.png,$T/black.png" -o "$tmp/c10.ppm" "$tmp/empty.txt" &&
	expect classic-10 "$tmp/c10.ppm" 0.4 0.2 0.2 1000 10 500 && ok || bad "--floor 1000,10 floor's pixels"
# The nearfar file's floor: KA KD 0 KR, cells of its own size from the origin.
printf '10 500 22.619864948040426 1\n1\n2\n10\n0.5 0.3 0.2\n0\n1\n21 22 100\n0\n0\n' >"$tmp/nf.txt"
# shellcheck disable=SC2086
"$W" -q $view --floor-texture "$T/white.bmp,$T/black.png" -o "$tmp/n.ppm" "$tmp/nf.txt" &&
	expect nearfar "$tmp/n.ppm" 0.5 0.3 0 inf 10 0 && ok || bad "nearfar floor's pixels"
# The same pixels as BMP and as PNG: the same image.
"$W" -q -s 64 --floor-texture "$T/white.bmp" -o "$tmp/b.ppm" "$top/scenes/scene.txt" &&
"$W" -q -s 64 --floor-texture "$T/white.png" -o "$tmp/p.ppm" "$top/scenes/scene.txt"
if cmp -s "$tmp/b.ppm" "$tmp/p.ppm"; then ok; else bad "white.bmp and white.png differ"; fi
"$W" -q -s 64 -o "$tmp/plain.ppm" "$top/scenes/scene.txt"
if cmp -s "$tmp/b.ppm" "$tmp/plain.ppm"; then bad "the texture changed nothing"; else ok; fi

# The images' contents are in the tiles' settings: a tile rendered with
# another image under the same name is refused by the merge.
cp "$T/white.bmp" "$tmp/w.bmp"
"$W" -q -s 32 --floor-texture "$tmp/w.bmp" --grid 1x2 --tile 1 -o "$tmp/t1.png" "$top/scenes/scene.txt"
"$W" -q -s 32 --floor-texture "$tmp/w.bmp" --grid 1x2 --tile 2 -o "$tmp/t2.png" "$top/scenes/scene.txt"
if "$W" merge -o "$tmp/m.png" "$tmp/t1.png" "$tmp/t2.png"; then ok; else bad "merge refused tiles of one texture"; fi
cp "$T/white.png" "$tmp/w.bmp"
"$W" -q -s 32 --floor-texture "$tmp/w.bmp" --grid 1x2 --tile 2 -o "$tmp/t2.png" "$top/scenes/scene.txt"
if "$W" merge -o "$tmp/m2.png" "$tmp/t1.png" "$tmp/t2.png" 2>/dev/null; then ok
else bad "the same pixels as PNG under that name: merge refused"; fi
# One byte of a pixel changed: another image.
cp "$T/white.bmp" "$tmp/w.bmp" && python3 -c "
import sys; b = bytearray(open(sys.argv[1], 'rb').read()); b[60] ^= 0xff; open(sys.argv[1], 'wb').write(b)" "$tmp/w.bmp"
"$W" -q -s 32 --floor-texture "$tmp/w.bmp" --grid 1x2 --tile 2 -o "$tmp/t2.png" "$top/scenes/scene.txt"
if "$W" merge -o "$tmp/m3.png" "$tmp/t1.png" "$tmp/t2.png" 2>/dev/null; then bad "merge took a tile of another image"; else ok; fi

# fails WANT GREP OPTION-VALUE [more options]: exit status, message, no output.
fails() {
	want=$1 msg=$2
	shift 2
	"$W" -q -s 16 "$@" -o "$tmp/out.png" "$top/scenes/scene.txt" 2>"$tmp/err"
	st=$?
	if [ "$st" != "$want" ]; then bad "$*: exit $st, expected $want: $(cat "$tmp/err")"
	elif ! grep -q -- "$msg" "$tmp/err"; then bad "$*: message '$(cat "$tmp/err")' lacks '$msg'"
	elif [ -e "$tmp/out.png" ]; then bad "$*: left the output"
	else ok; fi
	rm -f "$tmp/out.png"
}
: >"$tmp/empty.png"
head -c 60 "$T/white.png" >"$tmp/cut.png"
head -c 100 "$T/white.bmp" >"$tmp/cut.bmp"
fails 1 "$tmp/nothere.bmp: cannot open" --floor-texture "$tmp/nothere.bmp"
fails 1 "$tmp/nothere.png: cannot open" --floor-texture "$T/white.bmp,$tmp/nothere.png"
fails 1 "empty.png: an empty file, not an image" --floor-texture "$tmp/empty.png"
fails 1 "cut.png: cannot read the image" --floor-texture "$tmp/cut.png"
fails 1 "cut.bmp: truncated BMP" --floor-texture "$tmp/cut.bmp"
fails 1 "scene.txt: not an image" --floor-texture "$top/scenes/scene.txt"
fails 2 "expected WHITE\[,BLACK\]" --floor-texture ","
fails 2 "one comma" --floor-texture "a,b,c"
fails 2 "needs the floor" --floor-texture "$T/white.bmp" --no-floor

# The other forms of the same pixels whitted reads give the same image:
# an RGBA PNG (the alpha ignored), a 32-bit XRGB BMP, a top-down BMP.
same_image() {
	# shellcheck disable=SC2086
	"$W" -q -s 24 $view --floor-texture "$1" -o "$tmp/a.ppm" "$tmp/empty.txt" &&
		"$W" -q -s 24 $view --floor-texture "$2" -o "$tmp/b.ppm" "$tmp/empty.txt" &&
		cmp -s "$tmp/a.ppm" "$tmp/b.ppm"
}
for pair in "white.png white-rgba.png" "white.bmp white-xrgb.bmp" ",black.png ,black-topdown.bmp"; do
	# shellcheck disable=SC2086
	set -- $pair
	if same_image "$T/${1#,}" "$T/${2#,}"; then ok; else bad "$1 and $2 differ"; fi
done

# scene2pov writes each texture as an opaque 24-bit PNG of the decoded
# texels beside OUT.pov, which the image_map names; it holds the pixels
# of white.png.  When the .pov cannot be written, no PNG is left.
mkdir "$tmp/pov"
if "$B/scene2pov" -q -s 16 --floor-texture "$T/white-xrgb.bmp,$T/black-topdown.bmp" \
	-o "$tmp/pov/out.pov" "$top/scenes/scene.txt" &&
   grep -q 'image_map { png "out-floor-white.png"' "$tmp/pov/out.pov" &&
   grep -q 'image_map { png "out-floor-black.png"' "$tmp/pov/out.pov" &&
   python3 - "$tmp/pov/out-floor-white.png" "$T/white.png" "$tmp/pov/out-floor-black.png" \
	"$T/black.png" <<'PY'
import struct, sys, zlib
def rgb(path):
    data = open(path, "rb").read()
    w, h, depth, ctype = struct.unpack(">IIBB", data[16:26])
    assert depth == 8 and ctype == 2, (path, depth, ctype)  # opaque 8-bit RGB
    idat, i = b"", 8
    while i < len(data):
        n, = struct.unpack(">I", data[i:i + 4])
        if data[i + 4:i + 8] == b"IDAT":
            idat += data[i + 8:i + 8 + n]
        i += 12 + n
    raw, rows, prev, stride = zlib.decompress(idat), [], bytearray(3 * w), 3 * w
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            p = a + b - c
            pr = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
            line[x] = (line[x] + (0, a, b, (a + b) // 2, pr)[f]) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, rows
a = sys.argv[1:]
sys.exit(0 if rgb(a[0]) == rgb(a[1]) and rgb(a[2]) == rgb(a[3]) else 1)
PY
then ok; else bad "scene2pov's texture PNGs"; fi
mkdir "$tmp/pov2" "$tmp/pov2/out.pov"
if "$B/scene2pov" -q -s 16 --floor-texture "$T/white.bmp" -o "$tmp/pov2/out.pov" \
	"$top/scenes/scene.txt" 2>/dev/null; then
	bad "scene2pov to a directory named out.pov succeeded"
elif [ -n "$(find "$tmp/pov2" -name '*.png')" ]; then
	bad "scene2pov left $(find "$tmp/pov2" -name '*.png') after failing"
else ok; fi
echo "texture: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
