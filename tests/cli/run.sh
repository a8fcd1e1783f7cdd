#!/bin/bash
# End-to-end tests of the whitted command line: exit codes, --help and
# --version, option values, odd but valid scenes, the real scene files of
# tests/data/real-scenes, every malformed file of tests/errors (with its
# location and message from tests/errors/expected.tsv), output names and
# formats, atomic replacement, and output to pipes and /dev/stdout.
SUITE=clitest
. "$(dirname "$0")/lib.sh"
SCENE=$ROOT/scenes/scene.txt
ERRORS=$ROOT/tests/errors

# An error run: exit status, exactly one stderr line matching a pattern (a
# fixed string), and nothing left in the work directory.
expect_error() {
	local name=$1 want_rc=$2 pattern=$3
	shift 3
	clean_wd
	run "$@"
	[ "$rc" -eq "$want_rc" ] || { bad "$name" "exit $rc, expected $want_rc ($(head -1 "$T/err"))"; return; }
	grep -qF -- "$pattern" "$T/err" || { bad "$name" "stderr lacks '$pattern': $(cat "$T/err")"; return; }
	wd_empty || { bad "$name" "left files: $(wd_files)"; return; }
	ok
}

# Exit codes, help and version.
run --help
check help-exit [ "$rc" -eq 0 ]
check help-usage grep -q '^Usage: whitted' "$T/out"
check help-quiet [ ! -s "$T/err" ]
run -h
check help-short [ "$rc" -eq 0 ]
run --version
check version-exit [ "$rc" -eq 0 ]
check version-text grep -qE '^whitted [0-9]+\.[0-9]+\.[0-9]+$' "$T/out"
run -V
check version-short [ "$rc" -eq 0 ]
expect_error no-scene 2 'no SCENE' 
expect_error two-scenes 2 'one SCENE expected' "$SCENE" "$SCENE"
expect_error unknown-option 2 "unknown option '--bogus'" --bogus "$SCENE"
expect_error unknown-short-option 2 "unknown option '-x'" -x "$SCENE"
expect_error option-without-value 2 "option '-o' needs a value" "$SCENE" -o
expect_error long-option-without-value 2 "option '--size' needs a value" "$SCENE" --size
expect_error missing-scene 1 'whitted: error: nosuch.txt: cannot open: No such file or directory' nosuch.txt
expect_error scene-is-directory 1 ': is a directory, not a scene file' "$T"
expect_error test-scene-with-file 2 '--test-scene takes no SCENE' --test-scene "$SCENE"

# Every option with a value rejects non-numbers, trailing garbage and
# values out of range, with exit 2, a message naming it and no output.
bad_values() {
	local opt=$1 name=$2
	shift 2
	for v in "$@"; do
		expect_error "option $opt '$v'" 2 "$name" -o x.png "$opt" "$v" "$SCENE"
	done
}
bad_values -s --size abc 12x 12.5 '' ' 12' 0x10 1e3 0 -1 32769 16385 99999999999999999999
bad_values --size --size nan 8,8
bad_values -r --recursion abc 4x 0 -1 257 2.0 99999999999999999999
bad_values --recursion --recursion ''
bad_values -j --threads abc 2x 0 65 -3 1.5
bad_values --threads --threads ''
bad_values --fov --fov abc 60x 0 180 -10 1000 nan inf 0x10 ''
bad_values --eye --eye abc 1,2 1,2,3,4 1,,3 1,2,nan 1,2,3x '1,2,3,' '' 1,2,1e999
bad_values --look --look 1,2 a,b,c 1,2,inf
bad_values --up --up 0,0 0,0,1,0 0,0,x
bad_values --floor --floor 1000 0,20 1000,0 -1000,20 1000,-20 a,20 1000,20,3 1e12,1e-3 nan,20
bad_values --clamp --clamp levels '' FINAL
bad_values --format --format jpg '' pngx
bad_values --progress --progress sometimes ''
bad_values --region --region abc 0,0,8 0,0,8,8x 0,0,769,8 4,0,2,8 -1,0,8,8 0,0,0,0 1e3,0,8,8 ''
bad_values --frames --frames abc 0 2x 100000000 ''
bad_values --grid --grid 2x 0x2 2x2x2 x2 ''
bad_values --max-scene-size --max-scene-size abc 0 1X 12.5 -1 1MB '' 99999999999999999999G
# The scene file's size limit: a file over it refused (exit 1, naming the
# limit, the option and the default, no output), also from a pipe; one
# within it read; the units are powers of 1024.
expect_error max-scene-size-over 1 'the scene file is larger than the limit of 64 bytes (--max-scene-size SIZE changes it; the default here is' \
	-o x.png --max-scene-size 64 "$SCENE"
