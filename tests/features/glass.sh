#!/bin/sh
# --glass end to end: the option's errors (exit 2, a message naming it, no
# output), the images against the independent reference renderer (two
# indices, recursion 1, total internal reflection in a cube and a prism),
# the defaults, that the settings text of tiles and --stats
# carries it (and --samples and --floor-texture) so that merge refuses
# tiles of other glass, and that scene2pov writes the glass and its
# shadow twin, and the closed-solid note (plugins included).  The images
# are also checked against POV-Ray by povcheck and ray by ray by
# tests/unit/render/test_glass.c.  Ends with
# "glass: N passed, N failed, N skipped".
set -u
. "$(dirname "$0")/lib.sh"
scene=$top/scenes/sphere.txt

for spec in 0 99 1:0 1:-1 1:inf 1:1.5:1 1:1.5:0 1:x 1::0.5 1:1.5:0.5:9 "," 1,,2 -1 2,2:1.2 \
	1,3,1; do
	"$W" -q -s 16 --glass "$spec" -o "$tmp/e.png" "$scene" 2>"$tmp/err"
	st=$?
	if [ $st -ne 2 ]; then bad "--glass '$spec': exit $st"
	elif ! grep -q -- "--glass" "$tmp/err"; then bad "--glass '$spec': $(cat "$tmp/err")"
	elif [ -e "$tmp/e.png" ]; then bad "--glass '$spec' left its output"
	else ok; fi
	rm -f "$tmp/e.png"
done

# The images against the independent renderer (tests/reference/
# ref_render.py: Snell's law from the normal's side, total internal
# reflection a whole mirror), each within imgcmp's gate at 40x40: the
# default index and another, a recursion level that lets no ray through
# (glass is its surface only), and a cube and a prism of a high index
# (2.4), inside which most rays are totally reflected.
# ref NAME SCENE OPTIONS...
ref() {
	name=$1 sc=$2
	shift 2
	if ! python3 "$top/tests/reference/ref_render.py" "$sc" "$tmp/r.ppm" --size 40 "$@" 2>"$tmp/err" ||
	   ! "$W" -q -s 40 "$@" -o "$tmp/w.ppm" "$sc" 2>>"$tmp/err"; then
		bad "$name: $(cat "$tmp/err")"; return
	fi
	if line=$("$B/imgcmp" "$tmp/w.ppm" "$tmp/r.ppm" 2>&1); then ok
	else bad "$name against the reference renderer: $line"; fi
}
if command -v python3 >/dev/null 2>&1; then
	ref "sphere, index 1.5" "$scene" --recursion 4 --glass 2
	ref "sphere, index 1.33, kt 0.6" "$scene" --recursion 4 --glass 2:1.33:0.6
	ref "sphere at recursion 1" "$scene" --recursion 1 --glass 2
	ref "cube, index 2.4" "$top/tests/scenes/glass-cube.txt" --recursion 7 --glass 1:2.4:0.9
	ref "prism, index 2.4" "$top/tests/scenes/glass-prism.txt" --recursion 7 --glass 1:2.4:0.9
else
	echo "glass: NOT RUN: python3 is missing (the reference renderer)"
	fail=$((fail + 1))
fi
# The defaults: --glass 2 is --glass 2:1.5:0.8.
"$W" -q -s 48 -r 4 --glass 2 -o "$tmp/g.ppm" "$scene"
"$W" -q -s 48 -r 4 --glass 2:1.5:0.8 -o "$tmp/g2.ppm" "$scene"
if cmp -s "$tmp/g.ppm" "$tmp/g2.ppm"; then ok; else bad "--glass 2 is not --glass 2:1.5:0.8"; fi

"$W" -q --stats -s 16 --glass 2:1.33,3 --samples 2 --floor-texture "$top/tests/textures/white.bmp" \
	-o "$tmp/s.png" "$scene" 2>"$tmp/stats"
if grep -q "glass=2:1.33:0.8,3:1.5:0.8" "$tmp/stats" && grep -q "samples=2" "$tmp/stats" &&
   grep -q "floor-texture=$top/tests/textures/white.bmp" "$tmp/stats"; then ok
else bad "--stats lacks the new settings: $(grep settings "$tmp/stats")"; fi
# The list's order does not matter: the settings text is sorted by index.
"$W" -q --stats -s 16 --glass 3:1.2,1 -o "$tmp/s.png" "$scene" 2>"$tmp/stats31"
"$W" -q --stats -s 16 --glass 1,3:1.2 -o "$tmp/s.png" "$scene" 2>"$tmp/stats13"
if grep -q "glass=1:1.5:0.8,3:1.2:0.8" "$tmp/stats31" &&
   [ "$(grep settings "$tmp/stats31")" = "$(grep settings "$tmp/stats13")" ]; then ok
