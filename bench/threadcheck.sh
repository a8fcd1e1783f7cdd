#!/bin/sh
# The image must not depend on the number of threads: renders scenes with
# 1, 2, 3 and 7 threads and compares the files byte for byte.  The 12,000
# object scene is big enough for the hierarchy's build to split its work
# between threads too; helgrind then looks for data races in the build,
# the parse's hashing thread and the render, and in a PNG compressed by
# the render's threads or after it by the write's (without valgrind those
# runs are NOT RUN and counted as skipped; with it installed, a run that
# did not happen fails).  The PNG files of 1, 2, 3 and 7 threads are
# compared too (compressed during the render or after it), and a PNG
# whose second band is final before its first.  Every size leaves partial
# 16x16 blocks at the right and bottom edges (203 = 12 x 16 + 11).  Since
# images that agree with each other can all be wrong alike, the 203-pixel
# render is also checked against what does not share the block loop: the
# independent Python renderer (tests/reference/ref_render.py, imgcmp's
# gate) and a merge of --region renders cut off the 16-pixel grid (so
# every block falls elsewhere).
set -u
CHECK=threadcheck
# shellcheck source=bench/check_counts.sh
. "$(dirname "$0")/check_counts.sh"
BUILD=${BUILD:-build}
W=$BUILD/whitted
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
"$BUILD/gen_scene" 300 >"$T/gen.txt"
"$BUILD/gen_scene" 12000 >"$T/gen12k.txt"
for case in "scenes/scene.txt -s 203" "scenes/scene.txt -s 97" "$T/gen.txt -s 61" \
	"scenes/scene.txt -s 40 --clamp final" "$T/gen12k.txt -s 33"; do
	set -- $case
	for j in 1 2 3 7; do
		if ! "$W" -q -j $j -o "$T/j$j.ppm" "$@"; then
			failed "whitted failed: -j $j $case"
			continue
		fi
		[ "$j" -eq 1 ] || same "$T/j1.ppm" "$T/j$j.ppm" "-j $j differs from -j 1: $case"
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
	[ "$j" -eq 1 ] || same "$T/p1.png" "$T/p$j.png" "the PNG of -j $j differs from -j 1's"
done
# A strip of the PNG may be compressed only once the band above it is
# final too (its filter reads that band's last row).  Bands finish in
# order in most renders; here the last block of the first band (rows
# 48-63, columns 112-127 of 128) is a quad lit by 4000 lights, some 100
# times the work of the whole second band (sky: --no-floor), so that the
# second band is final first.  The PNG compressed during the render (as
# many threads as processors, at least 2) must be the one written after a
# one-thread render, three times over.
python3 - "$T/band.txt" <<'END'
import math, random, sys
size, lights = 128, 4000
eye, look, up0 = (0.0, -200.0, 10.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)
def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def add(a, b): return tuple(x + y for x, y in zip(a, b))
def mul(a, s): return tuple(x * s for x in a)
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def unit(a): return mul(a, 1 / math.sqrt(sum(x * x for x in a)))
fwd = unit(sub(look, eye)); right = unit(cross(fwd, up0)); up = cross(right, fwd)
h = math.tan(math.radians(40))
def corner(px, py):
    d = add(fwd, add(mul(right, (px / size * 2 - 1) * h), mul(up, (1 - py / size * 2) * h)))
    return ' '.join('%.9f' % v for v in add(eye, mul(d, 100)))
c = [corner(x, y) for x, y in ((112, 48), (128, 48), (128, 64), (112, 64))]
mat = '0.9 0.5 0.2\n0.4 0.3 0.2 0\n5\n'
r = random.Random(7)
with open(sys.argv[1], 'w') as f:
    f.write('1\n%d\n2\n' % size)
    for a, b, d in ((c[0], c[1], c[2]), (c[0], c[2], c[3])):
        f.write('triangle\n%s\n%s\n%s\n%s' % (a, b, d, mat))
    f.write('%d\n' % lights)
    for i in range(lights):
        f.write('%.3f %.3f %.3f 0.001 0.001 0.001\n' % (r.uniform(-300, 300), r.uniform(-400, -150),
                                                       r.uniform(20, 300)))