clean_wd
(cd "$T/wd" && "$W" -q -o x.png --max-scene-size 100 - <"$SCENE") >"$T/out" 2>"$T/err"
rc=$?
check max-scene-size-pipe-exit [ "$rc" -eq 1 ]
check max-scene-size-pipe-message grep -qF '<stdin>: the scene file is larger than the limit of 100 bytes' "$T/err"
check max-scene-size-pipe-no-file wd_empty
scene_bytes=$(wc -c <"$SCENE")
run -q -s 8 -o x.png --max-scene-size "$scene_bytes" "$SCENE"
check max-scene-size-exact [ "$rc" -eq 0 -a -s "$T/wd/x.png" ]
clean_wd
run -q -s 8 -o x.png --max-scene-size "$((scene_bytes - 1))" "$SCENE"
check max-scene-size-one-short [ "$rc" -eq 1 ]
clean_wd
expect_error "option --tile 'x'" 2 --tile -s 8 -o x.png --grid 2x2 --tile x "$SCENE"
expect_error "option --tile past the grid" 2 --tile -s 8 -o x.png --grid 2x2 --tile 5 "$SCENE"
expect_error "option --grid finer than the image" 2 --grid -s 8 -o x.png --grid 9x9 --tile 1 "$SCENE"
expect_error "option --tile without --grid" 2 --tile -s 8 -o x.png --tile 1 "$SCENE"
expect_error "option --frame 'x'" 2 --frame -s 8 -o 'f%04d.png' --frames 2 --frame x "$SCENE"
expect_error "option --frame past the last" 2 --frame -s 8 -o 'f%04d.png' --frames 2 --frame 3 "$SCENE"
expect_error "option --frame without --frames" 2 --frame -s 8 -o x.png --frame 1 "$SCENE"
expect_error "option --region with --grid" 2 --region -s 8 -o x.png --region 0,0,4,4 --grid 2x2 --tile 1 "$SCENE"
expect_error "--path missing" 1 'cannot open' -s 8 -o 'f%04d.png' --frames 2 --path "$T/nosuch" "$SCENE"
expect_error "--path binary" 1 'NUL byte' -s 8 -o 'f%04d.png' --frames 2 --path "$W" "$SCENE"
printf 'eye 0,-200,10 look 0,0,0 up 0,0,1 fov 80\neye 0,0,0 look 0,0,0 up 0,0,1 fov 80\n' >"$T/path.txt"
expect_error "--path bad keyframe: no frame written" 1 'the eye is at the look-at point' \
	-s 8 -o 'f%04d.png' --frames 3 --path "$T/path.txt" "$SCENE"
expect_error output-empty 2 '--output: expected a file name' -o '' "$SCENE"
expect_error eye-at-look 2 'whitted: error:' -s 8 -o x.png --eye 0,0,0 "$SCENE"
expect_error up-zero 2 'whitted: error:' -s 8 -o x.png --up 0,0,0 "$SCENE"
expect_error up-along-view 2 'whitted: error:' -s 8 -o x.png --eye 0,0,100 --up 0,0,1 "$SCENE"
# Good values of the same options are accepted.
clean_wd
run -s 8 -r 2 -j 2 --fov 60 --eye 0,-150,20 --look 0,0,5 --up 0,0,1 --floor 500,10 \
	--clamp final --progress never -q -o ok.png "$SCENE"
check good-options [ "$rc" -eq 0 ] && check good-options-png is_png "$T/wd/ok.png"

