#!/bin/bash
# Output faults: a missing directory, a directory that is a file, a
# read-only directory, a file-size limit that stops the write half way, a
# full device, and SIGINT or SIGTERM during a render (also inside one
# pixel's endless tree of glass rays).  Inputs that are not files (a named
# pipe with no writer, a device, a socket) where a file is expected: refused
# at once, where a scene may come from a pipe.  Each must exit
# non-zero with one message, leave neither the output nor a temporary file
# (.NAME.XXXXXX) behind, and leave an existing output file byte for byte as
# it was.
SUITE=faults
. "$(dirname "$0")/lib.sh"
SCENE=$ROOT/scenes/scene.txt

# fault NAME WANT_RC PATTERN DIR OUTPUT -- ARGS...: runs whitted in DIR with
# -o OUTPUT, twice: once with no output file, once over an existing one.
fault() {
	local name=$1 want_rc=$2 pattern=$3 dir=$4 output=$5
	shift 6
	local sum
	for existing in no yes; do
		rm -rf "$dir" && mkdir -p "$dir"
		if [ $existing = yes ]; then
			printf 'the old image\n' >"$dir/$output"
			sum=$(cksum <"$dir/$output")
		fi
		(cd "$dir" && "$W" -o "$output" "$@") >"$T/out" 2>"$T/err"
		rc=$?
		local what="$name (existing: $existing)"
		if [ "$rc" -ne "$want_rc" ]; then bad "$what" "exit $rc, expected $want_rc: $(cat "$T/err")"
		elif [ "$(err_lines)" -ne 1 ]; then bad "$what" "$(err_lines) stderr lines: $(cat "$T/err")"
		elif ! grep -qF -- "$pattern" "$T/err"; then bad "$what" "stderr lacks '$pattern': $(cat "$T/err")"
		elif [ $existing = no ] && [ -n "$(ls -A "$dir")" ]; then bad "$what" "left: $(ls -A "$dir")"
		elif [ $existing = yes ] && [ "$(ls -A "$dir")" != "$output" ]; then bad "$what" "left: $(ls -A "$dir")"
		elif [ $existing = yes ] && [ "$(cksum <"$dir/$output")" != "$sum" ]; then bad "$what" "the existing output changed"
		else ok
		fi
	done
}

# A missing directory, and a "directory" that is a regular file.
clean_wd
run -s 8 -o nodir/x.png "$SCENE"
check "missing dir exit" [ "$rc" -eq 1 ]
check "missing dir message" grep -qx 'whitted: error: nodir/x.png: cannot write: No such file or directory' "$T/err"
check "missing dir nothing created" wd_empty
printf 'a file\n' >"$T/wd/plain"
run -s 8 -o plain/x.png "$SCENE"
check "dir is a file exit" [ "$rc" -eq 1 ]
check "dir is a file message" grep -qx 'whitted: error: plain/x.png: cannot write: Not a directory' "$T/err"
check "dir is a file untouched" [ "$(cat "$T/wd/plain")" = 'a file' ]

# The output is a directory.
clean_wd
mkdir "$T/wd/d.png"
run -s 8 -o d.png "$SCENE"
check "output is a directory exit" [ "$rc" -eq 1 ]
check "output is a directory message" grep -qx 'whitted: error: d.png: cannot write: Is a directory' "$T/err"
check "output is a directory kept" [ -d "$T/wd/d.png" -a "$(wd_files)" = d.png ]
# A 254-byte name is valid; its temporary name must be too.
clean_wd
long=$(printf 'a%.0s' $(seq 250)).png
run -s 8 -o "$long" "$SCENE"
check "254-byte output name" [ "$rc" -eq 0 -a "$(wd_files)" = "$long" ]
run -s 8 -o "aa$long" "$SCENE"
check "256-byte output name fails" [ "$rc" -eq 1 -a "$(wd_files)" = "$long" ]

