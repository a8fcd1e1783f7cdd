#!/bin/sh
# End-to-end test of whitted-view under Xvfb, as a new user would use it:
# start it on a scene, press movement keys, press 0, then check that the
# printed command renders the capture exactly (byte for byte and pixel for
# pixel), that a screenshot of the window shows what the scene has, and
# that the window's projection is the tracer's camera (the screenshot
# against the command rendered at the window's size).  Four scenes: the
# course example (classic), a spot-dialect course file (a spotlight, drawn
# as a cone and lighting as a GL spotlight), a nearfar one (near plane,
# aspect 1.7778, the infinite checkerboard, a cube and a pyramid) and a
# nearfar scene whose near plane hides a cube and cuts a sphere.  Also:
# no display, SIGINT and SIGTERM during a capture (nothing left), and a
# plugin's failing tessellate.
# Usage: tests/viewer/e2e.sh BUILD/whitted-view BUILD/whitted
# Needs Xvfb, xdotool and ImageMagick (import, convert, compare), and the
# course files of tests/data.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
viewer=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
whitted=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
data=$root/tests/data
scene=$root/scenes/scene.txt
spot_scene=$data/course-files/munzer2.txt
nearfar_scene=$data/course-files/akib1689.txt
near_scene=$root/tests/scenes/near-plane.txt
pass=0 fail=0
xvfb_pid="" viewer_pid=""
tmp=$(mktemp -d "${TMPDIR:-/tmp}/whitted-view-e2e.XXXXXX")

