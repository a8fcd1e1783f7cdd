#!/bin/sh
# Installs the Debian packages a make target needs, when some are missing:
# with apt-get when run as root, otherwise by printing the command to run.
# Usage: scripts/deps.sh [--optional] PACKAGE...
# With --optional, a user who is not root is only told what is missing: the
# tests that need those packages then say NOT RUN, and a library that only
# makes whitted faster (libisal-dev) leaves its work to the fallback.
optional=no
if [ "${1:-}" = --optional ]; then
	optional=yes
	shift
fi
missing=""
for pkg in "$@"; do
	status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null)
	case "$status" in
	*"install ok installed"*) ;;
	*) missing="$missing $pkg" ;;
	esac
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
	echo "deps: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	if apt-get update -qq >/dev/null && apt-get install -y -qq --no-install-recommends $missing >/dev/null; then
		exit 0
	fi
	echo "deps: apt-get install$missing failed" >&2
	# Optional packages only cost their suites, which then say NOT RUN.
	[ "$optional" = yes ] && exit 0
	exit 1
fi
if [ "$optional" = yes ]; then
	echo "deps: optional packages missing (what needs them does without: its suite says NOT RUN, or a slower fallback does the work); as root:" >&2
	echo "  apt-get install -y$missing" >&2
	exit 0
fi
echo "deps: missing Debian packages; run as root:" >&2
echo "  apt-get install -y$missing" >&2
exit 1