# A read-only directory.  Root ignores permissions, so as root the check
# runs as the user nobody (setpriv); without a way to drop privileges it
# is reported as not run (and not counted as passed).
ro_run() {
	if [ "$(id -u)" -ne 0 ]; then
		"$@"
	elif command -v setpriv >/dev/null; then
		setpriv --reuid=65534 --regid=65534 --clear-groups "$@"
	else
		return 125
	fi
}
chmod 755 "$T"
mkdir -p "$T/ro"
cp "$SCENE" "$T/scene.txt"
chmod 644 "$T/scene.txt"
# A copy of the program, so that nobody can run it wherever the checkout is
# (a home directory of mode 700, say).
cp "$W" "$T/whitted"
chmod 755 "$T/whitted"
for existing in no yes; do
	rm -f "$T/ro/x.png"
	chmod 755 "$T/ro"
	[ $existing = yes ] && printf 'old\n' >"$T/ro/x.png" && chmod 666 "$T/ro/x.png"
	chmod 555 "$T/ro"
	ro_run "$T/whitted" -s 8 -o "$T/ro/x.png" "$T/scene.txt" >"$T/out" 2>"$T/err"
	rc=$?
	if [ $rc -eq 125 ]; then
		echo "faults: NOT RUN: read-only directory as root without setpriv"
		fail=$((fail + 1))
		break
	fi
	check "read-only dir exit ($existing)" [ "$rc" -eq 1 ]
	check "read-only dir message ($existing)" grep -qx "whitted: error: $T/ro/x.png: cannot write: Permission denied" "$T/err"
	if [ $existing = yes ]; then
		check "read-only dir existing untouched" [ "$(cat "$T/ro/x.png")" = old ]
		check "read-only dir nothing else" [ "$(ls -A "$T/ro")" = x.png ]
	else
		check "read-only dir nothing created" [ -z "$(ls -A "$T/ro")" ]
	fi
done
chmod 755 "$T/ro"
# The same run as root must work: the check above is about permissions.
"$W" -s 8 -o "$T/ro/x.png" "$T/scene.txt" 2>"$T/err"
check "read-only dir control run" [ $? -eq 0 ]

# A file-size limit during the write: whitted ignores SIGXFSZ, so the write
# fails with EFBIG.  1 block is far below every format's size at -s 128.
for f in png bmp ppm; do
	rm -rf "$T/fs" && mkdir -p "$T/fs"
	for existing in no yes; do
		[ $existing = yes ] && printf 'old\n' >"$T/fs/x.$f"
		(ulimit -f 1 && cd "$T/fs" && exec "$W" -s 128 -o "x.$f" "$SCENE") >"$T/out" 2>"$T/err"
		rc=$?
		check "file-size limit $f exit ($existing)" [ "$rc" -eq 1 ]
		check "file-size limit $f message ($existing)" grep -qE "^whitted: error: x\.$f: cannot write.*: File too large$" "$T/err"
		if [ $existing = yes ]; then
			check "file-size limit $f existing untouched" [ "$(cat "$T/fs/x.$f")" = old ]
			check "file-size limit $f no temporary" [ "$(ls -A "$T/fs")" = "x.$f" ]
		else
			check "file-size limit $f nothing left" [ -z "$(ls -A "$T/fs")" ]
		fi
	done
done

# A small PNG that fits the stdio buffer fails in the final flush instead.
rm -rf "$T/fs" && mkdir -p "$T/fs"
(ulimit -f 1 && cd "$T/fs" && exec "$W" -s 64 -o x.png "$SCENE") >"$T/out" 2>"$T/err"
check "file-size limit at the flush exit" [ $? -eq 1 ]
check "file-size limit at the flush message" grep -qx 'whitted: error: x.png: cannot write: File too large' "$T/err"
check "file-size limit at the flush nothing left" [ -z "$(ls -A "$T/fs")" ]

# A full device, written in place.
for f in png bmp ppm; do
	"$W" -s 64 -o /dev/full --format $f "$SCENE" >"$T/out" 2>"$T/err"
	rc=$?
	check "dev-full $f exit" [ "$rc" -eq 1 ]
	check "dev-full $f message" grep -qE '^whitted: error: /dev/full: cannot write.*: No space left on device$' "$T/err"
done

