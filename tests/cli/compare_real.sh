#!/usr/bin/env bash
# whitted compare and grade on what students really hand in: images from
# another camera (rendered by the independent renderer, with and without a
# mistake), two mistakes at once, any recursion level, another floor, a
# half turn, gamma with a truncating writer, a textured floor, ties at an
# odd size, a count-driven scene file (--lenient), where it differs object
# by object, the difference picture's legend; and grade over a Moodle
# folder, a zip file, two scenes and a points table.
# Usage: tests/cli/compare_real.sh [BUILD/whitted [BUILD/san/whitted]]
SUITE=comparereal
. "$(dirname "$0")/lib.sh"
[ -n "${1:-}" ] && W=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
REF=$ROOT/tests/reference/ref_render.py
SCENE=$ROOT/scenes/scene.txt
I=$T/img
mkdir -p "$I"
# jq-less JSON checks: python3 -c 'CODE' FILE, the object as j.
json() {
	local name=$1 code=$2
	check "$name" python3 -c "import json, sys
j = json.load(open(sys.argv[1]))
$code" "$T/out"
}

# --- Another camera: the student moved it before the capture.  The
# independent renderer draws the course example from a camera moved and
# turned the way the keyboard moves it; compare is given no camera.
CAM=(--eye 38,-172,46 --look 2,-60,14 --up 0.05,0.25,0.97 --fov 72)
python3 "$REF" "$SCENE" "$I/moved.ppm" --size 96 "${CAM[@]}"
run compare -q --json "$SCENE" "$I/moved.ppm"
check moved-exit [ "$rc" -eq 0 ]
json moved-json 'assert j["verdict"] == "match" and j["camera"]["moved"] is True, j["camera"]
assert j["best"]["causes"] == ["camera"] and j["best"]["explains"] is True, j["best"]
assert j["camera"]["psnr_given"] < 20, j["camera"]'
# The camera found renders what the true one does (>= 35 dB).
FOUND=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["camera"]["options"])' "$T/out")
run compare -q --json --no-camera-fit $FOUND "$SCENE" "$I/moved.ppm"
json moved-found-renders 'assert j["psnr"] is None or j["psnr"] >= 28, j["psnr"]'
run compare -q "$SCENE" "$I/moved.ppm"
check moved-text grep -q '^verdict: MATCH at the camera found$' "$T/out"
check moved-says grep -q '^your camera differs: found --eye .* --fov .*; at that camera your image matches' "$T/out"
# The same camera with the floor's tiles swapped: the camera is fitted
# with the swap rendered, and there the plain reference is farther from
# the image than at the given camera, which a note under the camera line
# explains (a lower PSNR "there" with no word of why read as a wrong
# camera).
python3 "$REF" "$SCENE" "$I/moved-swapped.ppm" --size 64 --mistake floor-swapped "${CAM[@]}"
run compare -q -s 64 "$SCENE" "$I/moved-swapped.ppm"
check swapped-camera-note eval 'grep -q "^camera: yours differs; found --eye 3[78]\.[0-9]*,-17[12]\.[0-9]*,4[56]\." "$T/out" &&
	grep -q "^  note: lower than at the camera given: the camera was fitted on the image.s greys" "$T/out" &&
	grep -q "^  1\. the floor.s tiles swapped " "$T/out"'
