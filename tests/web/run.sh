#!/bin/sh
# The web page's browser suite (make webtest): installs playwright-core
# (the version of tests/web/package.json) from npm into build/node once,
# then runs tests/web/run.mjs with Debian's chromium against build/web and
# build/whitted; screenshots and figures go to build/test-output/.
# Usage: tests/web/run.sh BUILD [--install-only]
set -u
SUITE=webtest
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=$build/test-output
for t in node npm; do
	if ! command -v $t >/dev/null 2>&1; then
		echo "$SUITE: NOT RUN: $t is not installed (make deps)"
		echo "$SUITE: 0 passed, 1 failed"
		exit 1
	fi
done
if ! command -v chromium >/dev/null 2>&1 && ! command -v chromium-browser >/dev/null 2>&1; then
	echo "$SUITE: NOT RUN: chromium is not installed (make deps)"
	echo "$SUITE: 0 passed, 1 failed"
	exit 1
fi
mods=$build/node
if ! cmp -s "$root/tests/web/package.json" "$mods/package.json" || [ ! -d "$mods/node_modules/playwright-core" ]; then
	mkdir -p "$mods"
	cp "$root/tests/web/package.json" "$mods/package.json"
	if ! (cd "$mods" && npm install --no-audit --no-fund --loglevel=error >/dev/null); then
		echo "$SUITE: npm install of playwright-core failed"
		echo "$SUITE: 0 passed, 1 failed"
		exit 1
	fi
fi
[ "${2:-}" = --install-only ] && exit 0
mkdir -p "$out"
exec node "$root/tests/web/run.mjs" "$build/web/index.html" "$build/whitted" "$root" "$out" "$mods/node_modules"