# A scene error leaves an existing output alone too.
fault "scene error" 1 'error: expected a number' "$T/se" x.png -- -s 8 "$ROOT/tests/errors/letter-in-number.txt"

# wait_whitted PID: until the program started as PID (env, nohup) has
# become whitted (at most 5 s): a loaded machine once took longer than a
# fixed 0.3 s to get there, and the signal went to the launcher.
wait_whitted() {
	local w_exe
	w_exe=$(readlink -f "$W")
	for _ in $(seq 100); do
		[ "$(readlink "/proc/$1/exe" 2>/dev/null)" = "$w_exe" ] && break
		[ -d "/proc/$1" ] || break
		sleep 0.05
	done
}

# SIGINT and SIGTERM during a render: exit 128+N, one message, no output,
# no temporary file, an existing output untouched.  The image is large
# enough (a few seconds) that the signal always comes during the render.
signal_test() {
	local sig=$1 want=$2 existing=$3 sum=""
	rm -rf "$T/sig" && mkdir -p "$T/sig"
	if [ $existing = yes ]; then
		printf 'old\n' >"$T/sig/big.png"
		sum=$(cksum <"$T/sig/big.png")
	fi
	# A hang-up ignored on entry (the suite run under nohup) stays
	# ignored, as it should: whitted is started with it at its default.
	(cd "$T/sig" && exec env --default-signal=HUP "$W" -q -s 6000 -r 8 -o big.png "$SCENE") \
		>"$T/out" 2>"$T/err" &
	local pid=$!
	# The signal comes once whitted runs in env's place, and is rendering.
	wait_whitted $pid
	sleep 0.3
	kill -s "$sig" $pid
	local sent=$?
	wait $pid
	rc=$?
	local what="$sig (existing: $existing)"
	check "$what sent during the render" [ "$sent" -eq 0 ]
	check "$what exit $want" [ "$rc" -eq "$want" ]
	check "$what one message" [ "$(err_lines)" -eq 1 ]
	check "$what message" grep -qx 'whitted: error: interrupted' "$T/err"
	if [ $existing = yes ]; then
		check "$what existing untouched" [ "$(cksum <"$T/sig/big.png")" = "$sum" ]
		check "$what no temporary" [ "$(ls -A "$T/sig")" = big.png ]
	else
		check "$what nothing left" [ -z "$(ls -A "$T/sig")" ]
	fi
}
signal_test INT 130 no
signal_test TERM 143 no
signal_test INT 130 yes
signal_test TERM 143 yes
signal_test HUP 129 no
# Under nohup a hang-up is ignored and the render completes (as large as
# above: at -s 2000 the render was over before the signal).
rm -rf "$T/sig" && mkdir -p "$T/sig"
(cd "$T/sig" && exec nohup "$W" -s 6000 -r 8 -o big.png "$SCENE") >/dev/null 2>&1 &
pid=$!
# The hang-up must come once nohup has made it ignored, that is once
# whitted runs in its place.
wait_whitted $pid
sleep 0.3
kill -s HUP $pid
sent=$?
wait $pid
rc=$?
check "HUP under nohup sent during the render" [ "$sent" -eq 0 ]
check "HUP under nohup completes" [ "$rc" -eq 0 -a -f "$T/sig/big.png" ]

# A signal while blocked opening a FIFO that nobody reads: the write is
# interrupted, and the exit status still says which signal it was.
rm -rf "$T/ff" && mkdir -p "$T/ff" && mkfifo "$T/ff/out.ppm"
(cd "$T/ff" && exec "$W" -q -s 8 -o out.ppm "$SCENE") >"$T/out" 2>"$T/err" &
pid=$!
sleep 0.5
kill -s TERM $pid
check "TERM while opening a FIFO sent" [ $? -eq 0 ]
wait $pid
rc=$?
check "TERM while opening a FIFO exit 143" [ "$rc" -eq 143 ]
check "TERM while opening a FIFO one message" [ "$(err_lines)" -eq 1 ]
check "TERM while opening a FIFO fifo kept" [ -p "$T/ff/out.ppm" ]