# A camera walked round to the far side of the objects and raised (as
# r10 of tests/data/student-renders-more): beyond the first look's box and
# near orbit, found by the far pass's orbit all round (before it: no
# camera, 8 dB).  At 64 pixels the camera comes within half a unit and the
# image within 37 dB.
python3 "$REF" "$SCENE" "$I/far.ppm" --size 64 --eye 130,170,120 --look 0,20,10 --up -0.3,-0.4,0.87 --fov 75
run compare -q --json "$SCENE" "$I/far.ppm"
json far-side-found 'import re
c = j["camera"]
assert c["moved"] is True and c["psnr"] >= 30, c
e = [float(v) for v in re.search(r"--eye (\S+)", c["options"]).group(1).split(",")]
assert max(abs(a - b) for a, b in zip(e, (130, 170, 120))) < 3, e'
# A correct render of a nearfar file (an endless floor, aliased up to the
# horizon) from a camera raised beside the objects: the camera is found
# to a hundredth of a pixel, yet the chequer near the horizon changes
# under any error, and some of its pixels stay unchanged by the six
# nudges of the ties by chance.  Edges are more than 30% of the image
# there, so only those mostly among ties become ties; before, 0.02% of
# the pixels (the gate's allowance) were off and it was called DIFFERS.
RA=$ROOT/tests/data/course-files/rafid013.txt
python3 "$REF" "$RA" "$I/horizon.ppm" --size 160 --eye -71.4667,-85.7778,85.2511 \
	--look -22.6997,-16.6002,36.0275 --up -0.1350,0,0.9908 --fov 81.135
run compare -q --json "$RA" "$I/horizon.ppm" -s 160
json horizon-ties-match 'assert j["camera"]["moved"] is True, j["camera"]
assert j["verdict"] == "match", (j["verdict"], j["camera"], j["diagnosis"])'
# A camera the greys alone weakly bear out stands only where a cause then
# comes close: r02 of the real renders (a view from nearer the objects,
# the cube elsewhere) once "found" a camera far back, 17 dB from the
# image, where nothing explained it.
R02=$DATA/student-renders-more
run compare -q --json "$R02/r02-scene.txt" "$R02/r02.png" --eye 0,-145,40 --look 0,0,40 --up 0,0,1
json weak-camera-not-taken 'assert j["camera"]["fitted"] is True and j["camera"]["moved"] is False, j["camera"]
assert j["verdict"] == "differs", j["verdict"]'
# --no-camera-fit judges at the given camera: it differs.
expect_rc() { [ "$rc" -eq "$1" ]; }
run compare -q --no-camera-fit "$SCENE" "$I/moved.ppm"
check moved-no-fit expect_rc 3

# ... and a mistake on top: named at the camera found.
python3 "$REF" "$SCENE" "$I/moved-noshadow.ppm" --size 96 "${CAM[@]}" --mistake no-shadows
run compare -q --json "$SCENE" "$I/moved-noshadow.ppm"
json moved-mistake 'assert j["camera"]["moved"] is True, j["camera"]
assert j["first"] == ["no-shadows"], j["first"]
assert j["best"]["causes"] == ["camera", "no-shadows"], j["best"]'

# ... another mistake, another scene: the tiles swapped pull the plain fit a
# cell away, and the refit with that cause finds the camera.  Run by the
# sanitized whitted: the refit's view once kept a pointer into a dead
# stack frame, which only this path reached.
AK=$ROOT/tests/data/course-files/an-akhand.txt
python3 "$REF" "$AK" "$I/moved-swapped.ppm" --size 64 --mistake floor-swapped --eye -41.6504,-117.0870,6.5255 \
	--look -27.1880,-18.3681,-0.2137 --up 0.0026,0.0677,0.9977 --fov 69.937
if [ -n "${2:-}" ]; then
	WSAN=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
	(cd "$T" && "$WSAN" compare -q --json "$AK" "$I/moved-swapped.ppm" >"$T/out" 2>"$T/err")
	rc=$?
	check moved-refit-sanitized eval '[ "$rc" -eq 3 ] && ! grep -q Sanitizer "$T/err"'
	json moved-refit-named 'assert j["camera"]["moved"] is True, j["camera"]
assert j["first"] == ["floor-swapped"], (j["first"], j["diagnosis"])'
else
	skip moved-refit-sanitized "no sanitized whitted given (make comparetest gives one)"
fi

