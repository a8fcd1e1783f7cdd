#!/bin/bash
# End-to-end tests of `whitted compare` and `whitted grade`: help and
# usage errors (exit 2), every image layout the reader takes (24-bit
# padded bottom-up BMP as the course's bitmap code writes it, 32-bit and
# top-down BMP, PNG, P6 and P3 PPM), every broken input (exit 1, one clear
# line, nothing written), the figures and the JSON, --diff, every dialect
# and the render options passed through, a cause found and "none comes
# close", and grade's rows, CSV and report.
SUITE=comparetest
. "$(dirname "$0")/lib.sh"
[ -n "$1" ] && W=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SCENE=$ROOT/scenes/scene.txt
I=$T/img
mkdir -p "$I"

# An error run: exit status, a first stderr line containing a fixed string
# (a usage error adds the --help hint as a second), nothing left in the
# work directory.
expect_error() {
	local name=$1 want_rc=$2 pattern=$3
	shift 3
	clean_wd
	run "$@"
	[ "$rc" -eq "$want_rc" ] || { bad "$name" "exit $rc, expected $want_rc ($(head -1 "$T/err"))"; return; }
	[ "$(err_lines)" -eq $((want_rc == 2 ? 2 : 1)) ] || { bad "$name" "$(err_lines) stderr lines: $(cat "$T/err")"; return; }
	head -1 "$T/err" | grep -qF -- "$pattern" || { bad "$name" "stderr lacks '$pattern': $(cat "$T/err")"; return; }
	wd_empty || { bad "$name" "left files: $(wd_files)"; return; }
	ok
}
# expect_status NAME RC ARGS...: the exit status alone.
expect_status() {
	local name=$1 want_rc=$2
	shift 2
	run "$@"
	[ "$rc" -eq "$want_rc" ] || { bad "$name" "exit $rc, expected $want_rc: $(head -3 "$T/err")"; return; }
	ok
}

# Help and usage.
run compare --help
check compare-help [ "$rc" -eq 0 ]
check compare-help-usage grep -q '^Usage: whitted compare' "$T/out"
check compare-help-options grep -q -- '--diff FILE' "$T/out"
run grade --help
check grade-help [ "$rc" -eq 0 ]
check grade-help-usage grep -q '^Usage: whitted grade' "$T/out"
expect_error compare-no-args 2 'no SCENE given' compare
expect_error compare-no-image 2 'no IMAGE given' compare "$SCENE"
expect_error compare-two-images 2 'one IMAGE expected' compare "$SCENE" a.png b.png
expect_error compare-unknown-option 2 "unknown option '--bogus'" compare --bogus "$SCENE" a.png
expect_error compare-bad-size 2 '--size' compare --size 0 "$SCENE" a.png
expect_error compare-diff-format 2 "cannot tell the format of 'd.gif'" compare --diff d.gif "$SCENE" a.png
expect_error compare-grade-option 2 "unknown option '--csv'" compare --csv x.csv "$SCENE" a.png
expect_error grade-no-scene 2 'no scene given (--scene SCENE)' grade a.png
expect_error grade-no-image 2 'no IMAGE given' grade --scene "$SCENE"
expect_error grade-compare-option 2 "unknown option '--json'" grade --json --scene "$SCENE" a.png

# The images: whitted's own renders in its three formats, and the other
# layouts written by make_images.py from the PPM.
"$W" -q -s 30 -o "$I/ref.png" "$SCENE"
"$W" -q -s 30 -o "$I/ref.bmp" "$SCENE"
"$W" -q -s 30 -o "$I/ref.ppm" "$SCENE"
python3 "$ROOT/tests/cli/make_images.py" "$I/ref.ppm" "$I" || bad make-images "make_images.py failed"
for f in ref.png ref.bmp ref.ppm bmp24.bmp bmp32.bmp topdown.bmp ascii.ppm p6-maxval-comment.ppm; do
	run compare -q -s 30 "$SCENE" "$I/$f"
	check "match-$f" [ "$rc" -eq 0 ]
	check "match-$f-verdict" grep -q '^verdict: MATCH' "$T/out"
	check "match-$f-inf" grep -q 'PSNR *inf dB' "$T/out"