# One pixel (11,10 of 32x32, where a ray bounces between the spheres)
# whose tree of glass rays has no end within any time (kr 1 and kt 0.9 in
# two facing spheres, recursion 256, a budget of 10^12 rays):
# the signal is seen inside the pixel, within a second.
cat >"$T/tree.txt" <<'EOF2'
256
32

2
sphere
-31 0 30
30
0.9 0.9 1.0
0.1 0.3 0.3 1.0
8

sphere
31 0 30
30
0.9 0.9 1.0
0.1 0.3 0.3 1.0
8

1
-100 -150 200
1 1 1
EOF2
for sig in INT TERM; do
	rm -rf "$T/sig" && mkdir -p "$T/sig"
	(cd "$T/sig" && exec "$W" -q --max-rays 1000000000000 --glass 1:1.5:0.9,2:1.5:0.9 \
		--region 11,10,12,11 -o one.png "$T/tree.txt") >"$T/out" 2>"$T/err" &
	pid=$!
	sleep 0.5
	kill -s $sig $pid
	t0=$(date +%s%N)
	wait $pid
	rc=$?
	ms=$((($(date +%s%N) - t0) / 1000000))
	want=$([ $sig = INT ] && echo 130 || echo 143)
	check "$sig inside one pixel's tree: exit $want, not $rc" [ "$rc" -eq "$want" ]
	check "$sig inside one pixel's tree: over within a second ($ms ms)" [ "$ms" -lt 1000 ]
	check "$sig inside one pixel's tree: nothing left ($(ls -A "$T/sig"))" [ -z "$(ls -A "$T/sig")" ]
done
# Without the large budget the same pixel is refused, naming it.
clean_wd
run -q --glass 1:1.5:0.9,2:1.5:0.9 --region 11,10,12,11 --max-rays 100000 -o one.png "$T/tree.txt"
check "a tree over --max-rays: exit 1" [ "$rc" -eq 1 ]
check "a tree over --max-rays: the message" grep -q "^whitted: error: pixel 11,10: a ray's tree of reflections and transmissions through glass needs more than 100000 rays at recursion 256; --max-rays N allows more" "$T/err"
check "a tree over --max-rays: nothing left" wd_empty
run -q --max-rays 255 "$SCENE"
check "--max-rays below 256 is a usage error" [ "$rc" -eq 2 ]