# Odd but valid scenes render, each with exit 0 and no error.
# Every file read says which dialect it was read as, in one note
# (tests/cli/dialects.sh checks those); the other lines are counted apart.
dialect_notes() { grep -c ': note: read as the ' "$T/err"; }
other_lines() { grep -vc ': note: read as the ' "$T/err"; }
odd() {
	local name=$1 text=$2 notes=${3:-0}
	clean_wd
	printf '%b' "$text" >"$T/odd.txt"
	run -s 4 -o odd.png "$T/odd.txt"
	if [ "$rc" -ne 0 ]; then bad "odd $name" "exit $rc: $(cat "$T/err")"; return; fi
	if [ "$(dialect_notes)" -ne 1 ]; then bad "odd $name" "not one dialect note: $(cat "$T/err")"; return; fi
	if [ "$(other_lines)" -ne "$notes" ]; then bad "odd $name" "$(other_lines) stderr lines besides the dialect note, expected $notes: $(cat "$T/err")"; return; fi
	is_png "$T/wd/odd.png" || { bad "odd $name" "no PNG written"; return; }
	ok
}
SPHERE='sphere\n0 0 10\n10\n1 0 0\n0.4 0.2 0.2 0.2\n10\n'
LIGHTS='2\n50 -50 50\n1 1 1\n-50 -50 50\n1 1 1\n'
odd zero-objects '4\n16\n0\n1\n0 0 100\n1 1 1\n'
odd zero-lights "4\n16\n1\n${SPHERE}0\n"
odd zero-everything '1\n1\n0\n0\n'
odd image-size-one "4\n1\n1\n${SPHERE}${LIGHTS}"
odd crlf "$(printf '%b' "4\n16\n1\n${SPHERE}${LIGHTS}" | sed 's/$/\r/')"
odd cr-only-is-not-a-newline-but-space "4\r16\r0\r0\r"
odd tabs-and-blank-lines "\t4\t\n\n\n16\n\n0\n\n\n0\n\n"
odd annotated "4\t\t- recursion level\n16\t- size\n1\n${SPHERE}2\n50 -50 50\t- position\n1 1 1\t- colour\n-50 -50 50\n1 1 1\n"
odd hash-and-slash-comments "# head\n4 // recursion\n16\n0 # none\n0\n"
odd no-trailing-newline "4\n16\n1\n${SPHERE}1\n0 0 100\n1 1 1"
odd lights-without-colours "4\n16\n1\n${SPHERE}2\n50 -50 50\n-50 -50 50\n"
odd integral-reals "4.0\n16.0\n1.0\n${SPHERE}0e0\n"
odd exponents-and-signs "+4\n1.6e1\n1\nsphere\n+0 -0 1e1\n.1e2\n1 0 0\n4e-1 .2 +0.2 0.2\n1E1\n0\n"
odd underflow-to-zero "4\n16\n1\nsphere\n0 0 10\n10\n1 0 1e-400\n0.4 0.2 0.2 0.2\n10\n0\n"
odd degenerate-triangle "4\n16\n1\ntriangle\n0 0 0\n1 1 1\n2 2 2\n1 0 0\n0.4 0.2 0.2 0.2\n10\n0\n" 1
odd trailing-text "4\n16\n0\n0\nInput explanation:\nblah\n" 1
# Numbers after the last light are not a trailer but data no count
# describes (and not a spotlight section: that would be 1 + 10 N numbers).
printf '4\n16\n0\n1\n0 0 100\n1 1 1\n1\n2 3 4\n' >"$T/trailing-numbers.txt"
expect_error "trailing-numbers" 1 "trailing-numbers.txt:7:1: error: expected the end of the data after the last light, found the number '1' (4 numbers follow: a count does not describe the data" \
	-s 4 -o odd.png "$T/trailing-numbers.txt"
odd byte-order-mark '\xef\xbb\xbf4\n16\n0\n1\n0 0 100\n1 1 1\n' 1
odd recursion-zero '0\n16\n0\n1\n0 0 100\n1 1 1\n' 1
odd light-colour-above-one '4\n16\n0\n1\n0 0 100\n2 1.5 1\n' 
odd big-coefficients "4\n16\n1\nsphere\n0 0 10\n10\n1 1 1\n1e300 1e300 1e300 1e300\n1e300\n1\n0 0 100\n1 1 1\n"
odd recursion-max "256\n8\n2\nsphere\n0 0 10\n10\n1 1 1\n0 0 0 1\n1\nsphere\n0 0 40\n10\n1 1 1\n0 0 0 1\n1\n0\n"
odd far-away-sphere "4\n8\n1\nsphere\n0 0 1e300\n1\n1 1 1\n1 1 1 1\n1\n1\n0 0 1e299\n1 1 1\n"