# ... and a mistake that pulls the plain fit far away: gamma brightens
# every pixel, and the plain reference's nearest camera looks into a
# sphere (another cause is then named: "transposed" at 48 pixels); the
# fit made again with the reference gamma-encoded finds the camera, and
# gamma is named.  At 96 pixels: at 48 the camera found is off by a
# third of a pixel, which moves two pixels of the floor's far edge, and a
# pair (gamma and the floor reaching the horizon) then covers them.
SAD=$ROOT/tests/data/course-files/sadathossain01.txt
python3 "$REF" "$SAD" "$I/moved-gamma.ppm" --size 96 --mistake gamma --eye 22.6229,-176.0732,5.6145 \
	--look 26.8829,-76.1901,7.8965 --up -0.0031,-0.0227,0.9997 --fov 62.512
run compare -q --json -s 96 "$SAD" "$I/moved-gamma.ppm"
json moved-tone 'assert j["camera"]["moved"] is True, j["camera"]
assert j["first"] == ["gamma"], (j["first"], j["diagnosis"])
assert j["best"]["causes"] == ["camera", "gamma"] and (j["best"]["psnr"] is None or j["best"]["psnr"] >= 35), j["best"]  # None: no pixel differs'

# ... and the floor's tiles swapped, which turn every cell of the floor
# the other colour: the plain fit ends at a camera that sees little of
# the floor (the old fit named recursion-fewer here); the fit made again
# with the tiles swapped finds the camera, and judges it with them.
python3 "$REF" "$AK" "$I/moved-tiles.ppm" --size 96 --mistake floor-swapped \
	--eye 43.0162,-195.2469,18.6553 --look 41.3437,-95.2776,10.1470 --up 0,0,1 --fov 67.229
run compare -q --json -s 96 "$AK" "$I/moved-tiles.ppm"
json moved-tiles-pull 'assert j["camera"]["moved"] is True, j["camera"]
assert j["first"] == ["floor-swapped"], (j["first"], j["diagnosis"])
assert j["best"]["causes"] == ["camera", "floor-swapped"] and j["best"]["explains"], j["best"]'

# ... and where the plain fit is not pulled away but lands a cell off:
# the tiles swapped look like the plain floor from an eye one cell along
# x (sadathossain01's big sphere keeps the rest near), so the refit with
# the tiles swapped starts from the best of that camera and its four
# one-cell neighbours (it drifted 20 units away from the camera found).
python3 "$REF" "$SAD" "$I/moved-odd.ppm" --size 96 --mistake floor-swapped --eye -21.1401,-211.8981,49.0561 \
	--look 10.2318,-118.2689,34.5167 --up -0.1231,0,0.9924 --fov 80.297
run compare -q --json -s 96 "$SAD" "$I/moved-odd.ppm"
json moved-tiles-odd 'assert j["first"] == ["floor-swapped"], (j["first"], j["diagnosis"])
assert j["best"]["causes"] == ["camera", "floor-swapped"] and j["best"]["explains"], j["best"]'

# --- A moved camera and gamma on a scene symmetric left-right: at the
# given camera the mirror and gamma come close (15.5 dB), and the camera
# found with gamma explains the image exactly; the mirror stays only when
# the camera found comes no nearer with what is ranked there (once pairs
# were scored on their own renders, this image was called mirrored).
python3 "$REF" "$SAD" "$I/moved-gamma.ppm" --size 128 --mistake gamma --eye 43.0162,-195.2469,18.6553 \
	--look 41.3437,-95.2776,10.1470 --up 0,0,1 --fov 67.229
run compare -q --json -s 128 "$SAD" "$I/moved-gamma.ppm"
json moved-gamma-symmetric 'assert j["first"] == ["gamma"], (j["first"], j["diagnosis"])
assert j["best"]["causes"] == ["camera", "gamma"] and j["best"]["explains"], j["best"]'

# --- A correct render of a scene that looks the same turned a quarter
# about the origin: the fit found the camera turned a quarter the other
# way, where the tiles swapped explain it exactly; the turned camera,
# nearer the one the student started from, is a plain match (it was
# called tiles swapped).  The moved-camera set's sadathossain01 camera 2.
python3 "$REF" "$SAD" "$I/moved-quarter.ppm" --size 128 --eye -55.5005,-177.9625,14.1913 \
	--look -6.1075,-91.0135,11.9906 --up 0,0,1 --fov 64.952
