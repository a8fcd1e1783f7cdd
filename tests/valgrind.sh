#!/bin/bash
# The CLI under valgrind (memcheck, every leak kind an error) on every scene
# of scenes/, the real scene files, every malformed file of tests/errors and
# a few command-line and output errors, hostile images, glass trees and a
# FIFO as an input, at a small size with two threads.
# Each run must end with its usual status (0 or 1 or 2), never valgrind's 99.
SUITE=valgrind
. "$(dirname "$0")/cli/lib.sh"
if ! command -v valgrind >/dev/null; then
	echo "valgrind: valgrind is not installed"
	echo "valgrind: 0 passed, 1 failed, 0 skipped"
	exit 1
fi
VG="valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all --error-exitcode=99"

# The cases in shards run at once, one a core (at most VG_SHARDS, default
# 2): memcheck runs a program's threads one at a time, so one run keeps
# one core busy.  Each shard is this script again with VG_SHARD set; it
# runs every VG_SHARDS-th case (mine), and this run adds up their counts.
if [ -z "${VG_SHARD:-}" ]; then
	shards=$(nproc 2>/dev/null || echo 1)
	want=${VG_SHARDS:-2}
	[ "$want" -ge 1 ] 2>/dev/null || want=1
	[ "$shards" -gt "$want" ] && shards=$want
	pids=""
	trap 'kill $pids 2>/dev/null; exit 130' INT TERM
	for i in $(seq 0 $((shards - 1))); do
		VG_SHARD=$i VG_SHARDS=$shards "$0" "$@" >"$T/shard$i" 2>&1 &
		pids="$pids $!"
	done
	wait
	for i in $(seq 0 $((shards - 1))); do
		grep -v "^$SUITE: [0-9]* passed" "$T/shard$i"
		line=$(grep "^$SUITE: [0-9]* passed, [0-9]* failed, [0-9]* skipped" "$T/shard$i" | tail -1)
		if [ -z "$line" ]; then
			bad "shard $i" "ended without its summary"
			continue
		fi
		set -- $(echo "$line" | sed 's/^[^:]*: \([0-9]*\) passed, \([0-9]*\) failed, \([0-9]*\) skipped.*/\1 \2 \3/')
		pass=$((pass + $1))
		fail=$((fail + $2))
		skipped=$((skipped + $3))
		why=$(echo "$line" | sed -n 's/^[^:]*: [0-9]* passed, [0-9]* failed, [0-9]* skipped: //p')
		[ -n "$why" ] && skip_why=${skip_why:+$skip_why; }$why
	done
	echo "($SUITE ran in $shards shards at once)"
	finish
fi
[ "${VG_SHARDS:-0}" -ge 1 ] 2>/dev/null || VG_SHARDS=1
vg_case=0
mine() {
	vg_case=$((vg_case + 1))
	[ $(((vg_case - 1) % VG_SHARDS)) -eq "$VG_SHARD" ]
}

# vg NAME WANT_RC ARGS...: whitted under valgrind in $T/wd.
vg() {
	local name=$1 want=$2
	shift 2
	mine || return 0
	clean_wd
	(cd "$T/wd" && $VG "$W" "$@") >"$T/out" 2>"$T/err"
	local rc=$?
	if [ "$rc" -ne "$want" ]; then
		bad "$name" "exit $rc, expected $want"
		sed 's/^/    /' "$T/err" | head -40
	elif grep -q '^==[0-9]*==' "$T/err"; then
		bad "$name" "valgrind reported:"
		sed 's/^/    /' "$T/err" | head -40
	else
		ok
	fi
}