cleanup() {
	[ -n "$viewer_pid" ] && kill "$viewer_pid" 2>/dev/null
	[ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null
	wait 2>/dev/null
	rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

ok() { pass=$((pass + 1)); echo "  ok   $1"; }
bad() { fail=$((fail + 1)); echo "  FAIL $1"; }
check() { if [ "$1" = 0 ]; then ok "$2"; else bad "$2"; fi; }
finish() {
	echo "viewer-e2e: $pass passed, $fail failed, 0 skipped"
	[ "$fail" = 0 ]
	exit
}
# Waits up to $1 tenths of a second for the command in $2 to succeed.
wait_for() {
	n=$1
	shift
	while [ "$n" -gt 0 ]; do
		eval "$1" && return 0
		sleep 0.1
		n=$((n - 1))
	done
	return 1
}

for tool in Xvfb xdotool import convert compare; do
	command -v "$tool" >/dev/null 2>&1 || { echo "viewer-e2e: FAIL: $tool is missing"; exit 1; }
done
for f in "$spot_scene" "$nearfar_scene" "$near_scene"; do
	[ -f "$f" ] || { echo "viewer-e2e: FAIL: $f is missing"; exit 1; }
done
cd "$tmp" || exit 1

# Without a display: one clear line, exit 1 (not freeglut's "failed to open
# display ''"), and an unreachable display says what to do too.
(unset DISPLAY; "$viewer" "$scene" >/dev/null 2>nodisplay.txt)
[ $? = 1 ] && grep -q "^whitted-view: error: no display: DISPLAY is not set (whitted-view needs an X display" nodisplay.txt &&
	[ "$(grep -vc 'note: ' nodisplay.txt)" = 1 ]
check $? "no DISPLAY: exit 1 and one line ($(grep -v 'note: ' nodisplay.txt))"
DISPLAY=:4097 "$viewer" "$scene" >/dev/null 2>nodisplay.txt
[ $? = 1 ] && grep -q "^whitted-view: error: failed to open display ':4097' (whitted-view needs an X display" nodisplay.txt
check $? "an unreachable display: exit 1 and what to do ($(grep -v 'note: ' nodisplay.txt))"

# A display of our own: -displayfd picks a free number and writes it once
# the server is ready.
# -noreset: without it the server resets whenever its last client leaves
# (each viewer that quits, each xdotool call), and a client that connects
# during the reset is refused.
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp -noreset 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb_pid=$!
if ! wait_for 100 '[ -s "$tmp/display" ]'; then
	bad "Xvfb started (log: $(cat "$tmp/xvfb.log"))"
	finish
fi
DISPLAY=:$(cat "$tmp/display")
export DISPLAY
if ! wait_for 100 'xdotool getmouselocation >/dev/null 2>&1'; then
	bad "Xvfb on $DISPLAY accepts clients (log: $(cat "$tmp/xvfb.log"))"
	finish
fi

# start_viewer TITLE-PATTERN VIEWER-ARGS...: starts the viewer (stdout in
# stdout.txt, stderr in stderr.txt), waits for its window and puts it at
# the corner with the focus; sets win, X, Y, WIDTH and HEIGHT.  Fails the
# suite when no window opens.
start_viewer() {
	title=$1
	shift
	tries=3
	while :; do
		: >stdout.txt
		"$viewer" "$@" >stdout.txt 2>stderr.txt &
		viewer_pid=$!
		win=""
		wait_for 200 find_window && break
		# A refused connection is the display's doing, not the viewer's:
		# try again while the server is up, and say so.
		tries=$((tries - 1))
		if [ "$tries" -gt 0 ] && grep -q "failed to open display" stderr.txt &&
			kill -0 "$xvfb_pid" 2>/dev/null && xdotool getmouselocation >/dev/null 2>&1; then
			echo "  note: the viewer could not open $DISPLAY ($(cat stderr.txt | tail -n 1)); trying again"
			kill "$viewer_pid" 2>/dev/null
			wait "$viewer_pid" 2>/dev/null
			continue
		fi
		alive=no
		kill -0 "$xvfb_pid" 2>/dev/null && alive=yes
		bad "a window titled '$title' opened (stderr: $(cat stderr.txt); Xvfb running: $alive; Xvfb: $(cat "$tmp/xvfb.log"))"
		finish
	done
	ok "window '$(xdotool getwindowname "$win")' opened"
	# Without a window manager GLUT's window sits at -1,-1, its first row
	# and column off the screen: move it to the corner for the screenshot.
	xdotool windowmove --sync "$win" 0 0 2>/dev/null || xdotool windowmove "$win" 0 0
	sleep 0.2
	eval "$(xdotool getwindowgeometry --shell "$win")"
	# No window manager: keyboard focus follows the pointer, so put it in
	# the window and give the window the focus too.
	xdotool mousemove --sync $((X + WIDTH / 2)) $((Y + HEIGHT / 2)) 2>/dev/null
	xdotool windowfocus --sync "$win" 2>/dev/null
	sleep 0.3
}
find_window() { win=$(xdotool search --name "$title" 2>/dev/null | head -n 1); [ -n "$win" ]; }

got_line() { grep -q '^captured ' stdout.txt; }
saw_progress=no
watch_title() {
	case $(xdotool getwindowname "$win" 2>/dev/null) in
	*tracing*) saw_progress=yes ;;
	esac
	got_line
}

# wait_capture: waits for the "captured" line after 0; sets line, capture
# (the PNG) and args (the command's arguments after "whitted").
wait_capture() {
	saw_progress=no
	if ! wait_for 900 watch_title; then
		bad "0 printed a 'captured' line within 90 s (stderr: $(cat stderr.txt))"
		finish
	fi
	line=$(grep '^captured ' stdout.txt | head -n 1)
	echo "  $line"
	capture=$(printf '%s\n' "$line" | sed -n 's/^captured \([^:]*\): whitted .*/\1/p')
	args=$(printf '%s\n' "$line" | sed -n 's/^captured [^:]*: whitted //p')
}

# reproduce SIZE: the command, run as printed, must reproduce the capture
# exactly, SIZE x SIZE pixels.
reproduce() {
	rm -f cli.png
	eval "\"\$whitted\" -q -o cli.png $args" 2>cli.err
	check $? "the printed command runs ($(cat cli.err))"
	if cmp -s "$capture" cli.png; then
		ok "the command's PNG is byte-identical to $capture ($(wc -c <cli.png) bytes)"
	else
		bad "the command's PNG is byte-identical to $capture"
	fi
	convert "$capture" -depth 8 rgb:capture.rgb && convert cli.png -depth 8 rgb:cli.rgb &&
		[ "$(wc -c <capture.rgb)" = $(($1 * $1 * 3)) ] && cmp -s capture.rgb cli.rgb
	check $? "decoded pixels equal: $1x$1, $(wc -c <capture.rgb 2>/dev/null) bytes of RGB compared"
}

# screenshot: the window (which still shows the captured view) into
# window.png.
screenshot() {
	xdotool mousemove 0 599 2>/dev/null
	sleep 0.3
	# The whole screen, cropped to the window.
	import -window root screen.png 2>import.err &&
		convert screen.png -crop "500x500+$X+$Y" +repage window.png 2>>import.err &&
		[ "$(identify -format %wx%h window.png)" = 500x500 ]
	check $? "screenshot of the window ($(cat import.err))"
}

# pixels FILE AWK-CONDITION: how many pixels of FILE meet the condition on
# r, g and b.
pixels() {
	convert "$1" -depth 8 rgb:- | od -An -v -tu1 -w3 |
		awk "{ r = \$1; g = \$2; b = \$3; if ($2) n++ } END { print n + 0 }"
}

# differ SCENE-ARGS...: pixels of window.png that differ by more than 20%
# from the printed command traced at 500 x 500 (with SCENE-ARGS instead of
# the printed scene, when given).
differ() {
	rm -f view500.png
	if [ $# -gt 0 ]; then
		view_args=$(printf '%s\n' "$args" | sed 's/^[^ ]* //')
		eval "\"\$whitted\" -q -o view500.png \"\$@\" $view_args --size 500" 2>/dev/null
	else
		eval "\"\$whitted\" -q -o view500.png $args --size 500" 2>/dev/null
	fi
	d=$(compare -metric AE -fuzz 20% window.png view500.png null: 2>&1)
	echo "${d%.*}"
}

quit_viewer() {
	xdotool key --window "$win" q 2>/dev/null || xdotool key q
	if wait_for 100 '! kill -0 "$viewer_pid" 2>/dev/null'; then
		wait "$viewer_pid"
		check $? "q quit with status 0"
		viewer_pid=""
	else
		bad "q quit within 10 s"
		kill "$viewer_pid" 2>/dev/null
		viewer_pid=""
	fi
}

echo "classic: the course example"
# An existing capture-1.png must survive: the capture goes to capture-2.png.
mkdir classic && cd classic || exit 1
echo "not a capture" >capture-1.png
start_viewer '^whitted: scene\.txt' -s 640 -r 3 --floor 1200,25 "$scene"
[ "$WIDTH" = 500 ] && [ "$HEIGHT" = 500 ]
check $? "window is 500x500 (${WIDTH}x${HEIGHT})"
# Forward, left, up, turn left, look up, tilt, back; then help and capture.
xdotool key --delay 40 Up Up Up Left Prior 1 3 5 Down h 0
wait_capture
[ "$(grep -c . stdout.txt)" = 1 ]
check $? "one line on stdout"
if [ "$saw_progress" = yes ]; then
	ok "the title showed the trace's progress"
else
	echo "  note: the trace ended before the title could be read"
fi
grep -q 'Page Up' stderr.txt
check $? "h listed the keys (on stderr)"
[ "$capture" = capture-2.png ] && [ "$(cat capture-1.png)" = "not a capture" ]
check $? "captured into capture-2.png, the existing capture-1.png untouched"
case $args in
*"--eye 0,-200,10 "*) bad "the keys moved the camera ($args)" ;;
*"--up 0,0,1 "*) bad "the keys turned the camera ($args)" ;;
*) ok "the keys moved and turned the camera" ;;
esac
case $args in
*"--size 640 --recursion 3 --floor 1200,25") ok "the command carries --size, --recursion and --floor" ;;
*) bad "the command carries --size, --recursion and --floor ($args)" ;;
esac
reproduce 640
screenshot
shot_classic=$PWD/window.png
stats=$(convert window.png -depth 8 rgb:- | od -An -v -tu1 -w3 | awk '
	{
		y = int((NR - 1) / 500); r = $1; g = $2; b = $3
		m = r; if (g > m) m = g; if (b > m) m = b
		if (y >= 350) { n++; if (m > 150) bright++; if (m < 20) dark++ }
		if (g > 100 && r < 0.6 * g && b < 0.6 * g) green++
		if (b > 60 && r < 0.5 * b && g < 0.5 * b) blue++
		if (r > 120 && g > 120 && b < 0.5 * g) yellow++
	}
	END { printf "%d %d %d %d %d %d\n", n, bright, dark, green, blue, yellow }')
set -- $stats
colours=$(convert window.png -format %k info:)
[ "$colours" -gt 100 ]
check $? "the screenshot is not one colour ($colours colours)"
[ "$2" -gt $(($1 / 10)) ] && [ "$3" -gt $(($1 / 10)) ]
check $? "the floor's checker: bright $2 and black $3 of the bottom $1 pixels"
[ "$4" -gt 200 ] && [ "$5" -gt 200 ] && [ "$6" -gt 200 ]
check $? "the objects: $4 green, $5 blue, $6 yellow pixels (more than 200 each)"
# The projection: the same command traced at the window's size differs
# from the screenshot only in shading, shadows, reflections and the light
# markers: about 800 pixels here, where a field of view off by 0.2 degrees
# gives 1800 and one off by half a degree 3400 (every checker edge moves).
n=$(differ)
[ "$n" -lt 2500 ] 2>/dev/null
check $? "the window matches the trace at 500x500: $n of 250000 pixels differ by more than 20% (limit 2500)"
quit_viewer
cd "$tmp" || exit 1

echo "spot: $(basename "$spot_scene") (a spotlight under the floor, a sphere of radius 150)"
# Its spotlight sits under the floor at (100, 100, -200), aimed up +z with
# a cutoff of 12 degrees, onto the underside of the big white sphere: the
# view starts under the floor, looking at it.  The file's own size (2000).
mkdir spot && cd spot || exit 1
start_viewer '^whitted: munzer2\.txt' --eye 330,380,-330 --look 80,80,-110 "$spot_scene"
grep -q 'note: read as the spot dialect (4 point lights, 1 spotlight)' stderr.txt
check $? "read as the spot dialect ($(grep 'read as' stderr.txt))"
xdotool key --delay 40 Left Left 1 Down 0
wait_capture
[ "$capture" = capture-1.png ]
check $? "captured into capture-1.png"
case $args in
*" --fov 80 --size 2000 --recursion 4") ok "the command carries the file's view and image ($args)" ;;
*) bad "the command carries the file's view and image ($args)" ;;
esac
reproduce 2000
screenshot
shot_spot=$PWD/window.png
# The spotlight's marker: unlit lines in its colour, pure green, besides
# its 9 x 9 dot; its light: a small lit patch on the sphere (about 900
# pixels here; the same view with GL lighting it as a point light, or a
# cutoff of 80 degrees, tints 68000).
n=$(pixels window.png 'g > 200 && r < 40 && b < 40')
[ "$n" -gt 200 ]
check $? "the spotlight is drawn as a cone: $n pure green pixels (more than 200; its dot has 81)"
n=$(pixels window.png 'g > r + 30 && g > b + 30 && r > 50')
[ "$n" -gt 100 ] && [ "$n" -lt 10000 ]
check $? "GL lights a cone of 12 degrees: $n lit green pixels (between 100 and 10000)"
n=$(differ)
[ "$n" -lt 2000 ] 2>/dev/null
check $? "the window matches the trace at 500x500: $n of 250000 pixels differ by more than 20% (limit 2000)"
quit_viewer
cd "$tmp" || exit 1