run compare -q --json -s 128 "$SAD" "$I/moved-quarter.ppm"
json moved-quarter-turn 'assert j["verdict"] == "match" and j["camera"]["moved"] is True, (j["verdict"], j["first"])
eye = [float(v) for v in j["camera"]["options"].split()[1].split(",")]
assert abs(eye[0] + 55.5) < 2 and abs(eye[1] + 178) < 2, eye'

# --- A moved camera and a white highlight: at the camera found, the
# reference's highlight on a small sphere is edges all over, which the
# found camera's ties leave out; the submitted white there is outside
# what any camera within a pixel gives (the reference's 3 x 3
# neighbourhood), so those pixels are judged (it was called a match).
python3 "$REF" "$AK" "$I/moved-white.ppm" --size 128 \
	--mistake white-highlight --eye 43.0162,-195.2469,18.6553 --look 41.3437,-95.2776,10.1470 \
	--up 0,0,1 --fov 67.229
run compare -q --json -s 128 "$AK" "$I/moved-white.ppm"
json moved-white-highlight 'assert j["verdict"] == "differs" and j["first"] == ["white-highlight"], (j["verdict"], j["first"])
assert j["camera"]["moved"] is True and "white-highlight" in j["best"]["causes"], j["best"]'

# --- Ties: a correct render at an odd size, where the middle row's rays
# meet the floor exactly on a cell's edge: either colour is right.
python3 "$REF" "$SCENE" "$I/odd.ppm" --size 129
run compare -q --json -s 129 "$SCENE" "$I/odd.ppm"
json odd-size-match 'assert j["verdict"] == "match", (j["verdict"], j["off2"])
assert j["ties"] > 0, j["ties"]'

# --- Any recursion level: no reflections at all, and two levels short.
"$W" -q -s 48 -r 1 -o "$I/r1.png" "$SCENE"
run compare -q --json -s 48 "$SCENE" "$I/r1.png"
json no-reflections 'assert j["first"] == ["no-reflections"] and j["causes"][0]["explains"], j["first"]'
"$W" -q -s 48 -r 2 -o "$I/r2.png" "$SCENE"
run compare -q -s 48 "$SCENE" "$I/r2.png"
check recursion-two grep -q '^  1\. another recursion level (recursion level 2 instead of 4) .*explains the image' "$T/out"

# --- Two transforms at once: a half turn (the right vector and the up
# vector both wrong), which neither alone explains.
python3 "$REF" "$SCENE" "$I/ref48.ppm" --size 48
python3 - "$I/ref48.ppm" "$I/half.ppm" "$I/flip-rb.ppm" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); m, dims, mx, px = d.split(b'\n', 3)
w, h = map(int, dims.split())
rows = [px[3 * w * y:3 * w * (y + 1)] for y in range(h)]
half = b''.join(bytes(b for x in range(w - 1, -1, -1) for b in r[3 * x:3 * x + 3]) for r in reversed(rows))
flip = b''.join(reversed(rows))
rb = bytearray(flip); rb[0::3], rb[2::3] = flip[2::3], flip[0::3]
for name, data in ((sys.argv[2], half), (sys.argv[3], bytes(rb))):
    open(name, 'wb').write(b'%s\n%s\n%s\n' % (m, dims, mx) + data)
PY
run compare -q --json -s 48 "$SCENE" "$I/half.ppm"
json half-turn 'assert j["first"] == ["mirrored+upside-down"] and j["causes"][0]["explains"], j["first"]
assert j["causes"][0]["pair"] is True'
run compare -q -s 48 "$SCENE" "$I/half.ppm"
check half-turn-words grep -q 'the image turned half round' "$T/out"
run compare -q --json -s 48 "$SCENE" "$I/flip-rb.ppm"
json flip-red-blue 'assert j["first"] == ["upside-down+red-blue"], j["first"]'

