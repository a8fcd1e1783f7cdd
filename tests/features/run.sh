#!/bin/sh
# The suites of issue 14's features (antialiasing, textured floors,
# refraction), each ending with "NAME: N passed, N failed, N skipped".
set -u
here=$(dirname "$0")
st=0
for t in samples texture glass ref; do
	[ -x "$here/$t.sh" ] || continue
	"$here/$t.sh" || st=1
done
exit $st
