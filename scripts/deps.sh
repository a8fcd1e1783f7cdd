#!/bin/sh
# Makes sure what a make target needs is here, named by its Debian
# packages.  Usage: scripts/deps.sh [--optional] PACKAGE...
#
# Each package is first looked for by what it provides, on any system:
# pkg-config (libpng, zlib, cmocka, glut), a header that compiles, or a
# command.  Only what is not found that way is a missing package.  Then:
#   - on Debian (dpkg-query and apt-get), as root: apt-get installs it,
#     after waiting (up to DEPS_LOCK_WAIT seconds, 300 by default, and
#     saying so) while another apt or unattended-upgrades holds the
#     package lock;
#   - on Debian, not root: the apt-get line to run is printed;
#   - elsewhere: what is missing is named, to install with the system's
#     own package manager.
# With --optional, a missing package only costs what needs it (its suite
# says NOT RUN, or a slower fallback does the work): the exit status is 0.
# For the tests (tests/cli/run.sh) and unusual systems, DPKG_QUERY and
# APT_GET name those programs (a missing one: not Debian) and DEPS_LOCKS
# the lock files (space-separated).
optional=no
if [ "${1:-}" = --optional ]; then
	optional=yes
	shift
fi
DPKG_QUERY=${DPKG_QUERY:-dpkg-query}
APT_GET=${APT_GET:-apt-get}
DEPS_LOCK_WAIT=${DEPS_LOCK_WAIT:-300}
DEPS_LOCKS=${DEPS_LOCKS:-/var/lib/dpkg/lock-frontend /var/lib/dpkg/lock /var/lib/apt/lists/lock /var/cache/apt/archives/lock}
CC=${CC:-cc}

# Whether a C file including $1 compiles and links with the rest ($2...).
compiles() {
	hdr=$1
	shift
	t=$(mktemp -d) || return 1
	printf '#include <stdarg.h>\n#include <stddef.h>\n#include <stdint.h>\n#include <setjmp.h>\n#include <%s>\nint main(void) { return 0; }\n' \
		"$hdr" >"$t/p.c"
	"$CC" -o "$t/p" "$t/p.c" "$@" >/dev/null 2>&1
	rc=$?
	rm -rf "$t"
	return $rc
}
has() { command -v "$1" >/dev/null 2>&1; }
pc() { has pkg-config && pkg-config --exists "$@" 2>/dev/null; }

# Whether what the Debian package provides is here, whatever installed it.
provided() {
	case $1 in
	build-essential) has "$CC" && has make ;;
	pkg-config) has pkg-config ;;
	libpng-dev) pc libpng || compiles png.h -lpng ;;
	zlib1g-dev) pc zlib || compiles zlib.h -lz ;;
	libstb-dev) compiles stb/stb_image.h ;;
	libcmocka-dev) pc cmocka || compiles cmocka.h -lcmocka ;;
	libisal-dev) compiles isa-l/igzip_lib.h -lisal ;;
	libzip-dev) pc libzip || compiles zip.h -lzip ;;
	libembree-dev) compiles embree3/rtcore.h -lembree3 ;;
	freeglut3-dev) pc glut gl ;;
	valgrind | python3 | povray | parallel | rsync | xdotool | xauth | bc) has "$1" ;;
	chromium) has chromium || has chromium-browser ;;
	mingw-w64) has x86_64-w64-mingw32-gcc-posix ;;
	wine) has wine ;;
	wine64) has wine64 || [ -x /usr/lib/wine/wine64 ] ;;
	dpkg-dev) has dpkg-source ;;
	emscripten) has emcc ;;
	nodejs) has node ;;
	npm) has npm ;;
	node-acorn) [ -f /usr/share/nodejs/acorn/package.json ] ;;
	openssh-client) has ssh ;;
	openssh-server) has sshd || [ -x /usr/sbin/sshd ] ;;
	xvfb) has Xvfb ;;
	imagemagick) has convert && has compare ;;
	man-db) has man ;;
	povray-includes) [ -f /usr/share/povray-3.7/include/colors.inc ] ;;
	fonts-liberation) [ -d /usr/share/fonts/truetype/liberation ] ;;
	*) return 1 ;;
	esac
}

debian=no
has "$DPKG_QUERY" && has "$APT_GET" && debian=yes
missing=""
for pkg in "$@"; do
	if [ $debian = yes ]; then
		case $("$DPKG_QUERY" -W -f='${Status}' "$pkg" 2>/dev/null) in
		*"install ok installed"*) continue ;;
		esac
	fi
	provided "$pkg" || missing="$missing $pkg"
done
[ -z "$missing" ] && exit 0

if [ $debian = no ]; then
	if [ "$optional" = yes ]; then
		echo "deps: not found (optional: what needs them does without):$missing" >&2
		exit 0
	fi
	echo "deps: not found:$missing (Debian's package names; not a Debian system, so nothing is" >&2
	echo "  installed: install what provides them with this system's package manager)" >&2
	exit 1
fi

# Whether one of the package locks is held (a POSIX lock, as apt takes:
# its inode in /proc/locks), and by which process.
lock_holder() {
	for f in $DEPS_LOCKS; do
		[ -e "$f" ] || continue
		ino=$(stat -c %i "$f" 2>/dev/null) || continue
		pid=$(awk -v ino="$ino" '{ n = split($6, a, ":"); if (a[n] == ino) { print $5; exit } }' \
			/proc/locks 2>/dev/null)
		if [ -n "$pid" ]; then
			printf '%s' "$pid"
			return 0
		fi
	done
	return 1
}

# Waits while another apt holds the lock, up to DEPS_LOCK_WAIT seconds.
wait_for_lock() {
	waited=0
	said=no
	while pid=$(lock_holder); do
		if [ $said = no ]; then
			name=$(cat "/proc/$pid/comm" 2>/dev/null)
			echo "deps: waiting for the package lock, held by process $pid${name:+ ($name)}:" \
				"another apt, or unattended-upgrades on a new machine (up to $DEPS_LOCK_WAIT s)" >&2
			said=yes
		fi
		if [ "$waited" -ge "$DEPS_LOCK_WAIT" ]; then
			echo "deps: the package lock is still held after $DEPS_LOCK_WAIT s; run make again" \
				"once the other apt has finished (or set DEPS_LOCK_WAIT)" >&2
			return 1
		fi
		sleep 1
		waited=$((waited + 1))
	done
	[ $said = yes ] && echo "deps: the package lock is free" >&2
	return 0
}

if [ "$(id -u)" = 0 ]; then
	echo "deps: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	if wait_for_lock &&
		"$APT_GET" -o DPkg::Lock::Timeout="$DEPS_LOCK_WAIT" update -qq >/dev/null &&
		"$APT_GET" -o DPkg::Lock::Timeout="$DEPS_LOCK_WAIT" install -y -qq --no-install-recommends $missing >/dev/null; then
		exit 0
	fi
	echo "deps: apt-get install$missing failed" >&2
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
