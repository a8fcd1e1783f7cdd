#!/bin/sh
# The image must not depend on the number of threads: renders scenes with
# 1, 2, 3 and 7 threads and compares the files byte for byte.
set -u
BUILD=${BUILD:-build}
W=$BUILD/whitted
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
"$BUILD/gen_scene" 300 >"$T/gen.txt"
for case in "scenes/scene.txt -s 97" "$T/gen.txt -s 61" "scenes/scene.txt -s 40 --clamp final"; do
	set -- $case
	for j in 1 2 3 7; do
		if ! "$W" -q -j $j -o "$T/j$j.ppm" "$@"; then
			echo "threadcheck: whitted failed: -j $j $case"
			fail=$((fail + 1))
			continue
		fi
		if [ $j -ne 1 ]; then
			if cmp -s "$T/j1.ppm" "$T/j$j.ppm"; then
				pass=$((pass + 1))
			else
				echo "threadcheck: -j $j differs from -j 1: $case"
				fail=$((fail + 1))
			fi
		fi
	done
done
echo "threadcheck: $pass passed, $fail failed"
[ $fail -eq 0 ]
