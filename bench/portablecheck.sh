#!/bin/sh
# The hierarchy's SSE2 code (the box tests of the traversal, the box
# growth and binning of the build) has a plain C twin for machines without
# SSE2, chosen by ACCEL_PORTABLE, and a big scene's walks have AVX-512 or
# AVX2 box tests over eight-child nodes where the processor has them
# (WHITTED_ISA=avx2 and WHITTED_ISA=sse2 cap them).  All must give the same
# images byte for byte:
# renders every scene in scenes/ and tests/scenes/ and generated ones with
# each build and compares the files.  Every scene must render with both
# builds: a scene that either refuses is a failure, not a skip (it would
# hide a crash of one build and leave the other unchecked).
# Usage: portablecheck.sh WHITTED PORTABLE_WHITTED
set -u
BUILD=${BUILD:-build}
W=$1
P=$2
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
: >"$T/walks"
"$BUILD/gen_scene" 12000 >"$T/surface.txt"
"$BUILD/gen_scene" --layout cloud 3000 >"$T/cloud.txt"
for scene in scenes/*.txt tests/scenes/*.txt "$T/surface.txt" "$T/cloud.txt"; do
	for j in 1 3; do
		if ! "$W" -q -j $j -s 96 -o "$T/sse.ppm" "$scene" 2>"$T/err"; then
			echo "portablecheck: $scene -j $j: the SSE2 build fails: $(head -3 "$T/err")"
			fail=$((fail + 1))
			continue
		fi
		if ! "$P" -q -j $j -s 96 -o "$T/portable.ppm" "$scene" 2>"$T/err"; then
			echo "portablecheck: $scene -j $j: the portable build fails: $(head -3 "$T/err")"
			fail=$((fail + 1))
		elif cmp -s "$T/sse.ppm" "$T/portable.ppm"; then
			pass=$((pass + 1))
		else
			echo "portablecheck: $scene -j $j: the portable build's image differs"
			fail=$((fail + 1))
		fi
		# The narrower walks where the processor would run wider ones.
		for isa in avx2 sse2; do
			if ! WHITTED_ISA=$isa "$W" -q --stats -j $j -s 96 -o "$T/$isa.ppm" "$scene" \
				2>"$T/err"; then
				echo "portablecheck: $scene -j $j: the walk under WHITTED_ISA=$isa fails: $(head -3 "$T/err")"
				fail=$((fail + 1))
			elif cmp -s "$T/sse.ppm" "$T/$isa.ppm"; then
				pass=$((pass + 1))
			else
				echo "portablecheck: $scene -j $j: the image under WHITTED_ISA=$isa differs from the default's"
				fail=$((fail + 1))
			fi
			sed -n 's/.*, \([a-z0-9]*\) walk).*/\1/p' "$T/err" >>"$T/walks"
		done
		"$W" -q --stats -j $j -s 8 -o "$T/w.ppm" "$scene" 2>&1 |
			sed -n 's/.*, \([a-z0-9]*\) walk).*/\1/p' >>"$T/walks"
	done
done
echo "portablecheck: $pass passed, $fail failed; walks compared with the portable build's: $(sort -u "$T/walks" | tr '\n' ' ')portable"
[ $fail -eq 0 ] && [ $pass -gt 0 ]