# --- A render mistake and a transform at once: the highlight left white
# in an image whose red and blue are swapped.
python3 "$REF" "$SCENE" "$I/white.ppm" --size 48 --mistake white-highlight
python3 - "$I/white.ppm" "$I/white-rb.ppm" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); m, dims, mx, px = d.split(b'\n', 3)
out = bytearray(px); out[0::3], out[2::3] = px[2::3], px[0::3]
open(sys.argv[2], 'wb').write(b'%s\n%s\n%s\n' % (m, dims, mx) + bytes(out))
PY
run compare -q --json -s 48 "$SCENE" "$I/white-rb.ppm"
json pair 'assert j["first"] == ["red-blue+white-highlight"], j["first"]
assert j["best"]["causes"] == ["red-blue", "white-highlight"] and j["best"]["explains"], j["best"]'

# --- Two render mistakes, one of them small: sr38's tiles swapped and
# white highlight (the student-renders README), by the independent
# renderer at that student's camera and floor.  The highlight alone
# ranks eighth (the floor's error hides it); the best cause is paired
# with every other, so the pair is found (the five best with one another
# named the tiles alone, 22.3 dB).
SR38=(--eye 100,90,20 --look 99,89,20 --up 0,0,1 --fov 90 --floor 3000,30)
python3 "$REF" "$DATA/student-renders/sr38-scene.txt" "$I/sr38-two.ppm" --size 64 "${SR38[@]}" \
	--mistake floor-swapped,white-highlight
run compare -q --json --no-camera-fit -s 64 "${SR38[@]}" "$DATA/student-renders/sr38-scene.txt" "$I/sr38-two.ppm"
json pair-far-down 'assert j["first"] == ["white-highlight+floor-swapped"] and j["best"]["explains"], j["causes"][:2]
alone = [c for c in j["causes"] if c["id"] == "white-highlight"]
assert alone and j["causes"].index(alone[0]) >= 5, [c["id"] for c in j["causes"]]'
# ... and the five likeliest with one another still, though the likeliest
# with every other makes more pairs than the renders in full keep: the
# best of them are kept, not the first (the course example with no
# shadows and the tiles swapped: the tiles alone, 41.8 dB, when the
# first twelve were kept).
python3 "$REF" "$SCENE" "$I/two-near.ppm" --size 64 --mistake no-shadows,floor-swapped
run compare -q --json --no-camera-fit -s 64 "$SCENE" "$I/two-near.ppm"
json pair-best-kept 'assert j["first"] == ["no-shadows+floor-swapped"] and j["best"]["explains"], j["causes"][:2]'

# --- Gamma written by a truncating program: explained whole.
python3 "$REF" "$SCENE" "$I/gamma-trunc.ppm" --size 48 --mistake gamma --truncate
run compare -q --json -s 48 "$SCENE" "$I/gamma-trunc.ppm"
json gamma-truncated 'assert j["first"] == ["gamma"] and j["causes"][0]["explains"], j["causes"][:2]'

# --- Another floor: twice as wide, cells twice as large (the independent
# renderer's --floor).
python3 "$REF" "$SCENE" "$I/wide.ppm" --size 64 --floor 2000,20
run compare -q --json -s 64 --no-camera-fit "$SCENE" "$I/wide.ppm"
json floor-size 'assert j["first"] == ["floor-size"] and j["causes"][0]["explains"], j["first"]
assert "2000 wide instead of 1000" in j["causes"][0]["with"], j["causes"][0]'
python3 "$REF" "$SCENE" "$I/cells.ppm" --size 64 --floor 1000,40
run compare -q --json -s 64 --no-camera-fit "$SCENE" "$I/cells.ppm"
json floor-cell 'assert j["first"] == ["floor-cell"] and j["causes"][0]["explains"], j["first"]'

