#!/bin/bash
# The Windows build (make windows) under wine, against the Linux build:
# every scene of scenes/ and every shared course file rendered by
# whitted.exe and by whitted, byte for byte (PPM files: the pixels with
# nothing of the PNG encoder in between) or the same located error and
# exit status; the bonus options (--samples, --glass, --floor-texture)
# and BMP output on one scene each; whitted.exe compare's verdicts and
# causes on a mistaken image and a correct one (its JSON the Linux
# build's but for the file names); scene2pov.exe's POV-Ray scene; the
# plugins' clear refusal.  Usage: tests/windows/run.sh WINDIR LINUXDIR
SUITE=wintest
. "$(dirname "$0")/../cli/lib.sh"
WIN=$(cd "${1:-$ROOT/build/windows}" && pwd)
LIN=$(cd "${2:-$ROOT/build}" && pwd)
W=$LIN/whitted
WEXE=$WIN/whitted.exe
SIZE=72

if ! command -v wine >/dev/null 2>&1; then
	echo "$SUITE: NOT RUN: wine is not installed (make deps installs it)"
	echo "$SUITE: 0 passed, 1 failed"
	exit 1
fi
for f in "$WEXE" "$WIN/scene2pov.exe"; do
	if [ ! -f "$f" ]; then
		echo "$SUITE: $f is missing (make windows)"
		echo "$SUITE: 0 passed, 1 failed"
		exit 1
	fi
done
# A prefix of the suite's own, its server kept up between the runs.
export WINEPREFIX=$T/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
wine wineboot --init >/dev/null 2>&1
# Kept up until the suite ends (-p with no time): a server that timed
# out between two runs once reset the next client's connection.
wineserver -p >/dev/null 2>&1
trap 'wineserver -k >/dev/null 2>&1; rm -rf "$T"' EXIT

# wine_run PROGRAM ARGS...: PROGRAM under wine in $T/wd, its output in
# $T/wout and $T/werr, its status in wrc.  Wine itself failing to start
# the program (a status none of whitted's programs gives: they exit 0 to
# 3; or wine's "wine client error" when its server went away) once
# left no file and no word of why on a loaded machine: such a start is
# tried once more, and said.  So is a failure that printed nothing at
# all: whitted's programs never fail without a word (a clean-clone CI
# saw render-sphere exit 1 under wine with no output, once; the rerun
# passed).
wine_run() {
	local try
	for try in 1 2; do
		(cd "$T/wd" && wine "$@") >"$T/wout" 2>"$T/werr"
		wrc=$?
		if [ "$wrc" -le 3 ] && ! grep -q '^wine client error' "$T/werr" &&
			{ [ "$wrc" -eq 0 ] || [ -s "$T/werr" ] || [ -s "$T/wout" ]; }; then
			return
		fi
		echo "$SUITE: wine exited $wrc starting $(basename "$1") (try $try): $(tr -d '\r' <"$T/werr" | head -3)"
	done
}

# wrun ARGS...: whitted.exe in $T/wd, like run; wine's own "\r" line
# ends taken off its stdout and stderr.
wrun() {
	wine_run "$WEXE" "$@"
	sed -i 's/\r$//' "$T/wout" "$T/werr"
}

# same_render NAME SCENE ARGS...: both builds render SCENE with ARGS to a
# PPM; the same bytes, or the same error line and status.
same_render() {
	local name=$1 scene=$2
	shift 2
	clean_wd
	cp "$scene" "$T/wd/scene.txt"
	run -q -s $SIZE "$@" -o lin.ppm scene.txt
	wrun -q -s $SIZE "$@" -o win.ppm scene.txt
	if [ "$rc" -ne "$wrc" ]; then
		bad "$name" "exit $wrc under wine, $rc on Linux: $(head -1 "$T/werr")"
	elif [ "$rc" -ne 0 ]; then
		if cmp -s "$T/err" "$T/werr"; then ok; else
			bad "$name" "messages differ: '$(head -1 "$T/err")' / '$(head -1 "$T/werr")'"
		fi
		errors=$((errors + 1))
	elif cmp -s "$T/wd/lin.ppm" "$T/wd/win.ppm"; then
		ok
		same=$((same + 1))
	else
		bad "$name" "the images differ: $("$LIN/imgcmp" "$T/wd/lin.ppm" "$T/wd/win.ppm" 2>&1 | tail -1)"
	fi
}

wrun --version
check version-note grep -q 'Windows build: no plugins' "$T/wout"

