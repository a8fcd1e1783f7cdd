#!/bin/bash
# The four dialects of the course format end to end (scene-format.md):
# every file of tests/data/course-files and tests/data/real-scenes with the
# outcome its README names (the dialect note, the notes, the error's place
# and message), --dialect forcing each dialect, the same files in scene2pov,
# and no output file for any refused one.
SUITE=dialects
. "$(dirname "$0")/lib.sh"
P=$ROOT/build/scene2pov
CF=$DATA/course-files
RS=$DATA/real-scenes

# renders NAME FILE DIALECT-NOTE [OTHER-NOTE-PATTERN...]: the file renders
# to a PNG, stderr holds the dialect note (exactly once) and each pattern.
renders() {
	local name=$1 file=$2 want=$3 pat
	shift 3
	clean_wd
	run -s 24 -o out.png "$file"
	if [ "$rc" -ne 0 ]; then bad "$name" "exit $rc: $(cat "$T/err")"; return; fi
	is_png "$T/wd/out.png" || { bad "$name" "no PNG"; return; }
	if [ "$(grep -c ': note: read as the ' "$T/err")" -ne 1 ]; then
		bad "$name" "not one dialect note: $(cat "$T/err")"; return
	fi
	grep -qF -- "note: read as the $want" "$T/err" ||
		{ bad "$name" "expected 'read as the $want': $(cat "$T/err")"; return; }
	for pat in "$@"; do
		grep -qE -- "$pat" "$T/err" || { bad "$name" "stderr lacks /$pat/: $(cat "$T/err")"; return; }
	done
	ok
}

# refused NAME FILE LOCATION MESSAGE [ARGS...]: exit 1, one stderr line
# FILE:LOCATION: error: ... MESSAGE ..., nothing written.
refused() {
	local name=$1 file=$2 loc=$3 msg=$4 line
	shift 4
	clean_wd
	run -s 24 -o out.png "$@" "$file"
	line=$(head -1 "$T/err")
	if [ "$rc" -ne 1 ]; then bad "$name" "exit $rc, expected 1: $line"
	elif [ "$(err_lines)" -ne 1 ]; then bad "$name" "$(err_lines) stderr lines: $(cat "$T/err")"
	elif [ "${line#"$file:$loc: error: "}" = "$line" ]; then bad "$name" "expected $file:$loc: error:, got: $line"
	elif ! printf '%s\n' "$line" | grep -qF -- "$msg"; then bad "$name" "message lacks '$msg': $line"
	elif ! wd_empty; then bad "$name" "left files: $(wd_files)"
	else ok
	fi
}

TRAIL='note: ignoring [0-9]+ lines? after the last'
renders munzer2 "$CF/munzer2.txt" "spot dialect (4 point lights, 1 spotlight)"
renders sadathossain01 "$CF/sadathossain01.txt" "spot dialect (6 point lights, 3 spotlights)" \
	'sadathossain01.txt:1: note: skipped the UTF-8 byte order mark'
renders an-akhand "$CF/an-akhand.txt" "nearfar dialect (1 point light, 1 spotlight)" "$TRAIL"
renders rafid013 "$CF/rafid013.txt" "nearfar dialect"
renders tanjeem29 "$CF/tanjeem29.txt" "nearfar dialect (1 point light, 1 spotlight)" \
	'note: each light has a colour line'
renders akib1689 "$CF/akib1689.txt" "nearfar dialect"
renders ishtiaqniloy "$CF/ishtiaqniloy.txt" "pyramid dialect"
renders mdraihansobhan "$RS/mdraihansobhan.txt" "spot dialect (4 point lights, 1 spotlight)"
renders anachor "$RS/anachor.txt" "classic dialect (4 point lights)" "$TRAIL"
for f in pistachio102 adibashaira ajakil; do
	renders "$f" "$RS/$f.txt" "classic dialect"
done
# A spotlight section of count 0 (the course example and a last "0"): the
# spot dialect, with no note of numbers left over, and the example's image.
(cat "$ROOT/scenes/scene.txt"; printf '\n0\n') >"$T/spot0.txt"
renders spot-zero "$T/spot0.txt" "spot dialect (4 point lights, 0 spotlights)"
check "spot-zero: nothing ignored" bash -c "! grep -q ignoring '$T/err'"
run -s 24 -o "$T/spot0.ppm" "$T/spot0.txt"
run -s 24 -o "$T/classic.ppm" "$ROOT/scenes/scene.txt"
check "spot-zero: the example's image" cmp -s "$T/spot0.ppm" "$T/classic.ppm"
refused thr0m3l "$CF/thr0m3l.txt" 79:5 "a count does not describe the data"
refused abir66-quad "$CF/abir66-quad.txt" 65:1 "unknown object 'quad'; known objects: sphere"
refused apurbostarry "$RS/apurbostarry.txt" 48:2 "expected an integer (light count), found end of file"
refused nazmultakbir "$RS/nazmultakbir.txt" 10:9 "expected an object keyword"

# The image of a nearfar file is square whatever its aspect ratio.
clean_wd
run -s 32 -o a.png "$CF/akib1689.txt"
check "akib1689 square" [ "$(png_width "$T/wd/a.png")" -eq 32 ]

# --floor resizes a nearfar file's floor and keeps its finish (KA KD 0 KR).
clean_wd
run -q --stats -s 16 -o f.png --floor 1000,50 "$CF/an-akhand.txt"
check "nearfar --floor keeps the file's finish" grep -qF "floor=1000,50 floor-finish=" "$T/err"

