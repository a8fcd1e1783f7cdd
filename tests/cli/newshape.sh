#!/bin/bash
# The proof that a new primitive is one new file under src/shapes/ plus one
# registry line: in a copy of the working tree, src/shapes/ball.c is
# src/shapes/sphere.c renamed (keyword "ball", table ball_ops, its static
# methods ball_*, no public constructor) and registry.c gets the line for
# ball_ops; nothing else changes.  The copy must build, pass `make unit
# clitest`, render a scene of balls byte for byte as the same scene of
# spheres, export it with scene2pov as the spheres are, and its viewer must
# draw a ball as it draws a sphere (the same screenshot under Xvfb, no note
# about a bounding box).
#
# The copy starts from the objects of build/ when they are there (make's
# timestamps then rebuild only what the two files change); NEWSHAPE_CLEAN=1
# builds it from nothing.  NEWSHAPE_UNIT=all runs every unit test instead of
# those of src/shapes/ and src/scenefile/ and any other that reads the
# registry (a minute more on two cores).
SUITE=newshape
. "$(dirname "$0")/lib.sh"
C=$T/tree
JOBS=${JOBS:-2}
# NEWSHAPE_KEEP=1 keeps the copy and the logs for a look afterwards.
[ -z "${NEWSHAPE_KEEP:-}" ] || trap 'echo "newshape: kept $T"' EXIT

# The copy: the working tree as it is (uncommitted work included), without
# .git, build/ and out/ (tests/data, the course files, travels with it).
mkdir -p "$C"
tar -C "$ROOT" --exclude=./.git --exclude=./build --exclude=./out --exclude='*.o' --exclude='*.d' \
	-cf - . | tar -C "$C" -xf -
[ -f "$C/Makefile" ] && [ -f "$C/src/shapes/sphere.c" ]
check "copied the working tree" [ $? -eq 0 ]
if [ -z "${NEWSHAPE_CLEAN:-}" ] && [ -d "$ROOT/build/san" ]; then
	tar -C "$ROOT" --exclude=./build/portable --exclude=./build/fuzz -cf - build | tar -C "$C" -xf -
fi

# ball.c: sphere.c with the keyword, the struct, the table and the static
# methods renamed, the messages' "sphere ..." too (not POV-Ray's "sphere {"),
# and the constructor made static (ball.c exports ball_ops and nothing else).
sed -E \
	-e 's/\bsphere_/ball_/g' \
	-e 's/\bstruct sphere\b/struct ball/g' \
	-e 's/"sphere"/"ball"/g' \
	-e 's/"sphere ([^{])/"ball \1/g' \
	-e 's/^(const )?struct shape \*ball_create\(/static struct shape *ball_create(/' \
	-e 's|^/\* The sphere:|/* The ball (a copy of the sphere, by tests/cli/newshape.sh):|' \
	"$C/src/shapes/sphere.c" >"$C/src/shapes/ball.c"
grep -q '^const struct shape_ops ball_ops = {' "$C/src/shapes/ball.c" &&
	grep -q '\.keyword = "ball"' "$C/src/shapes/ball.c"
check "ball.c defines ball_ops with keyword \"ball\"" [ $? -eq 0 ]

# registry.c: the one line X(sphere) of its list is repeated as X(ball).
cp "$C/src/shapes/registry.c" "$T/registry.orig"
sed -E '/^[[:space:]]*X\(sphere\)/{p;s/X\(sphere\)/X(ball)/}' "$T/registry.orig" >"$C/src/shapes/registry.c"
added=$(diff "$T/registry.orig" "$C/src/shapes/registry.c" | grep -c '^>')
check "registry.c: one line added for ball ($added)" [ "$added" -eq 1 ]

# Build the copy: the programs, then the unit tests and the CLI suite.
if ! make -C "$C" --no-print-directory -j"$JOBS" all >"$T/all.log" 2>&1; then
	bad "make all in the copy" "$(grep -m 5 -E 'error|Error' "$T/all.log")"
	finish
fi
ok
CW=$C/build/whitted
warn=$(grep -E '^src/shapes/(ball|registry)\.c:.*warning' "$T/all.log")
if [ -z "$warn" ]; then ok; else bad "ball.c and registry.c compile without warnings" "$warn"; fi
exports=$(nm -g --defined-only "$C/build/src/shapes/ball.o" 2>/dev/null | awk '{ print $3 }' | paste -sd ' ')
check "ball.o exports only ball_ops (exports: $exports)" [ "$exports" = ball_ops ]

if [ "${NEWSHAPE_UNIT:-}" = all ]; then
	unit_args=""
