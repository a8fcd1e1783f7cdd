# Shared helpers of the CLI test scripts (sourced, not run).  Sets ROOT,
# DATA (the course files copied into tests/data), W (the whitted binary) and T (a scratch directory removed on exit),
# and counts checks: ok NAME / bad NAME WHY / skip NAME WHY (a part that
# cannot run here: said NOT RUN and counted apart, never as passed), then
# finish prints the summary, "SUITE: N passed, N failed, N skipped[: why]".
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
DATA=$ROOT/tests/data
W=$ROOT/build/whitted
pass=0
fail=0
skipped=0
skip_why=""

ok() { pass=$((pass + 1)); }
bad() {
	fail=$((fail + 1))
	printf 'FAIL: %s: %s\n' "$1" "$2"
}
skip() {
	skipped=$((skipped + 1))
	printf 'NOT RUN: %s: %s\n' "$1" "$2"
	case "; $skip_why; " in
	*"; $2; "*) ;;
	*) skip_why=${skip_why:+$skip_why; }$2 ;;
	esac
}
# check NAME CONDITION-COMMAND...: passes when the command succeeds.
check() {
	local name=$1
	shift
	if "$@"; then ok; else bad "$name" "$*"; fi
}
finish() {
	echo "$SUITE: $pass passed, $fail failed, $skipped skipped${skip_why:+: $skip_why}"
	[ "$fail" -eq 0 ]
	exit $?
}

if [ ! -x "$W" ]; then
	echo "$SUITE: $W is missing (run make all)"
	echo "$SUITE: 0 passed, 1 failed, 0 skipped"
	exit 1
fi
if [ ! -f "$DATA/README.md" ]; then
	echo "$SUITE: the test data $DATA is missing"
	echo "$SUITE: 0 passed, 1 failed, 0 skipped"
	exit 1
fi
T=$(mktemp -d "${TMPDIR:-/tmp}/whitted-$SUITE.XXXXXX")
trap 'rm -rf "$T"' EXIT
trap 'exit 130' INT TERM

# run ARGS...: runs whitted in $T/wd, stdout to $T/out, stderr to $T/err,
# the status in $rc.
mkdir -p "$T/wd"
run() {
	(cd "$T/wd" && "$W" "$@") >"$T/out" 2>"$T/err"
	rc=$?
}
err_lines() { wc -l <"$T/err" | tr -d ' '; }
# The files in the work directory (hidden ones included), one per line.
wd_files() { (cd "$T/wd" && ls -A); }
wd_empty() { [ -z "$(wd_files)" ]; }
clean_wd() { rm -rf "$T/wd" && mkdir -p "$T/wd"; }
# The width of a PNG file (big-endian at byte 16).
png_width() { od -An -tu1 -j16 -N4 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }'; }
is_png() { [ "$(od -An -c -N4 "$1" | tr -d ' ')" = '211PNG' ]; }
is_bmp() { [ "$(head -c 2 "$1")" = BM ]; }
is_ppm() { [ "$(head -c 2 "$1")" = P6 ]; }