echo "nearfar: $(basename "$nearfar_scene") (near 1, FOVY 80, aspect 1.7778, the infinite checkerboard)"
mkdir nearfar && cd nearfar || exit 1
start_viewer '^whitted: akib1689\.txt' "$nearfar_scene"
grep -q 'note: read as the nearfar dialect' stderr.txt
check $? "read as the nearfar dialect ($(grep 'read as' stderr.txt))"
xdotool key --delay 40 Up Up Right 2 4 Prior 0
wait_capture
case $args in
*"--eye 0,-200,10 "*) bad "the keys moved the camera ($args)" ;;
*) ok "the keys moved the camera" ;;
esac
# No option sets the near plane, the aspect or the infinite floor: whitted
# reads them from the file again.
case $args in
*--floor* | *--no-floor* | *near* | *aspect* | *--dialect*)
	bad "the command leaves the file's lens and floor to the file ($args)" ;;
*" --fov 80 --size 720 --recursion 3") ok "the command carries the file's view and image" ;;
*) bad "the command carries the file's view and image ($args)" ;;
esac
reproduce 720
screenshot
shot_nearfar=$PWD/window.png
n=$(pixels window.png 'b > 100 && r < 0.5 * b && g < 0.8 * b')
[ "$n" -gt 500 ]
check $? "the cube: $n blue pixels (more than 500)"
n=$(pixels window.png 'r > 100 && g < 0.3 * r && b < 0.3 * r')
[ "$n" -gt 100 ]
check $? "the pyramid: $n red pixels (more than 100)"
# The horizontal field of view is 1.7778 x 80 degrees: about 2100 pixels
# differ from the trace here (shading and the floor's reflections), 18000
# from a trace of the file with aspect 1 and 4000 from one with aspect 1.8.
n=$(differ)
[ "$n" -lt 3200 ] 2>/dev/null
check $? "the window matches the trace at 500x500: $n of 250000 pixels differ by more than 20% (limit 3200)"
sed '1s/^1 1000 80 1.77777777777778/1 1000 80 1/' "$nearfar_scene" >aspect1.txt
n1=$(differ aspect1.txt)
[ "$n1" -gt 6400 ] 2>/dev/null
check $? "and not the trace with aspect 1: $n1 pixels differ (more than 6400)"
quit_viewer
cd "$tmp" || exit 1

