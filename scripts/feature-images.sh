#!/bin/sh
# Makes README's pictures of issue 14's features, each whitted beside
# POV-Ray 3.7 rendering scene2pov's export, into docs/img (or DIR):
#   feature-samples.png  one ray a pixel | --samples 4 | POV-Ray at 4x, box-reduced
#   feature-texture.png  --floor-texture (BMP on white cells, PNG on black) | POV-Ray
#   feature-glass.png    --glass (a sphere, a cube, a prism) | POV-Ray
# and prints the comparisons.  Needs povray and ImageMagick (convert).
# Usage: scripts/feature-images.sh [DIR]
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$top/docs/img}
B=$top/build
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/home"
S=240

# pov NAME SIZE ARGS...: POV-Ray's image of scene2pov's export in $tmp/NAME.png.
pov() {
	name=$1 size=$2
	shift 2
	"$B/scene2pov" -q -s "$size" -o "$tmp/$name.pov" "$@"
	(cd "$tmp" && HOME="$tmp/home" povray "$name.ini" +WT2 -V >/dev/null 2>&1)
}
side() { convert "$@" -background black -splice 4x0 +append -chop 4x0 "$tmp/row.png" && cat "$tmp/row.png"; }

# Antialiasing: the course example's edges, seen closer.
view="--eye 25,-90,40 --look 10,0,25 --fov 50"
# shellcheck disable=SC2086
"$B/whitted" -q --clamp final -s $S $view -o "$tmp/s1.png" "$top/scenes/scene.txt"
# shellcheck disable=SC2086
"$B/whitted" -q --clamp final -s $S --samples 4 $view -o "$tmp/s4.png" "$top/scenes/scene.txt"
# shellcheck disable=SC2086
pov samples $((4 * S)) $view "$top/scenes/scene.txt"
"$B/imgfilter" box 4 "$tmp/samples.png" "$tmp/samples-box.png"
echo "samples: $("$B/imgcmp" "$tmp/s4.png" "$tmp/samples-box.png" 2>&1 | head -1)"
side "$tmp/s1.png" "$tmp/s4.png" "$tmp/samples-box.png" >"$out/feature-samples.png"

# Textured floor: the test textures on the course example, from above.
t="$top/tests/textures"
tex="--floor-texture $t/white.bmp,$t/black.png --eye 60,-150,110 --look 0,0,10"
# shellcheck disable=SC2086
"$B/whitted" -q --clamp final -s $S $tex -o "$tmp/t.png" "$top/scenes/scene.txt"
# shellcheck disable=SC2086
pov texture $S $tex "$top/scenes/scene.txt"
echo "texture: $("$B/imgcmp" "$tmp/t.png" "$tmp/texture.png" 2>&1 | head -1)"
side "$tmp/t.png" "$tmp/texture.png" >"$out/feature-texture.png"

# Glass: the sphere scene's middle sphere, the nearfar file's cube, the prism.
"$B/whitted" -q --clamp final -s $S -r 6 --glass 2:1.5:0.8 --eye 0,-110,45 --look 0,0,30 -o "$tmp/g1.png" "$top/scenes/sphere.txt"
pov glass1 $S -r 6 --glass 2:1.5:0.8 --eye 0,-110,45 --look 0,0,30 "$top/scenes/sphere.txt"
"$B/whitted" -q --clamp final -s $S -r 6 --glass 1:1.5:0.8 -o "$tmp/g2.png" "$top/scenes/nearfar.txt"
pov glass2 $S -r 6 --glass 1:1.5:0.8 "$top/scenes/nearfar.txt"
"$B/whitted" -q --clamp final -s $S -r 6 --glass 1:1.5:0.85 -o "$tmp/g3.png" \
	"$top/tests/scenes/glass-prism.txt"
pov glass3 $S -r 6 --glass 1:1.5:0.85 "$top/tests/scenes/glass-prism.txt"
for k in 1 2 3; do
	echo "glass $k: $("$B/imgcmp" "$tmp/g$k.png" "$tmp/glass$k.png" 2>&1 | head -1)"
done
side "$tmp/g1.png" "$tmp/g2.png" "$tmp/g3.png" >"$tmp/gw.png"
side "$tmp/glass1.png" "$tmp/glass2.png" "$tmp/glass3.png" >"$tmp/gp.png"
convert "$tmp/gw.png" "$tmp/gp.png" -background black -splice 0x4 -append -chop 0x4 "$out/feature-glass.png"
