#!/bin/sh
# The benchmark's timer (bench/walltime.c) measures what it says: a sleep
# of 0.3 s as at least 0.3 s and well under a second, a program's peak
# memory (one that holds 64 MiB) as at least that, and it passes on the
# program's exit status (3, 128 + a signal, 127 for a missing program, 2
# for its own bad command line) and its streams.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
W="$root/build/walltime"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0

check() {
	what=$1
	shift
	if "$@"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "walltimetest: FAIL: $what"; fi
}
field() { cut -d' ' -f"$1" "$tmp/t"; }

"$W" -o "$tmp/t" sleep 0.3
check "exit 0 passed on" [ $? -eq 0 ]
check "a 0.3 s sleep takes 0.3 s to 1 s ($(field 1))" \
	awk -v t="$(field 1)" 'BEGIN { exit !(t >= 0.3 && t < 1.0) }'
"$W" -o "$tmp/t" python3 -c 'b = bytearray(64 << 20); b[::4096] = b"x" * len(b[::4096])'
check "64 MiB held: peak at least 65536 KiB ($(field 2))" [ "$(field 2)" -ge 65536 ]
"$W" -o "$tmp/t" sh -c 'exit 3'
check "exit 3 passed on" [ $? -eq 3 ]
"$W" -o "$tmp/t" sh -c 'kill -TERM $$'
check "a TERM gives 128 + 15" [ $? -eq 143 ]
"$W" -o "$tmp/t" "$tmp/no-such-program" 2>"$tmp/err"
check "a missing program gives 127" [ $? -eq 127 ]
check "and is named" grep -q "no-such-program" "$tmp/err"
"$W" -o "$tmp/t" 2>/dev/null
check "no command gives 2" [ $? -eq 2 ]
check "the program's output goes through" [ "$("$W" -o "$tmp/t" echo hello)" = hello ]
echo "walltimetest: $pass passed, $fail failed, 0 skipped"
[ "$fail" -eq 0 ]