else bad "--glass 3,1 and 1,3 differ: $(grep settings "$tmp/stats31" "$tmp/stats13")"; fi
# --stats counts the transmitted rays apart from the reflected ones.
"$W" -q --stats -s 16 -r 4 --glass 2 -o "$tmp/s.png" "$scene" 2>"$tmp/statsr"
if grep -Eq "rays: .* [1-9][0-9]* refracted" "$tmp/statsr"; then ok
else bad "--stats counts no refracted rays: $(grep rays "$tmp/statsr")"; fi
"$W" -q --stats -s 16 -r 4 -o "$tmp/s.png" "$scene" 2>"$tmp/statsr"
if grep -q " 0 refracted" "$tmp/statsr"; then ok
else bad "--stats counts refracted rays without glass: $(grep rays "$tmp/statsr")"; fi
"$W" -q -s 32 --glass 2 --grid 2x1 --tile 1 -o "$tmp/t1.png" "$scene"
"$W" -q -s 32 --glass 2:1.4 --grid 2x1 --tile 2 -o "$tmp/t2.png" "$scene"
if "$W" merge -o "$tmp/m.png" "$tmp/t1.png" "$tmp/t2.png" 2>/dev/null; then bad "merge took tiles of other glass"; else ok; fi
"$W" -q -s 32 --glass 2 --grid 2x1 --tile 2 -o "$tmp/t2.png" "$scene"
if "$W" merge -o "$tmp/m.png" "$tmp/t1.png" "$tmp/t2.png"; then ok; else bad "merge refused tiles of the same glass"; fi

"$B/scene2pov" -q -s 16 -r 4 --glass 2:1.33:0.6 -o "$tmp/g.pov" "$scene"
if grep -q "interior { ior 1.33 } no_shadow" "$tmp/g.pov" && grep -q "rgbt <.*,0.6>" "$tmp/g.pov" &&
   [ "$(grep -c "no_image no_reflection" "$tmp/g.pov")" = 1 ]; then ok
else bad "scene2pov's glass: $(grep -n "ior\|no_image" "$tmp/g.pov")"; fi
# Glass on what is not a closed solid is taken with a note (not with -q);
# on a sphere, a cube, a pyramid or a whole ellipsoid without one.
"$W" -s 8 --glass 1 -o "$tmp/n.png" "$top/scenes/triangle.txt" 2>"$tmp/note"
if grep -q "object 1 (triangle) is not a closed solid: refraction through it is only approximate" \
	"$tmp/note"; then ok; else bad "no note for a glass triangle: $(cat "$tmp/note")"; fi
"$W" -q -s 8 --glass 1 -o "$tmp/n.png" "$top/scenes/triangle.txt" 2>"$tmp/note"
if [ -s "$tmp/note" ]; then bad "-q printed: $(cat "$tmp/note")"; else ok; fi
for g in "$top/scenes/sphere.txt 1" "$top/scenes/nearfar.txt 1" "$top/tests/scenes/glass-prism.txt 1" \
	"$top/tests/scenes/glass-quadric-negated.txt 1"; do
	# shellcheck disable=SC2086
	set -- $g
	"$W" -s 8 --glass "$2" -o "$tmp/n.png" "$1" 2>"$tmp/note"
	if grep -q "closed solid" "$tmp/note"; then bad "$1: $(cat "$tmp/note")"; else ok; fi
done
# A plugin's shape says whether it is closed: the torus and the capped
# cylinder are, the quad is not.
for p in torus cylinder; do
	"$W" -s 8 --plugin "$B/plugins/$p.so" --glass 1 -o "$tmp/n.png" "$top/scenes/plugins/$p.txt" \
		2>"$tmp/note"
	if grep -q "closed solid" "$tmp/note"; then bad "$p: $(cat "$tmp/note")"; else ok; fi
done
"$W" -s 8 --plugin "$B/plugins/quad.so" --glass 1 -o "$tmp/n.png" "$top/scenes/plugins/quad.txt" \
	2>"$tmp/note"
if grep -q "object 1 (quad) is not a closed solid" "$tmp/note"; then ok
else bad "no note for a glass quad: $(cat "$tmp/note")"; fi
echo "glass: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
