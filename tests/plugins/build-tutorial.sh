#!/bin/sh
# Cuts disc.c, the tutorial plugin, out of docs/plugins.md (the C block
# after the line "<!-- disc.c -->") into DIR and builds DIR/disc.so with
# exactly the tutorial's command, against the whitted that pkg-config finds
# (set PKG_CONFIG_PATH to an installed PREFIX/lib/pkgconfig).  Used by
# tests/cli/install-test.sh and tests/viewer/e2e.sh.
# Usage: tests/plugins/build-tutorial.sh DIR
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=$1
awk '/^<!-- disc.c -->$/ { found = 1; next }
	found && /^```c$/ { inside = 1; next }
	inside && /^```$/ { exit }
	inside { print }' "$root/docs/plugins.md" >"$dir/disc.c"
[ -s "$dir/disc.c" ] || { echo "build-tutorial: no disc.c block in docs/plugins.md" >&2; exit 1; }
cd "$dir"
${CC:-cc} -std=c99 -Wall -Wextra -Wpedantic -Werror -shared -fPIC $(pkg-config --cflags whitted) \
	-o disc.so disc.c -lm
