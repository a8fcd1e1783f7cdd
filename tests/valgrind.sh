#!/bin/bash
# The CLI under valgrind (memcheck, every leak kind an error) on every scene
# of scenes/, the real scene files, every malformed file of tests/errors and
# a few command-line and output errors, at a small size with two threads.
# Each run must end with its usual status (0 or 1 or 2), never valgrind's 99.
SUITE=valgrind
. "$(dirname "$0")/cli/lib.sh"
if ! command -v valgrind >/dev/null; then
	echo "valgrind: valgrind is not installed"
	echo "valgrind: 0 passed, 1 failed"
	exit 1
fi
VG="valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all --error-exitcode=99"

# vg NAME WANT_RC ARGS...: whitted under valgrind in $T/wd.
vg() {
	local name=$1 want=$2
	shift 2
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
for f in "$SHARED"/real-scenes/*.txt; do
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
check "errors: at least 50 files" [ "$n" -ge 50 ]
vg "missing scene" 1 -o out.png "$T/nosuch.txt"
vg "scene is a directory" 1 -o out.png "$T"
vg "bad option value" 2 -s 12x "$ROOT/scenes/scene.txt"
vg "unknown option" 2 --bogus "$ROOT/scenes/scene.txt"
vg "unknown format" 2 -o x.jpg "$ROOT/scenes/scene.txt"
vg "camera error" 2 --eye 0,0,0 -o out.png "$ROOT/scenes/scene.txt"
vg "missing output directory" 1 -s 8 -o nodir/x.png "$ROOT/scenes/scene.txt"
vg "full device" 1 -s 8 -o /dev/full --format png "$ROOT/scenes/scene.txt"
vg "help" 0 --help

# The failure paths of the write and of an interrupted render.
for f in png bmp ppm; do
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

finish