# Inputs that are not files: a named pipe nobody writes to (which would
# block the open), a character device and a socket, wherever whitted reads
# a file other than the scene.  Each is refused at once (exit 1, one
# message that says what it is), nothing written.
rm -rf "$T/nf" && mkdir -p "$T/nf"
mkfifo "$T/nf/fifo.png"
python3 -c 'import socket,sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' "$T/nf/sock.png" 2>/dev/null
"$W" -q -s 4 -o "$T/nf/four.png" "$SCENE"
# not_a_file NAME PATTERN COMMAND...: COMMAND in $T/nf within 5 s exits 1
# with PATTERN (a grep pattern) on stderr, and writes nothing.
not_a_file() {
	local name=$1 pattern=$2
	shift 2
	(cd "$T/nf" && exec timeout -s KILL 5 "$@") >"$T/out" 2>"$T/err"
	rc=$?
	if [ "$rc" -ne 1 ]; then bad "$name" "exit $rc, expected 1: $(head -c 300 "$T/err")"
	elif ! grep -q -- "$pattern" "$T/err"; then bad "$name" "stderr lacks '$pattern': $(head -c 300 "$T/err")"
	elif ls "$T/nf" | grep -qv -e '^fifo.png$' -e '^sock.png$' -e '^four.png$'; then
		bad "$name" "left: $(ls -A "$T/nf")"
	else ok
	fi
}
for in in "fifo.png:is a named pipe, not a file" "/dev/zero:is a character device, not a file"; do
	f=${in%%:*} why=${in#*:}
	not_a_file "texture $f" "$f: $why" "$W" -q -s 8 --floor-texture "$f" -o out.png "$SCENE"
	not_a_file "compared image $f" "$f: $why" "$W" compare -s 4 "$SCENE" "$f"
	not_a_file "merged tile $f" "$f: $why" "$W" merge -o out.png "$f"
	not_a_file "plugin $f" "$f: $why" "$W" -q -s 8 --plugin "$f" -o out.png "$SCENE"
	not_a_file "--path $f" "$f: $why" "$W" -q -s 8 --frames 2 --path "$f" -o out%04d.png "$SCENE"
	not_a_file "scene2pov texture $f" "$f: $why" "$ROOT/build/scene2pov" -q --floor-texture "$f" -o out.pov "$SCENE"
done
# "-" (standard input, maybe a terminal) is only the scene's.
not_a_file "texture -" "-: is standard input, not a file" "$W" -q -s 8 --floor-texture - -o out.png "$SCENE"
not_a_file "compared image -" "-: is standard input, not a file" "$W" compare -s 4 "$SCENE" -
if [ -S "$T/nf/sock.png" ]; then
	not_a_file "texture socket" "sock.png: is a socket, not a file" \
		"$W" -q -s 8 --floor-texture sock.png -o out.png "$SCENE"
else
	bad "texture socket" "NOT RUN: no socket could be made (python3)"
fi
# grade names the unreadable image in its table and goes on.
(cd "$T/nf" && timeout -s KILL 5 "$W" grade -s 4 --scene "$SCENE" fifo.png four.png) >"$T/out" 2>"$T/err"
rc=$?
check "grade: a FIFO is unreadable, not waited on (exit $rc)" [ "$rc" -ne 137 ]
check "grade: the FIFO's row says why" grep -q 'is a named pipe, not a file' "$T/out"
# Hostile images (tests/tools/hostile_png.py), as a texture and as the
# compared image: image data that inflates far past the header's 16x16
# (64 MiB, or the right rows and 8 MiB more), too little data, damaged
# CRCs (critical and ancillary chunks), sizes over the limit (named), a
# small file claiming 16384x16384, a cut file, no IEND, a JPEG.  Each is
# refused with its message in little memory (ulimit -v: far below what
# inflating a bomb took) and time, nothing written.
python3 "$ROOT/tests/tools/hostile_png.py" "$T/hp" >/dev/null
for c in "bomb.png:too much image data: the header's 16x16 needs 784 bytes, the data inflates to more" \
	"bomb-tail.png:too much image data: the header's 16x16 needs 784 bytes" \
	"short-data.png:not enough image data: the header's 16x16 needs 784 bytes, the data ends after 392" \
	"bad-crc.png:damaged PNG file (bad CRC in its IDAT chunk)" \
	"bad-crc-text.png:damaged PNG file (bad CRC in its tEXt chunk)" \
	"huge-65535.png:65535x65535 is over the limit of 67108864 pixels (8192x8192)" \
	"huge-wide.png:2147483647x1 is over the limit of 67108864 pixels (8192x8192)" \
	"huge-30000.png:30000x30000 is over the limit of 67108864 pixels (8192x8192)" \
	"claims-16384.png:16384x16384 is over the limit" \
	"truncated.png:truncated PNG file: a chunk cut short" \
	"no-iend.png:truncated PNG file: it ends without an IEND chunk" \
	"jpeg.jpg:a JPEG image, which is not accepted: JPEG is lossy (its pixels are not the ones the program computed); save the image as PNG or BMP"; do
	f=${c%%:*} m=${c#*:}
	not_a_file "texture $f" "$f: .*$m" sh -c 'ulimit -v 262144; exec "$@"' sh \
		"$W" -q -s 8 --floor-texture "$T/hp/$f" -o out.png "$SCENE"
	not_a_file "compared $f" "$f: .*$m" sh -c 'ulimit -v 262144; exec "$@"' sh \
		"$W" compare -q -s 4 "$SCENE" "$T/hp/$f"
done

# The scene itself may be a pipe: read to its end.
clean_wd
mkfifo "$T/wd/scene.fifo"
(cat "$SCENE" >"$T/wd/scene.fifo" &)
run -q -s 8 -o from-fifo.png scene.fifo
check "a scene from a named pipe renders" [ "$rc" -eq 0 -a -s "$T/wd/from-fifo.png" ]

finish
