#!/bin/bash
# `make install` into a scratch prefix, then the installed tree as a user of
# the library sees it: the programs, libwhitted.a, whitted.pc, the headers and
# the man pages are there; the headers are only include/whitted/ and include
# nothing private (the tree's base/, cli/, test or thread headers); each
# compiles on its own with -I PREFIX/include alone; and a program built
# outside the tree with `pkg-config --cflags --libs whitted` renders scenes
# through the public API to the very bytes build/whitted writes.  A staged
# install (DESTDIR) keeps PREFIX in whitted.pc.
SUITE=install-test
. "$(dirname "$0")/lib.sh"
CC=${CC:-cc}
P=$T/prefix
mkdir -p "$P"
quiet() { "$@" >/dev/null 2>&1; }

# Installs with the tree's own make; `make install` depends on `all`, which
# make check has built already.
if ! make -C "$ROOT" --no-print-directory install PREFIX="$P" >"$T/install.log" 2>&1; then
	bad "make install PREFIX=$P" "$(tail -5 "$T/install.log")"
	finish
fi
ok

# The installed tree.
for f in bin/whitted bin/scene2pov; do
	check "installed $f is executable" [ -x "$P/$f" ]
done
if [ -x "$ROOT/build/whitted-view" ]; then
	check "installed bin/whitted-view is executable" [ -x "$P/bin/whitted-view" ]
fi
check "installed lib/libwhitted.a" [ -f "$P/lib/libwhitted.a" ]
check "installed lib/libwhitted.a is build/libwhitted.a" cmp -s "$P/lib/libwhitted.a" "$ROOT/build/libwhitted.a"
check "installed lib/pkgconfig/whitted.pc" [ -f "$P/lib/pkgconfig/whitted.pc" ]
check "installed bin/whitted runs" quiet "$P/bin/whitted" --version
n_src=$(cd "$ROOT/include/whitted" && ls -- *.h | wc -l)
n_inst=$(cd "$P/include/whitted" 2>/dev/null && ls -- *.h | wc -l)
[ "$n_src" -gt 0 ] && [ "$n_inst" -eq "$n_src" ]
check "installed include/whitted/*.h: $n_inst of $n_src headers" [ $? -eq 0 ]
for h in "$ROOT"/include/whitted/*.h; do
	check "installed include/whitted/${h##*/} is the tree's" cmp -s "$h" "$P/include/whitted/${h##*/}"