done

# Broken inputs: exit 1 and a message that says what is wrong.
expect_error truncated-bmp 1 'truncated BMP: its header gives 30x30 pixels' compare -q -s 30 "$SCENE" "$I/truncated.bmp"
expect_error header-only-bmp 1 'truncated BMP' compare -q -s 30 "$SCENE" "$I/header-only.bmp"
expect_error truncated-ppm 1 'truncated PPM' compare -q -s 30 "$SCENE" "$I/truncated.ppm"
expect_error truncated-ascii 1 'truncated PPM' compare -q -s 30 "$SCENE" "$I/truncated-ascii.ppm"
expect_error bad-sample 1 'bad PPM sample 2' compare -q -s 30 "$SCENE" "$I/bad-sample.ppm"
expect_error empty 1 'an empty file, not an image' compare -q -s 30 "$SCENE" "$I/empty.png"
expect_error text 1 'not an image: PNG, BMP or PPM expected' compare -q -s 30 "$SCENE" "$I/text.png"
expect_error bad-magic 1 'not an image' compare -q -s 30 "$SCENE" "$I/bad-magic.bmp"
expect_error rle-bmp 1 'cannot read the image' compare -q -s 30 "$SCENE" "$I/rle.bmp"
head -c 300 "$I/ref.png" >"$I/truncated.png"
expect_error truncated-png 1 'damaged or truncated' compare -q -s 30 "$SCENE" "$I/truncated.png"
expect_error missing 1 'nosuch.png: cannot open' compare -q -s 30 "$SCENE" nosuch.png
expect_error directory 1 'is a directory' compare -q -s 30 "$SCENE" "$I"
# Another size than the scene's: compared at its own, with a note.
run compare -q -s 32 "$SCENE" "$I/ref.png"
check other-size-matches [ "$rc" -eq 0 ]
check other-size-note grep -qF 'note: the image is 30x30, the scene'"'"'s size 32x32: compared with the reference rendered at 30x30' "$T/out"
run compare -q -s 32 --diff d.png "$SCENE" "$I/ref.png"
check other-size-diff [ "$rc" -eq 0 ] && [ -s "$T/wd/d.png" ]
expect_error scene-error 1 'cannot open' compare -q -s 30 nosuch.txt "$I/ref.png"

# A mistake found: the image mirrored (written by make_images.py's BMP
# writer from a mirrored PPM), with its figures, JSON and --diff.
python3 - "$I/ref.ppm" "$I/mirrored.ppm" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); m, dims, mx, px = d.split(b'\n', 3)
w, h = (int(v) for v in dims.split())
rows = [px[3 * w * y:3 * w * (y + 1)] for y in range(h)]
out = b''.join(b''.join(r[3 * (w - 1 - x):3 * (w - x)] for x in range(w)) for r in rows)
open(sys.argv[2], 'wb').write(b'P6\n%d %d\n255\n' % (w, h) + out)
PY
clean_wd
run compare -q -s 30 --diff diff.png "$SCENE" "$I/mirrored.ppm"
check mirrored-exit [ "$rc" -eq 3 ]
check mirrored-verdict grep -q '^verdict: DIFFERS' "$T/out"
check mirrored-first grep -q '^  1\. the image mirrored left-right .* inf dB  explains the image' "$T/out"
check mirrored-says grep -q '^matches the reference with the image mirrored left-right: the camera' "$T/out"
check mirrored-diff is_png "$T/wd/diff.png"
check mirrored-diff-width [ "$(png_width "$T/wd/diff.png")" -eq 60 ]
run compare -q -s 30 --json "$SCENE" "$I/mirrored.ppm"
check json-exit [ "$rc" -eq 3 ]
check json-fields python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "differs" and j["explained"] == "explained", j
assert j["width"] == 30 and j["height"] == 30
assert 0 < j["psnr"] < 60 and 0 < j["off2"] <= 1 and j["off8"] <= j["off2"] and j["off32"] <= j["off8"]
assert j["causes"][0]["id"] == "mirrored" and j["causes"][0]["psnr"] is None
assert j["causes"][0]["explains"] is True
assert all(c["psnr"] is None or c["psnr"] > 0 for c in j["causes"])
' "$T/out"
run compare -q -s 30 --json "$SCENE" "$I/ref.bmp"
check json-match python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "match" and j["identical"] is True and j["psnr"] is None and j["causes"] == []
' "$T/out"

