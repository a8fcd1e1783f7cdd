#!/bin/sh
# Runs each unit-test binary (built with ASan and UBSan) and sums the
# results; fails when any test fails or a binary dies.
pass=0 fail=0 bad=""
for t in "$@"; do
	out=$("$t" 2>&1)
	status=$?
	p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p')
	f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p')
	pass=$((pass + ${p:-0}))
	fail=$((fail + ${f:-0}))
	if [ "$status" -ne 0 ] || [ -z "$p" ]; then
		printf '%s\n' "$out"
		bad="$bad $t"
		[ -n "$f" ] || fail=$((fail + 1))
	fi
done
echo "unit: $pass passed, $fail failed ($# test programs)"
[ -z "$bad" ] || { echo "unit: failing:$bad"; exit 1; }
