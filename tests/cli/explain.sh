#!/bin/bash
# whitted explain end to end: --help, usage errors (no pixel, a bad one,
# one outside the image: exit 2), a scene's located error (exit 1), the
# text's and the JSON's 8-bit value equal to the rendered pixel on scenes
# of every dialect, the test scene, the object's line in the file, a
# shadowing object named, and --samples' sub-pixel colours.  (The value on
# many more pixels: tests/unit/render/test_explain.c.)
SUITE=explaintest
. "$(dirname "$0")/lib.sh"

run explain --help
check help [ "$rc" -eq 0 ]
check help-usage grep -q '^Usage: whitted explain' "$T/out"
run explain "$ROOT/scenes/scene.txt"
check no-pixel [ "$rc" -eq 2 ]
check no-pixel-message grep -q 'no pixel X,Y given' "$T/err"
run explain "$ROOT/scenes/scene.txt" 3,x
check bad-pixel [ "$rc" -eq 2 ]
run explain -s 32 "$ROOT/scenes/scene.txt" 32,0
check outside [ "$rc" -eq 2 ]
check outside-message grep -q 'outside the 32x32 image' "$T/err"
run explain "$DATA/course-files/thr0m3l.txt" 1,1
check bad-scene [ "$rc" -eq 1 ]
check bad-scene-located grep -q 'thr0m3l.txt:[0-9]*:[0-9]*: error:' "$T/err"

# pixel_of PPM X Y: "R, G, B" of a binary PPM's pixel (header of 3 lines).
pixel_of() {
	python3 -c 'import sys
d = open(sys.argv[1], "rb").read().split(b"\n", 3)
w = int(d[1].split()[0]); i = (int(sys.argv[3]) * w + int(sys.argv[2])) * 3
print(", ".join(str(b) for b in d[3][i:i + 3]))' "$@"
}
for s in scenes/scene.txt scenes/spot.txt scenes/pyramid.txt scenes/nearfar.txt \
	tests/data/course-files/an-akhand.txt; do
	"$W" -q -s 40 -o "$T/ref.ppm" "$ROOT/$s"
	for xy in 5,5 20,25 33,17; do
		run explain -q -s 40 "$ROOT/$s" $xy
		want=$(pixel_of "$T/ref.ppm" ${xy%,*} ${xy#*,})
		check "text-value $s $xy" grep -q "^8-bit value ($want)\$" "$T/out"
		run explain -q -s 40 --json "$ROOT/$s" $xy
		check "json-value $s $xy" grep -q "\"value\": \[$want\]}\$" "$T/out"
	done
done
run explain -q -s 40 --test-scene 20,20
check test-scene [ "$rc" -eq 0 ]

# The course example's middle: object 2, a sphere on line 12.
run explain -q "$ROOT/scenes/scene.txt" 326,329
check object-line grep -q 'hits object 2 (sphere, line 12)' "$T/out"
check shadow-named grep -q 'shadow ray blocked by object 3 (sphere, line 19)' "$T/out"
run explain -q -s 40 --samples 2 --json "$ROOT/scenes/sphere.txt" 20,20
check samples [ "$(grep -o '"sample": [0-9]*' "$T/out" | sort -u | wc -l)" -eq 4 ]
finish