# An image of another scene: the causes are listed and none explains it.
"$W" -q -s 30 -o "$I/other.png" "$ROOT/scenes/mirrors.txt"
run compare -q -s 30 "$SCENE" "$I/other.png"
check other-exit [ "$rc" -eq 3 ]
check other-none grep -q '^none of the known mistakes comes close' "$T/out"

# The right image with a faint difference no mistake makes (every fifth
# pixel's red 5 levels up: about 46 dB, a fifth of the pixels off by more
# than 2): it differs, and nearly matches, which is what a person sees.
"$W" -q -s 30 -o "$I/faint.ppm" "$SCENE"
python3 - "$I/faint.ppm" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
head = data.split(b'\n', 3)
assert head[0] == b'P6' and head[2] == b'255', head[:3]
w, h = head[1].split()
px = bytearray(head[3])
for k in range(0, len(px) // 3, 5):
    px[3 * k] = min(255, px[3 * k] + 5) if px[3 * k] < 250 else px[3 * k] - 5
open(sys.argv[1], 'wb').write(b'P6\n%s %s\n255\n' % (w, h) + bytes(px))
PY
run compare -q -s 30 --no-camera-fit "$SCENE" "$I/faint.ppm"
check faint-exit [ "$rc" -eq 3 ]
check faint-nearly grep -q '^nearly matches ([4-5][0-9]\.[0-9] dB; 20\.00% of the pixels differ): no known mistake comes nearer' "$T/out"

# A view of the bare floor (no object in it): any camera at its height
# and tilt sees the same checker, so no camera found is stood by (before,
# one 12 degrees wide looking away from the scene was "found").
"$W" -q -s 48 --eye 400,380,60 --look 400,420,0 --up 0,0,1 --fov 60 -o "$I/floor-only.png" "$SCENE"
run compare -q --json -s 48 "$SCENE" "$I/floor-only.png"
check floor-alone python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "differs" and j["camera"]["fitted"] is True, j
assert j["camera"]["moved"] is False and j["camera"]["floor_alone"] is True, j["camera"]
' "$T/out"

# Every dialect, and the render options passed through to the reference.
for f in scene.txt spot.txt pyramid.txt nearfar.txt; do
	"$W" -q -s 24 -o "$I/$f.png" "$ROOT/scenes/$f"
	expect_status "dialect-$f" 0 compare -q -s 24 "$ROOT/scenes/$f" "$I/$f.png"
done
OPTS=(-s 26 -r 2 --eye 30,-180,40 --look 0,10,5 --fov 60 --floor 600,25 --clamp final)
"$W" -q "${OPTS[@]}" -o "$I/opts.bmp" "$SCENE"
expect_status options-match 0 compare -q "${OPTS[@]}" "$SCENE" "$I/opts.bmp"
expect_status options-left-out 3 compare -q -s 26 "$SCENE" "$I/opts.bmp"
"$W" -q -s 26 -o "$I/nofloor.bmp" --no-floor "$SCENE"
expect_status no-floor 0 compare -q -s 26 --no-floor "$SCENE" "$I/nofloor.bmp"
"$W" -q -s 26 -o "$I/dialect.png" --dialect nearfar "$ROOT/scenes/nearfar.txt"
expect_status dialect-option 0 compare -q -s 26 --dialect nearfar "$ROOT/scenes/nearfar.txt" "$I/dialect.png"
"$W" -q -s 20 -o "$I/test-scene.png" --test-scene
expect_status test-scene 0 compare -q -s 20 --test-scene "$I/test-scene.png"

# Written by truncating 255 c (the course's (unsigned char)(c * 255)), by
# the independent renderer: a match, with the note; the mistake of never
# clamping in that form (the truncated byte wrapping) still named.
REF_RENDER=$ROOT/tests/reference/ref_render.py
python3 "$REF_RENDER" "$SCENE" "$I/trunc.ppm" --size 30 --truncate
run compare -q -s 30 "$SCENE" "$I/trunc.ppm"
check truncated-match [ "$rc" -eq 0 ]
check truncated-note grep -q 'written by truncating 255\*c, not rounding: fine' "$T/out"
run compare -q -s 30 --json "$SCENE" "$I/trunc.ppm"
check truncated-json python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "match" and j["conversion"] == "truncate", j
assert j["psnr_rounded"] is not None and j["psnr_rounded"] < 60, j
' "$T/out"
BRIGHT=$ROOT/scenes/bright-reflection.txt
python3 "$REF_RENDER" "$BRIGHT" "$I/wrap-trunc.ppm" --size 40 --truncate --mistake no-clamp
run compare -q -s 40 --json "$BRIGHT" "$I/wrap-trunc.ppm"
check truncated-wrap python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["first"] == ["no-clamp"] and j["causes"][0]["truncated"] is True, j
' "$T/out"

# Isolated outliers: the gate's PSNR leaves out the worst 0.02 % (one
# pixel of 80 x 80); a pixel more off by > 8 than that allows differs.
"$W" -q -s 80 -o "$I/ref80.ppm" "$SCENE"
python3 - "$I/ref80.ppm" "$I" <<'PY'
import sys
d = bytearray(open(sys.argv[1], 'rb').read()); head = len(d) - 80 * 80 * 3
d[head + 3 * 1000:head + 3 * 1000 + 3] = bytes(((v + 150) % 256 for v in d[head + 3 * 1000:head + 3 * 1000 + 3]))
open(sys.argv[2] + '/outlier1.ppm', 'wb').write(d)
d[head + 3 * 4000:head + 3 * 4000 + 3] = bytes(((v + 150) % 256 for v in d[head + 3 * 4000:head + 3 * 4000 + 3]))
open(sys.argv[2] + '/outlier2.ppm', 'wb').write(d)
PY
run compare -q -s 80 --json "$SCENE" "$I/outlier1.ppm"
check outlier-one python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["verdict"] == "match" and j["psnr"] < 60 and j["psnr_gate"] is None and j["left_out"] == 1, j
' "$T/out"
expect_status outlier-two 3 compare -q -s 80 "$SCENE" "$I/outlier2.ppm"
run compare -q -s 80 "$SCENE" "$I/outlier1.ppm"
check outlier-text grep -q 'PSNR of gate  *inf dB .*the worst 1 pixel' "$T/out"

# A scene symmetric left-right with an even number of tiles: mirrored and
# the tiles swapped are the same image; neither is preferred.
SYM=$DATA/course-files/sadathossain01.txt
python3 "$REF_RENDER" "$SYM" "$I/sym.ppm" --size 30 --mistake floor-swapped
run compare -q -s 30 --json "$SYM" "$I/sym.ppm"
check tie-json python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert sorted(j["first"]) == ["floor-swapped", "mirrored"], j
assert j["causes"][0]["first_equal"] and j["causes"][1]["first_equal"], j
assert not j["causes"][2]["first_equal"], j
' "$T/out"
run compare -q -s 30 "$SYM" "$I/sym.ppm"
check tie-text grep -q '^  1= the floor.s tiles swapped\|^  1= the image mirrored' "$T/out"
check tie-says grep -q 'or equally with' "$T/out"
clean_wd
run grade -q -s 30 --scene "$SYM" --csv tie.csv "$I/sym.ppm"
check tie-csv python3 -c '
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[0]
assert r["cause"] in ("mirrored or floor-swapped", "floor-swapped or mirrored"), r
' "$T/wd/tie.csv"

# File names: a non-UTF-8 name still gives valid JSON (U+FFFD for the
# bad bytes); a name that a spreadsheet would run as a formula is quoted
# as text in the CSV.
cp "$I/mirrored.ppm" "$I/$(printf 'bad\377\376name.ppm')"
run compare -q -s 30 --json "$SCENE" "$I/$(printf 'bad\377\376name.ppm')"
check json-non-utf8 python3 -c '
import json, sys
j = json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))
assert j["image"].endswith("bad\ufffd\ufffdname.ppm"), j["image"]
' "$T/out"
clean_wd
cp "$I/mirrored.ppm" "$T/wd/=1+1.ppm"
cp "$I/other.png" "$T/wd/-other.png"
run grade -q -s 30 --scene "$SCENE" --csv inj.csv ./=1+1.ppm =1+1.ppm ./-other.png
check csv-formula python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows[0]["file"] == "./=1+1.ppm" and rows[1]["file"] == "\x27=1+1.ppm", rows
' "$T/wd/inj.csv"

