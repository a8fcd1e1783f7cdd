#!/bin/sh
# The benchmark's Embree reference (build/whitted-embree: bench/embree_accel.c
# in place of src/accel/) still builds against the library and gives
# whitted's images, to the byte: the course example, its packets forced on
# and off, a small and a big generated scene, a cloud, glass.  So a change
# of the accel API or of the shading that the reference does not follow is
# caught here, not first by `make bench`.  Needs libembree-dev (make deps).
set -u
CHECK=embreecheck
# shellcheck source=bench/check_counts.sh
. "$(dirname "$0")/check_counts.sh"
BUILD=${BUILD:-build}
if [ ! -f /usr/include/embree3/rtcore.h ]; then
	echo "embreecheck: NOT RUN: libembree-dev is not installed (make deps installs it); nothing was compared"
	echo "embreecheck: 0 passed, 1 failed, 0 skipped"
	exit 1
fi
make --no-print-directory -s "$BUILD/whitted-embree" >/dev/null || {
	echo "embreecheck: build/whitted-embree does not build"
	exit 1
}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
"$BUILD/gen_scene" 300 >"$T/surface-300.txt"
"$BUILD/gen_scene" 5000 >"$T/surface-5000.txt"
"$BUILD/gen_scene" --layout cloud 3000 >"$T/cloud-3000.txt"
check() {
	what=$1
	shift
	if ! "$BUILD/whitted" -q -o "$T/w.ppm" "$@" 2>"$T/err" ||
		! "$BUILD/whitted-embree" -q -o "$T/e.ppm" "$@" 2>>"$T/err"; then
		failed "$what: a render fails: $(head -3 "$T/err")"
	else
		same "$T/w.ppm" "$T/e.ppm" "$what: Embree's image differs from whitted's"
	fi
}
for p in 0 1 default; do
	if [ $p = default ]; then unset WHITTED_PACKETS; else export WHITTED_PACKETS=$p; fi
	check "example, packets $p" -s 160 scenes/scene.txt
	check "example -r 9, packets $p" -s 120 -r 9 scenes/scene.txt
	check "surface 300, packets $p" -s 100 "$T/surface-300.txt"
	check "surface 5000, packets $p" -s 100 "$T/surface-5000.txt"
	check "cloud 3000, packets $p" -s 100 "$T/cloud-3000.txt"
	check "glass, packets $p" -s 100 --glass 1,2 scenes/scene.txt
done
unset WHITTED_PACKETS
echo "embreecheck: $pass passed, $fail failed, 0 skipped"
[ "$fail" = 0 ]