else
	# Those of src/shapes/ and src/scenefile/, and any other that looks
	# into the registry.
	unit_args="UNIT_BIN=$(cd "$C" && { ls tests/unit/shapes/test_*.c tests/unit/scenefile/test_*.c
		grep -l -E 'shape_ops_(all|find)|shape_keywords' tests/unit/*/test_*.c; } | sort -u |
		sed 's|^tests/\(.*\)\.c$|build/san/tests/\1|' | paste -sd ' ')"
fi
for suite in unit clitest; do
	if [ "$suite" = unit ] && [ -n "$unit_args" ]; then
		make -C "$C" --no-print-directory -j"$JOBS" "$unit_args" unit >"$T/$suite.log" 2>&1
	else
		make -C "$C" --no-print-directory -j"$JOBS" "$suite" >"$T/$suite.log" 2>&1
	fi
	status=$?
	summary=$(grep -E "^$suite: [0-9]+ passed" "$T/$suite.log" | tail -1)
	echo "newshape: the copy's $suite: ${summary#"$suite: "}"
	if [ "$status" -eq 0 ]; then ok
	else bad "make $suite in the copy (ball registered)" \
		"$(grep -m 8 -E '^FAIL|\[  FAILED  \]|\[  ERROR   \]|error:|Error' "$T/$suite.log")"
	fi
done

# Scenes of balls render as the same scenes of spheres, byte for byte; the
# tree without ball.c refuses them.
to_balls() { sed -E 's/^([[:space:]]*)sphere([[:space:]]|$)/\1ball\2/' "$1"; }
mkdir -p "$T/s" "$T/b"
n_scenes=0
for f in "$ROOT"/scenes/*.txt "$DATA/real-scenes/anachor.txt" "$DATA/real-scenes/pistachio102.txt"; do
	grep -qE '^[[:space:]]*sphere([[:space:]]|$)' "$f" || continue
	name=${f##*/}
	n_scenes=$((n_scenes + 1))
	cp "$f" "$T/s/$name"
	to_balls "$f" >"$T/b/$name"
	"$CW" -q -s 48 -o "$T/s/${name%.txt}.ppm" "$T/s/$name" 2>"$T/err.s"
	rs=$?
	"$CW" -q -s 48 -o "$T/b/${name%.txt}.ppm" "$T/b/$name" 2>"$T/err.b"
	rb=$?
	if [ "$rs" -ne 0 ] || [ "$rb" -ne 0 ]; then
		bad "render $name" "sphere: exit $rs $(cat "$T/err.s"); ball: exit $rb $(cat "$T/err.b")"
	else
		check "$name with balls is byte-identical to spheres" cmp -s "$T/s/${name%.txt}.ppm" "$T/b/${name%.txt}.ppm"
	fi
done
check "rendered scenes with spheres ($n_scenes)" [ "$n_scenes" -ge 4 ]
# One ball among spheres.
sed -E '0,/^([[:space:]]*)sphere([[:space:]]|$)/s//\1ball\2/' "$ROOT/scenes/scene.txt" >"$T/b/mixed.txt"
"$CW" -q -s 48 -o "$T/b/mixed.ppm" "$T/b/mixed.txt" 2>"$T/err.b" &&
	cmp -s "$T/b/mixed.ppm" "$T/s/scene.ppm"
check "scene.txt with one ball among the spheres is byte-identical ($(cat "$T/err.b"))" [ $? -eq 0 ]
"$W" -q -s 8 -o "$T/b/orig.ppm" "$T/b/scene.txt" 2>"$T/err.b"
[ $? -eq 1 ] && grep -q "unknown object 'ball'" "$T/err.b"
check "the tree's own whitted refuses ball ($(cat "$T/err.b"))" [ $? -eq 0 ]
# The parser's messages come from the new file and the registry.
printf '1\n8\n1\nball\n0 0 0\n-2\n1 1 1\n0 0 0 0 0\n0\n' >"$T/b/neg.txt"
"$CW" -q -o "$T/b/neg.ppm" "$T/b/neg.txt" 2>"$T/err.b"
[ $? -eq 1 ] && grep -q 'neg.txt:6:[0-9]*: error: ball radius must be > 0' "$T/err.b"
check "a ball's bad radius is an error of ball ($(cat "$T/err.b"))" [ $? -eq 0 ]
printf '1\n8\n1\ncube\n0\n' >"$T/b/cube.txt"
"$CW" -q -o "$T/b/cube.ppm" "$T/b/cube.txt" 2>"$T/err.b"
check "the known objects list ball ($(cat "$T/err.b"))" grep -q "known objects: .*ball" "$T/err.b"