# --- The floor's own finish (a student's coefficients, kawshikbuet17's
# 0.25 each and shininess 15): fitted, and named with those values; with
# spotlights' cones 2.47 times narrower (an unbracketed PI macro) at
# sr20's camera, the pair, the finish fitted again with the cones (the
# first fit, pulled by them, took ks 0.2).
python3 "$REF" "$SCENE" "$I/finish.ppm" --size 96 --floor-finish 0.25,0.25,0.25,0.25,15
run compare -q --json -s 96 --no-camera-fit "$SCENE" "$I/finish.ppm"
json floor-finish 'assert j["first"] == ["floor-finish"] and j["causes"][0]["explains"], j["causes"][:2]
assert "ka kd ks kr 0.25 0.25 0.25 0.25, shininess 15, not 0.4 0.2 0.2 0.2, 1" in j["causes"][0]["with"], j["causes"][0]'
# With the tiles swapped too (thr0m3l's finish, 0.5 0.3 0.4 0.2 and 10):
# no finish fits the reference's tiles; fitted again with the tiles swapped
# rendered, the pair, exactly.
python3 "$REF" "$SCENE" "$I/finish-swapped.ppm" --size 96 --floor-finish 0.5,0.3,0.4,0.2,10 \
	--mistake floor-swapped
run compare -q --json -s 96 --no-camera-fit "$SCENE" "$I/finish-swapped.ppm"
json finish-swapped 'assert j["first"] == ["floor-swapped+floor-finish"] and j["best"]["explains"], j["causes"][:2]
assert "0.5 0.3 0.4 0.2, shininess 10" in j["causes"][0]["with"], j["causes"][0]'
SR20=(--eye 100,100,43 --look 29.3,29.3,43 --up 0,0,1 --fov 80)
python3 "$REF" "$DATA/student-renders/sr20-scene.txt" "$I/sr20-finish.ppm" --size 96 "${SR20[@]}" \
	--floor-finish 0.25,0.25,0.25,0.25,15 --mistake spot-pi-macro
run compare -q --json -s 96 --no-camera-fit "${SR20[@]}" "$DATA/student-renders/sr20-scene.txt" "$I/sr20-finish.ppm"
json finish-with-cone 'assert j["first"] == ["spot-cone+floor-finish"] and j["best"]["explains"], j["causes"][:2]
assert "PI a macro" in j["causes"][0]["with"] and "0.25 0.25 0.25 0.25, shininess 15" in j["causes"][0]["with"], j["causes"][0]'

# --- Another floor and a moved camera at once (Avi-Dewan's sr04: a floor
# 400 wide with cells 10, then the camera moved): no camera of the scene's
# floor comes near, so the floor's widths are screened and the cells
# fitted with the camera.  Before, the fine checker passed for a textured
# floor and the image was called a match.
python3 "$REF" "$SCENE" "$I/floor-shape.ppm" --size 96 --floor 400,10 --eye 60,-230,95 --look 0,-40,5 \
	--up 0,0,1 --fov 75
run compare -q --json "$SCENE" "$I/floor-shape.ppm"
json floor-shape-moved 'assert j["verdict"] == "differs" and j["camera"]["moved"], (j["verdict"], j["camera"])
assert "floor-cell" in j["best"]["causes"] and "cells 10 wide" in j["causes"][0]["with"], j["causes"][:2]
eye = [float(x) for x in j["camera"]["options"].split()[1].split(",")]
assert max(abs(a - b) for a, b in zip(eye, (60, -230, 95))) < 3, eye'

