#!/bin/sh
# The hierarchy's SSE2 code (the box tests of the traversal, the box
# growth of the build) has a plain C twin for machines without SSE2,
# chosen by ACCEL_PORTABLE.  Both must give the same images byte for byte:
# renders every scene in scenes/ and generated ones with each build and
# compares the files.  Usage: portablecheck.sh WHITTED PORTABLE_WHITTED
set -u
BUILD=${BUILD:-build}
W=$1
P=$2
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
"$BUILD/gen_scene" 12000 >"$T/surface.txt"
"$BUILD/gen_scene" --layout cloud 3000 >"$T/cloud.txt"
for scene in scenes/*.txt "$T/surface.txt" "$T/cloud.txt"; do
	for j in 1 3; do
		if ! "$W" -q -j $j -s 96 -o "$T/sse.ppm" "$scene" 2>/dev/null; then
			continue	# a scene the renderer refuses: not this check's business
		fi
		if "$P" -q -j $j -s 96 -o "$T/portable.ppm" "$scene" 2>/dev/null &&
			cmp -s "$T/sse.ppm" "$T/portable.ppm"; then
			pass=$((pass + 1))
		else
			echo "portablecheck: $scene -j $j: the portable build's image differs"
			fail=$((fail + 1))
		fi
	done
done
echo "portablecheck: $pass passed, $fail failed"
[ $fail -eq 0 ] && [ $pass -gt 0 ]
