#!/usr/bin/env bash
# The README's picture of whitted compare on a real-looking case: the
# course example drawn by the independent renderer from a camera moved as
# the keyboard moves it, with no shadows; whitted finds the camera, names
# the mistake there, and draws the difference.  Writes
# docs/img/compare-camera.png (needs ImageMagick's montage).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
W=$root/build/whitted
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
CAM=(--eye 38,-172,46 --look 2,-60,14 --up 0.05,0.25,0.97 --fov 72)
python3 "$root/tests/reference/ref_render.py" "$root/scenes/scene.txt" "$T/student.ppm" --size 256 \
	"${CAM[@]}" --mistake no-shadows
"$W" compare -q --json --diff "$T/diff.png" "$root/scenes/scene.txt" "$T/student.ppm" >"$T/out.json" || true
found=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["camera"]["options"])' "$T/out.json")
# shellcheck disable=SC2086
"$W" -q -s 256 $found -o "$T/found.png" "$root/scenes/scene.txt"
"$W" -q -s 256 -o "$T/given.png" "$root/scenes/scene.txt"
montage -label 'the student' "$T/student.ppm" -label 'the camera given' "$T/given.png" \
	-label 'the camera found' "$T/found.png" -label 'the difference there' "$T/diff.png" \
	-tile 4x1 -geometry '+4+4' -pointsize 14 -font DejaVu-Sans "$root/docs/img/compare-camera.png"
python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["diagnosis"]); print(j["objects_line"])' "$T/out.json"