echo "near plane: $(basename "$near_scene") (NEAR 15: a red cube before the plane, a sphere cut by it)"
mkdir near && cd near || exit 1
start_viewer '^whitted: near-plane\.txt' "$near_scene"
xdotool key 0
wait_capture
reproduce 96
screenshot
# GL's near plane is the image plane: the cube between it and the eye is
# not drawn (55000 red pixels with a near plane of 0.5), and the window
# matches the trace (13000 pixels differ, the cut sphere's inside shaded
# otherwise; 78000 from the trace with a near plane of 0.5).
n=$(pixels window.png 'r > 100 && g < 0.3 * r && b < 0.3 * r')
[ "$n" -lt 100 ]
check $? "the cube before the near plane is not drawn: $n red pixels (fewer than 100)"
n=$(differ)
[ "$n" -lt 20000 ] 2>/dev/null
check $? "the window matches the trace at 500x500: $n of 250000 pixels differ by more than 20% (limit 20000)"
sed '/^15 1000 70 1.2/s/^15 /0.5 /' "$near_scene" >near0.5.txt
n1=$(differ near0.5.txt)
[ "$n1" -gt 40000 ] 2>/dev/null
check $? "and not the trace with a near plane of 0.5: $n1 pixels differ (more than 40000)"
quit_viewer
cd "$tmp" || exit 1

