#!/bin/sh
# The cost of --samples N, for `make bench`: whitted's render time (from
# --stats, so reading the file and writing the image are left out) at
# --samples N and size S against N*N times its time at one sample, and
# against one sample at size N*S (the same rays), on the course example.
# The runs of the three alternate, RUNS of each, and the fastest of each
# is taken: other programs on the machine only ever add time.  The
# issue's bound is a ratio of at most 1.10.  A benchmark, not a test: it
# fails only when a program fails.
#
# Environment: BUILD (build), RUNS (7), THREADS (2), SAMPLES_SIZE (1024),
# SAMPLES_N (default "2 3 4").
set -eu
BUILD=${BUILD:-build}
RUNS=${RUNS:-7}
THREADS=${THREADS:-2}
SIZE=${SAMPLES_SIZE:-1024}
WHITTED=$BUILD/whitted
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# render SIZE N: one run's render seconds.
render() {
	"$WHITTED" -q --stats --progress never -j "$THREADS" -s "$1" --samples "$2" \
		-o "$out/s.ppm" scenes/scene.txt 2>"$out/err"
	sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "$out/err"
}
fastest() { sort -g | head -n 1; }

echo "whitted --samples N at ${SIZE}x$SIZE on scenes/scene.txt, $THREADS threads, fastest of $RUNS alternating runs"
echo
echo "| N | render s | one sample s | N*N x one sample | ratio | one sample at N*S s | ratio |"
echo "|---|---|---|---|---|---|---|"
for n in ${SAMPLES_N:-2 3 4}; do
	: >"$out/t1" && : >"$out/tn" && : >"$out/tbig"
	i=0
	while [ $i -lt "$RUNS" ]; do
		render "$SIZE" 1 >>"$out/t1"
		render "$SIZE" "$n" >>"$out/tn"
		render $((n * SIZE)) 1 >>"$out/tbig"
		i=$((i + 1))
	done
	t1=$(fastest <"$out/t1") tn=$(fastest <"$out/tn") tbig=$(fastest <"$out/tbig")
	printf '| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n' "$n" "$tn" "$t1" \
		"$(echo "$n * $n * $t1" | bc -l)" "$(echo "$tn / ($n * $n * $t1)" | bc -l)" \
		"$tbig" "$(echo "$tn / $tbig" | bc -l)"
done

# The same comparison in instructions (callgrind, one thread, 128x128),
# which other programs on the machine cannot disturb: the whole run's
# count less that of an 8x8 render (reading, setting up, writing).
if command -v valgrind >/dev/null 2>&1; then
	ir() {
		valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$WHITTED" -q -j 1 -s "$1" \
			--samples "$2" -o "$out/s.ppm" scenes/scene.txt 2>&1 |
			sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
	}
	base=$(ir 8 1)
	if [ -z "$base" ]; then
		# valgrind ran but counted nothing (a binary whose debug info it
		# cannot read, such as clang's DWARF 5 under valgrind 3.19).
		echo
		echo "(callgrind counted nothing: no instruction counts)"
		exit 0
	fi
	one=$(($(ir 128 1) - base))
	echo
	echo "| N | instructions at 128x128 | N*N x one sample | ratio | one sample at N*128 | ratio |"
	echo "|---|---|---|---|---|---|"
	for n in ${SAMPLES_N:-2 3 4}; do
		tn=$(($(ir 128 "$n") - base)) big=$(($(ir $((n * 128)) 1) - base))
		printf '| %s | %s | %s | %.3f | %s | %.3f |\n' "$n" "$tn" $((n * n * one)) \
			"$(echo "$tn / ($n * $n * $one)" | bc -l)" "$big" "$(echo "$tn / $big" | bc -l)"
	done
else
	echo "(valgrind is missing: no instruction counts)"
fi