# Equivalent spellings give the same image, byte for byte.
same_image() {
	local name=$1 a=$2 b=$3
	printf '%b' "$a" >"$T/a.txt"
	printf '%b' "$b" >"$T/b.txt"
	(cd "$T" && "$W" -q -s 16 -o a.ppm a.txt && "$W" -q -s 16 -o b.ppm b.txt) 2>"$T/err"
	check "same $name" cmp -s "$T/a.ppm" "$T/b.ppm"
}
BASE="4\n16\n1\n${SPHERE}${LIGHTS}"
same_image crlf "$BASE" "$(printf '%b' "$BASE" | sed 's/$/\r/')"
same_image lights-without-colours "$BASE" "4\n16\n1\n${SPHERE}2\n50 -50 50\n-50 -50 50\n"
same_image annotated "$BASE" "4 - r\n16 - s\n1 - n\nsphere - kw\n0 0 10 - c\n10 - r\n1 0 0 - col\n0.4 0.2 0.2 0.2 - k\n10 - sh\n2 - n\n50 -50 50 - p\n1 1 1 - c\n-50 -50 50\n1 1 1\n"
same_image no-trailing-newline "$BASE" "$(printf '%b' "$BASE")"

# The real scene files, with the outcomes of their README.
real_ok() {
	local f=$1 notes=$2 pattern=$3
	clean_wd
	run -s 16 -o real.png "$DATA/real-scenes/$f"
	if [ "$rc" -ne 0 ]; then bad "real $f" "exit $rc: $(cat "$T/err")"; return; fi
	if [ "$(dialect_notes)" -ne 1 ]; then bad "real $f" "not one dialect note: $(cat "$T/err")"; return; fi
	if [ "$(other_lines)" -ne "$notes" ]; then bad "real $f" "$(other_lines) stderr lines besides the dialect note, expected $notes: $(cat "$T/err")"; return; fi
	if [ -n "$pattern" ] && ! grep -qE "$pattern" "$T/err"; then bad "real $f" "note does not match $pattern: $(cat "$T/err")"; return; fi
	is_png "$T/wd/real.png" || { bad "real $f" "no PNG"; return; }
	ok
}
NOTE_TRAIL='^/.*/real-scenes/[a-z0-9]+\.txt:[0-9]+: note: ignoring [0-9]+ lines after the last light$'
real_ok anachor.txt 1 "$NOTE_TRAIL"
real_ok pistachio102.txt 0
real_ok adibashaira.txt 0
real_ok ajakil.txt 0
# Read as the spot dialect now (tests/data/course-files/README.md): its
# spotlight section is data, not a trailer.
real_ok mdraihansobhan.txt 0
expect_error "real apurbostarry.txt" 1 "real-scenes/apurbostarry.txt:48:2: error: expected an integer (light count), found end of file" \
	-s 16 -o real.png "$DATA/real-scenes/apurbostarry.txt"
check "real apurbostarry.txt one line" [ "$(err_lines)" -eq 1 ]
expect_error "real nazmultakbir.txt" 1 "real-scenes/nazmultakbir.txt:10:9: error: expected an object keyword" \
	-s 16 -o real.png "$DATA/real-scenes/nazmultakbir.txt"
check "real nazmultakbir.txt one line" [ "$(err_lines)" -eq 1 ]
n_real=$(ls "$DATA"/real-scenes/*.txt | wc -l)
check "real-scenes: all 7 files tested" [ "$n_real" -eq 7 ]

# Every malformed file: exit 1, exactly one stderr line
# FILE:LINE:COL: error: with the expected location and message, no output
# (neither the named one nor the default one).
# {keywords} in a message stands for the registry's list of object
# keywords, as whitted names them (so that a new primitive changes no test).
printf '1 1\n1\nnosuchshape\n' >"$T/keywords.txt"
keywords=$("$W" -q "$T/keywords.txt" -o "$T/keywords.png" 2>&1 | sed -n 's/.*known objects: //p' | sed 's/ (.*//')
check "errors: the keyword list is known ($keywords)" [ -n "$keywords" ]
n_err=0
while IFS="$(printf '\t')" read -r f loc frag; do
	case $f in '#'* | '') continue ;; esac
	case $frag in *'{keywords}'*) frag="${frag%%\{keywords\}*}$keywords${frag#*\{keywords\}}" ;; esac
	n_err=$((n_err + 1))
	if [ ! -f "$ERRORS/$f" ]; then bad "errors/$f" "listed in expected.tsv but missing"; continue; fi
	for args in "-o out.png" ""; do
		clean_wd
		cp "$ERRORS/$f" "$T/wd/../$f"
		run -s 8 $args "../$f"
		line=$(head -1 "$T/err")
		if [ "$rc" -ne 1 ]; then bad "errors/$f" "exit $rc, expected 1"
		elif [ "$(err_lines)" -ne 1 ]; then bad "errors/$f" "$(err_lines) stderr lines: $(cat "$T/err")"
		elif [ "${line#"../$f:$loc: error: "}" = "$line" ]; then bad "errors/$f" "expected ../$f:$loc: error:, got: $line"
		elif ! printf '%s\n' "$line" | grep -qF -- "$frag"; then bad "errors/$f" "message lacks '$frag': $line"
		elif ! wd_empty; then bad "errors/$f" "left files: $(wd_files)"
		else ok
		fi
		rm -f "$T/$f"
	done