# --- Object by object: one sphere's colour changed in the file.
# (Sphere 1, green, made magenta: its reflections change a little of the
# others too.)
sed '0,/^0.0 1.0 0.0/s//1.0 0.0 1.0/' "$SCENE" >"$T/recoloured.txt"
cmp -s "$T/recoloured.txt" "$SCENE" && bad recolour "the scene was not changed"
"$W" -q -s 64 -o "$I/recoloured.png" "$T/recoloured.txt"
run compare -q --json -s 64 --no-camera-fit --diff "$T/wd/d.png" "$SCENE" "$I/recoloured.png"
json objects 'obj = {(o["keyword"], o["index"]): o for o in j["objects"]}
assert obj[("sphere", 1)]["off2"] > 0.9, obj
assert all(o["off2"] < 0.3 for k, o in obj.items() if k != ("sphere", 1)), obj
assert "sphere 1 differs" in j["objects_line"] and "sphere 2" not in j["objects_line"], j["objects_line"]'
# The difference picture: twice as wide, a legend band under it.
check diff-size python3 - "$T/wd/d.png" <<'PY'
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
w, h = struct.unpack('>II', d[16:24])
assert w == 128 and h > 64 and h <= 64 + 40, (w, h)
PY

# --- A textured floor (the Jan 2023 bonus task): judged without it.
SR=$DATA/student-renders
run compare -q --json --no-camera-fit -s 768 --eye 0,-160,60 --look 0,0,60 --up 0,0,1 \
	"$SR/sr02-scene.txt" "$SR/sr02.png"
json textured 'assert j["floor_textured"] is True and "textured" in j["diagnosis"], j["diagnosis"]'
# ... and its camera, moved before the capture, found though the floor
# that fills most of the image is not the reference's: the camera's
# figures weigh the image as it is at both cameras.
run compare -q --json -s 768 --eye 0,-160,60 --look 0,0,60 --up 0,0,1 \
	"$SR/sr02-scene.txt" "$SR/sr02.png"
json textured-moved 'c = j["camera"]
assert c["moved"] is True and c["psnr"] >= c["psnr_given"] + 3, c
assert j["floor_textured"] is True, j["diagnosis"]'
# --- A floor of another size and a moved camera at once: sr04's student
# draws the floor 400 wide with 10-unit tiles (the student-renders
# README), and pressed the keys before the capture.  With that floor
# given, the camera is found (84 units up, looking down 12 degrees) and
# the image comes within 25 dB; with the assignment's floor no camera
# comes near (9.5 dB), which is what the note on sr04 says.
run compare -q --json --floor 400,10 --eye 190,110,20 --look 189,109,20 --up 0,0,1 --fov 80 \
	"$SR/sr04-scene.txt" "$SR/sr04.png"
json other-floor-moved 'c = j["camera"]
eye = [float(v) for v in c["options"].split()[1].split(",")]
assert c["moved"] is True and c["psnr"] >= 25 and c["psnr_given"] < 15, c
assert 70 < eye[2] < 140 and abs(eye[0] - 190) < 60 and abs(eye[1] - 110) < 60, eye'

# --- A count-driven scene file: a render refuses it at its location (the
# strict reading is a render's default); compare reads it as the
# student's program did, saying so (the strict error as a note, the rest
# ignored with a note), with or without --lenient.
run -q -s 16 -o "$T/sr35.png" "$SR/sr35-scene.txt"
check strict-refuses eval '[ "$rc" -eq 1 ] && grep -q "sr35-scene.txt:79:5: error" "$T/err" && [ ! -e "$T/sr35.png" ]'
run compare --no-camera-fit -s 700 "$SR/sr35-scene.txt" "$SR/sr35.png"
check compare-falls-back eval '[ "$rc" -eq 3 ] && grep -q "sr35-scene.txt:79:5: note: expected the end of the data" "$T/err" &&
	grep -q "note: the strict reading refuses the file; read as the course.s count-driven programs read it" "$T/err"'