done
extra=$(cd "$P/include" && find . -type f ! -path './whitted/*.h')
check "nothing but whitted/*.h under include/ ($extra)" [ -z "$extra" ]
for m in "$ROOT"/docs/man/*.1; do
	check "installed share/man/man1/${m##*/}" cmp -s "$m" "$P/share/man/man1/${m##*/}"
done
for prog in whitted scene2pov whitted-view; do
	check "installed share/man/man1/$prog.1" [ -f "$P/share/man/man1/$prog.1" ]
done
if command -v man >/dev/null 2>&1; then
	check "man finds whitted(1) in PREFIX/share/man" \
		quiet env MAN_DISABLE_SECCOMP=1 man --manpath="$P/share/man" -w whitted
fi

# The headers: only standard C headers and each other; nothing private.
C99_HEADERS=" assert.h complex.h ctype.h errno.h fenv.h float.h inttypes.h iso646.h limits.h \
locale.h math.h setjmp.h signal.h stdarg.h stdbool.h stddef.h stdint.h stdio.h \
stdlib.h string.h tgmath.h time.h wchar.h wctype.h "
for h in "$P"/include/whitted/*.h; do
	name=${h##*/}
	bad_inc=""
	while read -r inc; do
		case $inc in
		'<'*'>')
			i=${inc#<}
			i=${i%>}
			case $C99_HEADERS in *" $i "*) ;; *) bad_inc="$bad_inc $inc" ;; esac ;;
		'"whitted/'*'"' | '"'*'"')
			i=${inc#\"}
			i=${i%\"}
			i=${i#whitted/}
			case $i in */*) bad_inc="$bad_inc $inc" ;; *) [ -f "$P/include/whitted/$i" ] || bad_inc="$bad_inc $inc" ;; esac ;;
		*) bad_inc="$bad_inc $inc" ;;
		esac
	done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*\([<"][^>"]*[>"]\).*/\1/p' "$h")
	if [ -z "$bad_inc" ]; then ok
	else bad "$name" "includes what is neither standard C99 nor an installed whitted/ header:$bad_inc"
	fi
	hits=$(grep -nE '"base/|alloc\.h|rt_alloc_fail_from|getopt|pthread|"cli/|cli\.h|support\.h|cmocka|_impl\.h|_private\.h' "$h")
	if [ -z "$hits" ]; then ok
	else bad "$name" "mentions something private (base/, alloc, getopt, pthread, cli, test support): $(echo $hits)"
	fi
	# On its own (twice, for the include guard), with the installed tree only.
	printf '#include <whitted/%s>\n#include <whitted/%s>\nint rt_install_test_dummy;\n' "$name" "$name" >"$T/one.c"
	if "$CC" -std=c99 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$P/include" "$T/one.c" 2>"$T/cc.err"; then
		ok
	else
		bad "$name compiles on its own" "$(grep -m 2 -E "error|warning" "$T/cc.err")"
	fi
done

# pkg-config.
export PKG_CONFIG_PATH=$P/lib/pkgconfig
unset PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR
version=$(sed -n 's/^#define RT_VERSION "\(.*\)"/\1/p' "$ROOT/include/whitted/version.h")
check "pkg-config --validate whitted" quiet pkg-config --validate whitted
check "pkg-config --modversion whitted is $version" [ "$(pkg-config --modversion whitted 2>&1)" = "$version" ]
check "pkg-config prefix is PREFIX" [ "$(pkg-config --variable=prefix whitted 2>&1)" = "$P" ]
check "whitted --version is $version" [ "$("$P/bin/whitted" --version)" = "whitted $version" ]
cflags=$(pkg-config --cflags whitted) libs=$(pkg-config --libs whitted)
case " $cflags $libs " in
*" -I$ROOT"* | *" -L$ROOT"*) bad "pkg-config names the source tree" "$cflags $libs" ;;
*) ok ;;
esac

# A program outside the tree, built with nothing but pkg-config's flags.
APP=$T/app
mkdir -p "$APP"
cp "$ROOT/tests/cli/install-app.c" "$APP/main.c"
if (cd "$APP" && $CC -std=c99 -Wall -Wextra -Wpedantic -Werror -o app main.c $cflags $libs) 2>"$T/cc.err"; then
	ok
	# The scenes: the course's example, quadrics, a file read with notes,
	# and the built-in test scene.
	render_same() {
		local name=$1 size=$2 scene=$3
		shift 3
		if ! (cd "$APP" && ./app "$scene" "$size" app.ppm) 2>"$T/app.err"; then
			bad "app renders $name" "$(cat "$T/app.err")"
			return
		fi
		if ! "$W" -q -s "$size" -o "$APP/cli.ppm" "$scene" 2>"$T/cli.err"; then
			bad "build/whitted renders $name" "$(cat "$T/cli.err")"
			return
		fi
		check "app's $name at $size is byte-identical to build/whitted's PPM" cmp "$APP/app.ppm" "$APP/cli.ppm"
		[ "$(head -c 2 "$APP/app.ppm")" = P6 ] && [ "$(wc -c <"$APP/app.ppm")" -gt $((size * size * 3)) ]
		check "app's $name is a ${size}x$size PPM" [ $? -eq 0 ]
		"$P/bin/whitted" -q -s "$size" -o "$APP/inst.ppm" "$scene" 2>/dev/null
		check "installed bin/whitted's $name is build/whitted's" cmp -s "$APP/inst.ppm" "$APP/cli.ppm"
	}
	render_same scene.txt 64 "$ROOT/scenes/scene.txt"
	render_same quadric.txt 48 "$ROOT/scenes/quadric.txt"
	render_same mirrors.txt 40 "$ROOT/scenes/mirrors.txt"
	render_same anachor.txt 32 "$DATA/real-scenes/anachor.txt"
	render_same test-scene 32 --test-scene
	# A bad scene fails with its location, through the API's diagnostics.
	printf '4\n16\n1\nsphere\n0 0 10\n-3\n' >"$APP/bad.txt"
	(cd "$APP" && ./app bad.txt 16 bad.ppm) 2>"$T/app.err"
	[ $? -eq 1 ] && grep -q '^bad.txt:6:[0-9]*: error: sphere radius' "$T/app.err" && [ ! -e "$APP/bad.ppm" ]
	check "app on a bad scene: exit 1, bad.txt:6:COL: error:, no image ($(cat "$T/app.err"))" [ $? -eq 0 ]
else
	bad "a program outside the tree builds with pkg-config --cflags --libs whitted ($cflags $libs)" \
		"$(grep -m 3 -E 'error|warning|undefined|cannot find' "$T/cc.err")"
fi

# Plugins: the example plugins installed, and docs/plugins.md's tutorial
# plugin built outside the tree with pkg-config's flags alone, loaded by the
# installed programs: the same image with 1, 2 and 7 threads and from
# merged tiles, POV-Ray's image of scene2pov's export alike (when povray
# is there: make check installs it), and valgrind clean.
check "pkg-config --variable=plugindir whitted is PREFIX/lib/whitted/plugins" \
	[ "$(pkg-config --variable=plugindir whitted)" = "$P/lib/whitted/plugins" ]
for so in quad cylinder torus; do
	check "installed lib/whitted/plugins/$so.so" cmp -s "$ROOT/build/plugins/$so.so" "$P/lib/whitted/plugins/$so.so"
done
TUT=$T/tutorial
mkdir -p "$TUT"
if "$ROOT/tests/plugins/build-tutorial.sh" "$TUT" 2>"$T/cc.err"; then
	ok
	cat >"$TUT/discs.txt" <<'SCENE'
2
96

3
disc
0 0 30
0 -1 1
40
0.9 0.6 0.1
0.2 0.6 0.4 0.2
20
torus
-60 20 20
0 0 1
25 8
0.2 0.4 0.9
0.2 0.7 0.2 0
4
disc
60 0 1
0 0 1
30
1 1 1
0 0 0 0.8
1
1
-100 -150 200
1 1 1
SCENE
	cd "$TUT" || exit 1
	export WHITTED_PLUGIN_PATH="$P/lib/whitted/plugins"
	run_tut() { "$P/bin/whitted" -q --plugin ./disc.so "$@" discs.txt; }
	run_tut -j1 -o j1.png && run_tut -j2 -o j2.png && run_tut -j7 -o j7.png
	check "the tutorial plugin renders (installed whitted, --plugin and WHITTED_PLUGIN_PATH)" [ $? -eq 0 -a -s j1.png ]
	check "the tutorial plugin: -j1, -j2 and -j7 give the same image" \
		bash -c 'cmp -s j1.png j2.png && cmp -s j1.png j7.png'
	for k in 1 2 3; do run_tut -j2 --grid 1x3 --tile $k -o tile-$k.png || bad "tile $k" "failed"; done
	"$P/bin/whitted" merge -o merged.png tile-1.png tile-2.png tile-3.png &&
		cmp -s j1.png merged.png
	check "the tutorial plugin: tiles merged give the same image" [ $? -eq 0 ]
	strings tile-1.png | grep -q 'plugins=disc@1.0#[0-9a-f]\{16\},torus@1.0#'
	check "its tiles record disc and torus" [ $? -eq 0 ]
	"$P/bin/whitted" --list-shapes --plugin ./disc.so | grep -q '^disc  *plugin disc 1.0 (./disc.so)'
	check "--list-shapes names the tutorial plugin" [ $? -eq 0 ]
	"$P/bin/scene2pov" -q --plugin ./disc.so -s 96 -o discs.pov discs.txt &&
		grep -q '^disc { <0,0,30>, <0,-0.7071067811865475,0.7071067811865475>, 40$' discs.pov
	check "installed scene2pov exports the disc" [ $? -eq 0 ]
	if command -v povray >/dev/null 2>&1; then
		mkdir -p home
		"$P/bin/whitted" -q --clamp final --plugin ./disc.so -o final.png discs.txt &&
			HOME=$TUT/home povray discs.ini +WT2 -V >pov.log 2>&1 &&
			"$ROOT/build/imgcmp" final.png discs.png >imgcmp.txt
		check "the tutorial scene matches POV-Ray ($(cat imgcmp.txt 2>/dev/null))" [ $? -eq 0 ]
	else
		bad "the tutorial scene against POV-Ray" "NOT RUN: povray is not installed (make deps)"
	fi
	if command -v valgrind >/dev/null 2>&1; then
		valgrind -q --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all \
			--error-exitcode=99 "$P/bin/whitted" -q -j2 -s 24 --plugin ./disc.so -o vg.png discs.txt \
			2>vg.log
		check "the tutorial plugin under valgrind: clean ($(head -c 400 vg.log))" [ $? -eq 0 -a ! -s vg.log ]
	else
		bad "the tutorial plugin under valgrind" "NOT RUN: valgrind is not installed (make deps)"
	fi
	unset WHITTED_PLUGIN_PATH
	cd "$T" || exit 1
else
	bad "docs/plugins.md's disc.c builds with pkg-config --cflags whitted" "$(head -5 "$T/cc.err")"
fi

# A staged install: files under DESTDIR, whitted.pc still naming PREFIX.
S=$T/stage
if make -C "$ROOT" --no-print-directory install DESTDIR="$S" PREFIX=/opt/whitted >"$T/install.log" 2>&1; then
	check "DESTDIR install: bin/whitted" [ -x "$S/opt/whitted/bin/whitted" ]
	check "DESTDIR install: whitted.pc names PREFIX, not DESTDIR" \
		grep -qx 'prefix=/opt/whitted' "$S/opt/whitted/lib/pkgconfig/whitted.pc"
else
	bad "make install DESTDIR=$S PREFIX=/opt/whitted" "$(tail -5 "$T/install.log")"
fi
finish
