#!/bin/sh
# Makes docs/img/validation.png: the example scene rendered by
# `whitted --clamp final`, by POV-Ray from scene2pov's export, and their
# difference amplified 32 times, side by side (needs povray and
# ImageMagick's montage).  Usage: tests/validation-image.sh [SIZE]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
size=${1:-256}
tmp="$build/validation-image"
for tool in povray montage; do
	command -v "$tool" >/dev/null 2>&1 || { echo "validation-image: $tool is not installed" >&2; exit 1; }
done
rm -rf "$tmp"
mkdir -p "$tmp/home" "$root/docs/img"
"$build/whitted" -q --clamp final -s "$size" "$root/scenes/scene.txt" -o "$tmp/whitted.png"
"$build/scene2pov" -q -s "$size" "$root/scenes/scene.txt" -o "$tmp/scene.pov"
(cd "$tmp" && HOME="$tmp/home" povray scene.ini +WT2 -V >povray.log 2>&1)
"$build/imgcmp" --diff "$tmp/diff.png" "$tmp/whitted.png" "$tmp/scene.png" | tee "$tmp/imgcmp.txt"
montage -label 'whitted --clamp final' "$tmp/whitted.png" \
	-label 'POV-Ray 3.7 (scene2pov)' "$tmp/scene.png" \
	-label 'difference x32' "$tmp/diff.png" \
	-tile 3x1 -geometry +6+6 -background white -pointsize 14 \
	"$root/docs/img/validation.png"
echo "wrote docs/img/validation.png"