echo "plugins: docs/plugins.md's disc built against an installed whitted, and the torus plugin"
# The tutorial plugin, built outside the tree with pkg-config against an
# install of this tree, and an example plugin: the viewer draws a disc from
# its bounding box (it has no tessellate) and the torus from its mesh, and
# the printed command names both plugins, so that it still reproduces the
# capture byte for byte.
mkdir plugins && cd plugins || exit 1
if make -C "$root" --no-print-directory install PREFIX="$tmp/prefix" BUILD="$(dirname "$whitted")" \
	>install.log 2>&1 &&
	PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig" "$root/tests/plugins/build-tutorial.sh" "$PWD" 2>cc.err; then
	ok "the tutorial plugin builds against the installed whitted"
	cat >discs.txt <<'SCENE'
2
200

2
disc
-20 0 30
0 -1 0.3
35
1 0.9 0
0.3 0.6 0.3 0
20
torus
40 0 20
0 -1 0.5
30 10
0 0.3 1
0.3 0.6 0.3 0
10
1
-100 -150 200
1 1 1
SCENE
	start_viewer '^whitted: discs\.txt' --plugin ./disc.so --plugin "$(dirname "$whitted")/plugins/torus.so" discs.txt
	xdotool key 0
	wait_capture
	case $args in
	*"--plugin ./disc.so --plugin "*"/plugins/torus.so "*) ok "the command names both plugins ($args)" ;;
	*) bad "the command names both plugins ($args)" ;;
	esac
	reproduce 200
	screenshot
	n=$(pixels window.png 'r > 150 && g > 120 && b < 60')
	[ "$n" -gt 500 ]
	check $? "the disc (its bounding box): $n yellow pixels (more than 500)"
	n=$(pixels window.png 'b > 120 && r < 60 && g < 0.6 * b')
	[ "$n" -gt 500 ]
	check $? "the torus (its mesh): $n blue pixels (more than 500)"
	quit_viewer