check fallback-note grep -q 'sr35-scene.txt:79: note: ignoring 12 numbers from line 79 on' "$T/err"
check fallback-notes-once eval '[ "$(grep -c "note: read as the classic dialect" "$T/err")" -eq 1 ]'
run compare -q --json --no-camera-fit -s 64 "$SR/sr35-scene.txt" "$SR/sr35.png"
json fallback-json 'assert j["lenient"] is True, j.get("lenient")'
run grade -q --no-camera-fit -s 64 --scene "$SR/sr35-scene.txt" --csv g35.csv "$SR/sr35.png"
check grade-falls-back eval '[ "$rc" -eq 3 ] && grep -q "sr35.png\",differs," "$T/wd/g35.csv"'
run compare --lenient --no-camera-fit -s 700 "$SR/sr35-scene.txt" "$SR/sr35.png"
check lenient-reads eval '[ "$rc" -eq 3 ] && ! grep -q "strict reading refuses" "$T/err"'
check lenient-note grep -q 'sr35-scene.txt:79: note: ignoring 12 numbers from line 79 on' "$T/err"

# --- Swapped operands.
run compare "$SR/sr38.png" "$SR/sr38-scene.txt"
check swapped-args [ "$rc" -eq 2 ] && grep -q 'SCENE comes first' "$T/err"

# --- grade: a Moodle folder and a zip of it, two scenes, a points table.
M=$T/moodle
mkdir -p "$M/Ada Lovelace_1001_assignsubmission_file_" "$M/Alan Turing_1002_assignsubmission_file_"
"$W" -q -s 40 -o "$M/Ada Lovelace_1001_assignsubmission_file_/scene.bmp" "$SCENE"
"$W" -q -s 40 -o "$M/Ada Lovelace_1001_assignsubmission_file_/mirrors.png" "$ROOT/scenes/mirrors.txt"
python3 "$REF" "$SCENE" "$M/Alan Turing_1002_assignsubmission_file_/scene.ppm" --size 40 --mistake no-shadows
"$W" -q -s 40 -r 1 -o "$M/Alan Turing_1002_assignsubmission_file_/mirrors.png" "$ROOT/scenes/mirrors.txt"
printf '# points\nmatch 5   # right\ncause no-shadows 3\ncause 1\n' >"$T/marks.txt"
(cd "$T" && python3 -c 'import zipfile, os
z = zipfile.ZipFile("class.zip", "w")
for root, ds, fs in os.walk("moodle"):
    for f in sorted(fs): z.write(os.path.join(root, f))
z.close()')
run grade -q -s 40 --no-camera-fit --scene "$SCENE" --scene "$ROOT/scenes/mirrors.txt" --marks "$T/marks.txt" \
	--csv "$T/wd/rows.csv" -o "$T/wd/report.html" "$M" "$T/class.zip"
check grade-exit [ "$rc" -eq 3 ]
check grade-summary grep -q '^class: 8 images of 4 students: 4 match, 4 differ, 0 unreadable' "$T/out"
check grade-csv python3 - "$T/wd/rows.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 8, len(rows)
ada = [r for r in rows if r["student"] == "Ada Lovelace"]
alan = [r for r in rows if r["student"] == "Alan Turing"]
assert len(ada) == 4 and len(alan) == 4 and {r["id"] for r in ada} == {"1001"}, rows
for r in ada:
    assert r["verdict"] == "match" and r["points"] == "5", r
    assert r["scene"].endswith(("scene.txt", "mirrors.txt")) and (r["scene"].endswith("mirrors.txt")) == ("mirrors" in r["file"]), r
byscene = {r["scene"].split("/")[-1]: r for r in alan}
assert byscene["scene.txt"]["cause"] == "no-shadows" and byscene["scene.txt"]["points"] == "3", byscene
assert byscene["mirrors.txt"]["best"] == "no-reflections" and byscene["mirrors.txt"]["points"] == "1", byscene
PY
check grade-report-students grep -q '<table id="students">' "$T/wd/report.html"
# A bad points table: its line and column, before anything is graded.
printf 'match 5\ncuase 3\n' >"$T/bad-marks.txt"
run grade -q -s 40 --scene "$SCENE" --marks "$T/bad-marks.txt" "$M"
check marks-error [ "$rc" -eq 1 ] && grep -q 'bad-marks.txt:2:1: error: expected match, camera' "$T/err"
check marks-error-first [ ! -s "$T/out" ]

finish
