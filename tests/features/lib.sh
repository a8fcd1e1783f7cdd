# shellcheck shell=sh disable=SC2034
# Sourced by the feature suites (glass.sh, samples.sh, texture.sh): the
# paths they run from (top: the checkout; B: the build, BUILD or build/;
# W: its whitted), a scratch folder removed on exit, and the counts with
# ok and bad (which says why).  Not a suite itself: run.sh runs those it
# names.  (SC2034: what it sets is for the suite that sources it.)
top=$(cd "$(dirname "$0")/../.." && pwd)
B=${BUILD:-$top/build}
W=$B/whitted
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }
