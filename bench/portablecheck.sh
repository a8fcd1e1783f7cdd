#!/bin/sh
# The hierarchy's SSE2 code (the box tests of the traversal, the box
# growth and binning of the build) has a plain C twin for machines without
# SSE2, chosen by ACCEL_PORTABLE, and a big scene's walks have AVX-512 or
# AVX2 box tests over eight-child nodes where the processor has them
# (WHITTED_ISA=avx2 and WHITTED_ISA=sse2 cap them), and packets of rays
# in each (WHITTED_PACKETS=1 forces them, =0 turns them off).  All must give the same
# images byte for byte:
# renders every scene in scenes/ and tests/scenes/ and generated ones with
# each build and compares the files.  Every scene must render with both
# builds: a scene that either refuses is a failure, not a skip (it would
# hide a crash of one build and leave the other unchecked).
# Usage: portablecheck.sh WHITTED PORTABLE_WHITTED
set -u
CHECK=portablecheck
# shellcheck source=bench/check_counts.sh
. "$(dirname "$0")/check_counts.sh"
BUILD=${BUILD:-build}
W=$1
P=$2
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
: >"$T/walks"
# Runs a command that writes image $2, and counts whether it ran and gave
# the default build's image ($T/sse.ppm) byte for byte; its stderr is
# left in $T/err.
same_as_default() {
	what=$1 out=$2
	shift 2
	if ! "$@" 2>"$T/err"; then
		failed "$scene -j $j: $what fails: $(head -3 "$T/err")"
	else
		same "$T/sse.ppm" "$out" "$scene -j $j: $what gives another image than the default build"
	fi
}
"$BUILD/gen_scene" 12000 >"$T/surface.txt"
"$BUILD/gen_scene" --layout cloud 3000 >"$T/cloud.txt"
for scene in scenes/*.txt tests/scenes/*.txt "$T/surface.txt" "$T/cloud.txt"; do
	for j in 1 3; do
		if ! "$W" -q -j $j -s 96 -o "$T/sse.ppm" "$scene" 2>"$T/err"; then
			failed "$scene -j $j: the SSE2 build fails: $(head -3 "$T/err")"
			continue
		fi
		same_as_default "the portable build" "$T/portable.ppm" \
			"$P" -q -j $j -s 96 -o "$T/portable.ppm" "$scene"
		# The narrower walks where the processor would run wider ones.
		for isa in avx2 sse2; do
			same_as_default "the walk under WHITTED_ISA=$isa" "$T/$isa.ppm" \
				env WHITTED_ISA=$isa "$W" -q --stats -j $j -s 96 -o "$T/$isa.ppm" "$scene"
			sed -n 's/.*, \([a-z0-9]*\) walk, .*/\1/p' "$T/err" >>"$T/walks"
		done
		# Packets forced where they would not run by themselves (the
		# portable build, the SSE2 walk), and single rays where they would.
		same_as_default "the portable build's packets" "$T/portable-packets.ppm" \
			env WHITTED_PACKETS=1 "$P" -q -j $j -s 96 -o "$T/portable-packets.ppm" "$scene"
		same_as_default "packets under WHITTED_ISA=sse2" "$T/sse2-packets.ppm" \
			env WHITTED_ISA=sse2 WHITTED_PACKETS=1 "$W" -q -j $j -s 96 -o "$T/sse2-packets.ppm" "$scene"
		same_as_default "single rays (WHITTED_PACKETS=0)" "$T/single.ppm" \
			env WHITTED_PACKETS=0 "$W" -q -j $j -s 96 -o "$T/single.ppm" "$scene"
		"$W" -q --stats -j $j -s 8 -o "$T/w.ppm" "$scene" 2>&1 |
			sed -n 's/.*, \([a-z0-9]*\) walk, .*/\1/p' >>"$T/walks"
	done
done
# A camera 1e17 away with a field of view of 6e-14 degrees (a 48-pixel
# view of the flat tiles' back wall): a ray's origin is so far that a box
# thinner along y than the origin's spacing of doubles (16) has one t for
# both its faces, its entry equal to its exit, which every walk must take
# as a hit (a strict box test loses the whole wall).
scene=tests/scenes/flat-tiles.txt
far="--eye 0,-1e17,20 --look 0,0,20 --fov 6e-14"
for j in 1 2; do
	# shellcheck disable=SC2086
	if ! "$W" -q -j $j -s 48 $far -o "$T/sse.ppm" "$scene" 2>"$T/err"; then
		failed "$scene (far eye) -j $j: the SSE2 build fails: $(head -3 "$T/err")"
		continue
	fi
	# shellcheck disable=SC2086
	same_as_default "the portable build (far eye)" "$T/portable.ppm" \
		"$P" -q -j $j -s 48 $far -o "$T/portable.ppm" "$scene"
	for isa in avx2 sse2; do
		# shellcheck disable=SC2086
		same_as_default "the walk under WHITTED_ISA=$isa (far eye)" "$T/$isa.ppm" \
			env WHITTED_ISA=$isa "$W" -q -j $j -s 48 $far -o "$T/$isa.ppm" "$scene"
	done
	# shellcheck disable=SC2086
	same_as_default "single rays (WHITTED_PACKETS=0, far eye)" "$T/single.ppm" \
		env WHITTED_PACKETS=0 "$W" -q -j $j -s 48 $far -o "$T/single.ppm" "$scene"
done
# The ray counts too (--stats), where a light lies in the floor's plane
# (N.L exactly 0 over the floor: no light and no shadow ray there), at
# 200 px: one ray at a time, packets by default and forced in each walk.
scene=tests/scenes/light-in-floor-plane.txt
k=0
for how in "WHITTED_PACKETS=0" "WHITTED_PACKETS=" "WHITTED_PACKETS=1" \
	"WHITTED_PACKETS=1 WHITTED_ISA=sse2" "WHITTED_PACKETS=1 WHITTED_ISA=avx2"; do
	k=$((k + 1))
	# shellcheck disable=SC2086
	env $how "$W" -q --stats -s 200 -o "$T/plane$k.ppm" "$scene" 2>&1 |
		sed -n 's/^rays: *\(.*\), [0-9.]* M rays\/s$/\1/p' >"$T/rays$k"
	if [ ! -s "$T/rays$k" ]; then
		failed "$scene under $how: no ray counts"
	elif [ $k -gt 1 ]; then
		if cmp -s "$T/plane1.ppm" "$T/plane$k.ppm" && cmp -s "$T/rays1" "$T/rays$k"; then
			pass=$((pass + 1))
		else
			failed "$scene under $how: $(cat "$T/rays$k"), one ray at a time $(cat "$T/rays1")$(cmp -s "$T/plane1.ppm" "$T/plane$k.ppm" || echo ', another image')"
		fi
	fi
done
echo "portablecheck: walks compared with the portable build's: $(sort -u "$T/walks" | tr '\n' ' ')portable"
echo "portablecheck: $pass passed, $fail failed, 0 skipped"
[ $fail -eq 0 ] && [ $pass -gt 0 ]