for f in "$ROOT"/scenes/*.txt; do
	vg "scenes/$(basename "$f")" 0 -s 24 -j 2 -o out.png "$f"
done
vg "scene.txt bmp" 0 -s 16 -j 2 -o out.bmp "$ROOT/scenes/scene.txt"
vg "scene.txt ppm to stdout" 0 -s 16 -j 1 -o /dev/stdout --format ppm "$ROOT/scenes/scene.txt"
vg "scene.txt from stdin" 0 -s 16 -o out.png - <"$ROOT/scenes/scene.txt"
vg "test scene, final clamp, no floor" 0 -s 16 --test-scene --clamp final --no-floor -o out.png
for f in "$DATA"/real-scenes/*.txt; do
	case $(basename "$f") in
	apurbostarry.txt | nazmultakbir.txt) want=1 ;;
	*) want=0 ;;
	esac
	vg "real-scenes/$(basename "$f")" $want -s 16 -j 2 -o out.png "$f"
done
n=0
for f in "$ROOT"/tests/errors/*.txt; do
	vg "errors/$(basename "$f")" 1 -s 16 -o out.png "$f"
	n=$((n + 1))
done
! mine || check "errors: at least 50 files" [ "$n" -ge 50 ]
vg "missing scene" 1 -o out.png "$T/nosuch.txt"
vg "scene is a directory" 1 -o out.png "$T"
vg "bad option value" 2 -s 12x "$ROOT/scenes/scene.txt"
vg "unknown option" 2 --bogus "$ROOT/scenes/scene.txt"
vg "unknown format" 2 -o x.jpg "$ROOT/scenes/scene.txt"
vg "camera error" 2 --eye 0,0,0 -o out.png "$ROOT/scenes/scene.txt"
vg "missing output directory" 1 -s 8 -o nodir/x.png "$ROOT/scenes/scene.txt"
vg "full device" 1 -s 8 -o /dev/full --format png "$ROOT/scenes/scene.txt"
# The plugins: loaded, their shapes rendered, unloaded at exit; and a
# load that fails after others were loaded.
PL=$ROOT/build/plugins
for p in quad cylinder torus; do
	vg "plugin $p" 0 -s 20 -j 2 --plugin "$PL/$p.so" -o out.png "$ROOT/scenes/plugins/$p.txt"
done
vg "plugin loaded twice, then a missing one" 1 -s 8 --plugin "$PL/quad.so" --plugin "$PL/quad.so" --plugin "$T/nosuch.so" \
	-o out.png "$ROOT/scenes/plugins/quad.txt"
for i in $(seq 40); do echo "not an ELF file"; done >"$T/text.so"
vg "a good plugin, then a file that is no shared object" 1 -s 8 --plugin "$PL/quad.so" --plugin "$T/text.so" \
	-o out.png "$ROOT/scenes/plugins/quad.txt"
mkdir -p "$T/pldir" && cp "$PL/quad.so" "$T/pldir/a.so" && cp "$T/text.so" "$T/pldir/b.so"
WHITTED_PLUGIN_PATH="$T/pldir" vg "WHITTED_PLUGIN_PATH: a good a.so, a stray b.so" 1 -s 8 -o out.png \
	"$ROOT/scenes/plugins/quad.txt"
vg "--list-shapes with a missing plugin" 1 --plugin "$PL/torus.so" --list-shapes --plugin "$T/nosuch.so"
vg "help" 0 --help
# Issue 14's options: antialiasing, textured floors (and a texture that
# cannot be read), glass.
TEX="$ROOT/tests/textures"
vg "samples 3" 0 -s 12 -j 2 --samples 3 -o out.png "$ROOT/scenes/mirrors.txt"
vg "floor texture bmp,png" 0 -s 16 -j 2 --floor-texture "$TEX/white.bmp,$TEX/black.png" -o out.png \
	"$ROOT/scenes/nearfar.txt"
vg "floor texture missing" 1 -s 16 --floor-texture "$TEX/white.bmp,$T/nosuch.png" -o out.png \
	"$ROOT/scenes/scene.txt"
vg "floor texture not an image" 1 -s 16 --floor-texture "$ROOT/scenes/scene.txt" -o out.png \
	"$ROOT/scenes/scene.txt"
vg "glass" 0 -s 16 -j 2 -r 5 --glass 1:1.5:0.8,2 -o out.png "$ROOT/scenes/nearfar.txt"
vg "glass beyond the objects" 2 -s 16 --glass 9 -o out.png "$ROOT/scenes/sphere.txt"
vg "glass nested" 0 -s 16 -j 2 -r 6 --glass 1:1.5:0.8,2:1.2:0.7 -o out.png \
	"$ROOT/tests/scenes/glass-nested.txt"
vg "glass on a triangle (a note)" 0 -s 16 --glass 1 -o out.png "$ROOT/scenes/triangle.txt"
vg "glass named twice" 2 -s 16 --glass 2,2:1.2 -o out.png "$ROOT/scenes/sphere.txt"
# scene2pov writing the textures' PNGs, and failing after them (OUT.pov a
# directory: they are removed).
for out in out.pov dir.pov; do
	mine || continue
	clean_wd
	mkdir "$T/wd/dir.pov"
	(cd "$T/wd" && $VG "$ROOT/build/scene2pov" -q -s 16 \
		--floor-texture "$TEX/white-xrgb.bmp,$TEX/black-topdown.bmp" -o "$out" \
		"$ROOT/scenes/scene.txt") >"$T/out" 2>"$T/err"
	rc=$?
	want=0
	[ "$out" = dir.pov ] && want=1
	if [ "$rc" -ne "$want" ] || grep -q '^==[0-9]*==' "$T/err"; then
		bad "scene2pov textures -o $out" "exit $rc, expected $want"
		sed 's/^/    /' "$T/err" | head -40
	elif [ "$want" = 1 ] && [ -n "$(find "$T/wd" -name '*.png')" ]; then
		bad "scene2pov textures -o $out" "left $(find "$T/wd" -name '*.png')"
	else
		ok
	fi
done

# The failure paths of the write and of an interrupted render.
for f in png bmp ppm; do
	mine || continue
	clean_wd
	(ulimit -f 1 && cd "$T/wd" && exec $VG "$W" -s 128 -o "x.$f" "$ROOT/scenes/scene.txt") >"$T/out" 2>"$T/err"
	rc=$?
	if [ "$rc" -ne 1 ] || grep -q '^==[0-9]*==' "$T/err" || ! wd_empty; then
		bad "file-size limit $f" "exit $rc, left: $(wd_files)"
		sed 's/^/    /' "$T/err" | head -40
	else
		ok
	fi
done
# compare and grade: a match, a mistake ranked on a sample (72 pixels: the
# sample, then the best causes in full), every kind of unreadable input,
# and a report.
CI=$T/compare-images
mkdir -p "$CI"
"$W" -q -s 72 -o "$CI/ref.ppm" "$ROOT/scenes/scene.txt"
"$W" -q -s 72 -o "$CI/other.png" "$ROOT/scenes/mirrors.txt"
python3 "$ROOT/tests/cli/make_images.py" "$CI/ref.ppm" "$CI"
vg "compare match" 0 compare -q -s 72 -j 2 "$ROOT/scenes/scene.txt" "$CI/bmp24.bmp"
vg "compare differs, --diff, --json" 3 compare -q -s 72 -j 2 --json --no-camera-fit --diff d.png "$ROOT/scenes/scene.txt" "$CI/other.png"
# An image of another scene: no camera comes near, so the fit's every pass
# runs (the plain one, then with gamma and with the tiles swapped, each
# from the coarse search on), and the refits with causes.  At 16 pixels:
# the fit's cost hardly shrinks with the image, and under valgrind each
# pass is minutes at 72.
"$W" -q -s 16 -o "$CI/other16.png" "$ROOT/scenes/mirrors.txt"
vg "compare another scene, the camera fit's passes" 3 compare -q -s 16 -j 2 --json "$ROOT/scenes/scene.txt" "$CI/other16.png"
for f in truncated.bmp truncated.ppm truncated-ascii.ppm bad-sample.ppm empty.png text.png rle.bmp; do
	vg "compare $f" 1 compare -q -s 72 -j 2 "$ROOT/scenes/scene.txt" "$CI/$f"
done
vg "compare another size" 0 compare -q -s 40 "$ROOT/scenes/scene.txt" "$CI/ascii.ppm"
# The floor's own finish with the highlight left white: the finish fitted,
# the causes ranked, the finish fitted again with the highlight, ranked
# again (the independent renderer's image).
python3 "$ROOT/tests/reference/ref_render.py" "$ROOT/scenes/scene.txt" "$CI/finish.ppm" --size 48 \
	--floor-finish 0.25,0.25,0.25,0.25,15 --mistake white-highlight
vg "compare the floor's finish and a mistake" 3 compare -q -s 48 -j 2 --json --no-camera-fit "$ROOT/scenes/scene.txt" "$CI/finish.ppm"
# A file the strict reading refuses, read again by the count-driven rule
# (the held notes), and one that neither reading takes.
vg "compare strict refused" 3 compare -s 72 --no-camera-fit "$DATA/course-files/thr0m3l.txt" "$CI/bmp24.bmp"
printf '1\n72\n\nsphere 0 0\n' >"$T/unread.txt"
vg "compare unreadable scene" 1 compare -s 72 "$T/unread.txt" "$CI/bmp24.bmp"
# The camera fit, the ties, the objects and grade's folders and zips.
"$W" -q -s 48 --eye 30,-180,40 -o "$CI/moved.png" "$ROOT/scenes/scene.txt"
vg "compare another camera" 0 compare -q -s 48 -j 2 --json --diff d2.png "$ROOT/scenes/scene.txt" "$CI/moved.png"
mkdir -p "$CI/class/Ada_1_assignsubmission_file_"
cp "$CI/moved.png" "$CI/bmp24.bmp" "$CI/class/Ada_1_assignsubmission_file_/"
(cd "$CI" && python3 -c 'import zipfile; z = zipfile.ZipFile("class.zip", "w"); z.write("class/Ada_1_assignsubmission_file_/bmp24.bmp"); z.close()')
vg "grade a folder and a zip" 3 grade -q -s 72 -j 2 --no-camera-fit --scene "$ROOT/scenes/scene.txt" --scene "$ROOT/scenes/mirrors.txt" \
	--csv r2.csv -o r2.html "$CI/class" "$CI/class.zip"
vg "grade with a report" 3 grade -q -s 72 -j 2 --no-camera-fit --scene "$ROOT/scenes/scene.txt" -o r.html --csv r.csv \
	"$CI/topdown.bmp" "$CI/other.png" "$CI/truncated.bmp"
# explain: glass and samples as JSON, a located scene error, a pixel
# outside the image.
vg "explain glass samples" 0 explain -q -s 32 --glass 2 --samples 2 --json "$ROOT/scenes/sphere.txt" 10,12
vg "explain bad scene" 1 explain -q "$DATA/course-files/thr0m3l.txt" 1,1
vg "explain outside" 2 explain -q -s 8 "$ROOT/scenes/scene.txt" 9,1
# Hostile inputs of the sturdiness pass: images (hostile_png.py) as a
# texture and compared, a tree of glass rays over --max-rays, the glass
# sphere at recursion 256, a FIFO as a texture.
python3 "$ROOT/tests/tools/hostile_png.py" "$T/hp" >/dev/null
for f in bomb.png bad-crc.png short-data.png huge-30000.png claims-16384.png truncated.png jpeg.jpg; do
	vg "texture $f" 1 -s 8 --floor-texture "$T/hp/$f" -o out.png "$ROOT/scenes/scene.txt"
	vg "compared $f" 1 compare -q -s 8 "$ROOT/scenes/scene.txt" "$T/hp/$f"
done
printf '256 32 2 sphere -31 0 30 30 0.9 0.9 1 0.1 0.3 0.3 1 8 sphere 31 0 30 30 0.9 0.9 1 0.1 0.3 0.3 1 8 1 -100 -150 200 1 1 1\n' >"$T/tree.txt"
vg "a glass tree over --max-rays" 1 -j 2 --glass 1:1.5:0.9,2:1.5:0.9 --max-rays 3000 -o out.png "$T/tree.txt"
printf '256 32 1 sphere 0 0 30 30 0.9 0.9 1 0.1 0.3 0.3 0.5 8 1 -100 -150 200 1 1 1\n' >"$T/sphere256.txt"
vg "a glass sphere at recursion 256" 0 -j 2 --glass 1 -o out.png "$T/sphere256.txt"
rm -f "$T/fifo.png" && mkfifo "$T/fifo.png"
vg "a FIFO as a texture" 1 -s 8 --floor-texture "$T/fifo.png" -o out.png "$ROOT/scenes/scene.txt"

if mine; then
	clean_wd
	(cd "$T/wd" && exec $VG "$W" -s 1000 -j 2 -o x.png "$ROOT/scenes/scene.txt") >"$T/out" 2>"$T/err" &
	pid=$!
	sleep 3
	kill -s INT $pid
	sent=$?
	wait $pid
	rc=$?
	if [ "$sent" -ne 0 ] || [ "$rc" -ne 130 ] || grep -q '^==[0-9]*==' "$T/err" || ! wd_empty; then
		bad "SIGINT during a render" "signal sent: $sent, exit $rc, left: $(wd_files)"
		sed 's/^/    /' "$T/err" | head -40
	else
		ok
	fi
fi

finish
