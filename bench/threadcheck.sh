#!/bin/sh
# The image must not depend on the number of threads: renders scenes with
# 1, 2, 3 and 7 threads and compares the files byte for byte.  The 12,000
# object scene is big enough for the hierarchy's build to split its work
# between threads too; helgrind (when valgrind is installed) then looks
# for data races in the build, the parse's hashing thread and the render.
set -u
BUILD=${BUILD:-build}
W=$BUILD/whitted
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
"$BUILD/gen_scene" 300 >"$T/gen.txt"
"$BUILD/gen_scene" 12000 >"$T/gen12k.txt"
for case in "scenes/scene.txt -s 97" "$T/gen.txt -s 61" "scenes/scene.txt -s 40 --clamp final" \
	"$T/gen12k.txt -s 33"; do
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
# The 12k file (over 1 MiB) is read in parts by several threads, and its
# tree built by several: helgrind looks for races there, memcheck for
# leaks and bad reads and writes.
if command -v valgrind >/dev/null 2>&1; then
	for tool in "--tool=helgrind" "--tool=memcheck --leak-check=full --errors-for-leak-kinds=all"; do
		# shellcheck disable=SC2086
		if valgrind $tool -q --error-exitcode=9 "$W" -q -j 3 -s 16 -o "$T/vg.ppm" \
			"$T/gen12k.txt" 2>"$T/vg.err"; then
			pass=$((pass + 1))
		else
			echo "threadcheck: valgrind $tool reports:"
			cat "$T/vg.err"
			fail=$((fail + 1))
		fi
	done
else
	echo "threadcheck: helgrind and memcheck NOT RUN (valgrind is not installed)"
fi
echo "threadcheck: $pass passed, $fail failed"
[ $fail -eq 0 ]
