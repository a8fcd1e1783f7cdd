#!/bin/sh
# --samples N end to end.  The identity that defines it: whitted at size S
# with --samples N equals whitted at N*S reduced by N x N box averaging
# (imgfilter box) to within one level, on every scene in scenes/ for
# N = 2, 3, 4, under both clamp modes (each sample is clamped to [0, 1]
# before the mean, so --clamp final's one clamp is per sample); the image
# is the same for 1 and 3 threads and when rendered as tiles and merged;
# --samples 1 is byte-identical to no option.  Ends with "samples: N
# passed, N failed, N skipped".
set -u
. "$(dirname "$0")/lib.sh"
S=20

# within1 A B: every channel of every pixel within one level.
within1() {
	line=$("$B/imgcmp" --min-psnr 0 --max-off2 100 --max-off8 100 "$1" "$2" 2>&1)
	case $line in
	*" max=0 "* | *" max=1 "*) return 0 ;;
	*) echo "$line"; return 1 ;;
	esac
}

for scene in "$top"/scenes/*.txt; do
	name=$(basename "$scene" .txt)
	for n in 2 3 4; do
		for clamp in level final; do
			"$W" -q -j 2 -s $S --clamp $clamp --samples $n -o "$tmp/a.png" "$scene" &&
			"$W" -q -j 2 -s $((S * n)) --clamp $clamp -o "$tmp/big.png" "$scene" &&
			"$B/imgfilter" box $n "$tmp/big.png" "$tmp/b.png" || { bad "$name N=$n $clamp: render"; continue; }
			if within1 "$tmp/a.png" "$tmp/b.png"; then ok; else bad "$name N=$n $clamp: not the box average of $((S * n))"; fi
		done
	done
done

scene=$top/scenes/mirrors.txt
"$W" -q -s 37 --samples 3 -j 1 -o "$tmp/j1.png" "$scene"
"$W" -q -s 37 --samples 3 -j 3 -o "$tmp/j3.png" "$scene"
if cmp -s "$tmp/j1.png" "$tmp/j3.png"; then ok; else bad "threads: -j 1 and -j 3 differ"; fi
set --
for k in 1 2 3 4 5 6; do
	"$W" -q -s 37 --samples 3 --grid 3x2 --tile $k -o "$tmp/t$k.png" "$scene" || bad "tile $k"
	set -- "$@" "$tmp/t$k.png"
done
"$W" merge -o "$tmp/merged.png" "$@" && "$B/imgfilter" gamma 1 "$tmp/merged.png" "$tmp/m1.png" &&
	"$B/imgfilter" gamma 1 "$tmp/j1.png" "$tmp/f1.png"
if cmp -s "$tmp/m1.png" "$tmp/f1.png"; then ok; else bad "tiles: merged tiles differ from the full image"; fi
"$W" -q -s 37 -o "$tmp/t1x.png" --region 0,0,12,18 "$scene"
if "$W" merge -o "$tmp/mixed.png" "$tmp/t1x.png" "$tmp/t2.png" "$tmp/t3.png" "$tmp/t4.png" \
	"$tmp/t5.png" "$tmp/t6.png" 2>/dev/null; then bad "merge took a tile without --samples"; else ok; fi
"$W" -q -s 37 -o "$tmp/d.png" "$scene"
"$W" -q -s 37 --samples 1 -o "$tmp/d1.png" "$scene"
if cmp -s "$tmp/d.png" "$tmp/d1.png"; then ok; else bad "--samples 1 differs from the default"; fi
for v in 0 17 x 2.5; do
	if "$W" -q --samples $v -o "$tmp/e.png" "$scene" 2>"$tmp/err"; then bad "--samples $v accepted"
	elif [ $? -eq 2 ] && grep -q -- --samples "$tmp/err" && [ ! -e "$tmp/e.png" ]; then ok
	else bad "--samples $v: $(cat "$tmp/err")"; fi
done
echo "samples: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