done <"$ERRORS/expected.tsv"
n_files=$(ls "$ERRORS"/*.txt | wc -l)
check "errors: every file is in expected.tsv" [ "$n_err" -eq "$n_files" ]
check "errors: at least 50 files" [ "$n_files" -ge 50 ]

# Hostile files: each is refused quickly (timeout) within a memory limit
# (ulimit -v), with one located line and no output.
hostile() {
	local name=$1 pattern=$2 file=$3
	clean_wd
	(ulimit -v 1000000 && cd "$T/wd" && exec timeout 20 "$W" -s 8 -o x.png "$file") >"$T/out" 2>"$T/err"
	rc=$?
	if [ "$rc" -ne 1 ]; then bad "hostile $name" "exit $rc: $(cat "$T/err")"
	elif [ "$(err_lines)" -ne 1 ]; then bad "hostile $name" "$(err_lines) stderr lines"
	elif ! grep -qE -- "$pattern" "$T/err"; then bad "hostile $name" "stderr does not match $pattern: $(cat "$T/err")"
	elif ! wd_empty; then bad "hostile $name" "left files: $(wd_files)"
	else ok
	fi
}
head -c 10000000 /dev/zero | tr '\0' 7 >"$T/token.txt"
hostile "10 MB single token" 'token\.txt:1:1: error: token too long' "$T/token.txt"
# The first token of an ELF file ends at its first white-space byte, which
# moves with the program's code: a short token or one over 256 bytes.
hostile "binary file" '^.*/whitted:1:1: error: (expected an integer \(recursion level\)|token too long \(over 256 bytes\) where an integer \(recursion level\) was expected)' "$W"
truncate -s 300M "$T/sparse.txt"
hostile "300 MiB file (sparse) refused by size" 'whitted: error: [^ ]*sparse\.txt: the scene file is larger than the limit of 256 MiB \(--max-scene-size' "$T/sparse.txt"
rm -f "$T/sparse.txt"
yes '# a comment' | head -n 1000000 >"$T/comments.txt"
hostile "a million comment lines" 'comments\.txt:1000001:1: error: .*the file has no data' "$T/comments.txt"
printf '4\n16\n10000000\nsphere 0 0 10 1 1 1 1 0 0 0 0 0\n' >"$T/count.txt"
hostile "object count of ten million, one object" 'count\.txt:5:1: error: expected an object keyword .* for object 2 of 10000000, found end of file' "$T/count.txt"
printf '4\n16\n0\n100000\n0 0 100\n' >"$T/lights.txt"
hostile "light count of 100000, one light" 'lights\.txt:6:1: error: .*found end of file \(100000 lights need 600000 numbers' "$T/lights.txt"
hostile "scene from /dev/zero" '^whitted: error: /dev/zero: the scene file is larger than the limit of 256 MiB' /dev/zero
hostile "scene is /dev/null" '^/dev/null:1:1: error: .*\(the file is empty\)' /dev/null
rm -f "$T/token.txt" "$T/comments.txt"

# A long path (over 256 bytes) is named whole in the message.
long=$T/$(printf 'd%.0s' $(seq 200))/$(printf 'e%.0s' $(seq 200))
mkdir -p "$long"
cp "$ERRORS/nan.txt" "$long/x.txt"
run -s 8 -o x.png "$long/x.txt"
check "long scene path named whole" grep -q "^$long/x.txt:1:1: error: " "$T/err"
rm -rf "$T/$(printf 'd%.0s' $(seq 200))"

# Default output name: SCENE's base name with .png, in the current directory.
default_name() {
	local scene=$1 want=$2
	clean_wd
	mkdir -p "$T/in"
	cp "$SCENE" "$T/in/$scene"
	run -s 4 "../in/$scene"
	check "default name $scene -> $want" [ "$rc" -eq 0 -a -f "$T/wd/$want" ] &&
		check "default name $scene only" [ "$(wd_files)" = "$want" ]
	rm -rf "$T/in"
}
default_name scene.txt scene.png
default_name my.scene.txt my.scene.png
default_name noext noext.png
default_name .hidden .hidden.png
clean_wd
(cd "$T/wd" && "$W" -s 4 - <"$SCENE") 2>"$T/err"
check "default name stdin -> stdin.png" [ -f "$T/wd/stdin.png" ]

# Formats by extension and by --format.
fmt() {
	local name=$1 file=$2 test=$3
	shift 3
	clean_wd
	run -s 8 -o "$file" "$@" "$SCENE"
	check "format $name" [ "$rc" -eq 0 ] && check "format $name content" "$test" "$T/wd/$file"
}
fmt png x.png is_png
fmt bmp x.bmp is_bmp
fmt ppm x.ppm is_ppm
fmt upper-case x.PNG is_png
fmt format-bmp x.img is_bmp --format bmp
fmt format-overrides x.png is_ppm --format ppm
fmt format-upper x.out is_ppm --format PPM
clean_wd
run -s 8 -o x.png "$SCENE"
check "png width" [ "$(png_width "$T/wd/x.png")" -eq 8 ]
run -s 8 -o x.ppm "$SCENE"
check "ppm size" [ "$(wc -c <"$T/wd/x.ppm")" -eq $((11 + 8 * 8 * 3)) ]
run -s 8 -o x.bmp "$SCENE"
check "bmp size" [ "$(wc -c <"$T/wd/x.bmp")" -eq $((54 + 8 * 24)) ]
expect_error unknown-extension 2 "cannot tell the format of 'x.jpg'" -s 8 -o x.jpg "$SCENE"
expect_error no-extension 2 "cannot tell the format of 'x'" -s 8 -o x "$SCENE"
expect_error dot-in-directory 2 "cannot tell the format" -s 8 -o a.png/x "$SCENE"

# -o over an existing file replaces it atomically: a new inode (a hard link
# to the old one keeps the old bytes), the old permissions, no temporary
# file left.
clean_wd
printf 'old image\n' >"$T/wd/x.png"
chmod 640 "$T/wd/x.png"
ln "$T/wd/x.png" "$T/old-link"
run -s 8 -o x.png "$SCENE"
check "replace exit" [ "$rc" -eq 0 ]
check "replace new content" is_png "$T/wd/x.png"
check "replace old inode untouched" [ "$(cat "$T/old-link")" = 'old image' ]
check "replace keeps mode" [ "$(stat -c %a "$T/wd/x.png")" = 640 ]
check "replace no temporary" [ "$(wd_files)" = x.png ]
rm -f "$T/old-link"
clean_wd
(umask 027 && cd "$T/wd" && "$W" -s 4 -o new.png "$SCENE")
check "new file honours umask" [ "$(stat -c %a "$T/wd/new.png")" = 640 ]

# Output to a pipe, /dev/stdout and a FIFO is written directly.
clean_wd
(cd "$T" && "$W" -s 8 -o ref.ppm "$SCENE")
(cd "$T/wd" && "$W" -s 8 -o /dev/stdout --format ppm "$SCENE" | cat >"$T/pipe.ppm")
check "stdout pipe" cmp -s "$T/pipe.ppm" "$T/ref.ppm"
(cd "$T/wd" && "$W" -s 8 -o /dev/stdout --format ppm "$SCENE" >"$T/redir.ppm")
check "stdout redirected to a file" cmp -s "$T/pipe.ppm" "$T/redir.ppm"
check "/dev/stdout still a link" [ -L /dev/stdout ]
check "stdout leaves nothing" wd_empty
mkfifo "$T/wd/fifo.ppm"
cat "$T/wd/fifo.ppm" >"$T/fifo.out" &
reader=$!
run -s 8 -o fifo.ppm "$SCENE"
wait $reader
check "fifo exit" [ "$rc" -eq 0 ]
check "fifo content" cmp -s "$T/pipe.ppm" "$T/fifo.out"
check "fifo still a fifo" [ -p "$T/wd/fifo.ppm" ]
check "fifo no temporary" [ "$(wd_files)" = fifo.ppm ]
clean_wd
run -s 8 -o /dev/null --format png "$SCENE"
check "dev-null exit" [ "$rc" -eq 0 ] && check "dev-null still a device" [ -c /dev/null ]

# Scene from standard input, and --test-scene.
clean_wd
(cd "$T/wd" && "$W" -s 8 -o in.ppm - <"$SCENE") 2>"$T/err"
(cd "$T/wd" && "$W" -s 8 -o file.ppm "$SCENE") 2>>"$T/err"
check "stdin same as file" cmp -s "$T/wd/in.ppm" "$T/wd/file.ppm"
printf '4 8 0 x' | (cd "$T/wd" && "$W" -o e.png -) 2>"$T/err"
check "stdin error located" grep -q '^<stdin>:1:7: error: ' "$T/err"
run -s 8 -o t.png --test-scene
check "test scene" [ "$rc" -eq 0 ]

# The first word: a mistyped subcommand, `whitted help`, a program's name
# (whitted-view, scene2pov) are not scene files; a scene file of any name
# is still read when it is there.  Unknown options of every program get a
# "did you mean".
clean_wd
usage_case() {
	local name=$1 want=$2
	shift 2
	(cd "$T/wd" && "$@") >"$T/out" 2>"$T/err"
	rc=$?
	check "$name: exit 2, not $rc" [ "$rc" -eq 2 ]
	check "$name: message ($(head -1 "$T/err"))" grep -qF -- "$want" "$T/err"
	check "$name: nothing written" wd_empty
}
usage_case "whitted comapre" "error: 'comapre' is not a subcommand (and no file); did you mean 'whitted compare'?" \
	"$W" comapre "$SCENE" x.png
usage_case "whitted grdae" "did you mean 'whitted grade'?" "$W" grdae --scene "$SCENE" x.png
usage_case "whitted view" "'view' is not a subcommand (and no file): the viewer is its own program, whitted-view SCENE" \
	"$W" view x.txt
usage_case "whitted render" "whitted renders without one, whitted [OPTIONS] SCENE" "$W" render "$SCENE"
usage_case "whitted help bogus" "help: no subcommand 'bogus'" "$W" help bogus
(cd "$T/wd" && "$W" help) >"$T/out" 2>"$T/err"
check "whitted help: exit 0 and the usage" [ $? -eq 0 ] && check "whitted help: the usage" grep -q '^Usage: whitted \[OPTIONS\] SCENE' "$T/out"
(cd "$T/wd" && "$W" help compare) >"$T/out" 2>"$T/err"
check "whitted help compare: compare's usage" grep -q '^Usage: whitted compare' "$T/out"
cp "$SCENE" "$T/wd/comapre"
run -q -s 8 -o c.png comapre
check "a scene file named comapre is a scene" [ "$rc" -eq 0 -a -s "$T/wd/c.png" ]
clean_wd
usage_case "whitted --samles" "unknown option '--samles'; did you mean '--samples'?" "$W" --samles 2 "$SCENE"
usage_case "whitted --recusrion=3" "unknown option '--recusrion=3'; did you mean '--recursion'?" "$W" --recusrion=3 "$SCENE"
usage_case "whitted --bogus (nothing near)" "unknown option '--bogus'" "$W" --bogus "$SCENE"
check "whitted --bogus: no guess" bash -c "! grep -q 'did you mean' '$T/err'"
usage_case "merge --ouput" "unknown option '--ouput'; did you mean '--output'?" "$W" merge --ouput x.png a.png
usage_case "compare --difff" "unknown option '--difff'; did you mean '--diff'?" "$W" compare --difff d.png "$SCENE" a.png
usage_case "grade --cvs" "unknown option '--cvs'; did you mean '--csv'?" "$W" grade --cvs x.csv --scene "$SCENE" a.png
usage_case "scene2pov --finsh" "unknown option '--finsh'; did you mean '--finish'?" "$ROOT/build/scene2pov" --finsh plain "$SCENE"
# scripts/deps.sh (make render, make check): what the build needs is looked
# for by what it provides, so that a system without dpkg but with the
# libraries needs nothing (DPKG_QUERY names a program that is not there);
# what is missing there is named, and nothing installed; on Debian as root
# apt-get waits for a package lock held by another process (here a POSIX
# lock on a file of ours, as apt takes it), says so, and gives up after
# DEPS_LOCK_WAIT seconds (apt-get and dpkg-query are fakes that record).
DEPS=$ROOT/scripts/deps.sh
DPKG_QUERY=/nonexistent "$DEPS" build-essential pkg-config libpng-dev zlib1g-dev libstb-dev >"$T/out" 2>"$T/err"
check "deps: no dpkg, the libraries found: exit 0, silent ($(cat "$T/err"))" [ $? -eq 0 -a ! -s "$T/err" -a ! -s "$T/out" ]
DPKG_QUERY=/nonexistent "$DEPS" libpng-dev libnothere-dev >"$T/out" 2>"$T/err"
check "deps: no dpkg, one missing: exit 1" [ $? -eq 1 ]
check "deps: no dpkg, one missing: named, nothing installed" grep -q "not found: libnothere-dev (Debian's package names; not a Debian system, so nothing is" "$T/err"
DPKG_QUERY=/nonexistent "$DEPS" --optional libnothere-dev >"$T/out" 2>"$T/err"
check "deps: no dpkg, an optional one missing: exit 0" [ $? -eq 0 ]
mkdir -p "$T/deps"
printf '#!/bin/sh\nexit 1\n' >"$T/deps/dpkg-query"
printf '#!/bin/sh\necho "$@" >>"%s/deps/apt.log"\n' "$T" >"$T/deps/apt-get"
chmod +x "$T/deps/dpkg-query" "$T/deps/apt-get"
: >"$T/deps/lock"
if [ "$(id -u)" = 0 ] && command -v python3 >/dev/null; then
	hold_lock() {
		python3 -c 'import fcntl, sys, time
f = open(sys.argv[1], "w"); fcntl.lockf(f, fcntl.LOCK_EX); open(sys.argv[1] + ".held", "w").close()
time.sleep(float(sys.argv[2]))' "$T/deps/lock" "$1" &
		holder=$!
		for _ in $(seq 50); do [ -e "$T/deps/lock.held" ] && break; sleep 0.1; done
	}
	hold_lock 2
	DPKG_QUERY="$T/deps/dpkg-query" APT_GET="$T/deps/apt-get" DEPS_LOCKS="$T/deps/lock" DEPS_LOCK_WAIT=20 \
		"$DEPS" libnothere-dev >"$T/out" 2>"$T/err"
	check "deps: a held lock: waited, then installed (exit $?)" grep -q 'install -y -qq --no-install-recommends libnothere-dev' "$T/deps/apt.log"
	check "deps: a held lock: says so" grep -q "^deps: waiting for the package lock, held by process $holder (python3)" "$T/err"
	check "deps: a held lock: the lock's timeout passed on to apt-get" grep -q 'DPkg::Lock::Timeout=20 install' "$T/deps/apt.log"
	wait "$holder"
	rm -f "$T/deps/apt.log" "$T/deps/lock.held"
	hold_lock 30
	DPKG_QUERY="$T/deps/dpkg-query" APT_GET="$T/deps/apt-get" DEPS_LOCKS="$T/deps/lock" DEPS_LOCK_WAIT=1 \
		"$DEPS" libnothere-dev >"$T/out" 2>"$T/err"
	rc=$?
	kill "$holder" 2>/dev/null
	wait "$holder" 2>/dev/null
	check "deps: a lock held too long: exit 1" [ "$rc" -eq 1 ]
	check "deps: a lock held too long: says why" grep -q "the package lock is still held after 1 s" "$T/err"
	check "deps: a lock held too long: apt-get not run" [ ! -e "$T/deps/apt.log" ]
else
	DPKG_QUERY="$T/deps/dpkg-query" APT_GET="$T/deps/apt-get" "$DEPS" libnothere-dev >"$T/out" 2>"$T/err"
	check "deps: not root: the apt-get line" grep -q 'apt-get install -y libnothere-dev' "$T/err"
fi

# scene2pov says what it wrote, and its .ini names its directory, so that
# povray runs it from anywhere (tests/povcheck.sh runs it so).
clean_wd
mkdir "$T/wd/pov"
(cd "$T/wd" && "$ROOT/build/scene2pov" -q -s 8 -o pov/s.pov "$SCENE") >"$T/out" 2>"$T/err"
check "scene2pov: exit 0" [ $? -eq 0 ]
pov_dir=$(cd "$T/wd/pov" && pwd -P)
check "scene2pov: says what it wrote ($(cat "$T/out"))" \
	[ "$(cat "$T/out")" = "scene2pov: wrote pov/s.pov and pov/s.ini; 'povray pov/s.ini' renders $pov_dir/s.png" ]
check "scene2pov: the .ini's library path is its directory" grep -qx "Library_Path=\"$pov_dir\"" "$T/wd/pov/s.ini"
check "scene2pov: the .ini writes the PNG beside it" grep -qx "Output_File_Name=\"$pov_dir/s.png\"" "$T/wd/pov/s.ini"
check "scene2pov: the .ini reads the scene by its name" grep -qx 'Input_File_Name="s.pov"' "$T/wd/pov/s.ini"
clean_wd
if [ -x "$ROOT/build/whitted-view" ]; then
	usage_case "whitted-view --fvo" "unknown option '--fvo'; did you mean '--fov'?" "$ROOT/build/whitted-view" --fvo 50 "$SCENE"
fi

finish