# grade: one row per image, the CSV, the report; a differing or unreadable
# image makes the exit status 3 and still gets its row.
clean_wd
run grade -q -s 30 --scene "$SCENE" -o report.html --csv rows.csv "$I/ref.png" "$I/mirrored.ppm" \
	"$I/truncated.bmp" "$I/other.png"
check grade-exit [ "$rc" -eq 3 ]
check grade-rows [ "$(grep -c . "$T/out")" -eq 6 ]
check grade-row-match grep -q 'ref.png  *match  *inf  *10  matches the reference$' "$T/out"
check grade-summary grep -q '^class: 4 images of 4 students: 1 match, 2 differ, 1 unreadable; by outcome: match 1, mirrored 1, unreadable 1, ' "$T/out"
check grade-row-mirrored grep -q 'mirrored.ppm  *differs .*matches the reference with the image mirrored' "$T/out"
check grade-row-unreadable grep -q 'truncated.bmp  *unreadable .*truncated BMP' "$T/out"
check grade-csv-lines [ "$(wc -l <"$T/wd/rows.csv")" -eq 5 ]
check grade-csv-parse python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["verdict"] for r in rows] == ["match", "differs", "unreadable", "differs"], rows
assert rows[1]["cause"] == "mirrored" and rows[1]["explains"] == "yes"
assert rows[0]["psnr"] == "inf" and rows[3]["explains"] == ""
assert rows[3]["cause"] == "" and rows[3]["cause_psnr"] == "", rows[3]
' "$T/wd/rows.csv"
check grade-report grep -q '<table id="summary">' "$T/wd/report.html"
check grade-report-rows [ "$(grep -c '<tr class="row ' "$T/wd/report.html")" -eq 4 ]
check grade-report-inline [ "$(grep -o 'src="data:image/png;base64,' "$T/wd/report.html" | wc -l)" -eq 9 ]
check grade-report-offline bash -c "! grep -qE 'src=\"(https?:|//)' '$T/wd/report.html'"
run grade -q -s 30 --scene "$SCENE" "$I/ref.png" "$I/ref.bmp"
check grade-all-match [ "$rc" -eq 0 ]
expect_status grade-report-unwritable 1 grade -q -s 30 --scene "$SCENE" -o /nonexistent/r.html "$I/ref.png"
# ... found before the first image is graded: no row printed.
check grade-unwritable-first [ ! -s "$T/out" ]
check grade-unwritable-says grep -q "cannot write --output '/nonexistent/r.html'.*checked before grading" "$T/err"

finish
