#!/bin/bash
# `whitted compare` and `whitted grade` through the command line, on what
# the ranking of the causes must keep whatever its code becomes: the
# submissions are made by the independent renderer (ref_render.py
# --mistake), not by whitted.
#  - Causes whose figures are equal come in the causes' table order: on a
#    scene symmetric left-right with an even number of tiles, the mirrored
#    image and the floor's tiles swapped are the same image, and "mirrored"
#    comes first ("1=" twice, "mirrored or floor-swapped" in grade's CSV),
#    on every pixel (30 px) and on a sample (80 px).
#  - The first cause is never the sample's estimate: it is rendered again
#    on every pixel (no "~" before its figure, "estimated": false), for a
#    cause that explains the image and, with 3 levels of noise added to
#    every seventh pixel, for one that comes close without explaining it
#    (a finite figure, which a sample's estimate would not match).
#  - A cause of several forms is ranked by the form nearest the image: a
#    light behind the surface darkening it (the signed diffuse, the third
#    form) is named first.
# Usage: compare_order.sh [WHITTED]
SUITE=compareorder
. "$(dirname "$0")/lib.sh"
[ -n "${1:-}" ] && W=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
REF_RENDER=$ROOT/tests/reference/ref_render.py
I=$T/img
mkdir -p "$I"

# json_check NAME FILE PYTHON: the assertions of PYTHON on the JSON j.
json_check() {
	local name=$1 file=$2 code=$3
	if python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
c = j['causes']
$code
" "$file" 2>"$T/py.err"; then ok
	else bad "$name" "$(tail -1 "$T/py.err")"; fi
}

# Equal causes in table order: mirrored before floor-swapped.
SYM=$DATA/course-files/sadathossain01.txt
for size in 30 80; do
	python3 "$REF_RENDER" "$SYM" "$I/sym$size.ppm" --size $size --mistake floor-swapped
	run compare -q -s $size --json "$SYM" "$I/sym$size.ppm"
	check "tie $size: exit 3" [ "$rc" -eq 3 ]
	json_check "tie $size: mirrored, then floor-swapped (table order)" "$T/out" '
assert j["first"] == ["mirrored", "floor-swapped"], j["first"]
assert [x["id"] for x in c[:2]] == ["mirrored", "floor-swapped"], [x["id"] for x in c[:3]]
assert c[0]["first_equal"] and c[1]["first_equal"] and not c[2]["first_equal"], c[:3]
assert not c[0]["estimated"] and not c[1]["estimated"], c[:2]'
	run compare -q -s $size "$SYM" "$I/sym$size.ppm"
	check "tie $size: the text's two 1= lines in table order" \
		[ "$(grep -E '^  1= ' "$T/out" | sed -E 's/^  1= (.*[a-z]) +(~ +)?inf dB.*/\1/')" = \
		"$(printf "the image mirrored left-right\nthe floor's tiles swapped")" ]
	clean_wd
	run grade -q -s $size --scene "$SYM" --csv tie.csv "$I/sym$size.ppm"
	check "tie $size: grade's CSV says 'mirrored or floor-swapped'" python3 -c '
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[0]
assert r["cause"] == "mirrored or floor-swapped", r["cause"]
' "$T/wd/tie.csv"
done

# The first cause rendered on every pixel (96 px: the ranking samples).
# first_full NAME SCENE MISTAKE WANT EXPLAINS [noisy]: the first cause is
# WANT, not estimated, with no "~" in the text, and explains the image or
# not (True, False); "noisy" adds 3 to the red of every seventh pixel.
first_full() {
	local name=$1 scene=$2 mistake=$3 want=$4 explains=$5 noisy=${6:-}
	python3 "$REF_RENDER" "$scene" "$I/$name.ppm" --size 96 --mistake "$mistake"
	[ -z "$noisy" ] || python3 -c '
import sys
d = bytearray(open(sys.argv[1], "rb").read())
start = d.index(b"255\n") + 4
for k in range(start, len(d), 21):
    d[k] = min(255, d[k] + 3)
open(sys.argv[1], "wb").write(d)
' "$I/$name.ppm"
	run compare -q -s 96 --json "$scene" "$I/$name.ppm"
	json_check "$name: first cause $want, on every pixel" "$T/out" "
assert j['first'] == ['$want'], j['first']
assert c[0]['id'] == '$want' and c[0]['estimated'] is False, c[0]
assert c[0]['explains'] is $explains, c[0]
assert any(x['estimated'] for x in c[1:]), 'no cause after the first was estimated: no sample'"
	run compare -q -s 96 "$scene" "$I/$name.ppm"
	check "$name: no '~' on the first cause" grep -qE '^  1\. [^~]*dB' "$T/out"
}
first_full no-shadows "$ROOT/scenes/scene.txt" no-shadows no-shadows True
first_full no-shadows-noisy "$ROOT/scenes/scene.txt" no-shadows no-shadows False noisy
first_full no-shadows-noisy-2 "$ROOT/scenes/shadows.txt" no-shadows no-shadows False noisy
# A cause's forms: the nearest one counts.
first_full light-behind-signed "$ROOT/scenes/shadows.txt" light-behind-signed light-behind True
first_full light-behind-signed-noisy "$ROOT/scenes/shadows.txt" light-behind-signed light-behind False noisy
finish
