#!/bin/sh
# End-to-end test of whitted-view under Xvfb, as a new user would use it:
# start it on the course scene, press movement keys, press 0, then check
# that the printed command renders the capture exactly (byte for byte and
# pixel for pixel), that a screenshot of the window shows the floor's
# checker and the objects, and that the window's projection is the tracer's
# camera (the screenshot against the command rendered at the window's size).
# Usage: tests/viewer/e2e.sh BUILD/whitted-view BUILD/whitted
# Needs Xvfb, xdotool and ImageMagick (import, convert, compare).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
viewer=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
whitted=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
scene=$root/scenes/scene.txt
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
	echo "viewer-e2e: $pass passed, $fail failed"
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
cd "$tmp" || exit 1

# A display of our own: -displayfd picks a free number and writes it once
# the server is ready.
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
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

# An existing capture-1.png must survive: the capture goes to capture-2.png.
echo "not a capture" >capture-1.png
"$viewer" -s 640 -r 3 --floor 1200,25 "$scene" >stdout.txt 2>stderr.txt &
viewer_pid=$!

win=""
find_window() { win=$(xdotool search --name '^whitted: scene\.txt' 2>/dev/null | head -n 1); [ -n "$win" ]; }
if ! wait_for 200 find_window; then
	bad "a window titled 'whitted: scene.txt' opened (stderr: $(cat stderr.txt); Xvfb: $(cat "$tmp/xvfb.log"))"
	finish
fi
ok "window '$(xdotool getwindowname "$win")' opened"
# Without a window manager GLUT's window sits at -1,-1, its first row and
# column off the screen: move it to the corner for the screenshot.
xdotool windowmove --sync "$win" 0 0 2>/dev/null || xdotool windowmove "$win" 0 0
sleep 0.2
eval "$(xdotool getwindowgeometry --shell "$win")"
[ "$WIDTH" = 500 ] && [ "$HEIGHT" = 500 ]
check $? "window is 500x500 (${WIDTH}x${HEIGHT})"

# No window manager: keyboard focus follows the pointer, so put it in the
# window and give the window the focus too.
xdotool mousemove --sync $((X + WIDTH / 2)) $((Y + HEIGHT / 2)) 2>/dev/null
xdotool windowfocus --sync "$win" 2>/dev/null
sleep 0.3
# Forward, left, up, turn left, look up, tilt, back; then help and capture.
xdotool key --delay 40 Up Up Up Left Prior 1 3 5 Down h 0

got_line() { grep -q '^captured ' stdout.txt; }
saw_progress=no
watch_title() {
	case $(xdotool getwindowname "$win" 2>/dev/null) in
	*tracing*) saw_progress=yes ;;
	esac
	got_line
}
if ! wait_for 600 watch_title; then
	bad "0 printed a 'captured' line within 60 s (stderr: $(cat stderr.txt))"
	finish
fi
line=$(grep '^captured ' stdout.txt | head -n 1)
echo "  $line"
[ "$(grep -c . stdout.txt)" = 1 ]
check $? "one line on stdout"
if [ "$saw_progress" = yes ]; then
	ok "the title showed the trace's progress"
else
	echo "  note: the trace ended before the title could be read"
fi
grep -q 'Page Up' stderr.txt
check $? "h listed the keys (on stderr)"

capture=$(printf '%s\n' "$line" | sed -n 's/^captured \([^:]*\): whitted .*/\1/p')
args=$(printf '%s\n' "$line" | sed -n 's/^captured [^:]*: whitted //p')
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

# The command, run as printed, must reproduce the capture exactly.
eval "\"\$whitted\" -q -o cli.png $args" 2>cli.err
check $? "the printed command runs ($(cat cli.err))"
if cmp -s "$capture" cli.png; then
	ok "the command's PNG is byte-identical to $capture ($(wc -c <cli.png) bytes)"
else
	bad "the command's PNG is byte-identical to $capture"
fi
convert "$capture" -depth 8 rgb:capture.rgb && convert cli.png -depth 8 rgb:cli.rgb &&
	[ "$(wc -c <capture.rgb)" = $((640 * 640 * 3)) ] && cmp -s capture.rgb cli.rgb
check $? "decoded pixels equal: 640x640, $(wc -c <capture.rgb 2>/dev/null) bytes of RGB compared"

# The window still shows the captured view.
xdotool mousemove 0 599 2>/dev/null
sleep 0.3
# The whole screen, cropped to the window.
import -window root screen.png 2>import.err &&
	convert screen.png -crop "500x500+$X+$Y" +repage window.png 2>>import.err &&
	[ "$(identify -format %wx%h window.png)" = 500x500 ]
check $? "screenshot of the window ($(cat import.err))"
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
eval "\"\$whitted\" -q -o view500.png $args --size 500" 2>/dev/null
differ=$(compare -metric AE -fuzz 20% window.png view500.png null: 2>&1)
[ "${differ%.*}" -lt 2500 ] 2>/dev/null
check $? "the window matches the trace at 500x500: $differ of 250000 pixels differ by more than 20% (limit 2500)"

xdotool key --window "$win" q 2>/dev/null || xdotool key q
if wait_for 100 '! kill -0 "$viewer_pid" 2>/dev/null'; then
	wait "$viewer_pid"
	check $? "q quit with status 0"
	viewer_pid=""
else
	bad "q quit within 10 s"
fi
[ "${KEEP_SHOTS:-}" ] && cp window.png "$KEEP_SHOTS/viewer-window.png" && cp "$capture" "$KEEP_SHOTS/viewer-capture.png"
finish