else
	bad "the tutorial plugin builds against the installed whitted ($(tail -3 install.log; head -3 cc.err 2>/dev/null))"
fi
echo "issue 14: a textured floor, a glass sphere and --samples 2 (sphere.txt)"
# The floor's cells under the test textures (white.bmp's green and blue
# quarters are colours the plain checkerboard never has), the middle sphere
# glass, seen through blended; the capture traces with the options, and
# the printed command carries them.
mkdir features && cd features || exit 1
cp "$root/tests/textures/white.bmp" "$root/tests/textures/black.png" .
start_viewer '^whitted: sphere\.txt' -s 120 -r 5 --samples 2 --floor-texture white.bmp,black.png \
	--glass 2:1.4:0.7 "$root/scenes/sphere.txt"
xdotool key 0
wait_capture
case $args in
*" --size 120 --recursion 5 --samples 2 --floor-texture white.bmp,black.png --glass 2:1.4:0.7")
	ok "the command carries --samples, --floor-texture and --glass" ;;
*) bad "the command carries --samples, --floor-texture and --glass ($args)" ;;
esac
reproduce 120
screenshot
n=$(pixels window.png 'g > 120 && r < 0.5 * g && b < 0.5 * g')
[ "$n" -gt 500 ]
check $? "the textured floor: $n pixels of white.bmp's green quarter (more than 500)"
n=$(pixels window.png 'b > 120 && r < 0.5 * b && g < 0.5 * b')
[ "$n" -gt 500 ]
check $? "the textured floor: $n pixels of white.bmp's blue quarter (more than 500)"
"$viewer" -s 120 --floor-texture nothere.png "$root/scenes/sphere.txt" >/dev/null 2>err.txt
[ $? = 1 ] && grep -q "nothere.png" err.txt
check $? "a missing texture: exit 1 naming it ($(cat err.txt))"
quit_viewer
mv window.png window-glass.png
# The same view with the sphere opaque: the glass one is seen through.
start_viewer '^whitted: sphere\.txt' -s 120 -r 5 --floor-texture white.bmp,black.png \
	"$root/scenes/sphere.txt"