END
bj=$np
[ "$bj" -ge 2 ] || bj=2
if "$W" -q -j 1 --no-floor -o "$T/band1.png" "$T/band.txt"; then
	for k in 1 2 3; do
		"$W" -q -j $bj --no-floor -o "$T/bandj.png" "$T/band.txt"
		same "$T/band1.png" "$T/bandj.png" \
			"a PNG whose second band is final before the first differs (-j $bj, run $k)"
	done
else
	failed "whitted failed on the two-band scene"
fi
# The 203-pixel course scene with 1 and 7 threads against the reference
# renderer, and against the merge of nine regions whose edges (5, 101 and
# 7, 150) lie off the block grid.
"$W" -q -j 1 -s 203 -o "$T/full1.ppm" scenes/scene.txt &&
	"$W" -q -j 7 -s 203 -o "$T/full7.ppm" scenes/scene.txt || {
	failed "whitted failed on scenes/scene.txt -s 203"
}
if python3 tests/reference/ref_render.py scenes/scene.txt "$T/ref.ppm" --size 203; then
	for j in 1 7; do
		if "$BUILD/imgcmp" "$T/full$j.ppm" "$T/ref.ppm" >"$T/cmp.txt" 2>&1; then
			pass=$((pass + 1))
		else
			failed "-j $j at 203 differs from the reference renderer: $(cat "$T/cmp.txt")"
		fi
	done
else
	failed "the reference renderer (python3 tests/reference/ref_render.py) failed"
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
	failed "nine regions off the block grid, merged, differ from the full render $(cat "$T/merge.err")"
fi
# The 12k file (over 1 MiB) is read in parts by several threads, and its
# tree built by several: helgrind looks for races there, memcheck for
# leaks and bad reads and writes.  Without valgrind these five runs are
# NOT RUN, counted as skipped; with it (on PATH, or installed as a
# package) every one of them must have run.
VG_RUNS=5
vg_ran=0
skipped=0 why=""
if command -v valgrind >/dev/null 2>&1; then
	# valgrind_run TOOL WHERE ARGS...: valgrind TOOL (its options, split
	# on spaces) on whitted ARGS; WHERE says what ran in the message of a
	# failure.
	valgrind_run() {
		tool=$1 where=$2
		shift 2
		vg_ran=$((vg_ran + 1))
		# shellcheck disable=SC2086
		if valgrind $tool -q --error-exitcode=9 "$W" -q "$@" 2>"$T/vg.err"; then
			pass=$((pass + 1))
		else
			echo "threadcheck: valgrind $tool reports$where:"
			cat "$T/vg.err"
			fail=$((fail + 1))
		fi
	}
	for tool in "--tool=helgrind" "--tool=memcheck --leak-check=full --errors-for-leak-kinds=all"; do
		valgrind_run "$tool" "" -j 3 -s 16 -o "$T/vg.ppm" "$T/gen12k.txt"
	done
	# helgrind_png WHAT THREADS SIZE [SCENE]: helgrind on a PNG of the
	# course scene (or SCENE).
	helgrind_png() {
		valgrind_run --tool=helgrind " on the PNG $1" -j "$2" -s "$3" -o "$T/vg.png" \
			"${4:-scenes/scene.txt}"
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
	if [ "$vg_ran" -ne "$VG_RUNS" ]; then
		echo "threadcheck: FAIL: valgrind is installed, but $((VG_RUNS - vg_ran)) of its $VG_RUNS runs did not run"
		fail=$((fail + VG_RUNS - vg_ran))
	fi
elif dpkg-query -W -f='${Status}' valgrind 2>/dev/null | grep -q "install ok installed"; then
	echo "threadcheck: FAIL: the valgrind package is installed, but valgrind is not on PATH: helgrind and memcheck did not run"
	fail=$((fail + VG_RUNS))
else
	echo "threadcheck: NOT RUN: helgrind and memcheck ($VG_RUNS runs): valgrind is not installed (make deps)"
	skipped=$VG_RUNS why=": valgrind is not installed"
fi
echo "threadcheck: $pass passed, $fail failed, $skipped skipped$why"
[ $fail -eq 0 ]
