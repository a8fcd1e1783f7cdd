#!/bin/sh
# The hierarchy's SSE2 code (the box tests of the traversal, the box
# growth and binning of the build) has a plain C twin for machines without
# SSE2, chosen by ACCEL_PORTABLE, and the walks have AVX2 box tests chosen
# where the processor has them (WHITTED_ISA=sse2 keeps the SSE2 ones).  All
# must give the same images byte for byte:
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
		# The SSE2 walks where the processor would run the AVX2 ones.
		if ! WHITTED_ISA=sse2 "$W" -q -j $j -s 96 -o "$T/sse2.ppm" "$scene" 2>"$T/err"; then
			echo "portablecheck: $scene -j $j: the SSE2 walk fails: $(head -3 "$T/err")"
			fail=$((fail + 1))
		elif cmp -s "$T/sse.ppm" "$T/sse2.ppm"; then
			pass=$((pass + 1))
		else
			echo "portablecheck: $scene -j $j: the SSE2 walk's image differs from the default's"
			fail=$((fail + 1))
		fi
	done
done
echo "portablecheck: $pass passed, $fail failed"
[ $fail -eq 0 ] && [ $pass -gt 0 ]