screenshot
n=$(compare -metric AE -fuzz 10% window.png window-glass.png null: 2>&1)
[ "${n%.*}" -gt 1000 ] 2>/dev/null
check $? "the glass sphere is drawn see-through: $n pixels differ from the opaque one (more than 1000)"
quit_viewer
cd "$tmp" || exit 1

echo "signals: Ctrl-C and SIGTERM during a capture"
# A capture long enough (1600 px, 9 samples a pixel) that the signal comes
# while it is traced: the viewer exits 128 + N and leaves no capture-N.png
# (the name it reserved) and no temporary file.
for sig in INT TERM; do
	mkdir "sig-$sig" && cd "sig-$sig" || exit 1
	start_viewer '^whitted: scene\.txt' -s 1600 --samples 3 "$scene"
	xdotool key 0
	wait_for 100 '[ -e capture-1.png ]'
	check $? "SIG$sig: 0 reserved capture-1.png"
	sleep 0.3
	kill -s "$sig" "$viewer_pid"
	if wait_for 100 '! kill -0 "$viewer_pid" 2>/dev/null'; then
		wait "$viewer_pid"
		rc=$?
		viewer_pid=""
		want=$([ "$sig" = INT ] && echo 130 || echo 143)
		[ "$rc" = "$want" ]
		check $? "SIG$sig during a capture: exit $want (got $rc)"
		[ -z "$(ls -A | grep -v -x -e stdout.txt -e stderr.txt)" ]
		check $? "SIG$sig during a capture: nothing left ($(ls -A | tr '\n' ' '))"
	else
		bad "SIG$sig ended the viewer within 10 s"
		kill -9 "$viewer_pid" 2>/dev/null
		viewer_pid=""
	fi
	cd "$tmp" || exit 1
done

echo "plugins: a tessellate that fails"
# A plugin whose tessellate returns 5 (tests/plugins/hostile.c): exit 1,
# naming the shape and the plugin, never a crash.
cc -std=c99 -I"$root/include" -fPIC -shared -DTESS_POSITIVE -o tess.so "$root/tests/plugins/hostile.c" -lm &&
	printf '1\n16\n\n1\nblob\n0 0 20\n0.9 0.2 0.2\n0.1 0.5 0.4 0.0\n10\n\n1\n-100 -150 200\n1 1 1\n' >blob.txt
"$viewer" --plugin ./tess.so blob.txt >/dev/null 2>tess.txt &
tess_pid=$!
if wait_for 100 '! kill -0 "$tess_pid" 2>/dev/null'; then
	wait "$tess_pid"
	[ $? = 1 ] && grep -q "error: shape 'blob' of the plugin ./tess.so: its tessellate returned neither 0 nor an error (returned 5)" tess.txt
	check $? "a tessellate returning 5: exit 1 naming it ($(grep -v note: tess.txt))"
else
	kill "$tess_pid" 2>/dev/null
	bad "a tessellate returning 5: the viewer ended"
fi

# The screenshots, for docs/img (viewer-nearfar.png there is an-akhand.txt's,
# the Jan 2023 handout's own scene, at the starting view).
if [ "${KEEP_SHOTS:-}" ]; then
	cp "$shot_classic" "$KEEP_SHOTS/viewer-window.png"
	cp classic/capture-2.png "$KEEP_SHOTS/viewer-capture.png"
	cp "$shot_spot" "$KEEP_SHOTS/viewer-spot.png"
	cp "$shot_nearfar" "$KEEP_SHOTS/viewer-nearfar-akib1689.png"
fi
finish
