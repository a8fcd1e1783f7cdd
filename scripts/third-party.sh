#!/bin/sh
# The C sources that the cross builds (make web, make windows) compile in
# with the library: zlib and libpng from Debian's source packages, and
# stb_image from libstb-dev's header.  Debian's emscripten cannot fetch
# its own ports (no network at build time), and MinGW-w64 has no libpng
# package, so both build these sources themselves, the same files for
# both.  Usage: scripts/third-party.sh DIR
#
# DIR/zlib/ and DIR/libpng/ get the unpacked sources (Debian's patches
# applied by dpkg-source), DIR/include/stb/ the stb header.  The source
# packages are fetched with apt-get source through a private apt state
# under DIR/apt (deb-src lines made from this system's deb lines, the
# security suite left out), so nothing of the system's apt set-up is
# changed and no root is needed; a second run finds them there.
set -eu
dir=${1:?usage: scripts/third-party.sh DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)

if [ ! -f "$dir/include/stb/stb_image.h" ]; then
	if [ ! -f /usr/include/stb/stb_image.h ]; then
		echo "third-party: /usr/include/stb/stb_image.h not found (Debian: libstb-dev; make deps)" >&2
		exit 1
	fi
	mkdir -p "$dir/include/stb"
	cp /usr/include/stb/stb_image.h "$dir/include/stb/"
fi
[ -f "$dir/zlib/zlib.h" ] && [ -f "$dir/libpng/png.h" ] && exit 0

for t in apt-get dpkg-source; do
	if ! command -v $t >/dev/null 2>&1; then
		echo "third-party: $t is needed to fetch zlib and libpng from Debian's sources (Debian: apt, dpkg-dev)" >&2
		exit 1
	fi
done
apt=$dir/apt
rm -rf "$apt"
mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial" "$apt/parts" "$apt/dl"
# Each deb stanza of the system's sources as a deb-src one; the security
# archive keeps no source of superseded versions, so it is left out.
found=no
for f in /etc/apt/sources.list.d/*.sources; do
	[ -f "$f" ] || continue
	awk 'BEGIN { RS = ""; ORS = "\n\n" } /debian-security/ { next }
		/Types:[^\n]*deb/ { sub(/Types:[^\n]*/, "Types: deb-src"); print }' "$f" >>"$apt/parts/src.sources"
	found=yes
done
if [ -f /etc/apt/sources.list ]; then
	sed -n 's/^deb \(.*\)/deb-src \1/p' /etc/apt/sources.list | grep -v security >"$apt/parts/src.list" || true
	[ -s "$apt/parts/src.list" ] && found=yes
fi
if [ $found = no ]; then
	echo "third-party: no Debian package sources found in /etc/apt" >&2
	exit 1
fi
set -- -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$apt/parts" \
	-o Dir::State::Lists="$apt/lists" -o Dir::Cache="$apt/cache" -o APT::Sandbox::User=root -qq
echo "third-party: fetching Debian's sources of zlib and libpng1.6"
apt-get "$@" update
(cd "$apt/dl" && apt-get "$@" source --download-only zlib libpng1.6 >/dev/null)
for pkg in zlib libpng1.6; do
	dsc=$(ls "$apt/dl/${pkg}_"*.dsc | head -n 1)
	name=${pkg%1.6}
	rm -rf "$dir/$name"
	dpkg-source --no-check -x "$dsc" "$dir/$name" >/dev/null
done
cp "$dir/libpng/scripts/pnglibconf.h.prebuilt" "$dir/libpng/pnglibconf.h"
echo "third-party: $dir/zlib $dir/libpng"