# Every file of both folders is named here.
for f in "$CF"/*.txt "$RS"/*.txt; do
	grep -qF "$(basename "$f" .txt)" "$0" || bad "named" "$(basename "$f") is not tested"
done

# --dialect: a forced dialect reads as it, and a file of another dialect
# is refused where it stops fitting.
clean_wd
run -s 24 -o out.png --dialect spot "$CF/munzer2.txt"
check "forced spot renders" [ "$rc" -eq 0 ]
check "forced spot: the note says so" grep -qF "read as the spot dialect, as asked (4 point lights" "$T/err"
clean_wd
run -s 24 -o out.png --dialect classic "$CF/munzer2.txt"
check "a spot file as classic: exit 1" [ "$rc" -eq 1 ]
check "a spot file as classic: the spotlight count is where the data should end" \
	grep -qF "expected the end of the data after the last light, found the number" "$T/err"
check "a spot file as classic: nothing written" wd_empty
# ... and says what the numbers are and what auto-detection reads, rather
# than that a count of N would need 10 N numbers when 10 N follow.
check "a spot file as classic: a whole spotlight section" \
	grep -qE "they are a whole spotlight section \(a count of [0-9]+ and [0-9]+ numbers\), which only the spot dialect has" "$T/err"
check "a spot file as classic: what auto-detection reads" \
	grep -qF "; auto-detection (no --dialect classic) reads it without error as the spot dialect" "$T/err"
check "a spot file as classic: no 'would need'" bash -c "! grep -q 'would need' '$T/err'"
clean_wd
run -s 24 -o out.png --dialect nearfar "$RS/ajakil.txt"
check "a classic file as nearfar: exit 1" [ "$rc" -eq 1 ]
check "a classic file as nearfar: located" grep -qE 'ajakil.txt:[0-9]+:[0-9]+: error: ' "$T/err"
check "a classic file as nearfar: what auto-detection reads" \
	grep -qF "; auto-detection (no --dialect nearfar) reads it without error as the classic dialect" "$T/err"
clean_wd
run -s 24 -o out.png --dialect pyramid "$CF/ishtiaqniloy.txt"
check "forced pyramid renders" [ "$rc" -eq 0 ]
clean_wd
run -s 24 -o out.png --dialect classic "$CF/ishtiaqniloy.txt"
check "a pyramid file as classic: exit 1" [ "$rc" -eq 1 ]
check "a pyramid file as classic: the keyword is not classic's" \
	grep -qF "unknown object 'pyramid' in the classic dialect" "$T/err"
check "a pyramid file as classic: what auto-detection reads" \
	grep -qF "reads it without error as the pyramid dialect" "$T/err"
# A forced dialect's error on a file that auto-detection cannot read either
# says nothing of it.
clean_wd
run -s 24 -o out.png --dialect classic "$ROOT/tests/errors/nearfar-nan-fovy.txt"
check "a broken file as classic: exit 1" [ "$rc" -eq 1 ]
check "a broken file as classic: no auto-detection clause" bash -c "! grep -q 'auto-detection' '$T/err'"
clean_wd
run -s 24 -o out.png --dialect bogus "$RS/ajakil.txt"
check "--dialect bogus: exit 2" [ "$rc" -eq 2 ]
check "--dialect bogus: message" grep -qF "expected auto, classic, spot, pyramid or nearfar" "$T/err"

# A forced dialect reads the same as the detected one.
for f in "$CF/munzer2.txt:spot" "$CF/an-akhand.txt:nearfar" "$CF/ishtiaqniloy.txt:pyramid" \
	"$RS/ajakil.txt:classic"; do
	file=${f%:*} d=${f##*:}
	clean_wd
	run -q -s 24 -o auto.ppm "$file" && run -q -s 24 -o forced.ppm --dialect "$d" "$file"
	check "$(basename "$file") auto = --dialect $d" cmp -s "$T/wd/auto.ppm" "$T/wd/forced.ppm"
done

# scene2pov reads every dialect the same way.
for f in munzer2 an-akhand tanjeem29 ishtiaqniloy sadathossain01; do
	clean_wd
	(cd "$T/wd" && "$P" -q -s 24 -o "$f.pov" "$CF/$f.txt") >"$T/out" 2>"$T/err"
	check "scene2pov $f" [ $? -eq 0 -a -s "$T/wd/$f.pov" -a -s "$T/wd/$f.ini" ]
done
clean_wd
(cd "$T/wd" && "$P" -q -o t.pov "$CF/thr0m3l.txt") >"$T/out" 2>"$T/err"
check "scene2pov thr0m3l refused" [ $? -eq 1 ]
check "scene2pov thr0m3l nothing written" wd_empty

# Under valgrind: every course file, rendered or refused, with no memory
# error and no leak.
if command -v valgrind >/dev/null 2>&1; then
	for f in "$CF"/*.txt; do
		clean_wd
		(cd "$T/wd" && valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=all \
			"$W" -q -j2 -s 8 -o v.png "$f") >"$T/out" 2>"$T/err"
		rc=$?
		check "valgrind $(basename "$f") (exit $rc)" [ "$rc" -eq 0 -o "$rc" -eq 1 ]
	done
else
	bad "valgrind" "valgrind is not installed (make deps)"
fi

finish