same=0
errors=0
for s in "$ROOT"/scenes/*.txt "$DATA"/course-files/*.txt; do
	same_render "render-$(basename "$s" .txt)" "$s"
done
scenes_same=$same
same_render samples-glass "$ROOT/scenes/sphere.txt" --samples 2 --glass 2:1.5
same_render clamp-final-recursion "$ROOT/scenes/mirrors.txt" --clamp final -r 3 --eye 150,-150,80
same_render glass-nearfar "$ROOT/scenes/nearfar.txt" --glass 1 -r 5
clean_wd
cp "$ROOT"/tests/textures/white.bmp "$ROOT"/tests/textures/black.png "$T/wd/"
run -q -s $SIZE --floor-texture white.bmp,black.png -o lin.ppm "$ROOT/scenes/scene.txt"
wrun -q -s $SIZE --floor-texture white.bmp,black.png -o win.ppm "$(winepath -w "$ROOT/scenes/scene.txt" 2>/dev/null)"
check floor-texture cmp -s "$T/wd/lin.ppm" "$T/wd/win.ppm"
# BMP and PNG files: BMP byte for byte; a PNG's pixels (its deflate may
# differ where the Linux build has ISA-L).
run -q -s $SIZE -o lin.bmp "$ROOT/scenes/spot.txt"
wrun -q -s $SIZE -o win.bmp "$(winepath -w "$ROOT/scenes/spot.txt" 2>/dev/null)"
check bmp cmp -s "$T/wd/lin.bmp" "$T/wd/win.bmp"
wrun -q -s $SIZE -o win.png "$(winepath -w "$ROOT/scenes/spot.txt" 2>/dev/null)"
check png-pixels "$LIN/imgcmp" --min-psnr 999 "$T/wd/lin.bmp" "$T/wd/win.png" >/dev/null
# An output that exists is replaced (rename over it).
wrun -q -s 16 -o win.png "$(winepath -w "$ROOT/scenes/spot.txt" 2>/dev/null)"
check png-replaced [ "$wrc" -eq 0 ] && check png-replaced-size [ "$(png_width "$T/wd/win.png")" -eq 16 ]

# compare: the verdict, the causes, the whole JSON but its file names.
compare_same() {
	local name=$1 want=$2
	shift 2
	run compare --json "$@"
	cp "$T/out" "$T/lin.json"
	wrun compare --json "$@"
	if [ "$rc" -ne "$wrc" ]; then
		bad "$name" "exit $wrc under wine, $rc on Linux"
	elif ! grep -q "\"verdict\": \"$want\"" "$T/wout"; then
		bad "$name" "no verdict $want: $(head -c 300 "$T/wout")"
	elif ! cmp -s "$T/lin.json" "$T/wout"; then
		bad "$name" "the JSON differs: $(diff <(tr , '\n' <"$T/lin.json") <(tr , '\n' <"$T/wout") | head -6)"
	else
		ok
		verdicts=$((verdicts + 1))
	fi
}
verdicts=0
clean_wd
cp "$ROOT/scenes/scene.txt" "$T/wd/"
run -q -s 64 -r 1 -o flat.bmp scene.txt
run -q -s 64 -o right.bmp scene.txt
compare_same compare-recursion differs -s 64 scene.txt flat.bmp
grep -q '"first": \["no-reflections"\]' "$T/wout" && ok || bad compare-recursion-cause "$(grep -o '"first": [^]]*]' "$T/wout")"
compare_same compare-match match -s 64 scene.txt right.bmp
cp "$DATA/student-renders/sr12-scene.txt" "$DATA/student-renders/sr12.png" "$T/wd/"
compare_same compare-student differs --eye 100,100,50 --look 99,99,50 --no-camera-fit -s 96 sr12-scene.txt sr12.png

# scene2pov.exe: the same POV-Ray scene (its .ini names directories the
# Windows way).
clean_wd
cp "$ROOT/scenes/scene.txt" "$T/wd/"
(cd "$T/wd" && "$LIN/scene2pov" -q -o lin.pov scene.txt) >/dev/null 2>&1
wine_run "$WIN/scene2pov.exe" -q -o win.pov scene.txt
if [ "$wrc" -eq 0 ]; then ok; else
	bad scene2pov-status "exit $wrc: $(tr -d '\r' <"$T/werr" | head -3)"
fi
# (Its text files have Windows' line ends there.)
check scene2pov-crlf grep -q $'\r$' "$T/wd/win.pov"
check scene2pov cmp -s "$T/wd/lin.pov" <(tr -d '\r' <"$T/wd/win.pov")

# A plugin (a Linux shared object, whose ELF checks pass): refused with
# the Windows build's reason.
cp "$LIN/plugins/quad.so" "$T/wd/"
wrun --plugin quad.so scene.txt
check plugin-refused [ "$wrc" -eq 1 ]
check plugin-message grep -q 'not supported by the Windows build' "$T/werr"

echo "$SUITE: $scenes_same scenes byte-identical, $errors with the same located error, $verdicts compare verdicts the same"
finish