# scene2pov writes a ball as it writes a sphere.
if (cd "$T/s" && "$C/build/scene2pov" -q -s 48 scene.txt) >/dev/null 2>"$T/err.s" &&
	(cd "$T/b" && "$C/build/scene2pov" -q -s 48 scene.txt) >/dev/null 2>"$T/err.b"; then
	ok
	check "scene2pov: the balls' scene.pov is the spheres'" \
		cmp -s <(grep -v '^// Written by' "$T/s/scene.pov") <(grep -v '^// Written by' "$T/b/scene.pov")
	check "scene2pov: the balls' scene.ini is the spheres' (but for their directories)" \
		cmp -s <(sed "s|$(cd "$T/s" && pwd -P)|DIR|" "$T/s/scene.ini") \
		<(sed "s|$(cd "$T/b" && pwd -P)|DIR|" "$T/b/scene.ini")
	check "scene2pov: scene.pov has the spheres" [ "$(grep -c '^sphere {' "$T/b/scene.pov")" -eq 3 ]
else
	bad "scene2pov exports the balls" "$(cat "$T/err.s" "$T/err.b")"
fi

# The viewer: a ball is drawn as a sphere is (one object, no floor, the same
# screenshot), and nothing says it is drawn as a bounding box.
viewer_check() {
	local V=$C/build/whitted-view tool xvfb_pid="" vpid="" win="" n
	if [ ! -x "$V" ]; then
		bad viewer "the copy's whitted-view is not built (freeglut3-dev is missing: make deps)"
		return
	fi
	for tool in Xvfb xdotool import convert compare; do
		command -v "$tool" >/dev/null 2>&1 || { bad viewer "$tool is missing (make deps)"; return; }
	done
	mkdir -p "$T/vs" "$T/vb"
	printf '1\n64\n1\nsphere\n0 0 10\n50\n0.1 0.9 0.2\n0.4 0.5 0.2 0\n10\n1\n0 -200 100\n1 1 1\n' >"$T/vs/one.txt"
	to_balls "$T/vs/one.txt" >"$T/vb/one.txt"
	Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp -noreset 3>"$T/display" 2>"$T/xvfb.log" &
	xvfb_pid=$!
	for n in $(seq 100); do [ -s "$T/display" ] && break; sleep 0.1; done
	if [ ! -s "$T/display" ]; then
		bad viewer "Xvfb did not start: $(cat "$T/xvfb.log")"
		kill "$xvfb_pid" 2>/dev/null
		return
	fi
	export DISPLAY=:$(cat "$T/display")
	for n in $(seq 100); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.1; done
	for d in vs vb; do
		(cd "$T/$d" && exec "$V" --no-floor one.txt) >"$T/$d/stdout" 2>"$T/$d/stderr" &
		vpid=$!
		win=""
		for n in $(seq 200); do
			win=$(xdotool search --name '^whitted: one\.txt' 2>/dev/null | head -n 1)
			[ -n "$win" ] && break
			kill -0 "$vpid" 2>/dev/null || break
			sleep 0.1
		done
		if [ -z "$win" ]; then
			bad "viewer ($d)" "no window: $(cat "$T/$d/stderr")"
			kill "$vpid" 2>/dev/null
			continue
		fi
		xdotool windowmove --sync "$win" 0 0 2>/dev/null || xdotool windowmove "$win" 0 0
		sleep 0.5
		import -window root "$T/$d/screen.png" 2>"$T/$d/import.err" &&
			convert "$T/$d/screen.png" -crop 500x500+0+0 +repage "$T/$d/window.png" 2>>"$T/$d/import.err"
		check "viewer ($d): screenshot ($(cat "$T/$d/import.err"))" [ -s "$T/$d/window.png" ]
		xdotool key --window "$win" q 2>/dev/null
		for n in $(seq 100); do kill -0 "$vpid" 2>/dev/null || break; sleep 0.1; done
		kill "$vpid" 2>/dev/null
		wait "$vpid" 2>/dev/null
	done
	kill "$xvfb_pid" 2>/dev/null
	wait "$xvfb_pid" 2>/dev/null
	[ -s "$T/vs/window.png" ] && [ -s "$T/vb/window.png" ] || return
	green=$(convert "$T/vb/window.png" -depth 8 rgb:- | od -An -v -tu1 -w3 |
		awk '$2 > 60 && $1 < 0.6 * $2 && $3 < 0.6 * $2 { n++ } END { print n + 0 }')
	check "viewer: the ball is drawn ($green green pixels, more than 2000)" [ "$green" -gt 2000 ]
	differ=$(compare -metric AE "$T/vs/window.png" "$T/vb/window.png" null: 2>&1)
	check "viewer: the ball's window is the sphere's ($differ pixels differ)" [ "$differ" = 0 ]
	notes=$(grep -iE 'bounding box|ball' "$T/vb/stderr")
	if [ -z "$notes" ]; then ok; else bad "viewer: a note about the ball" "$notes"; fi
	check "viewer: the same messages for the ball as for the sphere" cmp -s "$T/vs/stderr" "$T/vb/stderr"
}
viewer_check
finish
