#!/bin/sh
# issue 14's features against the independent reference renderer
# (tests/reference/ref_render.py, written from README's rules apart from
# whitted): --samples under both clamp modes, --floor-texture on the three
# kinds of floor (BMP and PNG, one texture or two, lights that fall off),
# --glass on a sphere, a lifted cube, a prism, a clipped quadric and
# several objects at once (not the nearfar pyramid, whose base lies in the
# floor's plane: a tie), boxes met at one t (flat tiles far away), each
# within imgcmp's gate at 40x40.  Ends with "ref: N passed, N failed, N
# skipped".
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
B=${BUILD:-$top/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
S=$top/scenes T=$top/tests/textures
if ! command -v python3 >/dev/null 2>&1; then
	echo "ref: NOT RUN: python3 is missing"; echo "ref: 0 passed, 1 failed, 0 skipped"; exit 1
fi

# ref NAME SCENE OPTIONS...: whitted and the reference at 40x40, gated.
ref() {
	name=$1 scene=$2
	shift 2
	if ! python3 "$top/tests/reference/ref_render.py" "$scene" "$tmp/r.ppm" --size 40 "$@" 2>"$tmp/err" ||
	   ! "$B/whitted" -q -s 40 "$@" -o "$tmp/w.ppm" "$scene" 2>>"$tmp/err"; then
		fail=$((fail + 1)); echo "FAIL: $name: $(cat "$tmp/err")"; return
	fi
	if line=$("$B/imgcmp" "$tmp/w.ppm" "$tmp/r.ppm" 2>&1); then pass=$((pass + 1))
	else fail=$((fail + 1)); echo "FAIL: $name: $line"; fi
}
ref samples3 "$S/mirrors.txt" --samples 3
ref samples2-final "$S/bright-reflection.txt" --samples 2 --clamp final
ref samples4-spot "$S/spot.txt" --samples 4
ref texture-classic "$S/scene.txt" --floor-texture "$T/white.bmp,$T/black.png" --eye 30,-120,140
ref texture-nearfar "$S/nearfar.txt" --floor-texture "$T/white.png,$T/black.png"
ref texture-pyramid-black "$S/pyramid.txt" --floor-texture ",$T/black.png"
# Lights that fall off (exp(-0.1) to exp(-2) over the scene) on a
# textured floor, whose highlight keeps the cell's colour: the falloff
# scales each light's whole term, diffuse and highlight.
ref texture-falloff "$S/falloff.txt" --floor-texture "$T/white.png,$T/black.png"
ref texture-floor-7 "$S/shadows.txt" --floor 300,7 --floor-texture "$T/white.bmp" --eye 20,-80,120
ref glass-sphere "$S/sphere.txt" --recursion 5 --glass 2:1.5:0.8
ref glass-cube "$top/tests/scenes/glass-cube.txt" --recursion 6 --glass 1:1.5:0.8
ref glass-prism "$top/tests/scenes/glass-prism.txt" --recursion 6 --glass 1:1.5:0.85
ref glass-quadric "$S/quadric.txt" --recursion 5 --glass 1:1.4:0.7
ref glass-all "$top/tests/scenes/glass-cube.txt" --recursion 5 --glass 1,3:1.2:0.5,4 --samples 2 \
	--floor-texture "$T/white.bmp"
# Boxes whose entry and exit are one t: the flat tiles seen from 1e17
# away (portablecheck compares every walk there too).
ref flat-tiles-far "$top/tests/scenes/flat-tiles.txt" --eye 0,-1e17,20 --look 0,0,20 --fov 6e-14
echo "ref: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
