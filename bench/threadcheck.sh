#!/bin/sh
# The image must not depend on the number of threads: renders scenes with
# 1, 2, 3 and 7 threads and compares the files byte for byte.  The 12,000
# object scene is big enough for the hierarchy's build to split its work
# between threads too; helgrind (when valgrind is installed) then looks
# for data races in the build, the parse's hashing thread and the render,
# and in a PNG compressed by the render's threads or after it by the
# write's.  The PNG files of 1, 2, 3 and 7 threads are compared too
# (compressed during the render or after it).  Every size leaves partial
# 16x16 blocks at the right and bottom edges (203 = 12 x 16 + 11).  Since
# images that agree with each other can all be wrong alike, the 203-pixel
# render is also checked against what does not share the block loop: the
# independent Python renderer (tests/reference/ref_render.py, imgcmp's
# gate) and a merge of --region renders cut off the 16-pixel grid (so
# every block falls elsewhere).
set -u
BUILD=${BUILD:-build}
W=$BUILD/whitted
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
pass=0 fail=0
"$BUILD/gen_scene" 300 >"$T/gen.txt"
"$BUILD/gen_scene" 12000 >"$T/gen12k.txt"
for case in "scenes/scene.txt -s 203" "scenes/scene.txt -s 97" "$T/gen.txt -s 61" \
	"scenes/scene.txt -s 40 --clamp final" "$T/gen12k.txt -s 33"; do
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
# The PNG file too: with as many threads as processors or more, the
# render's threads compress its strips as they are rendered; with fewer,
# the write compresses them after the render.  The bytes are the same.
# The processor count is in the list so that a machine of more than 7
# reaches the first path too.
np=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)
for j in 1 2 3 7 $np; do
	"$W" -q -j $j -s 203 -o "$T/p$j.png" scenes/scene.txt || echo "threadcheck: PNG -j $j failed"
	if [ $j -ne 1 ]; then
		if cmp -s "$T/p1.png" "$T/p$j.png"; then
			pass=$((pass + 1))
		else
			echo "threadcheck: the PNG of -j $j differs from -j 1's"
			fail=$((fail + 1))
		fi
	fi
done
# The 203-pixel course scene with 1 and 7 threads against the reference
# renderer, and against the merge of nine regions whose edges (5, 101 and
# 7, 150) lie off the block grid.
"$W" -q -j 1 -s 203 -o "$T/full1.ppm" scenes/scene.txt &&
	"$W" -q -j 7 -s 203 -o "$T/full7.ppm" scenes/scene.txt || {
	echo "threadcheck: whitted failed on scenes/scene.txt -s 203"
	fail=$((fail + 1))
}
if python3 tests/reference/ref_render.py scenes/scene.txt "$T/ref.ppm" --size 203; then
	for j in 1 7; do
		if "$BUILD/imgcmp" "$T/full$j.ppm" "$T/ref.ppm" >"$T/cmp.txt" 2>&1; then
			pass=$((pass + 1))
		else
			echo "threadcheck: -j $j at 203 differs from the reference renderer: $(cat "$T/cmp.txt")"
			fail=$((fail + 1))
		fi
	done
else
	echo "threadcheck: the reference renderer (python3 tests/reference/ref_render.py) failed"
	fail=$((fail + 1))
fi
n=0
for y in 0,7 7,150 150,203; do
	for x in 0,5 5,101 101,203; do
		n=$((n + 1))
		"$W" -q -j 3 -s 203 --region "${x%,*},${y%,*},${x#*,},${y#*,}" -o "$T/r$n.png" \
			scenes/scene.txt || echo "threadcheck: region ${x%,*},${y%,*},${x#*,},${y#*,} failed"
	done
done
if "$W" merge -o "$T/merged.ppm" "$T"/r?.png 2>"$T/merge.err" && cmp -s "$T/merged.ppm" "$T/full1.ppm"; then
	pass=$((pass + 1))
else
	echo "threadcheck: nine regions off the block grid, merged, differ from the full render $(cat "$T/merge.err")"
	fail=$((fail + 1))
fi
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
	# helgrind_png WHAT THREADS SIZE [SCENE]: helgrind on a PNG of the
	# course scene (or SCENE).
	helgrind_png() {
		if valgrind --tool=helgrind -q --error-exitcode=9 "$W" -q -j "$2" -s "$3" \
			-o "$T/vg.png" "${4:-scenes/scene.txt}" 2>"$T/vg.err"; then
			pass=$((pass + 1))
		else
			echo "threadcheck: valgrind --tool=helgrind reports on the PNG $1:"
			cat "$T/vg.err"
			fail=$((fail + 1))
		fi
	}
	# The PNG compressed during the render, three strips on three threads
	# (or on one a processor, where there are more).
	vj=3
	[ "$np" -gt 3 ] && vj=$np
	helgrind_png "compressed during the render" $vj 130
	# And compressed after a one-thread render by the write's own
	# threads, whose first calls into the deflate library (ISA-L picks
	# its code for the processor then) must not race.
	helgrind_png "written after the render" 1 400
	# An image over 2 MiB (900 px: 2.4 MB), which the allocator zeroes
	# on one thread a processor (base/huge_pages.c) before the render's
	# threads write it.
	helgrind_png "of 900 px, its memory zeroed on several threads" 2 900 scenes/sphere.txt
else
	echo "threadcheck: helgrind and memcheck NOT RUN (valgrind is not installed)"
fi
echo "threadcheck: $pass passed, $fail failed"
[ $fail -eq 0 ]
