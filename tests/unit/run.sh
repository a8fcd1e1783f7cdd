#!/bin/sh
# Runs each unit-test binary (built with ASan and UBSan) and sums the
# results; fails when any test fails or a binary dies.  Skipped tests are
# counted apart, with their reasons (a test of a set of instructions the
# processor lacks prints "skip: AVX-512 not on this CPU" and skips), and
# the sets of instructions whose tests ran ("isa: avx2") are named; a set
# this processor has (its /proc/cpuinfo flags, not the code under test,
# say so) none of whose tests ran fails the run, as does a skip of one.
# The last line is "unit: N passed, N failed, N skipped[: reasons]".
pass=0 fail=0 skipped=0 bad=""
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/isa"
: >"$tmp/why"
: >"$tmp/parts"
# Every set is tested whatever the caller's environment caps.
unset WHITTED_ISA
for t in "$@"; do
	out=$("$t" 2>&1)
	status=$?
	p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p')
	f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p')
	s=$(printf '%s\n' "$out" | sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p')
	pass=$((pass + ${p:-0}))
	fail=$((fail + ${f:-0}))
	skipped=$((skipped + ${s:-0}))
	printf '%s\n' "$out" | sed -n 's/^isa: //p' >>"$tmp/isa"
	printf '%s\n' "$out" | sed -n 's/^skip: //p' >>"$tmp/why"
	# A part of a test left out (a set the walk comparisons go without):
	# once a program and reason.
	printf '%s\n' "$out" | sed -n 's/^part-skip: //p' | sort -u |
		sed "s|^|$(basename "$t") |" >>"$tmp/parts"
	if [ "$status" -ne 0 ] || [ -z "$p" ]; then
		printf '%s\n' "$out"
		bad="$bad $t"
		[ -n "$f" ] || fail=$((fail + 1))
	fi
done

# The sets of instructions: which ran, which this processor has.
has() { grep -qx "$1" "$tmp/isa"; }
# (UNIT_CPUINFO: another file in its place, to test this check.)
cpuinfo=${UNIT_CPUINFO:-/proc/cpuinfo}
flags=""
if [ "$(uname -m)" = x86_64 ] && [ -r "$cpuinfo" ]; then
	flags=" $(sed -n 's/^flags[[:space:]]*: //p' "$cpuinfo" | head -1) "
fi
ran="" notrun=""
for isa in base avx2 avx512; do
	case $isa in
	base) name="SSE2 (base)" want=yes ;;
	avx2) name="AVX2" want=$(case $flags in *" avx2 "*) echo yes ;; esac) ;;
	avx512) name="AVX-512" want=$(case $flags in *" avx512f "*" fma "* | *" fma "*" avx512f "*) echo yes ;; esac) ;;
	esac
	if has $isa; then
		ran="$ran${ran:+, }$name"
	else
		notrun="$notrun${notrun:+, }$name"
		if [ -n "$flags" ] && [ "$want" = yes ]; then
			echo "unit: FAIL: this CPU has $name (/proc/cpuinfo), but none of its tests ran"
			fail=$((fail + 1))
		fi
	fi
	if [ "$isa" != base ] && [ -n "$flags" ] && [ "$want" = yes ] &&
	   grep -q "$name not on this CPU" "$tmp/why" "$tmp/parts"; then
		echo "unit: FAIL: this CPU has $name (/proc/cpuinfo), but tests said it has not"
		fail=$((fail + 1))
	fi
done
[ -n "$flags" ] || [ "$(uname -m)" != x86_64 ] ||
	echo "unit: note: /proc/cpuinfo unreadable: the sets this CPU has are not checked"
echo "unit: $# test programs; sets of instructions tested on this CPU: $ran${notrun:+; NOT RUN: $notrun}"
if [ -s "$tmp/parts" ]; then
	sed 's/^\([^ ]*\) \(.*\)/\2: left out of \1/' "$tmp/parts" | sort | awk -F': left out of ' '
		$1 != last { if (last != "") print "unit: " last ": left out of the comparisons of every set in " list
			     last = $1; list = $2; next }
		{ list = list ", " $2 }
		END { if (last != "") print "unit: " last ": left out of the comparisons of every set in " list }'
fi
why=$(sort -u "$tmp/why" | paste -sd ';' - | sed 's/;/; /g')
[ "$skipped" -eq 0 ] || [ -n "$why" ] || why="no reason given"
[ -z "$bad" ] || echo "unit: failing:$bad"
echo "unit: $pass passed, $fail failed, $skipped skipped${why:+: $why}"
[ -z "$bad" ] && [ "$fail" -eq 0 ]
